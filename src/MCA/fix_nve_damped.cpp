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

#include "fix_nve_damped.h"

#include "atom.h"
#include "atom_vec_mca.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "mca_compat.h"
#include "update.h"

#include "mca_integration.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

/* ----------------------------------------------------------------------
   fix ID group nve/damped gamma [angular gamma_r] [spin yes|no] [disc]
------------------------------------------------------------------------- */

FixNVEDamped::FixNVEDamped(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), gamma(0.0), gamma_r(0.0), inertia_factor(0.4), spin(0), automata(nullptr),
    dtv(0.0), dtf(0.0)
{
  if (narg < 4) utils::missing_cmd_args(FLERR, "fix nve/damped (needs gamma)", error);
  gamma = damping_rate(lmp, "nve/damped", "gamma", arg[3]);
  gamma_r = gamma;
  // the spin of finite-size spheres, where the atom style has it
  const int spheres =
      atom->radius_flag && atom->rmass_flag && atom->omega_flag && atom->torque_flag;
  spin = spheres;
  int disc = 0;
  int iarg = 4;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "angular") == 0) {
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, "fix nve/damped angular", error);
      gamma_r = damping_rate(lmp, "nve/damped", "angular gamma_r", arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "spin") == 0) {
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, "fix nve/damped spin", error);
      spin = utils::logical(FLERR, arg[iarg + 1], false, lmp);
      if (spin && !spheres)
        error->all(FLERR,
                   "Fix nve/damped spin yes requires finite-size spheres (atom_style sphere: "
                   "radius, rmass, omega, torque), not atom_style {}",
                   atom->atom_style);
      iarg += 2;
    } else if (strcmp(arg[iarg], "disc") == 0) {
      disc = 1;
      iarg += 1;
    } else {
      error->all(FLERR, "Unknown fix nve/damped keyword {} (allowed: angular, spin, disc)",
                 arg[iarg]);
    }
  }
  if (disc && domain->dimension != 2)
    error->all(FLERR, "Fix nve/damped disc requires dimension 2 (a disc's J = m r^2 / 2)");
  if (disc) inertia_factor = 0.5;
  // automata (atom_style mca, e.g. the particles of bond_style beam): their
  // moments of inertia, and the orientation turned with the spin
  automata = MCAAtomFields::find(atom);
  if (automata && disc)
    error->all(FLERR,
               "Fix nve/damped disc: automata (atom_style mca) have their own moments of "
               "inertia (mca_set inertia)");
  if (automata && !spin)
    error->all(FLERR, "Fix nve/damped spin no: automata (atom_style mca) always spin");

  time_integrate = 1;
  scalar_flag = 1;
  global_freq = 1;
  extscalar = 1;
  ecouple_flag = 1;
  restart_global = 1;
}

/* ---------------------------------------------------------------------- */

int FixNVEDamped::setmask()
{
  return INITIAL_INTEGRATE | FINAL_INTEGRATE;
}

/* ---------------------------------------------------------------------- */

void FixNVEDamped::init()
{
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "Fix nve/damped does not support run_style respa");
  // the style may have been replaced since the fix was defined
  automata = MCAAtomFields::find(atom);
  if (automata) {
    automata->sync_host();
    automata->require_mass_and_inertia(lmp, igroup, "Fix nve/damped");
  }
  reset_dt();
}

void FixNVEDamped::reset_dt()
{
  dtv = update->dt;
  dtf = 0.5 * update->dt * force->ftm2v;
}

/* ---------------------------------------------------------------------- */

void FixNVEDamped::initial_integrate(int /*vflag*/)
{
  double mvsq = 0.0, jwsq = 0.0;
  half_step(mvsq, jwsq);
  tally(mvsq, jwsq);
}

void FixNVEDamped::final_integrate()
{
  double mvsq = 0.0, jwsq = 0.0;
  full_step(mvsq, jwsq);
  tally(mvsq, jwsq);
}

/* ----------------------------------------------------------------------
   the damping's work over a step, c dt (|v(n)|^2 + |v(n+1)|^2) / 2: half
   of it from each full-step velocity (mca_integration.h)
------------------------------------------------------------------------- */

void FixNVEDamped::tally(double mvsq, double jwsq)
{
  dissipated.local += 0.5 * dtv * force->mvv2e * (gamma * mvsq + gamma_r * jwsq);
}

/* ---------------------------------------------------------------------- */

void FixNVEDamped::half_step(double &mvsq, double &jwsq)
{
  double **x = atom->x, **v = atom->v, **f = atom->f;
  const double *rmass = atom->rmass, *mass = atom->mass;
  const int *type = atom->type, *mask = atom->mask;
  const double a = 0.5 * gamma * dtv, a_r = 0.5 * gamma_r * dtv;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double m = rmass ? rmass[i] : mass[type[i]];
    mvsq += m * MCAKernels::damped_half_step(v[i], f[i], dtf / m, a);
    x[i][0] += dtv * v[i][0];
    x[i][1] += dtv * v[i][1];
    x[i][2] += dtv * v[i][2];
    if (spin) {
      const double j = automata ? automata->inertia[i]
                                : inertia_factor * m * atom->radius[i] * atom->radius[i];
      jwsq += j * MCAKernels::damped_half_step(atom->omega[i], atom->torque[i], dtf / j, a_r);
      if (automata) MCAKernels::rotate_quaternion(automata->quat[i], atom->omega[i], dtv);
    }
  }
}

void FixNVEDamped::full_step(double &mvsq, double &jwsq)
{
  double **v = atom->v, **f = atom->f;
  const double *rmass = atom->rmass, *mass = atom->mass;
  const int *type = atom->type, *mask = atom->mask;
  const double a = 0.5 * gamma * dtv, a_r = 0.5 * gamma_r * dtv;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double m = rmass ? rmass[i] : mass[type[i]];
    mvsq += m * MCAKernels::damped_full_step(v[i], f[i], dtf / m, a);
    if (spin) {
      const double j = automata ? automata->inertia[i]
                                : inertia_factor * m * atom->radius[i] * atom->radius[i];
      jwsq += j * MCAKernels::damped_full_step(atom->omega[i], atom->torque[i], dtf / j, a_r);
    }
  }
}

/* ----------------------------------------------------------------------
   energy taken out so far, all ranks (cumulative: ecouple)
------------------------------------------------------------------------- */

double FixNVEDamped::compute_scalar()
{
  return dissipated.total(world);
}

/* ----------------------------------------------------------------------
   the energy taken out so far, so that a restarted run continues the tally
------------------------------------------------------------------------- */

void FixNVEDamped::write_restart(FILE *fp)
{
  dissipated.write_restart(fp, world, comm->me);
}

void FixNVEDamped::restart(char *buf)
{
  dissipated.restart(buf, comm->me);
}
