/* -*- c++ -*- ----------------------------------------------------------
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
   The elastic link pass on several links at once (the CPU style, and the
   kk style on host threads: host only):
   the links the automata evaluate are taken MCA_LINK_BATCH at a time, in
   the order of link_pass_of; what the law reads of each is copied into
   the columns of a batch (one column a link), the law (linked_pair, the
   same function as every pass) runs over the columns in a loop the
   compiler can vectorize, and what each link gives its automata is added
   in the same order as link_pass_of adds it: the same numbers, bit for
   bit, where the compiler contracts no multiply-add (pair_mca_batch.cpp
   and cmake/Modules/Packages/MCA.cmake say how that file is compiled).
   For the elastic law alone, precision double, without damping
   (PairMCA::batched_link_pass_applies).
------------------------------------------------------------------------- */

#ifndef LMP_MCA_LINK_BATCH_H
#define LMP_MCA_LINK_BATCH_H

#include "mca_link_passes.h"

namespace LAMMPS_NS {
namespace MCAKernels {

#ifndef MCA_LINK_BATCH
#define MCA_LINK_BATCH 8
#endif

// the loops over a row's 24 values unrolled completely, so that its values
// become scalars of the vectorized loop (GCC peels 16 iterations at most)
#if defined(__GNUC__) && !defined(__clang__)
#define MCA_UNROLL_ROW _Pragma("GCC unroll 32")
#else
#define MCA_UNROLL_ROW
#endif

  // the layout the law sees in a batch: the elastic block only, known to
  // the compiler, so that no test of an optional part is left in the loop
  // (the rows may hold blocks of fracture, contacts or healing after it:
  // the elastic law does not read them)
  constexpr MCALinkLayout BATCH_LAYOUT = {H_SIZE,
                                          A_SIZE,
                                          {0, -1, -1, -1, -1, -1, -1, -1},
                                          {0, -1, -1, -1, -1, -1, -1, -1},
                                          0,
                                          H_SIZE,
                                          0,
                                          {0u, 0u, 0u, 0u}};

  /* the columns of a batch: a value of every link of the batch in a row
     of W doubles, read and written with unit stride by the vectorized
     loop.  In: the elastic block of the row, the ends (x and omega of lo
     and hi), the mean stresses, the face factor and the materials.  Out:
     what MCALinkForces holds that the automata are given, and the row   */

  struct MCALinkBatch {
    static constexpr int W = MCA_LINK_BATCH;
    enum EndColumn { E_XLO = 0, E_XHI = 3, E_WLO = 6, E_WHI = 9, E_SIZE = 12 };
    enum MeanColumn { M_DSMLO = 0, M_DSMHI, M_SMLO, M_SMHI, M_SIZE };
    enum MaterialColumn { MAT_SHEAR = 0, MAT_BULK, MAT_COUPLING, MAT_SIZE };
    enum OutColumn { O_F = 0, O_TQLO = 3, O_TQHI = 6, O_TRAC = 9, O_N = 12, O_R = 15, O_SIZE = 16 };

    double h[H_SIZE][W];
    double ends[E_SIZE][W];
    double mean[M_SIZE][W];
    double chi[W];
    double mat_lo[MAT_SIZE][W], mat_hi[MAT_SIZE][W];
    double out[O_SIZE][W];
    // 1 where the twist of the link is beyond the series' range (a double:
    // SSE2 turns a comparison of doubles into a double, not into an int)
    double beyond[W];

    // the links of the batch: row, automaton, partner, ends
    double *row[W];
    int i[W], j[W], lo[W], hi[W];
    int n = 0;
  };

  // column k of a batch: what link_ends_of and the materials give the law
  template <class D> inline void batch_fill(MCALinkBatch &b, const D &d, int k)
  {
    const double *row = b.row[k];
    for (int s = 0; s < H_SIZE; s++) b.h[s][k] = row[s];
    const int lo = b.lo[k], hi = b.hi[k];
    double scratch[12];
    const double *x_lo = d.x_row(lo, scratch), *x_hi = d.x_row(hi, scratch + 3);
    const double *w_lo = d.omega_row(lo, scratch + 6), *w_hi = d.omega_row(hi, scratch + 9);
    for (int m = 0; m < 3; m++) {
      b.ends[MCALinkBatch::E_XLO + m][k] = x_lo[m];
      b.ends[MCALinkBatch::E_XHI + m][k] = x_hi[m];
      b.ends[MCALinkBatch::E_WLO + m][k] = w_lo[m];
      b.ends[MCALinkBatch::E_WHI + m][k] = w_hi[m];
    }
    b.mean[MCALinkBatch::M_DSMLO][k] = d.dsmean(lo);
    b.mean[MCALinkBatch::M_DSMHI][k] = d.dsmean(hi);
    b.mean[MCALinkBatch::M_SMLO][k] = d.smean_pred(lo);
    b.mean[MCALinkBatch::M_SMHI][k] = d.smean_pred(hi);
    b.chi[k] = face_moment_factor(d.packing(lo));
    const MCAMaterial &m_lo = d.material(d.type(lo)), &m_hi = d.material(d.type(hi));
    b.mat_lo[MCALinkBatch::MAT_SHEAR][k] = m_lo.shear;
    b.mat_lo[MCALinkBatch::MAT_BULK][k] = m_lo.bulk;
    b.mat_lo[MCALinkBatch::MAT_COUPLING][k] = m_lo.coupling;
    b.mat_hi[MCALinkBatch::MAT_SHEAR][k] = m_hi.shear;
    b.mat_hi[MCALinkBatch::MAT_BULK][k] = m_hi.bulk;
    b.mat_hi[MCALinkBatch::MAT_COUPLING][k] = m_hi.coupling;
  }

  // the material the elastic law reads (shear, bulk, coupling) from columns
  MCA_FORCE_INLINE MCAMaterial batch_material(const double (*col)[MCALinkBatch::W], int k)
  {
    MCAMaterial m = {};
    m.shear = col[MCALinkBatch::MAT_SHEAR][k];
    m.bulk = col[MCALinkBatch::MAT_BULK][k];
    m.coupling = col[MCALinkBatch::MAT_COUPLING][k];
    return m;
  }

  MCA_FORCE_INLINE void batch_ends(const MCALinkBatch &b, int k, double dt, double *xw,
                                   MCALinkEnds &e)
  {
    for (int m = 0; m < 12; m++) xw[m] = b.ends[m][k];
    e.x_lo = xw + MCALinkBatch::E_XLO;
    e.x_hi = xw + MCALinkBatch::E_XHI;
    e.w_lo = xw + MCALinkBatch::E_WLO;
    e.w_hi = xw + MCALinkBatch::E_WHI;
    e.dsm_lo = b.mean[MCALinkBatch::M_DSMLO][k];
    e.dsm_hi = b.mean[MCALinkBatch::M_DSMHI][k];
    e.sm_lo = b.mean[MCALinkBatch::M_SMLO][k];
    e.sm_hi = b.mean[MCALinkBatch::M_SMHI][k];
    e.chi = b.chi[k];
    e.dt = dt;
    e.layout = &BATCH_LAYOUT;
  }

  MCA_FORCE_INLINE void batch_store(MCALinkBatch &b, int k, const double *h,
                                    const MCALinkForces &out)
  {
    MCA_UNROLL_ROW
    for (int s = 0; s < H_SIZE; s++) b.h[s][k] = h[s];
    for (int m = 0; m < 3; m++) {
      b.out[MCALinkBatch::O_F + m][k] = out.f[m];
      b.out[MCALinkBatch::O_TQLO + m][k] = out.tq_lo[m];
      b.out[MCALinkBatch::O_TQHI + m][k] = out.tq_hi[m];
      b.out[MCALinkBatch::O_TRAC + m][k] = out.trac[m];
      b.out[MCALinkBatch::O_N + m][k] = out.n[m];
    }
    b.out[MCALinkBatch::O_R][k] = out.r;
  }

  // the law on column k: with the series of the twist (the vectorized
  // loop), or exactly (a link whose twist is beyond the series' range)
  template <class Twist>
  MCA_FORCE_INLINE void batch_link(MCALinkBatch &b, int k, double dt, Twist &twist)
  {
    double h[H_SIZE], xw[12];
    MCA_UNROLL_ROW
    for (int s = 0; s < H_SIZE; s++) h[s] = b.h[s][k];
    MCALinkEnds e;
    batch_ends(b, k, dt, xw, e);
    const MCAMaterial m_lo = batch_material(b.mat_lo, k), m_hi = batch_material(b.mat_hi, k);
    MCALinkForces out;
    linked_pair(h, e, m_lo, m_hi, out, twist);
    batch_store(b, k, h, out);
  }

  // what column k gives the automata (the forces the law left in it)
  MCA_FORCE_INLINE void batch_forces(const MCALinkBatch &b, int k, MCALinkForces &out)
  {
    for (int m = 0; m < 3; m++) {
      out.f[m] = b.out[MCALinkBatch::O_F + m][k];
      out.tq_lo[m] = b.out[MCALinkBatch::O_TQLO + m][k];
      out.tq_hi[m] = b.out[MCALinkBatch::O_TQHI + m][k];
      out.trac[m] = b.out[MCALinkBatch::O_TRAC + m][k];
      out.n[m] = b.out[MCALinkBatch::O_N + m][k];
    }
    out.r = b.out[MCALinkBatch::O_R][k];
  }

  // the law on the columns of a batch: the vectorized loop
  // (pair_mca_batch.cpp, compiled for it)
  void evaluate_link_batch(MCALinkBatch &b, double dt);

  /* the pass: Evaluate is the loop over the columns (evaluate_link_batch).
     A batch that is not full repeats its first link in the columns left,
     whose results nobody reads                                           */

  // (the automata first to last - 1: all local ones, or a chunk of them on
  // host threads, as the kk styles' chunked sums take them)
  template <class Evaluate, class D, class Sums, class Tally, class Totals>
  void link_pass_batched(Evaluate evaluate, MCALinkBatch &b, const D &d, const Sums &sums,
                         const Tally &tally, const MCALinkPassFlags &p, Totals &totals, int first,
                         int last)
  {
    constexpr int W = MCALinkBatch::W;
    auto run = [&]() {
      for (int k = 0; k < b.n; k++) batch_fill(b, d, k);
      for (int k = b.n; k < W; k++) {
        b.row[k] = b.row[0];
        b.lo[k] = b.lo[0];
        b.hi[k] = b.hi[0];
        batch_fill(b, d, k);
      }
      evaluate(b, p.dt);
      for (int k = 0; k < b.n; k++) {
        if (b.beyond[k] != 0.0) {
          // again from the stored row, with cos() and sin()
          batch_fill(b, d, k);
          MCAExactTwist exact;
          batch_link(b, k, p.dt, exact);
        }
        if (p.commit)
          for (int s = 0; s < H_SIZE; s++) b.row[k][s] = b.h[s][k];
        MCALinkForces out;
        batch_forces(b, k, out);
        auto add = sums.begin(b.i[k]);
        add_link_outputs(d, sums, add, tally, p, b.i[k], b.j[k], b.h[H_WORK][k], out, totals);
      }
      b.n = 0;
    };
    b.n = 0;
    for (int i = first; i < last; i++) {
      for (int m = 0; m < d.nlinks(i); m++) {
        double *row;
        int j;
        if (!evaluates<LINK_LINKED>(d, i, m, row, j)) continue;
        const bool ilo = d.tag(i) < d.tag(j);
        const int k = b.n++;
        b.row[k] = row;
        b.i[k] = i;
        b.j[k] = j;
        b.lo[k] = ilo ? i : j;
        b.hi[k] = ilo ? j : i;
        if (b.n == W) run();
      }
    }
    if (b.n > 0) run();
  }

}    // namespace MCAKernels
}    // namespace LAMMPS_NS

#endif
