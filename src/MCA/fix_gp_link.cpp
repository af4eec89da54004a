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

#include "fix_gp_link.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "gp_link.h"
#include "group.h"
#include "mca_compat.h"
#include "memory.h"
#include "pair.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;

static constexpr int MIN_MEMBERS = 4;

/* ----------------------------------------------------------------------
   fix ID group gp/link real-group [members N] [cutoff d] [level adjacent|same]
       [coupling force|energy] [fit linear|quadratic]
------------------------------------------------------------------------- */

FixGPLink::FixGPLink(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), max_members(MAX_MEMBERS), cutoff(0.0), same_level(0), energy_coupling(0),
    quadratic_fit(0), linked(0), level(nullptr), nmax_arrays(0), nmembers(nullptr),
    members(nullptr), weights(nullptr), returned(nullptr), nmax_returned(0)
{
  if (narg < 4) utils::missing_cmd_args(FLERR, "fix gp/link", error);
  real_group = group->find(arg[3]);
  if (real_group < 0)
    error->all(FLERR, "Fix gp/link: no group named {} (the real particles to link to)", arg[3]);
  if (real_group == igroup)
    error->all(FLERR,
               "Fix gp/link: the real group {} is the fix's group (the imaginary particles); they "
               "must differ",
               arg[3]);
  real_bit = group->bitmask[real_group];

  // a keyword with two values: 0 for the first, 1 for the second
  auto second_of = [&](const std::string &key, const std::string &value, const char *first,
                       const char *second) {
    if (value == first) return 0;
    if (value == second) return 1;
    error->all(FLERR, "Fix gp/link: {} must be {} or {}, got {}", key, first, second, value);
    return 0;
  };

  int iarg = 4;
  while (iarg < narg) {
    const std::string key = arg[iarg];
    if (iarg + 2 > narg) error->all(FLERR, "Fix gp/link: keyword {} needs a value", key);
    if (key == "members") {
      max_members = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (max_members < MIN_MEMBERS || max_members > MAX_MEMBERS)
        error->all(FLERR, "Fix gp/link: members must be from {} to {}, got {}", MIN_MEMBERS,
                   static_cast<int>(MAX_MEMBERS), arg[iarg + 1]);
    } else if (key == "cutoff") {
      cutoff = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (!(cutoff > 0.0))
        error->all(FLERR, "Fix gp/link: cutoff must be > 0 (distance units), got {}",
                   arg[iarg + 1]);
    } else if (key == "level") {
      same_level = second_of(key, arg[iarg + 1], "adjacent", "same");
    } else if (key == "coupling") {
      energy_coupling = second_of(key, arg[iarg + 1], "force", "energy");
    } else if (key == "fit") {
      quadratic_fit = second_of(key, arg[iarg + 1], "linear", "quadratic");
    } else {
      error->all(FLERR,
                 "Fix gp/link: unknown keyword {} (allowed: members, cutoff, level, coupling, fit)",
                 key);
    }
    iarg += 2;
  }

  vector_flag = 1;
  size_vector = 4;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
  restart_peratom = 1;
  stores_ids = 1;
  comm_forward = 3;
  comm_reverse = 3;
  create_attribute = 1;
  if (energy_coupling) {
    // the returned forces act at the members, not where the pair style
    // put them: their virial differs by sum w_j (x_j - x_I) f_I
    virial_global_flag = 1;
    thermo_virial = 1;
  }
  stats[0] = stats[1] = stats[2] = stats[3] = 0.0;

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
}

/* ---------------------------------------------------------------------- */

FixGPLink::~FixGPLink()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(nmembers);
  memory->destroy(members);
  memory->destroy(weights);
  memory->destroy(returned);
}

/* ---------------------------------------------------------------------- */

int FixGPLink::setmask()
{
  // (PRE_FORCE for setup_pre_force: the links and the first positions
  // before the forces of a setup; a step moves the particles after the drift)
  return POST_INTEGRATE | PRE_FORCE | POST_FORCE | MIN_PRE_FORCE | MIN_POST_FORCE;
}

/* ----------------------------------------------------------------------
   the levels of the types come from the GP pair style
------------------------------------------------------------------------- */

void FixGPLink::init()
{
  if (atom->map_style == Atom::MAP_NONE)
    error->all(FLERR, "Fix gp/link requires an atom map (atom_modify map array or hash)");
  int dim = 0;
  level = force->pair ? static_cast<const int *>(force->pair->extract("gp_level", dim)) : nullptr;
  if (!level || dim != 1)
    error->all(FLERR,
               "Fix gp/link needs a GP pair style (gp/morse, gp/lj/cut, gp/eam/alloy or gp/eam/fs) "
               "for the levels of the atom types");
}

/* ----------------------------------------------------------------------
   at a setup (and in a minimization) the ghosts are current: the linked
   particles follow, then their ghost copies are brought up to date
------------------------------------------------------------------------- */

void FixGPLink::setup_pre_force(int /*vflag*/)
{
  if (!linked) link();
  follow(true);
}

void FixGPLink::setup(int vflag)
{
  post_force(vflag);
}

void FixGPLink::min_setup(int vflag)
{
  post_force(vflag);
}

void FixGPLink::min_pre_force(int /*vflag*/)
{
  follow(true);
}

void FixGPLink::min_post_force(int vflag)
{
  post_force(vflag);
}

/* ----------------------------------------------------------------------
   after the drift the ghosts of the members still hold the last step's
   positions: brought up to date first; the ghost copies of the linked
   particles are updated by the communication (or the exchange) of the
   step that follows
------------------------------------------------------------------------- */

void FixGPLink::post_integrate()
{
  follow(false);
}

void FixGPLink::post_force(int vflag)
{
  if (energy_coupling) return_forces(vflag);
  zero_motion();
}

/* ----------------------------------------------------------------------
   coupling energy: x_I = sum_j w_j x_j makes the force on a linked
   particle, f_I, the force w_j f_I on each member (the chain rule of the
   energy the pair style computes); members that are ghosts get theirs by
   reverse communication
------------------------------------------------------------------------- */

void FixGPLink::return_forces(int vflag)
{
  v_init(vflag);
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  if (nall > nmax_returned) {
    nmax_returned = atom->nmax;
    memory->destroy(returned);
    memory->create(returned, nmax_returned, 3, "gp/link:returned");
  }
  for (int i = 0; i < nall; i++) returned[i][0] = returned[i][1] = returned[i][2] = 0.0;
  double **x = atom->x;
  double **f = atom->f;
  for (int i = 0; i < nlocal; i++) {
    const int n = nmembers[i];
    if (n == 0) continue;
    for (int k = 0; k < n; k++) {
      const int j = member_index(i, k);
      double fj[3];
      for (int d = 0; d < 3; d++) {
        fj[d] = weights[i][k] * f[i][d];
        returned[j][d] += fj[d];
      }
      if (evflag) {
        const double dx = x[j][0] - x[i][0], dy = x[j][1] - x[i][1], dz = x[j][2] - x[i][2];
        double v[6] = {dx * fj[0], dy * fj[1], dz * fj[2], dx * fj[1], dx * fj[2], dy * fj[2]};
        v_tally(i, v);
      }
    }
  }
  MCACompat::reverse_comm(comm, this);
  for (int i = 0; i < nlocal; i++)
    for (int d = 0; d < 3; d++) f[i][d] += returned[i][d];
}

void FixGPLink::follow(bool ghosts_current)
{
  if (!ghosts_current) MCACompat::forward_comm(comm, this);
  update();
  if (ghosts_current) MCACompat::forward_comm(comm, this);
}

/* ----------------------------------------------------------------------
   member k of linked particle i: its image closest to i
------------------------------------------------------------------------- */

int FixGPLink::member_index(int i, int k)
{
  const int j = atom->map(members[i][k]);
  if (j < 0)
    error->one(FLERR,
               "Fix gp/link: member {} of imaginary particle {} is not on this processor or "
               "its ghosts (use comm_modify cutoff to reach it)",
               members[i][k], atom->tag[i]);
  return domain->closest_image(i, j);
}

/* ----------------------------------------------------------------------
   x_I = x_I + sum_j w_j (x_j - x_I) over the members' closest images
------------------------------------------------------------------------- */

void FixGPLink::update()
{
  double **x = atom->x;
  const int nlocal = atom->nlocal;
  double offset[MAX_MEMBERS][3];
  for (int i = 0; i < nlocal; i++) {
    const int n = nmembers[i];
    if (n == 0) continue;
    for (int k = 0; k < n; k++) {
      const int j = member_index(i, k);
      for (int d = 0; d < 3; d++) offset[k][d] = x[j][d] - x[i][d];
    }
    double xnew[3];
    GPKernels::linked_position(n, weights[i], offset, x[i], xnew);
    for (int d = 0; d < 3; d++) x[i][d] = xnew[d];
  }
}

/* ----------------------------------------------------------------------
   imaginary particles are not integrated: no force, no velocity
------------------------------------------------------------------------- */

void FixGPLink::zero_motion()
{
  double **f = atom->f;
  double **v = atom->v;
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit)
      for (int d = 0; d < 3; d++) f[i][d] = v[i][d] = 0.0;
}

/* ----------------------------------------------------------------------
   the links: for each imaginary particle the max_members nearest real
   particles (owned or ghost) of the adjacent levels (or of its own level)
   within the search distance, ties broken by tag so that any number of
   processors makes the same links; cells of the search distance over the
   candidates
------------------------------------------------------------------------- */

void FixGPLink::link()
{
  const double cut = (cutoff > 0.0) ? cutoff : force->pair->cutforce;
  for (int d = 0; d < 3; d++)
    if (domain->periodicity[d] && 2.0 * cut >= domain->prd[d])
      error->all(FLERR,
                 "Fix gp/link: the search distance {} is at least half the periodic box length "
                 "{} along {}: a member could be linked through two images",
                 cut, domain->prd[d], "xyz"[d]);

  double **x = atom->x;
  const int *mask = atom->mask;
  const int *type = atom->type;
  const tagint *tag = atom->tag;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;

  // cells over the candidates (at most 64^3 of them)
  std::vector<int> candidates;
  double lo[3] = {0.0, 0.0, 0.0}, hi[3] = {0.0, 0.0, 0.0};
  for (int j = 0; j < nall; j++) {
    if (!(mask[j] & real_bit)) continue;
    for (int d = 0; d < 3; d++) {
      lo[d] = candidates.empty() ? x[j][d] : std::min(lo[d], x[j][d]);
      hi[d] = candidates.empty() ? x[j][d] : std::max(hi[d], x[j][d]);
    }
    candidates.push_back(j);
  }
  int ncell[3];
  double size[3];
  for (int d = 0; d < 3; d++) {
    size[d] = std::max(cut, (hi[d] - lo[d]) / 64.0);
    ncell[d] = static_cast<int>((hi[d] - lo[d]) / size[d]) + 1;
  }
  auto cell_of = [&](const double *p, int *c) {
    for (int d = 0; d < 3; d++)
      c[d] = std::min(std::max(static_cast<int>(floor((p[d] - lo[d]) / size[d])), 0), ncell[d] - 1);
  };
  std::vector<int> head(static_cast<std::size_t>(ncell[0]) * ncell[1] * ncell[2], -1);
  std::vector<int> next(candidates.size(), -1);
  for (std::size_t c = 0; c < candidates.size(); c++) {
    int cc[3];
    cell_of(x[candidates[c]], cc);
    int &first = head[(static_cast<std::size_t>(cc[2]) * ncell[1] + cc[1]) * ncell[0] + cc[0]];
    next[c] = first;
    first = static_cast<int>(c);
  }

  int nlinked = 0, nmember_sum = 0;
  double longest = 0.0, largest_sum = 0.0;
  std::vector<std::pair<double, int>> near;
  double d[MAX_MEMBERS][3];
  for (int i = 0; i < nlocal; i++) {
    nmembers[i] = 0;
    if (!(mask[i] & groupbit)) continue;
    if (mask[i] & real_bit)
      error->one(FLERR, "Fix gp/link: particle {} is in both the imaginary and the real group",
                 tag[i]);
    const int li = level[type[i]];
    near.clear();
    int ci[3];
    cell_of(x[i], ci);
    for (int a = std::max(ci[0] - 1, 0); a <= std::min(ci[0] + 1, ncell[0] - 1); a++)
      for (int b = std::max(ci[1] - 1, 0); b <= std::min(ci[1] + 1, ncell[1] - 1); b++)
        for (int c = std::max(ci[2] - 1, 0); c <= std::min(ci[2] + 1, ncell[2] - 1); c++)
          for (int k = head[(static_cast<std::size_t>(c) * ncell[1] + b) * ncell[0] + a]; k >= 0;
               k = next[k]) {
            const int j = candidates[k];
            const int lj = level[type[j]];
            if (same_level ? (lj != li) : (std::abs(lj - li) != 1)) continue;
            const double dx = x[j][0] - x[i][0], dy = x[j][1] - x[i][1], dz = x[j][2] - x[i][2];
            const double r = sqrt(dx * dx + dy * dy + dz * dz);
            if (r < cut) near.emplace_back(r, j);
          }
    // nearest first; equal distances (to round-off) by tag
    std::sort(near.begin(), near.end(),
              [&](const std::pair<double, int> &p, const std::pair<double, int> &q) {
                if (fabs(p.first - q.first) > 1.0e-10 * cut) return p.first < q.first;
                return tag[p.second] < tag[q.second];
              });
    const int n = std::min(static_cast<int>(near.size()), max_members);
    if (n < MIN_MEMBERS)
      error->one(FLERR,
                 "Fix gp/link: imaginary particle {} (type {}, level {}) has {} real particles of "
                 "the {} level within {} (needs at least {})",
                 tag[i], type[i], li, n, same_level ? "same" : "adjacent", cut, MIN_MEMBERS);
    // the n nearest; where they lie on a plane (the nearest real particles
    // of an image far beyond a surface), the farthest gives way to the
    // next nearest candidates until one lies off it
    auto take = [&](int k, int c) {
      const int j = near[c].second;
      members[i][k] = tag[j];
      for (int dd = 0; dd < 3; dd++) d[k][dd] = x[j][dd] - x[i][dd];
    };
    for (int k = 0; k < n; k++) take(k, k);
    // fit quadratic: where the members are coarser than the particle (the
    // interpolation spans their spacing); members of a finer level follow
    // the field at their own, smaller spacing, and quadratic weights would
    // pass their atomic-scale motion on amplified (doc: measured)
    const bool quadratic = quadratic_fit && level[type[near[0].second]] > li;
    auto fit = [&]() {
      return quadratic ? GPKernels::link_weights_quadratic(n, d, weights[i])
                       : GPKernels::link_weights(n, d, weights[i]);
    };
    double quality = fit();
    std::size_t farthest = n - 1;
    for (std::size_t c = n; quality == 0.0 && c < near.size(); c++) {
      take(n - 1, static_cast<int>(c));
      quality = fit();
      farthest = c;
    }
    if (quality == 0.0)
      error->one(FLERR,
                 "Fix gp/link: the real particles of the {} level within {} of imaginary particle "
                 "{} lie on a plane or a line (their deformation gradient is undefined): use a "
                 "larger cutoff",
                 same_level ? "same" : "adjacent", cut, tag[i]);
    longest = std::max(longest, near[farthest].first);
    double amplification = 0.0;
    for (int k = 0; k < n; k++) amplification += fabs(weights[i][k]);
    largest_sum = std::max(largest_sum, amplification);
    nmembers[i] = n;
    nlinked++;
    nmember_sum += n;
  }

  double local[2] = {(double) nlinked, (double) nmember_sum}, all[2];
  MPI_Allreduce(local, all, 2, MPI_DOUBLE, MPI_SUM, world);
  MPI_Allreduce(&longest, &stats[2], 1, MPI_DOUBLE, MPI_MAX, world);
  MPI_Allreduce(&largest_sum, &stats[3], 1, MPI_DOUBLE, MPI_MAX, world);
  stats[0] = all[0];
  stats[1] = (all[0] > 0.0) ? all[1] / all[0] : 0.0;
  linked = 1;
  if (comm->me == 0)
    utils::logmesg(
        lmp,
        "fix gp/link: {:.0f} imaginary particles linked to {:.2f} real particles each on "
        "average, the farthest at {:.6g}, weights summing to at most {:.4g} in magnitude\n",
        stats[0], stats[1], stats[2], stats[3]);
}

/* ----------------------------------------------------------------------
   linked particles, members per particle, largest member distance, largest
   sum of |weights| (the members' noise it passes on; 1 for a plain mean)
   at linking (0 after a restart)
------------------------------------------------------------------------- */

double FixGPLink::compute_vector(int n)
{
  return stats[n];
}

/* ----------------------------------------------------------------------
   forward communication of the positions (as the atom style does it)
------------------------------------------------------------------------- */

int FixGPLink::pack_forward_comm(int n, int *list, double *buf, int pbc_flag, int *pbc)
{
  double **x = atom->x;
  double dx = 0.0, dy = 0.0, dz = 0.0;
  if (pbc_flag) {
    if (domain->triclinic == 0) {
      dx = pbc[0] * domain->xprd;
      dy = pbc[1] * domain->yprd;
      dz = pbc[2] * domain->zprd;
    } else {
      dx = pbc[0] * domain->xprd + pbc[5] * domain->xy + pbc[4] * domain->xz;
      dy = pbc[1] * domain->yprd + pbc[3] * domain->yz;
      dz = pbc[2] * domain->zprd;
    }
  }
  int m = 0;
  for (int k = 0; k < n; k++) {
    const int j = list[k];
    buf[m++] = x[j][0] + dx;
    buf[m++] = x[j][1] + dy;
    buf[m++] = x[j][2] + dz;
  }
  return m;
}

void FixGPLink::unpack_forward_comm(int n, int first, double *buf)
{
  double **x = atom->x;
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int d = 0; d < 3; d++) x[i][d] = buf[m++];
}

int FixGPLink::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int d = 0; d < 3; d++) buf[m++] = returned[i][d];
  return m;
}

void FixGPLink::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int k = 0; k < n; k++)
    for (int d = 0; d < 3; d++) returned[list[k]][d] += buf[m++];
}

/* ----------------------------------------------------------------------
   global restart data: whether the links exist
------------------------------------------------------------------------- */

void FixGPLink::write_restart(FILE *fp)
{
  if (comm->me == 0) {
    const double list[2] = {(double) linked, (double) max_members};
    const int size = sizeof(list);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(list, sizeof(double), 2, fp);
  }
}

void FixGPLink::restart(char *buf)
{
  const auto list = reinterpret_cast<double *>(buf);
  linked = static_cast<int>(list[0]);
}

/* ----------------------------------------------------------------------
   per-atom data: the member count, tags and weights
------------------------------------------------------------------------- */

double FixGPLink::memory_usage()
{
  return (double) atom->nmax * (sizeof(int) + MAX_MEMBERS * (sizeof(tagint) + sizeof(double)));
}

void FixGPLink::grow_arrays(int nmax)
{
  memory->grow(nmembers, nmax, "gp/link:nmembers");
  memory->grow(members, nmax, MAX_MEMBERS, "gp/link:members");
  memory->grow(weights, nmax, MAX_MEMBERS, "gp/link:weights");
  // (atoms that come without links: not linked)
  for (int i = nmax_arrays; i < nmax; i++) nmembers[i] = 0;
  nmax_arrays = std::max(nmax_arrays, nmax);
}

void FixGPLink::set_arrays(int i)
{
  nmembers[i] = 0;
}

void FixGPLink::copy_arrays(int i, int j, int /*delflag*/)
{
  nmembers[j] = nmembers[i];
  for (int k = 0; k < nmembers[i]; k++) {
    members[j][k] = members[i][k];
    weights[j][k] = weights[i][k];
  }
}

int FixGPLink::pack_exchange(int i, double *buf)
{
  int m = 0;
  buf[m++] = nmembers[i];
  for (int k = 0; k < nmembers[i]; k++) {
    buf[m++] = ubuf(members[i][k]).d;
    buf[m++] = weights[i][k];
  }
  return m;
}

int FixGPLink::unpack_exchange(int nlocal, double *buf)
{
  int m = 0;
  nmembers[nlocal] = static_cast<int>(buf[m++]);
  for (int k = 0; k < nmembers[nlocal]; k++) {
    members[nlocal][k] = (tagint) ubuf(buf[m++]).i;
    weights[nlocal][k] = buf[m++];
  }
  return m;
}

int FixGPLink::pack_restart(int i, double *buf)
{
  const int n = pack_exchange(i, &buf[1]);
  buf[0] = n + 1;
  return n + 1;
}

void FixGPLink::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  m++;
  const int n = static_cast<int>(extra[nlocal][m]);
  if (n > MAX_MEMBERS)
    error->one(FLERR, "Fix gp/link: restart file holds {} members for a particle, more than {}", n,
               static_cast<int>(MAX_MEMBERS));
  unpack_exchange(nlocal, &extra[nlocal][m]);
}

int FixGPLink::size_restart(int nlocal)
{
  return 2 + 2 * nmembers[nlocal];
}

int FixGPLink::maxsize_restart()
{
  return 2 + 2 * MAX_MEMBERS;
}
