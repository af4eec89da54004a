// clang-format off
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
// clang-format on

#include "compute_mca_fracture.h"

#include "atom.h"
#include "atom_vec_mca.h"
#include "error.h"
#include "fix_mca_links.h"
#include "mca_compat.h"
#include "mca_link_law.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace MCAKernels;

// the vector: links broken (all criteria), by criterion (BreakCriterion
// order), and the elastic energy their breaks released
static constexpr int NVALUES = 1 + (NBREAK - 1) + 1;

/* ----------------------------------------------------------------------
   compute ID group mca/fracture
   each automaton in the group counts half of each of its broken links
------------------------------------------------------------------------- */

ComputeMCAFracture::ComputeMCAFracture(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), links(nullptr)
{
  if (narg != 3) error->all(FLERR, "Compute mca/fracture takes no arguments, got {}", narg - 3);
  if (!MCAAtomFields::find(atom))
    error->all(FLERR, "Compute mca/fracture requires atom_style mca, not {}", atom->atom_style);
  vector_flag = 1;
  size_vector = NVALUES;
  extvector = 1;
  vector = new double[NVALUES];
}

/* ---------------------------------------------------------------------- */

ComputeMCAFracture::~ComputeMCAFracture()
{
  delete[] vector;
}

/* ---------------------------------------------------------------------- */

void ComputeMCAFracture::init()
{
  links = dynamic_cast<FixMCALinks *>(MCACompat::fix_by_id(modify, "MCA_LINKS"));
  if (!links) error->all(FLERR, "Compute mca/fracture requires pair_style mca (it has no links)");
  if (links->model.layout().link_offset[PART_FRACTURE] < 0)
    error->all(FLERR,
               "Compute mca/fracture requires the fracture part of pair_style mca ('fracture "
               "links'); the link model is: {}",
               links->model.names());
}

/* ----------------------------------------------------------------------
   each link is counted by both of its automata (its row, or what they
   kept of a forgotten link), so the sums are halved
------------------------------------------------------------------------- */

void ComputeMCAFracture::compute_vector()
{
  invoked_vector = update->ntimestep;
  links->to_host();
  const int ff = links->model.layout().link_offset[PART_FRACTURE];
  const int fa = links->model.layout().atom_offset[PART_FRACTURE];
  double local[NVALUES] = {0.0};
  double work[MAX_ROW_SIZE];
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    for (int m = 0; m < links->nlinks[i]; m++) {
      if (links->link_state(i, m) != LINK_BROKEN) continue;
      const double *row = links->read_row(i, m, work);
      const int cause = static_cast<int>(row[ff + F_CAUSE]);
      if (cause > BREAK_NONE && cause < NBREAK) local[cause] += 1.0;
      local[NVALUES - 1] += row[ff + F_RELEASED];
    }
    const double *state = links->atom_state[i];
    for (int c = 1; c < NBREAK; c++) local[c] += state[fa + FA_FORGOTTEN + c - 1];
    local[NVALUES - 1] += state[fa + FA_RELEASED];
  }
  for (int c = 1; c < NBREAK; c++) local[0] += local[c];
  MPI_Allreduce(local, vector, NVALUES, MPI_DOUBLE, MPI_SUM, world);
  for (int k = 0; k < NVALUES; k++) vector[k] *= 0.5;
}
