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

#include "fix_mlp_traction.h"

#include "atom.h"
#include "atom_masks.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_mlp_frame.h"
#include "force.h"
#include "mca_compat.h"
#include "memory.h"
#include "mlp_kernels.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair_mlp.h"
#include "update.h"

#include <cmath>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
constexpr int RECORD = 3 + 3 * FixMLPTraction::MAXREF;    // count, S, (ID, X) per neighbour
}    // namespace

/* ----------------------------------------------------------------------
   fix ID group mlp/traction
------------------------------------------------------------------------- */

FixMLPTraction::FixMLPTraction(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), pair(nullptr), list(nullptr), made(0), ref(nullptr), out(nullptr),
    counted(-1), nplan(0)
{
  if (narg > 3)
    error->all(FLERR, "Fix mlp/traction takes no arguments after the style, found {}", arg[3]);
  if (domain->dimension != 2)
    error->all(FLERR,
               "Fix mlp/traction requires dimension 2 (the surface forces of pair_style mlp, "
               "a lattice in the plane)");
  if (atom->map_style == Atom::MAP_NONE)
    error->all(FLERR,
               "Fix mlp/traction requires an atom map (atom_modify map array or hash) to find "
               "each atom's lattice neighbours");
  counts[0] = counts[1] = 0;
  counts_all[0] = counts_all[1] = 0.0;

  vector_flag = 1;
  size_vector = 2;
  global_freq = 1;
  extvector = 0;
  peratom_flag = 1;
  size_peratom_cols = 4;
  peratom_freq = 1;
  restart_peratom = 1;
  restart_global = 1;
  maxexchange = RECORD;
  // what the force reads and adds to (a KOKKOS run syncs only these)
  datamask_read = X_MASK | F_MASK | TAG_MASK | TYPE_MASK | MASK_MASK | MOLECULE_MASK;
  datamask_modify = F_MASK;

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
}

/* ---------------------------------------------------------------------- */

FixMLPTraction::~FixMLPTraction()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(ref);
  memory->destroy(out);
}

/* ---------------------------------------------------------------------- */

int FixMLPTraction::setmask()
{
  return POST_NEIGHBOR | MIN_POST_NEIGHBOR | POST_FORCE | MIN_POST_FORCE;
}

/* ---------------------------------------------------------------------- */

void FixMLPTraction::init()
{
  pair = dynamic_cast<PairMLP *>(force->pair);
  if (!pair)
    error->all(FLERR, "Fix mlp/traction requires pair_style mlp (or mlp/kk), not {}",
               force->pair_style ? force->pair_style : "none");
  // the lattice neighbours are those of the first run's first step
  if (!made) MCACompat::request_full_occasional(neighbor, this, 0);
}

void FixMLPTraction::init_list(int /*id*/, NeighList *ptr)
{
  list = ptr;
}

/* ---------------------------------------------------------------------- */

void FixMLPTraction::setup(int vflag)
{
  if (!made) make_reference();
  build_plan();
  post_force(vflag);
}

void FixMLPTraction::min_setup(int vflag)
{
  setup(vflag);
}

/* ----------------------------------------------------------------------
   each atom of the group keeps its neighbours within the return force's
   cutoff (their IDs and the vectors X_ij to them) and its surface vector
   S = -sum (k1 r) e_ij (0 in the bulk, where the neighbours' unit vectors
   cancel)
------------------------------------------------------------------------- */

void FixMLPTraction::make_reference()
{
  if (!list) error->all(FLERR, "Fix mlp/traction has no neighbor list to find the lattice from");
  MCACompat::build_occasional(neighbor, list);
  const double *const *x = atom->x;
  const int *type = atom->type;
  const int *mask = atom->mask;
  const tagint *tag = atom->tag;
  const double *special_lj = force->special_lj;
  const int variant = pair->return_variant();
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    ref[i][0] = ref[i][1] = ref[i][2] = 0.0;
    if (!(mask[i] & groupbit)) continue;
    const int *jlist = list->firstneigh[i];
    int count = 0;
    double sx = 0.0, sy = 0.0, weights = 0.0;
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const double factor = special_lj[(jlist[jj] >> SBBITS) & 3];
      const int j = jlist[jj] & NEIGHMASK;
      const double dx = x[j][0] - x[i][0], dy = x[j][1] - x[i][1];
      const double rsq = dx * dx + dy * dy;
      const MLPKernels::MLPCoeff &p = pair->coefficients(type[i], type[j]);
      if (rsq >= p.cutsq) continue;
      if (count == MAXREF)
        error->one(FLERR,
                   "Fix mlp/traction: atom {} has more than {} neighbours within the pair "
                   "cutoff (a lattice's first shell has 4 or 6)",
                   tag[i], MAXREF);
      const double r = sqrt(rsq);
      const double w = factor * MLPKernels::return_stiffness_length(p, variant, r);
      sx -= w * dx / r;
      sy -= w * dy / r;
      weights += fabs(w);
      double *row = &ref[i][3 + 3 * count];
      row[0] = ubuf(tag[j]).d;
      row[1] = dx;
      row[2] = dy;
      count++;
    }
    // (the bulk: a full shell's vectors cancel to round-off)
    if (sqrt(sx * sx + sy * sy) <= 1.0e-10 * weights) sx = sy = 0.0;
    ref[i][0] = count;
    ref[i][1] = sx;
    ref[i][2] = sy;
  }
  made = 1;
}

/* ----------------------------------------------------------------------
   the plan of this local numbering: the surface atoms of the group and the
   local index of the closest image of each of their lattice neighbours;
   the per-atom output gets the surface vectors and no force
------------------------------------------------------------------------- */

void FixMLPTraction::post_neighbor()
{
  build_plan();
}

void FixMLPTraction::min_post_neighbor()
{
  build_plan();
}

void FixMLPTraction::build_plan()
{
  const int nlocal = atom->nlocal;
  const int *mask = atom->mask;
  const FixMLPFrame *frame = pair ? pair->lattice_frame() : nullptr;
  nplan = 0;
  plan_atom.clear();
  plan_body.clear();
  plan_partner.clear();
  plan_ref.clear();
  for (int i = 0; i < nlocal; i++) {
    const double *record = ref[i];
    out[i][0] = out[i][1] = out[i][2] = out[i][3] = 0.0;
    if (!(mask[i] & groupbit)) continue;
    out[i][0] = record[1];
    out[i][1] = record[2];
    if (record[1] == 0.0 && record[2] == 0.0) continue;
    const int count = static_cast<int>(record[0]);
    plan_atom.push_back(i);
    plan_body.push_back(frame ? frame->body_of(i) : -1);
    plan_ref.push_back(record[1]);
    plan_ref.push_back(record[2]);
    plan_ref.push_back(count);
    for (int k = 0; k < MAXREF; k++) {
      const double *row = &record[3 + 3 * k];
      int j = i;
      if (k < count) {
        const auto partner = static_cast<tagint>(ubuf(row[0]).i);
        j = atom->map(partner);
        if (j < 0)
          error->one(FLERR,
                     "Fix mlp/traction: atom {}'s lattice neighbour {} is neither owned nor a "
                     "ghost here (it moved beyond the ghost cutoff: raise comm_modify cutoff)",
                     atom->tag[i], partner);
        j = domain->closest_image(i, j);
      }
      plan_partner.push_back(j);
      plan_ref.push_back(k < count ? row[1] : 0.0);
      plan_ref.push_back(k < count ? row[2] : 0.0);
    }
    nplan++;
  }
}

/* ----------------------------------------------------------------------
   f_i = R cof(R^T F - I) S at the plan's atoms
------------------------------------------------------------------------- */

void FixMLPTraction::post_force(int /*vflag*/)
{
  counted = -1;
  apply();
}

void FixMLPTraction::min_post_force(int vflag)
{
  post_force(vflag);
}

namespace {
// the plan's rows and the positions as the shared kernel reads them
template <class T> struct Rows {
  const T *base;
  int width;
  T operator()(int m, int k) const { return base[m * width + k]; }
};
struct Positions {
  double **x;
  double operator()(int j, int d) const { return x[j][d]; }
};
}    // namespace

void FixMLPTraction::apply()
{
  double **f = atom->f;
  const Positions x = {atom->x};
  const Rows<int> partners = {plan_partner.data(), MAXREF};
  const Rows<double> refs = {plan_ref.data(), PLAN_REF};
  const FixMLPFrame *frame = pair->lattice_frame();
  const double *angles = frame ? frame->body_angles() : nullptr;
  counts[0] = counts[1] = 0;
  for (int m = 0; m < nplan; m++) {
    const int i = plan_atom[m];
    // (no frame: no turn to take the cosine of)
    const double a = plan_body[m] < 0 ? 0.0 : angles[plan_body[m]];
    const double ca = plan_body[m] < 0 ? 1.0 : cos(a), sa = plan_body[m] < 0 ? 0.0 : sin(a);
    double fx, fy;
    if (!MLPKernels::surface_force(x, partners, refs, m, i, ca, sa, fx, fy)) {
      out[i][2] = out[i][3] = 0.0;
      counts[1]++;
      continue;
    }
    f[i][0] += fx;
    f[i][1] += fy;
    out[i][2] = fx;
    out[i][3] = fy;
    counts[0]++;
  }
}

/* ----------------------------------------------------------------------
   whether the reference was made (the atoms' records are in the file)
------------------------------------------------------------------------- */

void FixMLPTraction::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  const double list[1] = {(double) made};
  const int size = (int) sizeof(list);
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(list, sizeof(double), 1, fp);
}

void FixMLPTraction::restart(char *buf)
{
  made = static_cast<int>(((const double *) buf)[0]);
}

/* ----------------------------------------------------------------------
   the atoms given a force at the last step, the atoms of the surface
   whose neighbours do not span the plane (no gradient: no force)
------------------------------------------------------------------------- */

double FixMLPTraction::compute_vector(int n)
{
  if (counted != update->ntimestep) {
    double local[2] = {(double) counts[0], (double) counts[1]};
    MPI_Allreduce(local, counts_all, 2, MPI_DOUBLE, MPI_SUM, world);
    counted = update->ntimestep;
  }
  return counts_all[n];
}

/* ---------------------------------------------------------------------- */

double FixMLPTraction::memory_usage()
{
  return (double) (RECORD + 4) * atom->nmax * sizeof(double);
}

/* ---------------------------------------------------------------------- */

void FixMLPTraction::grow_arrays(int nmax)
{
  memory->grow(ref, nmax, RECORD, "mlp/traction:ref");
  memory->grow(out, nmax, 4, "mlp/traction:out");
  array_atom = out;
}

void FixMLPTraction::copy_arrays(int i, int j, int /*delflag*/)
{
  const int n = record_size(i);
  for (int k = 0; k < n; k++) ref[j][k] = ref[i][k];
  for (int k = 0; k < 4; k++) out[j][k] = out[i][k];
}

// atoms created after the reference was made have no neighbours and no force
void FixMLPTraction::set_arrays(int i)
{
  ref[i][0] = ref[i][1] = ref[i][2] = 0.0;
  out[i][0] = out[i][1] = out[i][2] = out[i][3] = 0.0;
}

int FixMLPTraction::pack_exchange(int i, double *buf)
{
  const int n = record_size(i);
  for (int k = 0; k < n; k++) buf[k] = ref[i][k];
  return n;
}

int FixMLPTraction::unpack_exchange(int nlocal, double *buf)
{
  const int n = 3 + 3 * static_cast<int>(buf[0]);
  for (int k = 0; k < n; k++) ref[nlocal][k] = buf[k];
  for (int k = 0; k < 4; k++) out[nlocal][k] = 0.0;
  return n;
}

/* ---------------------------------------------------------------------- */

int FixMLPTraction::pack_restart(int i, double *buf)
{
  const int n = record_size(i);
  // pack buf[0] this way because other fixes unpack it
  buf[0] = n + 1;
  for (int k = 0; k < n; k++) buf[k + 1] = ref[i][k];
  return n + 1;
}

void FixMLPTraction::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  // skip to the nth set of extended data
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  const int n = static_cast<int>(extra[nlocal][m]) - 1;
  m++;
  for (int k = 0; k < n; k++) ref[nlocal][k] = extra[nlocal][m++];
  for (int k = 0; k < 4; k++) out[nlocal][k] = 0.0;
}

int FixMLPTraction::size_restart(int nlocal)
{
  return record_size(nlocal) + 1;
}

int FixMLPTraction::maxsize_restart()
{
  return RECORD + 1;
}
