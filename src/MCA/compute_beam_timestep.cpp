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

#include "compute_beam_timestep.h"

#include "bond_beam.h"
#include "error.h"
#include "force.h"
#include "update.h"

using namespace LAMMPS_NS;

static constexpr int NVALUES = 5;

/* ----------------------------------------------------------------------
   compute ID group beam/timestep: the stable time step of the scene's
   beams (the group is not used)
------------------------------------------------------------------------- */

ComputeBeamTimestep::ComputeBeamTimestep(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), bond(nullptr)
{
  if (narg != 3) error->all(FLERR, "Compute beam/timestep takes no arguments, got {}", narg - 3);
  scalar_flag = vector_flag = 1;
  size_vector = NVALUES;
  extscalar = extvector = 0;
  vector = new double[NVALUES];
}

ComputeBeamTimestep::~ComputeBeamTimestep()
{
  delete[] vector;
}

void ComputeBeamTimestep::init()
{
  bond = dynamic_cast<BondBeam *>(force->bond);
  if (!bond)
    error->all(FLERR, "Compute beam/timestep requires bond_style beam (or beam/kk), not {}",
               force->bond_style ? force->bond_style : "none");
}

/* ---------------------------------------------------------------------- */

double ComputeBeamTimestep::compute_scalar()
{
  compute_vector();
  invoked_scalar = update->ntimestep;
  scalar = vector[0];
  return scalar;
}

void ComputeBeamTimestep::compute_vector()
{
  invoked_vector = update->ntimestep;
  if (!bond) init();
  BondBeam::StableStep s;
  if (!bond->stable_timestep(s))
    error->all(FLERR,
               "Compute beam/timestep: the estimate is made from the bond list, which is built at "
               "the first run; use 'run 0' before asking for it");
  vector[0] = s.dt;
  vector[1] = update->dt / s.dt;
  vector[2] = s.omega;
  vector[3] = s.zeta;
  vector[4] = (double) s.atom;
}
