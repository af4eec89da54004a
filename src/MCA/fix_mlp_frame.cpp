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

#include "fix_mlp_frame.h"

#include "atom.h"
#include "atom_masks.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "math_const.h"
#include "mca_compat.h"
#include "memory.h"
#include "mlp_kernels.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
// per body: sum m, sum m X (2), sum m x (2), sum m X x x, sum m X . x
constexpr int NSUM = 7;
}    // namespace

/* ----------------------------------------------------------------------
   fix ID group mlp/frame N [body group|molecule]
------------------------------------------------------------------------- */

FixMLPFrame::FixMLPFrame(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), by_molecule(0), nbody(1), xref(nullptr), step_measured(-1), rate_known(0)
{
  if (narg < 4) utils::missing_cmd_args(FLERR, "fix mlp/frame", error);
  if (domain->dimension != 2)
    error->all(FLERR,
               "Fix mlp/frame requires dimension 2 (the lattice frame of pair_style mlp is "
               "an angle in the plane)");
  nevery = utils::inumeric(FLERR, arg[3], false, lmp);
  if (nevery < 1) error->all(FLERR, "Fix mlp/frame: N must be an integer >= 1, not {}", arg[3]);
  int iarg = 4;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "body") == 0) {
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, "fix mlp/frame body", error);
      if (strcmp(arg[iarg + 1], "group") == 0)
        by_molecule = 0;
      else if (strcmp(arg[iarg + 1], "molecule") == 0)
        by_molecule = 1;
      else
        error->all(FLERR, "Fix mlp/frame: body must be group or molecule, not {}", arg[iarg + 1]);
      iarg += 2;
    } else {
      error->all(FLERR, "Fix mlp/frame: unknown keyword {} (allowed: body)", arg[iarg]);
    }
  }
  if (by_molecule && !atom->molecule_flag)
    error->all(FLERR,
               "Fix mlp/frame body molecule requires an atom style with molecule IDs "
               "(atom_style {} has none)",
               atom->atom_style);

  const int nlocal = atom->nlocal;
  if (by_molecule) {
    tagint maxmol = 0;
    for (int i = 0; i < nlocal; i++)
      if (atom->mask[i] & groupbit) maxmol = MAX(maxmol, atom->molecule[i]);
    tagint maxall;
    MPI_Allreduce(&maxmol, &maxall, 1, MPI_LMP_TAGINT, MPI_MAX, world);
    if (maxall < 1)
      error->all(FLERR, "Fix mlp/frame body molecule: no atom of group {} has a molecule ID > 0",
                 group->names[igroup]);
    if (maxall > 1000000)
      error->all(FLERR,
                 "Fix mlp/frame body molecule: molecule IDs up to {} (at most 1000000 bodies, "
                 "numbered 1 to N)",
                 maxall);
    nbody = static_cast<int>(maxall);
  }
  angle.assign(nbody, 0.0);
  measured.assign(nbody, 0.0);
  rate.assign(nbody, 0.0);

  vector_flag = 1;
  size_vector = nbody;
  global_freq = 1;    // the angles in use at any step (the last measurement)
  extvector = 0;
  restart_peratom = 1;
  restart_global = 1;
  // what the measurement reads and writes (a KOKKOS run syncs only these)
  datamask_read = X_MASK | IMAGE_MASK | MASK_MASK | TYPE_MASK | RMASS_MASK | MOLECULE_MASK;
  datamask_modify = EMPTY_MASK;

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);

  // the reference: the positions now, about each body's centroid
  std::vector<double> sums(3 * nbody, 0.0), all(3 * nbody);
  const double *rmass = atom->rmass;
  const double *mass = atom->mass;
  const int *type = atom->type;
  double unwrap[3];
  for (int i = 0; i < nlocal; i++) {
    xref[i][0] = xref[i][1] = xref[i][2] = 0.0;
    const int b = body_of(i);
    if (b < 0) continue;
    const double m = rmass ? rmass[i] : mass[type[i]];
    domain->unmap(atom->x[i], atom->image[i], unwrap);
    sums[3 * b] += m;
    sums[3 * b + 1] += m * unwrap[0];
    sums[3 * b + 2] += m * unwrap[1];
  }
  MPI_Allreduce(sums.data(), all.data(), 3 * nbody, MPI_DOUBLE, MPI_SUM, world);
  // (molecules without mass are bodies that never turn; the group must have one)
  if (!by_molecule && !(all[0] > 0.0))
    error->all(FLERR, "Fix mlp/frame: group {} has no atoms of positive mass",
               group->names[igroup]);
  for (int i = 0; i < nlocal; i++) {
    const int b = body_of(i);
    if (b < 0 || !(all[3 * b] > 0.0)) continue;
    domain->unmap(atom->x[i], atom->image[i], unwrap);
    xref[i][0] = unwrap[0] - all[3 * b + 1] / all[3 * b];
    xref[i][1] = unwrap[1] - all[3 * b + 2] / all[3 * b];
    xref[i][2] = 1.0;
  }
}

/* ---------------------------------------------------------------------- */

FixMLPFrame::~FixMLPFrame()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(xref);
}

/* ---------------------------------------------------------------------- */

int FixMLPFrame::setmask()
{
  return PRE_FORCE;
}

/* ----------------------------------------------------------------------
   the angles of the positions the forces of this step see: measured
   before the force computation at the start of a run and every N steps,
   extrapolated linearly in between.  Axes that lag the body brake it: a
   measurement after the step (one step late) takes 1.5 % of the angular
   momentum of the test's spinning disc over 30 degrees, axes held for 20
   steps 60 % of the example's over 90 degrees; extrapolated, the lag of a
   steady spin is zero
------------------------------------------------------------------------- */

void FixMLPFrame::setup_pre_force(int /*vflag*/)
{
  measure();
}

void FixMLPFrame::pre_force(int /*vflag*/)
{
  // (and at the first step after a first measurement: the rate)
  if (update->ntimestep % nevery == 0 || !rate_known) {
    measure();
    return;
  }
  const double steps = (double) (update->ntimestep - step_measured);
  for (int b = 0; b < nbody; b++) angle[b] = measured[b] + rate[b] * steps;
}

/* ---------------------------------------------------------------------- */

int FixMLPFrame::body_of(int i) const
{
  return MLPKernels::frame_body(atom->mask[i], groupbit, by_molecule,
                                by_molecule ? atom->molecule[i] : 0, nbody);
}

/* ----------------------------------------------------------------------
   the best-fit rotation of each body: with X the reference about the
   reference centroid and x' = x - x_c about the current one, the angle
   maximising sum m x' . R X is atan2(sum m X x x', sum m X . x'); one pass
   with sum m X x x' = sum m X x x - (sum m X) x x_c (sum m X is zero while
   the body keeps its atoms)
------------------------------------------------------------------------- */

void FixMLPFrame::measure()
{
  std::vector<double> sums(NSUM * nbody, 0.0), all(NSUM * nbody);
  const double *rmass = atom->rmass;
  const double *mass = atom->mass;
  const int *type = atom->type;
  const int nlocal = atom->nlocal;
  double unwrap[3];
  for (int i = 0; i < nlocal; i++) {
    const int b = body_of(i);
    if (b < 0 || xref[i][2] == 0.0) continue;
    const double m = rmass ? rmass[i] : mass[type[i]];
    domain->unmap(atom->x[i], atom->image[i], unwrap);
    double *s = &sums[NSUM * b];
    s[0] += m;
    s[1] += m * xref[i][0];
    s[2] += m * xref[i][1];
    s[3] += m * unwrap[0];
    s[4] += m * unwrap[1];
    s[5] += m * (xref[i][0] * unwrap[1] - xref[i][1] * unwrap[0]);
    s[6] += m * (xref[i][0] * unwrap[0] + xref[i][1] * unwrap[1]);
  }
  MPI_Allreduce(sums.data(), all.data(), NSUM * nbody, MPI_DOUBLE, MPI_SUM, world);
  std::vector<double> next(measured);
  for (int b = 0; b < nbody; b++) {
    const double *s = &all[NSUM * b];
    if (!(s[0] > 0.0)) continue;
    const double xc = s[3] / s[0], yc = s[4] / s[0];
    const double cross = s[5] - (s[1] * yc - s[2] * xc);
    const double dot = s[6] - (s[1] * xc + s[2] * yc);
    if (cross == 0.0 && dot == 0.0) continue;    // a body of one atom: no rotation
    // continuous over turns: add the change since the last measurement,
    // taken within (-pi, pi]
    next[b] = measured[b] + remainder(atan2(cross, dot) - measured[b], MathConst::MY_2PI);
  }
  // the rate over the last interval; measured again at the same step (a
  // new run) the rate stays; the first measurement or a step back in time
  // (reset_timestep): none
  const bigint now = update->ntimestep;
  const bool interval = step_measured >= 0 && now > step_measured;
  const bool no_rate = step_measured < 0 || now < step_measured;
  for (int b = 0; b < nbody; b++) {
    if (interval)
      rate[b] = (next[b] - measured[b]) / (double) (now - step_measured);
    else if (no_rate)
      rate[b] = 0.0;
    measured[b] = angle[b] = next[b];
  }
  if (interval || no_rate) rate_known = interval;
  step_measured = now;
}

/* ----------------------------------------------------------------------
   the last measurement and the rate, so that a restarted run extrapolates
   as the uninterrupted one
------------------------------------------------------------------------- */

void FixMLPFrame::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  std::vector<double> list;
  list.push_back((double) nbody);
  list.push_back((double) step_measured);
  for (int b = 0; b < nbody; b++) {
    list.push_back(measured[b]);
    list.push_back(rate[b]);
  }
  list.push_back((double) rate_known);
  const int size = (int) (list.size() * sizeof(double));
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(list.data(), sizeof(double), list.size(), fp);
}

void FixMLPFrame::restart(char *buf)
{
  const auto *list = (const double *) buf;
  if (static_cast<int>(list[0]) != nbody)
    error->all(FLERR,
               "Fix mlp/frame: the restart file has {} bodies, this fix {} (define it with "
               "the same group and body keyword)",
               static_cast<int>(list[0]), nbody);
  step_measured = static_cast<bigint>(list[1]);
  rate_known = static_cast<int>(list[2 + 2 * nbody]);
  for (int b = 0; b < nbody; b++) {
    measured[b] = angle[b] = list[2 + 2 * b];
    rate[b] = list[3 + 2 * b];
  }
}

/* ----------------------------------------------------------------------
   the angle body n has turned (degrees)
------------------------------------------------------------------------- */

double FixMLPFrame::compute_vector(int n)
{
  return angle[n] * 180.0 / MathConst::MY_PI;
}

/* ---------------------------------------------------------------------- */

double FixMLPFrame::memory_usage()
{
  return 3.0 * atom->nmax * sizeof(double) + (double) angle.size() * sizeof(double);
}

/* ---------------------------------------------------------------------- */

void FixMLPFrame::grow_arrays(int nmax)
{
  memory->grow(xref, nmax, 3, "mlp/frame:xref");
}

void FixMLPFrame::copy_arrays(int i, int j, int /*delflag*/)
{
  for (int k = 0; k < 3; k++) xref[j][k] = xref[i][k];
}

// atoms created after the definition have no reference and do not count
void FixMLPFrame::set_arrays(int i)
{
  xref[i][0] = xref[i][1] = xref[i][2] = 0.0;
}

int FixMLPFrame::pack_exchange(int i, double *buf)
{
  for (int k = 0; k < 3; k++) buf[k] = xref[i][k];
  return 3;
}

int FixMLPFrame::unpack_exchange(int nlocal, double *buf)
{
  for (int k = 0; k < 3; k++) xref[nlocal][k] = buf[k];
  return 3;
}

/* ---------------------------------------------------------------------- */

int FixMLPFrame::pack_restart(int i, double *buf)
{
  // pack buf[0] this way because other fixes unpack it
  buf[0] = 4;
  for (int k = 0; k < 3; k++) buf[k + 1] = xref[i][k];
  return 4;
}

void FixMLPFrame::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  // skip to the nth set of extended data
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  m++;
  for (int k = 0; k < 3; k++) xref[nlocal][k] = extra[nlocal][m++];
}

int FixMLPFrame::size_restart(int /*nlocal*/)
{
  return 4;
}

int FixMLPFrame::maxsize_restart()
{
  return 4;
}
