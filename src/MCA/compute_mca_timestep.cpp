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

#include "compute_mca_timestep.h"

#include "error.h"
#include "force.h"
#include "pair_mca.h"
#include "update.h"

using namespace LAMMPS_NS;

// the vector: stable time step, recommended time step, the time step
// against the stable one, angular frequency and damping ratio of the
// fastest mode
static constexpr int NVALUES = 5;

/* ----------------------------------------------------------------------
   compute ID group mca/timestep: the stable time step pair mca estimates
   for the whole scene (the group is not used)
------------------------------------------------------------------------- */

ComputeMCATimestep::ComputeMCATimestep(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), pair(nullptr)
{
  if (narg != 3) error->all(FLERR, "Compute mca/timestep takes no arguments, got {}", narg - 3);
  scalar_flag = vector_flag = 1;
  size_vector = NVALUES;
  extscalar = extvector = 0;
  vector = new double[NVALUES];
}

ComputeMCATimestep::~ComputeMCATimestep()
{
  delete[] vector;
}

void ComputeMCATimestep::init()
{
  pair = dynamic_cast<PairMCA *>(force->pair);
  if (!pair)
    error->all(FLERR, "Compute mca/timestep requires pair_style mca (or mca/kk), not {}",
               force->pair_style ? force->pair_style : "none");
}

/* ---------------------------------------------------------------------- */

double ComputeMCATimestep::compute_scalar()
{
  invoked_scalar = update->ntimestep;
  if (!pair) init();
  const MCAStableTimestep::Result *r = pair->stable_timestep();
  if (!r)
    error->all(FLERR,
               "Compute mca/timestep: the stable time step is estimated from the links of pair "
               "mca, which are made at the first run; use 'run 0' before asking for it");
  scalar = r->dt;
  return scalar;
}

void ComputeMCATimestep::compute_vector()
{
  invoked_vector = update->ntimestep;
  const double dt = compute_scalar();
  const MCAStableTimestep::Result *r = pair->stable_timestep();    // (made by compute_scalar)
  vector[0] = dt;
  vector[1] = PairMCA::RECOMMENDED_FRACTION * dt;
  vector[2] = update->dt / dt;
  vector[3] = r->omega;
  vector[4] = r->zeta;
}
