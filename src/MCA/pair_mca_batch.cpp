/* ----------------------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   LAMMPS development team: developers@lammps.org

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   The elastic link pass of pair mca over batches of links
   (mca_link_batch.h).  cmake/Modules/Packages/MCA.cmake compiles this
   file, with GCC or Clang, with -O3 (the loop vectorizer and the complete
   unrolling of the law's small loops), -fno-math-errno and
   -fno-trapping-math (so that sqrt and the law's guarded divisions need
   no branch), and -ffp-contract=off (no multiply-add is contracted: each
   column computes what the scalar pass computes, bit for bit, whatever
   instruction set the build targets).  With GCC on x86-64 Linux the loop
   is compiled twice, for AVX2 and for the build's target, and the loader
   picks the one the processor runs (target_clones).
------------------------------------------------------------------------- */

#include "pair_mca.h"
#include "pair_mca_host.h"

#include "mca_link_batch.h"

using namespace LAMMPS_NS;
using namespace MCAKernels;

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define MCA_BATCH_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define MCA_BATCH_CLONES
#endif

// the law on every column of a batch, the twist by its series (a link whose
// twist is beyond the series' range is marked and evaluated again)
MCA_BATCH_CLONES void MCAKernels::evaluate_link_batch(MCALinkBatch &b, double dt)
{
  for (int k = 0; k < MCALinkBatch::W; k++) {
    MCASeriesTwist twist;
    batch_link(b, k, dt, twist);
    b.beyond[k] = twist.beyond ? 1.0 : 0.0;
  }
}

/* ----------------------------------------------------------------------
   the batched pass computes what link_pass_of<LAW_ELASTIC> computes: the
   elastic law alone (no damping, whose block the batch does not carry),
   rows stored in doubles (precision mixed decodes each row)
------------------------------------------------------------------------- */

bool PairMCA::batched_link_pass_applies() const
{
  const MCALinkLayout &layout = model.layout();
  return batch_links && !layout.mixed && layout.link_offset[PART_DAMPING] < 0 &&
      layout.link_offset[PART_PLASTICITY] < 0;
}

void PairMCA::batched_link_pass(const HostData &d, const HostLinkSums &sums, const HostTally &tally,
                                const MCALinkPassFlags &p, MCAHostTotals &totals)
{
  MCALinkBatch batch;
  link_pass_batched(evaluate_link_batch, batch, d, sums, tally, p, totals, 0, d.nlocal);
}
