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

#include "fix_beam_state.h"

#include "atom.h"
#include "atom_masks.h"
#include "atom_vec_mca.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "mca_compat.h"
#include "memory.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;
using namespace BeamKernels;

/* ----------------------------------------------------------------------
   fix ID group BEAM_STATE (made by bond_style beam)
------------------------------------------------------------------------- */

FixBeamState::FixBeamState(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), avec(nullptr), particle_criterion(0), sums(nullptr), pstate(nullptr),
    maxbond(0), reverse_stage(REVERSE_PARTICLE), nslot(SLOT_REF + nref(domain->dimension)),
    state(nullptr), nmax_old(0)
{
  if (narg != 3) error->all(FLERR, "Illegal fix BEAM_STATE command (internal fix of bond beam)");
  if (!atom->molecular || atom->bond_per_atom <= 0)
    error->all(FLERR, "Fix BEAM_STATE requires an atom style with bonds");

  restart_peratom = 1;
  create_attribute = 1;
  // bond_style beam asks for a neighbor list build after a bond broke
  // (special lists changed): Neighbor checks next_reneighbor each step
  force_reneighbor = 1;
  next_reneighbor = -1;
  restart_global = 1;
  scalar_flag = 1;
  global_freq = 1;
  extscalar = 1;
  ecouple_flag = 1;
  comm_forward = 4;
  comm_reverse = gershgorin_size(domain->dimension);
  // per-atom array: the particle criterion's state of each particle
  // (zero unless a bond type uses it)
  peratom_flag = 1;
  size_peratom_cols = NPSTATE;
  peratom_freq = 1;
  maxexchange = atom->bond_per_atom * nslot + NPSTATE;
  // under KOKKOS: syncs only the orientations, itself (send_orientations)
  datamask_read = EMPTY_MASK;
  datamask_modify = EMPTY_MASK;
  maxbond = atom->bond_per_atom;
  avec = MCAAtomFields::find(atom);

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
}

/* ---------------------------------------------------------------------- */

FixBeamState::~FixBeamState()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(state);
  memory->destroy(sums);
  memory->destroy(pstate);
}

/* ---------------------------------------------------------------------- */

int FixBeamState::setmask()
{
  return PRE_FORCE | MIN_PRE_FORCE;
}

/* ---------------------------------------------------------------------- */

void FixBeamState::init()
{
  avec = MCAAtomFields::find(atom);
  if (!avec) error->all(FLERR, "Bond style beam requires atom_style mca (the orientations)");
  if (atom->bond_per_atom != maxbond)
    error->all(FLERR,
               "Bond style beam: the bonds per atom changed from {} to {} after the beams "
               "were defined",
               maxbond, atom->bond_per_atom);
}

/* ----------------------------------------------------------------------
   the energy the bonds' damping took out so far, all ranks (ecouple);
   kept in restart files
------------------------------------------------------------------------- */

double FixBeamState::compute_scalar()
{
  return dissipated.total(world);
}

void FixBeamState::write_restart(FILE *fp)
{
  dissipated.write_restart(fp, world, comm->me);
}

void FixBeamState::restart(char *buf)
{
  dissipated.restart(buf, comm->me);
}

/* ----------------------------------------------------------------------
   the ghosts' orientations before the bond forces
------------------------------------------------------------------------- */

void FixBeamState::setup_pre_force(int /*vflag*/)
{
  send_orientations();
}

void FixBeamState::pre_force(int /*vflag*/)
{
  send_orientations();
}

void FixBeamState::min_pre_force(int /*vflag*/)
{
  send_orientations();
}

void FixBeamState::send_orientations()
{
  avec->orientation_to_host();
  MCACompat::forward_comm(comm, this);
  avec->orientation_changed_on_host();
}

int FixBeamState::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  double **quat = avec->quat;
  int m = 0;
  for (int k = 0; k < n; k++) {
    const double *q = quat[list[k]];
    buf[m++] = q[0];
    buf[m++] = q[1];
    buf[m++] = q[2];
    buf[m++] = q[3];
    if (particle_criterion)
      for (int c = 0; c < NPSTATE; c++) buf[m++] = pstate[list[k]][c];
  }
  return m;
}

void FixBeamState::unpack_forward_comm(int n, int first, double *buf)
{
  double **quat = avec->quat;
  int m = 0;
  for (int i = first; i < first + n; i++) {
    quat[i][0] = buf[m++];
    quat[i][1] = buf[m++];
    quat[i][2] = buf[m++];
    quat[i][3] = buf[m++];
    if (particle_criterion)
      for (int c = 0; c < NPSTATE; c++) pstate[i][c] = buf[m++];
  }
}

/* ----------------------------------------------------------------------
   the particle criterion (BeamKernels::particle_stress), set at each
   run's init: its sums and their communication exist while bond types
   use it; the particles' states are cleared when none does any more
------------------------------------------------------------------------- */

void FixBeamState::use_particle_criterion(int on)
{
  // (the bond style's init runs before Comm's, which sizes the buffers)
  if (!on) {
    if (particle_criterion)
      for (int i = 0; i < nmax_old; i++)
        for (int k = 0; k < NPSTATE; k++) pstate[i][k] = 0.0;
    particle_criterion = 0;
    comm_forward = 4;
    comm_reverse = gershgorin_size(domain->dimension);
    return;
  }
  particle_criterion = 1;
  comm_forward = 4 + NPSTATE;
  comm_reverse = MAX(NPSUM, gershgorin_size(domain->dimension));
  memory->grow(sums, atom->nmax, NPSUM, "beam:sums");
}

void FixBeamState::clear_sums(int n)
{
  for (int i = 0; i < n; i++) {
    for (int k = 0; k < NPSUM; k++) sums[i][k] = 0.0;
    sums[i][PSUM_MEASURE] = -1.0;    // no candidate
  }
}

int FixBeamState::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  if (reverse_stage == REVERSE_GERSHGORIN) {
    const int size = gershgorin_size(domain->dimension);
    for (int i = first; i < first + n; i++)
      for (int k = 0; k < size; k++) buf[m++] = gershgorin[(std::size_t) i * size + k];
    return m;
  }
  for (int i = first; i < first + n; i++)
    for (int k = 0; k < NPSUM; k++) buf[m++] = sums[i][k];
  return m;
}

void FixBeamState::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  if (reverse_stage == REVERSE_GERSHGORIN) {
    const int size = gershgorin_size(domain->dimension);
    for (int k = 0; k < n; k++)
      for (int c = 0; c < size; c++) gershgorin[(std::size_t) list[k] * size + c] += buf[m++];
    return;
  }
  for (int k = 0; k < n; k++) {
    double *s = sums[list[k]];
    for (int c = 0; c < 6; c++) s[PSUM_VIRIAL + c] += buf[m + PSUM_VIRIAL + c];
    take_candidate(s, buf[m + PSUM_MEASURE], buf[m + PSUM_PARTNER]);
    m += NPSUM;
  }
}

void FixBeamState::sum_gershgorin()
{
  reverse_stage = REVERSE_GERSHGORIN;
  MCACompat::reverse_comm(comm, this);
  reverse_stage = REVERSE_PARTICLE;
}

/* ----------------------------------------------------------------------
   after the bond loop: each owned particle's stress and candidate, kept
   until the next evaluation (which breaks the bonds it decides)
------------------------------------------------------------------------- */

void FixBeamState::decide_particles(int newton_bond)
{
  // with newton_bond off each owned atom has all its bonds' shares here
  if (newton_bond) MCACompat::reverse_comm(comm, this);
  const int dimension = domain->dimension;
  const double *radius = atom->radius;
  for (int i = 0; i < atom->nlocal; i++) {
    const double volume = particle_volume(dimension, radius[i]);
    double *p = pstate[i];
    // (a particle of radius 0 has no candidate: the bond style refuses it)
    if (volume > 0.0)
      particle_stress(sums[i] + PSUM_VIRIAL, dimension, volume, p[PSTATE_SIGMA], p[PSTATE_TAU]);
    else
      p[PSTATE_SIGMA] = p[PSTATE_TAU] = 0.0;
    p[PSTATE_PARTNER] = sums[i][PSUM_MEASURE] >= 0.0 ? sums[i][PSUM_PARTNER] : 0.0;
  }
}

/* ----------------------------------------------------------------------
   slot of the bond of local atom i with partner ID, or nullptr
------------------------------------------------------------------------- */

double *FixBeamState::find_slot(int i, tagint partner) const
{
  const tagint *bond_atom = atom->bond_atom[i];
  const int nbond = atom->num_bond[i];
  for (int m = 0; m < nbond; m++)
    if (bond_atom[m] == partner) return &state[i][m * nslot];
  return nullptr;
}

const double *FixBeamState::stored_reference(int i, int j) const
{
  if (i >= atom->nlocal) return nullptr;
  const double *slot = find_slot(i, atom->tag[j]);
  if (!slot || slot[SLOT_PARTNER] != static_cast<double>(atom->tag[j])) return nullptr;
  return slot + SLOT_REF;
}

/* ---------------------------------------------------------------------- */

const double *FixBeamState::reference(int i1, int i2, int newton_bond)
{
  const tagint *tag = atom->tag;
  double *slot = find_slot(i1, tag[i2]);
  if (!slot) return nullptr;
  if (slot[SLOT_PARTNER] == static_cast<double>(tag[i2])) return slot + SLOT_REF;

  // a bond that moved to another slot of the atom (delete_bonds compresses
  // the bond arrays): its state is found by the partner's ID and follows it
  if (take_moved_state(i1, slot, tag[i2])) return slot + SLOT_REF;

  // a new bond: stress-free in its present geometry, in the order lower
  // atom ID first (both copies of a bond under newton_bond off hold the
  // same numbers, and the element is evaluated in that order)
  const int lo = (tag[i1] < tag[i2]) ? i1 : i2, hi = (lo == i1) ? i2 : i1;
  double **x = atom->x;
  double **quat = avec->quat;
  slot[SLOT_PARTNER] = static_cast<double>(tag[i2]);
  const double d[3] = {x[hi][0] - x[lo][0], x[hi][1] - x[lo][1], x[hi][2] - x[lo][2]};
  fresh_reference(domain->dimension, d, quat[lo], quat[hi], slot + SLOT_REF);

  // with newton_bond off the partner stores the bond too; its owner sets
  // a ghost partner's copy when it lists the bond, at the same step
  if (!newton_bond && i2 < atom->nlocal) {
    double *mirror = find_slot(i2, tag[i1]);
    if (mirror && mirror[SLOT_PARTNER] != static_cast<double>(tag[i1]) &&
        !take_moved_state(i2, mirror, tag[i1])) {
      mirror[SLOT_PARTNER] = static_cast<double>(tag[i1]);
      for (int k = SLOT_REF; k < nslot; k++) mirror[k] = slot[k];
    }
  }
  return slot + SLOT_REF;
}

/* ---------------------------------------------------------------------- */

void FixBeamState::set_reference(int i1, int i2, int newton_bond, const double *ref)
{
  const tagint *tag = atom->tag;
  const int nvalues = nslot - SLOT_REF;
  double *slot = find_slot(i1, tag[i2]);
  if (slot)
    for (int k = 0; k < nvalues; k++) slot[SLOT_REF + k] = ref[k];
  if (!newton_bond && i2 < atom->nlocal) {
    double *mirror = find_slot(i2, tag[i1]);
    if (mirror)
      for (int k = 0; k < nvalues; k++) mirror[SLOT_REF + k] = ref[k];
  }
}

/* ----------------------------------------------------------------------
   the state of partner ID among the slots of atom i, swapped into slot
------------------------------------------------------------------------- */

bool FixBeamState::take_moved_state(int i, double *slot, tagint partner)
{
  // a bond moved from the end of the arrays (the last slot, now beyond the
  // count) or from another live slot; what it leaves behind beyond the
  // count is cleared, so that a bond made again later starts stress-free
  const double id = static_cast<double>(partner);
  for (int m = 0; m < maxbond; m++) {
    double *other = &state[i][m * nslot];
    if (other == slot || other[SLOT_PARTNER] != id) continue;
    for (int k = 0; k < nslot; k++) {
      const double value = other[k];
      other[k] = slot[k];
      slot[k] = value;
    }
    if (m >= atom->num_bond[i]) memset(other, 0, nslot * sizeof(double));
    return true;
  }
  return false;
}

/* ----------------------------------------------------------------------
   bond m of local atom i is removed: the bond arrays move their last bond
   into slot m, and so does the fix
------------------------------------------------------------------------- */

void FixBeamState::remove_slot(int i, int m)
{
  const int last = atom->num_bond[i] - 1;
  if (m != last) memcpy(&state[i][m * nslot], &state[i][last * nslot], nslot * sizeof(double));
  memset(&state[i][last * nslot], 0, nslot * sizeof(double));
}

void FixBeamState::clear_slot(int i, int m)
{
  memset(&state[i][m * nslot], 0, nslot * sizeof(double));
}

/* ---------------------------------------------------------------------- */

double FixBeamState::memory_usage()
{
  const int per_atom = maxbond * nslot + NPSTATE + (particle_criterion ? NPSUM : 0);
  return static_cast<double>(atom->nmax) * per_atom * sizeof(double);
}

/* ----------------------------------------------------------------------
   new rows start empty: partner ID 0 belongs to no atom
------------------------------------------------------------------------- */

void FixBeamState::grow_arrays(int nmax)
{
  const int ncol = (maxbond > 0 ? maxbond : 1) * nslot;
  const int old = state ? nmax_old : 0;
  memory->grow(state, nmax, ncol, "beam:state");
  memory->grow(pstate, nmax, NPSTATE, "beam:pstate");
  for (int i = old; i < nmax; i++) {
    memset(state[i], 0, ncol * sizeof(double));
    memset(pstate[i], 0, NPSTATE * sizeof(double));
  }
  if (particle_criterion) memory->grow(sums, nmax, NPSUM, "beam:sums");
  array_atom = pstate;
  nmax_old = nmax;
}

// an atom created (create_atoms, read_data add) in a row that a deleted
// atom left: no slots of that atom's bonds
void FixBeamState::set_arrays(int i)
{
  memset(state[i], 0, (maxbond > 0 ? maxbond : 1) * nslot * sizeof(double));
  memset(pstate[i], 0, NPSTATE * sizeof(double));
}

void FixBeamState::copy_arrays(int i, int j, int /*delflag*/)
{
  memcpy(state[j], state[i], maxbond * nslot * sizeof(double));
  memcpy(pstate[j], pstate[i], NPSTATE * sizeof(double));
}

/* ----------------------------------------------------------------------
   all slots travel with an atom, the live ones and those beyond the bond
   count (a bond that delete_bonds moved leaves its state there until the
   bond style sees it again), and so does the particle's state (the
   particle criterion's decision, applied at the next evaluation)
------------------------------------------------------------------------- */

int FixBeamState::pack_exchange(int i, double *buf)
{
  const int n = maxbond * nslot;
  memcpy(buf, state[i], n * sizeof(double));
  memcpy(buf + n, pstate[i], NPSTATE * sizeof(double));
  return n + NPSTATE;
}

int FixBeamState::unpack_exchange(int nlocal, double *buf)
{
  const int n = maxbond * nslot;
  memcpy(state[nlocal], buf, n * sizeof(double));
  memcpy(pstate[nlocal], buf + n, NPSTATE * sizeof(double));
  return n + NPSTATE;
}

/* ----------------------------------------------------------------------
   restart record of an atom: its length, the number of slots, the slots
------------------------------------------------------------------------- */

int FixBeamState::pack_restart(int i, double *buf)
{
  const int n = maxbond * nslot;
  buf[0] = n + 2;
  buf[1] = maxbond;
  memcpy(buf + 2, state[i], n * sizeof(double));
  return n + 2;
}

/* ----------------------------------------------------------------------
   the fix is made at the first run after read_restart: the records are
   still in the order of the atoms read, unless a command moved atoms in
   between (LAMMPS keeps the records in place): checked against the bonds
------------------------------------------------------------------------- */

void FixBeamState::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; k++) m += static_cast<int>(extra[nlocal][m]);
  const double *record = &extra[nlocal][m];
  const int nbond = static_cast<int>(record[1]);
  bool valid = static_cast<int>(record[0]) == nbond * nslot + 2 && nbond == maxbond;
  memset(state[nlocal], 0, maxbond * nslot * sizeof(double));
  if (valid) memcpy(state[nlocal], record + 2, maxbond * nslot * sizeof(double));
  // a live slot holds its bond's partner, or nothing yet
  for (int b = 0; valid && b < atom->num_bond[nlocal]; b++) {
    const double partner = state[nlocal][b * nslot + SLOT_PARTNER];
    if (partner != 0.0 && partner != static_cast<double>(atom->bond_atom[nlocal][b])) valid = false;
  }
  if (!valid)
    error->one(FLERR,
               "Fix BEAM_STATE: the restart record of atom {} does not match its bonds (define "
               "the run, which restores the beams' reference states, before commands that add, "
               "delete or move atoms after read_restart)",
               atom->tag[nlocal]);
}

int FixBeamState::size_restart(int /*nlocal*/)
{
  return maxbond * nslot + 2;
}

int FixBeamState::maxsize_restart()
{
  return maxbond * nslot + 2;
}
