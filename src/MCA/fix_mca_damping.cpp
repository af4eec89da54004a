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

#include "fix_mca_damping.h"

#include "atom.h"
#include "atom_vec_mca.h"
#include "comm.h"
#include "error.h"
#include "update.h"

#include "mca_integration.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

/* ----------------------------------------------------------------------
   fix ID group mca/damping gamma [angular gamma_r]
------------------------------------------------------------------------- */

FixMCADamping::FixMCADamping(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), gamma(0.0), gamma_r(0.0), avec(nullptr)
{
  if (narg < 4) utils::missing_cmd_args(FLERR, "fix mca/damping (needs gamma)", error);
  gamma = damping_rate(lmp, "mca/damping", "gamma", arg[3]);
  gamma_r = gamma;
  int iarg = 4;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "angular") == 0) {
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, "fix mca/damping angular", error);
      gamma_r = damping_rate(lmp, "mca/damping", "angular gamma_r", arg[iarg + 1]);
      iarg += 2;
    } else {
      error->all(FLERR, "Unknown fix mca/damping keyword {} (allowed: angular)", arg[iarg]);
    }
  }
  if (!MCAAtomFields::find(atom))
    error->all(FLERR, "Fix mca/damping requires atom_style mca, not {}", atom->atom_style);

  scalar_flag = 1;
  global_freq = 1;
  extscalar = 1;
  ecouple_flag = 1;
  restart_global = 1;
}

/* ---------------------------------------------------------------------- */

int FixMCADamping::setmask()
{
  return POST_FORCE;
}

/* ---------------------------------------------------------------------- */

void FixMCADamping::init()
{
  avec = MCAAtomFields::find(atom);
  if (!avec) error->all(FLERR, "Fix mca/damping requires atom_style mca");
}

/* ---------------------------------------------------------------------- */

void FixMCADamping::setup(int /*vflag*/)
{
  apply();
}

/* ----------------------------------------------------------------------
   in a step the velocities are those of the half step, with which the
   positions drifted: the power times dt is the work of the damping
   forces over the step (to the integrator's order)
------------------------------------------------------------------------- */

void FixMCADamping::post_force(int /*vflag*/)
{
  dissipated.local += update->dt * apply();
}

/* ---------------------------------------------------------------------- */

double FixMCADamping::apply()
{
  avec->sync_host();
  double **v = atom->v, **f = atom->f, **omega = atom->omega, **torque = atom->torque;
  const double *rmass = atom->rmass, *inertia = avec->inertia;
  const int *mask = atom->mask;
  double power = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit)
      power += MCAKernels::global_damping(gamma, gamma_r, rmass[i], inertia[i], v[i], omega[i],
                                          f[i], torque[i]);
  return power;
}

/* ----------------------------------------------------------------------
   energy taken out so far, all ranks (cumulative: ecouple)
------------------------------------------------------------------------- */

double FixMCADamping::compute_scalar()
{
  return dissipated.total(world);
}

/* ----------------------------------------------------------------------
   the energy taken out so far, so that a restarted run continues the tally
------------------------------------------------------------------------- */

void FixMCADamping::write_restart(FILE *fp)
{
  dissipated.write_restart(fp, world, comm->me);
}

void FixMCADamping::restart(char *buf)
{
  dissipated.restart(buf, comm->me);
}
