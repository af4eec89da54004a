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

#include "compute_beam_timestep.h"

#include "bond_beam.h"
#include "error.h"
#include "force.h"
#include "update.h"

using namespace LAMMPS_NS;

/* ----------------------------------------------------------------------
   compute ID group beam/timestep: the stable time step of the scene's
   beams (the group is not used): dt, dt_run / dt, omega, zeta, the atom
------------------------------------------------------------------------- */

ComputeBeamTimestep::ComputeBeamTimestep(LAMMPS *lmp, int narg, char **arg) :
    ComputeStableStep(lmp, narg, arg, 5), bond(nullptr)
{
  not_ready = "the estimate is made from the bond list, which is built at the first run; "
              "use 'run 0' before asking for it";
}

void ComputeBeamTimestep::init()
{
  bond = dynamic_cast<BondBeam *>(force->bond);
  if (!bond)
    error->all(FLERR, "Compute beam/timestep requires bond_style beam (or beam/kk), not {}",
               force->bond_style ? force->bond_style : "none");
}

/* ---------------------------------------------------------------------- */

bool ComputeBeamTimestep::estimate(double *values)
{
  if (!bond) init();
  BondBeam::StableStep s;
  if (!bond->stable_timestep(s)) return false;
  values[0] = s.dt;
  values[1] = update->dt / s.dt;
  values[2] = s.omega;
  values[3] = s.zeta;
  values[4] = (double) s.atom;
  return true;
}
