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

#include "fix_nve_mca.h"

#include "atom.h"
#include "atom_vec_mca.h"
#include "error.h"
#include "mca_integration.h"

using namespace LAMMPS_NS;
using namespace FixConst;

/* ---------------------------------------------------------------------- */

FixNVEMCA::FixNVEMCA(LAMMPS *lmp, int narg, char **arg) : FixNVE(lmp, narg, arg), avec(nullptr)
{
  // FixNVE accepts exactly 3 arguments; checked there
  if (narg > 3)
    error->all(FLERR,
               "Illegal fix nve/mca command: unexpected argument '{}' "
               "(fix nve/mca takes no keywords)",
               arg[3]);

  avec = MCAAtomFields::find(atom);
  if (!avec)
    error->all(FLERR, "Fix nve/mca requires atom_style mca, not atom_style {}", atom->atom_style);

  time_integrate = 1;
}

/* ---------------------------------------------------------------------- */

void FixNVEMCA::init()
{
  FixNVE::init();

  // the style may have been replaced since the fix was defined
  avec = MCAAtomFields::find(atom);
  if (!avec) error->all(FLERR, "Fix nve/mca requires atom_style mca");

  avec->require_mass_and_inertia(lmp, igroup, "Fix nve/mca");
}

/* ----------------------------------------------------------------------
   velocity Verlet, first half: kick v and omega by dt/2, then drift x and
   the orientation by dt with the half-step velocities
------------------------------------------------------------------------- */

void FixNVEMCA::initial_integrate(int /*vflag*/)
{
  double **x = atom->x;
  double **v = atom->v;
  double **f = atom->f;
  double **omega = atom->omega;
  double **torque = atom->torque;
  double **quat = avec->quat;
  const double *rmass = atom->rmass;
  const double *inertia = avec->inertia;
  const int *mask = atom->mask;
  int nlocal = atom->nlocal;
  if (igroup == atom->firstgroup) nlocal = atom->nfirst;

  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit) {
      MCAKernels::kick(v[i], omega[i], f[i], torque[i], dtf, rmass[i], inertia[i]);
      MCAKernels::drift(x[i], quat[i], v[i], omega[i], dtv);
    }
}

/* ----------------------------------------------------------------------
   velocity Verlet, second half: kick v and omega by dt/2
------------------------------------------------------------------------- */

void FixNVEMCA::final_integrate()
{
  double **v = atom->v;
  double **f = atom->f;
  double **omega = atom->omega;
  double **torque = atom->torque;
  const double *rmass = atom->rmass;
  const double *inertia = avec->inertia;
  const int *mask = atom->mask;
  int nlocal = atom->nlocal;
  if (igroup == atom->firstgroup) nlocal = atom->nfirst;

  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit)
      MCAKernels::kick(v[i], omega[i], f[i], torque[i], dtf, rmass[i], inertia[i]);
}
