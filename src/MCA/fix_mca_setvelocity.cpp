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

#include "fix_mca_setvelocity.h"

#include "atom.h"
#include "error.h"
#include "input.h"
#include "mca_compat.h"
#include "memory.h"
#include "modify.h"
#include "respa.h"
#include "update.h"
#include "variable.h"

#include "mca_prescribe.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

/* ----------------------------------------------------------------------
   fix ID group mca/setvelocity vx vy vz
   each component: a number, NULL (left free) or v_name (equal- or
   atom-style variable)
------------------------------------------------------------------------- */

FixMCASetVelocity::FixMCASetVelocity(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), vatom(nullptr)
{
  if (narg < 6) utils::missing_cmd_args(FLERR, "fix mca/setvelocity (needs vx vy vz)", error);
  if (narg > 6)
    error->all(FLERR,
               "Illegal fix mca/setvelocity command: unexpected argument '{}' (arguments "
               "are vx vy vz, each a number, NULL or v_name)",
               arg[6]);

  vector_flag = 1;
  size_vector = 3;
  global_freq = 1;
  extvector = 1;
  respa_level_support = 1;
  ilevel_respa = 0;
  maxatom = 0;
  reaction_flag = 0;

  for (int k = 0; k < 3; k++) {
    varname[k] = nullptr;
    ivar[k] = -1;
    value[k] = 0.0;
    reaction[k] = reaction_all[k] = 0.0;
    const char *word = arg[3 + k];
    if (strcmp(word, "NULL") == 0) {
      style[k] = NONE;
    } else if (utils::strmatch(word, "^v_")) {
      varname[k] = utils::strdup(word + 2);
      style[k] = EQUAL;    // decided in init()
    } else {
      value[k] = utils::numeric(FLERR, word, false, lmp);
      style[k] = CONSTANT;
    }
  }
  if (style[0] == NONE && style[1] == NONE && style[2] == NONE)
    error->all(FLERR, "Fix mca/setvelocity: all of vx, vy, vz are NULL; nothing to prescribe");
}

/* ---------------------------------------------------------------------- */

FixMCASetVelocity::~FixMCASetVelocity()
{
  for (auto &name : varname) delete[] name;
  memory->destroy(vatom);
}

/* ---------------------------------------------------------------------- */

int FixMCASetVelocity::setmask()
{
  return POST_FORCE | POST_FORCE_RESPA;
}

/* ---------------------------------------------------------------------- */

void FixMCASetVelocity::init()
{
  const char *names[3] = {"vx", "vy", "vz"};
  for (int k = 0; k < 3; k++) {
    if (!varname[k]) continue;
    ivar[k] = input->variable->find(varname[k]);
    if (ivar[k] < 0)
      error->all(FLERR, "Fix mca/setvelocity {}: variable {} does not exist", names[k], varname[k]);
    if (input->variable->equalstyle(ivar[k]))
      style[k] = EQUAL;
    else if (input->variable->atomstyle(ivar[k]))
      style[k] = ATOM;
    else
      error->all(FLERR, "Fix mca/setvelocity {}: variable {} must be equal- or atom-style",
                 names[k], varname[k]);
  }
  if (utils::strmatch(update->integrate_style, "^respa"))
    ilevel_respa = (dynamic_cast<Respa *>(update->integrate))->nlevels - 1;
}

/* ---------------------------------------------------------------------- */

void FixMCASetVelocity::setup(int vflag)
{
  if (utils::strmatch(update->integrate_style, "^verlet"))
    post_force(vflag);
  else {
    (dynamic_cast<Respa *>(update->integrate))->copy_flevel_f(ilevel_respa);
    post_force_respa(vflag, ilevel_respa, 0);
    (dynamic_cast<Respa *>(update->integrate))->copy_f_flevel(ilevel_respa);
  }
}

/* ----------------------------------------------------------------------
   record the force on the group (the reaction to the prescribed motion),
   then set the velocity and remove the force of each prescribed component,
   so that the time integrator moves the automata at that velocity
------------------------------------------------------------------------- */

void FixMCASetVelocity::post_force(int /*vflag*/)
{
  double **v = atom->v;
  double **f = atom->f;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;

  if (atom->nmax > maxatom) {
    maxatom = atom->nmax;
    memory->destroy(vatom);
    memory->create(vatom, maxatom, 3, "mca/setvelocity:vatom");
  }
  evaluate_targets();

  reaction[0] = reaction[1] = reaction[2] = 0.0;
  reaction_flag = 0;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    for (int k = 0; k < 3; k++) {
      const double target = (style[k] == ATOM) ? vatom[i][k] : value[k];
      reaction[k] += MCAKernels::prescribe_velocity(style[k] != NONE, target, v[i][k], f[i][k]);
    }
  }
}

/* ----------------------------------------------------------------------
   the target velocities of this step: equal-style variables into value,
   atom-style variables into vatom (allocated by the caller)
------------------------------------------------------------------------- */

void FixMCASetVelocity::evaluate_targets()
{
  modify->clearstep_compute();
  for (int k = 0; k < 3; k++) {
    if (style[k] == EQUAL)
      value[k] = input->variable->compute_equal(ivar[k]);
    else if (style[k] == ATOM)
      input->variable->compute_atom(ivar[k], igroup, &vatom[0][k], 3, 0);
  }
  modify->addstep_compute(update->ntimestep + 1);
}

/* ---------------------------------------------------------------------- */

void FixMCASetVelocity::post_force_respa(int vflag, int ilevel, int /*iloop*/)
{
  if (ilevel == ilevel_respa) post_force(vflag);
}

/* ----------------------------------------------------------------------
   total force on the group before it was removed
------------------------------------------------------------------------- */

double FixMCASetVelocity::compute_vector(int n)
{
  if (reaction_flag == 0) {
    MPI_Allreduce(reaction, reaction_all, 3, MPI_DOUBLE, MPI_SUM, world);
    reaction_flag = 1;
  }
  return reaction_all[n];
}

/* ---------------------------------------------------------------------- */

double FixMCASetVelocity::memory_usage()
{
  return 3.0 * maxatom * sizeof(double);
}
