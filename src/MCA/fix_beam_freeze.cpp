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

#include "fix_beam_freeze.h"

#include "atom.h"
#include "atom_masks.h"
#include "beam_kernels.h"
#include "bond_beam.h"
#include "comm.h"
#include "error.h"
#include "fix_beam_state.h"
#include "force.h"
#include "mca_compat.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

/* ----------------------------------------------------------------------
   fix ID group beam/freeze N btype dc [prob P seed] [maxbond Nb]
------------------------------------------------------------------------- */

FixBeamFreeze::FixBeamFreeze(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), btype(0), capture(0.0), probability(1.0), seed(0), maxbond(0),
    list(nullptr), fix_state(nullptr), status(nullptr), choice(nullptr), nmax(0), sending(nullptr),
    made_last(0), made_total(0), warned_room(0)
{
  if (narg < 6) utils::missing_cmd_args(FLERR, "fix beam/freeze (N btype dc)", error);
  if (!atom->molecular || atom->nbondtypes <= 0)
    error->all(FLERR, "Fix beam/freeze requires an atom style with bonds and bond types");

  nevery = utils::inumeric(FLERR, arg[3], false, lmp);
  if (nevery < 1)
    error->all(FLERR, "Fix beam/freeze N (steps between attempts) must be >= 1, not {}", nevery);
  btype = utils::inumeric(FLERR, arg[4], false, lmp);
  if (btype < 1 || btype > atom->nbondtypes)
    error->all(FLERR, "Fix beam/freeze btype {} is not a bond type (1 to {})", btype,
               atom->nbondtypes);
  capture = utils::numeric(FLERR, arg[5], false, lmp);
  if (!(capture > 0.0))
    error->all(FLERR, "Fix beam/freeze dc (capture distance) must be > 0, not {}", arg[5]);

  for (int iarg = 6; iarg < narg;) {
    const std::string word = arg[iarg];
    if (word == "prob") {
      if (iarg + 3 > narg) utils::missing_cmd_args(FLERR, "fix beam/freeze prob (P seed)", error);
      probability = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (!(probability > 0.0 && probability <= 1.0))
        error->all(FLERR, "Fix beam/freeze prob P must be in (0, 1], not {}", arg[iarg + 1]);
      seed = utils::inumeric(FLERR, arg[iarg + 2], false, lmp);
      if (seed <= 0) error->all(FLERR, "Fix beam/freeze prob seed must be > 0, not {}", seed);
      iarg += 3;
    } else if (word == "maxbond") {
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, "fix beam/freeze maxbond (Nb)", error);
      maxbond = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (maxbond < 1) error->all(FLERR, "Fix beam/freeze maxbond must be >= 1, not {}", maxbond);
      iarg += 2;
    } else
      error->all(FLERR, "Unknown fix beam/freeze keyword {} (prob or maxbond)", word);
  }

  // the bonds are made before Neighbor decides whether to build the lists
  // of this step: it builds them when bonds were made
  force_reneighbor = 1;
  next_reneighbor = -1;
  vector_flag = 1;
  size_vector = 2;
  global_freq = 1;
  extvector = 0;
  comm_forward = 1;
  // under KOKKOS the atom data go to the host only at the steps of an attempt
  datamask_read_attempt = datamask_read;
  datamask_modify_attempt = datamask_modify;
}

/* ---------------------------------------------------------------------- */

FixBeamFreeze::~FixBeamFreeze()
{
  memory->destroy(status);
  memory->destroy(choice);
}

/* ---------------------------------------------------------------------- */

int FixBeamFreeze::setmask()
{
  return POST_INTEGRATE;
}

/* ---------------------------------------------------------------------- */

void FixBeamFreeze::init()
{
  if (!force->bond || !utils::strmatch(force->bond_style, "^beam"))
    error->all(FLERR,
               "Fix beam/freeze requires bond_style beam (the new bonds are beams, stress-free "
               "where they form), not {}",
               force->bond ? force->bond_style : "none");
  // (made by the bond style's init, which comes first)
  fix_state = dynamic_cast<FixBeamState *>(MCACompat::fix_by_id(modify, "BEAM_STATE"));
  if (!fix_state) error->all(FLERR, "Fix beam/freeze found no fix BEAM_STATE of bond_style beam");
  if (!force->pair)
    error->all(FLERR,
               "Fix beam/freeze requires a pair style (the contacts of particles that are not "
               "bonded; pair_style zero for none)");
  const double *lj = force->special_lj, *coul = force->special_coul;
  if (!BondBeam::bonded_pairs_excluded(force))
    error->all(FLERR,
               "Fix beam/freeze requires special_bonds lj/coul 0 1 1 (or lj 0 1 1 coul 1 1 1): "
               "bonded pairs are left out of the neighbor lists and broken ones come back into "
               "them; found lj {} {} {} coul {} {} {}",
               lj[1], lj[2], lj[3], coul[1], coul[2], coul[3]);
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "Fix beam/freeze does not support run_style respa");

  // the list of the last neighbor list build holds every pair closer than
  // dc now while no atom has moved by more than half the skin
  const double cutoff = capture + neighbor->skin;
  // (the ghost cutoff Comm will take; Neighbor sets its own part of it
  // after this, in LAMMPS 2021 after the fixes' init)
  const double ghost_cutoff = MAX(comm->cutghostuser, force->pair->cutforce + neighbor->skin);
  if (cutoff > ghost_cutoff)
    error->all(FLERR,
               "Fix beam/freeze dc + skin = {} exceeds the ghost cutoff {}: raise it with "
               "comm_modify cutoff",
               cutoff, ghost_cutoff);
  MCACompat::request_full_occasional(neighbor, this, 0, cutoff);
}

/* ---------------------------------------------------------------------- */

void FixBeamFreeze::init_list(int /*id*/, NeighList *ptr)
{
  list = ptr;
}

/* ---------------------------------------------------------------------- */

void FixBeamFreeze::setup(int /*vflag*/)
{
  set_datamasks(update->ntimestep + 1);
}

void FixBeamFreeze::set_datamasks(bigint next_step)
{
  const bool attempting = (next_step % nevery) == 0;
  datamask_read = attempting ? datamask_read_attempt : EMPTY_MASK;
  datamask_modify = attempting ? datamask_modify_attempt : EMPTY_MASK;
}

/* ---------------------------------------------------------------------- */

void FixBeamFreeze::post_integrate()
{
  if (update->ntimestep % nevery == 0) attempt();
  set_datamasks(update->ntimestep + 1);
}

/* ----------------------------------------------------------------------
   one attempt: every particle of the group says whether it takes a bond
   and has room for it, picks the closest unbonded particle that does
   within dc (ties: the lower ID), and pairs that picked each other bond
------------------------------------------------------------------------- */

void FixBeamFreeze::attempt()
{
  // the ghosts at this step's positions (the integrator moved the atoms)
  comm->forward_comm();
  MCACompat::build_occasional(neighbor, list);

  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(status);
    memory->destroy(choice);
    memory->create(status, nmax, "beam/freeze:status");
    memory->create(choice, nmax, "beam/freeze:choice");
  }

  const int *mask = atom->mask;
  const int *num_bond = atom->num_bond;
  int **nspecial = atom->nspecial;
  for (int i = 0; i < nlocal; i++) {
    int s = 0;
    // (the 1-2 special partners are a particle's bonds, stored by it or by them)
    if ((mask[i] & groupbit) && (maxbond == 0 || nspecial[i][0] < maxbond)) s |= STATUS_TAKES;
    if (num_bond[i] < atom->bond_per_atom) s |= STATUS_ROOM_BOND;
    if (nspecial[i][2] < atom->maxspecial) s |= STATUS_ROOM_SPECIAL;
    status[i] = s;
  }
  sending = status;
  MCACompat::forward_comm(comm, this);

  const double *const *x = atom->x;
  const tagint *tag = atom->tag;
  const int newton_bond = force->newton_bond;
  const double cut2 = capture * capture;
  const bigint step = update->ntimestep;
  for (int i = 0; i < nall; i++) choice[i] = 0.0;
  int roomless = 0;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int si = static_cast<int>(status[i]);
    if (!(si & STATUS_TAKES)) continue;
    const int *jlist = list->firstneigh[i];
    double best_rsq = cut2;
    tagint best = 0;
    bool blocked = false;
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      // (entries with special bits are bonded pairs)
      if ((jlist[jj] >> SBBITS) & 3) continue;
      const int j = jlist[jj] & NEIGHMASK;
      const int sj = static_cast<int>(status[j]);
      if (!(sj & STATUS_TAKES) || tag[j] == tag[i]) continue;
      const double dx = x[j][0] - x[i][0], dy = x[j][1] - x[i][1], dz = x[j][2] - x[i][2];
      const double rsq = dx * dx + dy * dy + dz * dz;
      if (rsq > best_rsq || (rsq == best_rsq && best && tag[j] > best)) continue;
      // room: in both special lists, and in the bond arrays of the atom
      // that stores the bond (the lower ID with newton_bond on, else both)
      const int storer = newton_bond ? (tag[i] < tag[j] ? si : sj) : (si & sj);
      if (!(si & sj & STATUS_ROOM_SPECIAL) || !(storer & STATUS_ROOM_BOND)) {
        blocked = true;
        continue;
      }
      if (probability < 1.0) {
        const tagint lo = MIN(tag[i], tag[j]), hi = MAX(tag[i], tag[j]);
        if (BeamKernels::step_draw(seed, lo, hi, step) >= probability) continue;
      }
      best_rsq = rsq;
      best = tag[j];
    }
    choice[i] = static_cast<double>(best);
    if (blocked && !best) roomless++;
  }
  sending = choice;
  MCACompat::forward_comm(comm, this);

  made_last = make_bonds();
  made_total += made_last;

  int roomless_all;
  MPI_Allreduce(&roomless, &roomless_all, 1, MPI_INT, MPI_SUM, world);
  if (roomless_all && !warned_room && comm->me == 0) {
    error->warning(FLERR,
                   "Fix beam/freeze: {} particles at step {} had a partner within the capture "
                   "distance but no room for the bond (raise extra/bond/per/atom or "
                   "extra/special/per/atom of create_box or read_data)",
                   roomless_all, step);
    warned_room = 1;
  }
}

/* ----------------------------------------------------------------------
   the pairs that picked each other bond; returns the number of bonds made
   on all ranks
------------------------------------------------------------------------- */

bigint FixBeamFreeze::make_bonds()
{
  const tagint *tag = atom->tag;
  const int nlocal = atom->nlocal;
  const int newton_bond = force->newton_bond;
  bigint counted = 0;
  for (int i = 0; i < nlocal; i++) {
    const auto partner = static_cast<tagint>(choice[i]);
    if (!partner) continue;
    const int j = atom->map(partner);
    if (j < 0) error->one(FLERR, "Fix beam/freeze: the chosen partner {} is not here", partner);
    if (static_cast<tagint>(choice[j]) != tag[i]) continue;
    add_bond(i, partner, !newton_bond || tag[i] < partner);
    // (each bond counted once, by the owner of its lower ID)
    if (tag[i] < partner) counted++;
  }
  bigint total;
  MPI_Allreduce(&counted, &total, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (total) {
    atom->nbonds += total;
    next_reneighbor = update->ntimestep;
  }
  return total;
}

/* ----------------------------------------------------------------------
   a new bond of local atom i: in its bond arrays if it stores the bond,
   and among its 1-2 special partners (which come first in its list)
------------------------------------------------------------------------- */

void FixBeamFreeze::add_bond(int i, tagint partner, bool store)
{
  if (store) {
    const int m = atom->num_bond[i];
    fix_state->clear_slot(i, m);
    atom->bond_type[i][m] = btype;
    atom->bond_atom[i][m] = partner;
    atom->num_bond[i] = m + 1;
  }
  int *count = atom->nspecial[i];
  tagint *special = atom->special[i];
  for (int m = count[2]; m > count[0]; m--) special[m] = special[m - 1];
  special[count[0]] = partner;
  for (int k = 0; k < 3; k++) count[k]++;
}

/* ---------------------------------------------------------------------- */

double FixBeamFreeze::compute_vector(int n)
{
  return static_cast<double>(n == 0 ? made_last : made_total);
}

/* ---------------------------------------------------------------------- */

int FixBeamFreeze::pack_forward_comm(int n, int *list_send, double *buf, int /*pbc_flag*/,
                                     int * /*pbc*/)
{
  for (int k = 0; k < n; k++) buf[k] = sending[list_send[k]];
  return n;
}

void FixBeamFreeze::unpack_forward_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; k++) sending[first + k] = buf[k];
}

/* ---------------------------------------------------------------------- */

double FixBeamFreeze::memory_usage()
{
  return 2.0 * nmax * sizeof(double);
}
