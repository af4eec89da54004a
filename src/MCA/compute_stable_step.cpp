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

#include "compute_stable_step.h"

#include "error.h"
#include "update.h"

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

ComputeStableStep::ComputeStableStep(LAMMPS *lmp, int narg, char **arg, int nvalues) :
    Compute(lmp, narg, arg)
{
  if (narg != 3) error->all(FLERR, "Compute {} takes no arguments, got {}", style, narg - 3);
  scalar_flag = vector_flag = 1;
  size_vector = nvalues;
  extscalar = extvector = 0;
  vector = new double[nvalues];
}

ComputeStableStep::~ComputeStableStep()
{
  delete[] vector;
}

/* ---------------------------------------------------------------------- */

double ComputeStableStep::compute_scalar()
{
  compute_vector();
  invoked_scalar = update->ntimestep;
  scalar = vector[0];
  return scalar;
}

void ComputeStableStep::compute_vector()
{
  invoked_vector = update->ntimestep;
  if (!estimate(vector)) error->all(FLERR, "Compute {}: {}", style, not_ready);
}
