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

#include "compute_mlp_timestep.h"

#include "error.h"
#include "force.h"
#include "pair_mlp.h"
#include "update.h"

using namespace LAMMPS_NS;

/* ----------------------------------------------------------------------
   compute ID group mlp/timestep: the stable time step of pair_style mlp
   (the group is not used): dt, dt_run / dt, omega, the atom
------------------------------------------------------------------------- */

ComputeMLPTimestep::ComputeMLPTimestep(LAMMPS *lmp, int narg, char **arg) :
    ComputeStableStep(lmp, narg, arg, 4), pair(nullptr)
{
  not_ready = "the estimate is made from the neighbour list, which is built at the first "
              "run; use 'run 0' before asking for it";
}

void ComputeMLPTimestep::init()
{
  pair = dynamic_cast<PairMLP *>(force->pair);
  if (!pair)
    error->all(FLERR, "Compute mlp/timestep requires pair_style mlp (or mlp/kk), not {}",
               force->pair_style ? force->pair_style : "none");
}

/* ---------------------------------------------------------------------- */

bool ComputeMLPTimestep::estimate(double *values)
{
  if (!pair) init();
  PairMLP::StableStep s;
  if (!pair->stable_timestep(s)) return false;
  values[0] = s.dt;
  values[1] = update->dt / s.dt;
  values[2] = s.omega;
  values[3] = (double) s.atom;
  return true;
}
