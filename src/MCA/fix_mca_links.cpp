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

#include "fix_mca_links.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "mca_compat.h"
#include "mca_link_passes.h"
#include "mca_row_codec.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"

#include <algorithm>
#include <cstring>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;
using namespace MCAKernels;

// the global restart record begins with this marker and names the blocks
// of the rows (records of earlier versions begin with the capacity, > 0)
static constexpr double NAMED_BLOCKS = -1.0;
// history layout 1 (restart files written before 3 Dec 2026): the size of
// its elastic block and of its plasticity block
static constexpr int LAYOUT1 = 1, LAYOUT1_SIZE = 27, LAYOUT1_PLASTICITY_SIZE = 2;

/* ----------------------------------------------------------------------
   fix ID group MCA_LINKS name link_size atom_size [name link_size atom_size ...]
                          [precision double/mixed]
------------------------------------------------------------------------- */

FixMCALinks::FixMCALinks(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), nmax_atoms(0), nlinks(nullptr), partner(nullptr), slot(nullptr),
    rows(nullptr), nrows(0), maxrows(0), atom_state(nullptr), list(nullptr)
{
  int nblock_args = narg - 3;
  if (narg >= 5 && strcmp(arg[narg - 2], "precision") == 0) {
    if (strcmp(arg[narg - 1], "mixed") != 0 && strcmp(arg[narg - 1], "double") != 0)
      error->all(FLERR, "Fix MCA_LINKS: precision {} is not double or mixed", arg[narg - 1]);
    model.set_mixed(strcmp(arg[narg - 1], "mixed") == 0);
    nblock_args -= 2;
  }
  if (nblock_args < 3 || nblock_args % 3 != 0)
    error->all(FLERR,
               "Illegal fix MCA_LINKS command (internal fix of pair mca: the blocks of its "
               "link model as name link_size atom_size, then precision double/mixed)");
  for (int iarg = 3; iarg < 3 + nblock_args; iarg += 3) {
    const int part = link_part_id(arg[iarg]);
    model.add_part(part, arg[iarg], utils::inumeric(FLERR, arg[iarg + 1], false, lmp),
                   utils::inumeric(FLERR, arg[iarg + 2], false, lmp), link_part_exact_slots(part));
  }
  row_size = model.layout().row_size;
  atom_size = model.layout().atom_size;
  stored_size = model.layout().stored_size;
  if (row_size > MAX_ROW_SIZE)
    error->all(FLERR, "Fix MCA_LINKS: a link row of {} values is longer than the {} supported",
               row_size, static_cast<int>(MAX_ROW_SIZE));

  restart_global = 1;
  restart_peratom = 1;
  stores_ids = 1;
  create_attribute = 1;    // atoms made by create_atoms, read_data, ... start without links
  created = 0;
  maxlinks = 0;
  set_capacity(1);

  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
}

/* ---------------------------------------------------------------------- */

FixMCALinks::~FixMCALinks()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);

  memory->destroy(nlinks);
  memory->destroy(partner);
  memory->destroy(slot);
  memory->destroy(rows);
  memory->destroy(atom_state);
}

/* ---------------------------------------------------------------------- */

int FixMCALinks::setmask()
{
  return PRE_EXCHANGE | MIN_PRE_EXCHANGE | POST_RUN;
}

/* ----------------------------------------------------------------------
   the links are made once, from an occasional full neighbor list
------------------------------------------------------------------------- */

void FixMCALinks::init()
{
  if (!created) MCACompat::request_full_occasional(neighbor, this, 0);
}

/* ----------------------------------------------------------------------
   atoms are about to move between processors or be sorted
------------------------------------------------------------------------- */

void FixMCALinks::pre_exchange()
{
  to_host();
  host_changed();    // by the exchange and sorting of atoms that follow
}

void FixMCALinks::min_pre_exchange()
{
  pre_exchange();
}

void FixMCALinks::post_run()
{
  to_host();
}

/* ---------------------------------------------------------------------- */

void FixMCALinks::init_list(int /*id*/, NeighList *ptr)
{
  list = ptr;
}

/* ---------------------------------------------------------------------- */

NeighList *FixMCALinks::build_full_list()
{
  if (!list) error->all(FLERR, "Fix MCA_LINKS has no neighbor list to make links from");
  neighbor->build_one(list);
  return list;
}

/* ----------------------------------------------------------------------
   change the number of links per atom, keeping the existing links (the
   pool of rows is not touched)
------------------------------------------------------------------------- */

void FixMCALinks::set_capacity(int capacity)
{
  if (capacity == maxlinks) return;
  to_host();
  const int nlocal = atom->nlocal;

  // keep the links of the local atoms while the tables are reallocated
  std::vector<tagint> kept_partner;
  std::vector<int> kept_slot;
  if (partner) {
    for (int i = 0; i < nlocal; i++) {
      if (nlinks[i] > capacity)
        error->one(FLERR, "Cannot reduce the link capacity of pair mca below {} links", nlinks[i]);
      kept_partner.insert(kept_partner.end(), partner[i], partner[i] + nlinks[i]);
      kept_slot.insert(kept_slot.end(), slot[i], slot[i] + nlinks[i]);
    }
  }
  maxlinks = capacity;
  if (!nlinks) {
    reserve_atoms(atom->nlocal + 1);
  } else {
    allocate_links(nmax_atoms);
  }
  size_t p = 0;
  for (int i = 0; i < nlocal && !kept_partner.empty(); i++) {
    std::copy(kept_partner.data() + p, kept_partner.data() + p + nlinks[i], partner[i]);
    std::copy(kept_slot.data() + p, kept_slot.data() + p + nlinks[i], slot[i]);
    p += nlinks[i];
  }
  host_changed();

  // largest record an atom sends when it moves to another processor
  maxexchange = values_per_atom(maxlinks, stored_size);
}

/* ---------------------------------------------------------------------- */

void FixMCALinks::remove_row(int i, int m)
{
  const int last = nlinks[i] - 1;
  if (m != last) {
    partner[i][m] = partner[i][last];
    slot[i][m] = slot[i][last];
  }
  nlinks[i] = last;
}

/* ----------------------------------------------------------------------
   the per-atom tables hold the local atoms and one more (Atom::sort and
   first_reorder swap atoms through index nlocal), not the ghost atoms,
   whose links nothing reads: they grow with the local atoms (a move from
   another processor, a new atom, a restart file), not with atom->nmax,
   which counts the ghosts and LAMMPS's margin of 16384 atoms (at 32000
   automata on one processor, nmax is 49152)
------------------------------------------------------------------------- */

void FixMCALinks::reserve_atoms(int n)
{
  if (n <= nmax_atoms) return;
  to_host();
  const int old = nmax_atoms;
  // (a margin, so that atoms arriving one by one seldom reallocate)
  nmax_atoms = n + n / 32 + 64;
  resize_atom_tables(nmax_atoms);
  for (int i = old; i < nmax_atoms; i++) clear_atom(i);
  host_changed();
}

// atom i without links, its law state zeros (host)
void FixMCALinks::clear_atom(int i)
{
  nlinks[i] = 0;
  for (int k = 0; k < atom_size; k++) atom_state[i][k] = 0.0;
}

void FixMCALinks::resize_atom_tables(int nmax)
{
  memory->grow(nlinks, nmax, "mca/links:nlinks");
  memory->grow(partner, nmax, maxlinks, "mca/links:partner");
  memory->grow(slot, nmax, maxlinks, "mca/links:slot");
  memory->grow(atom_state, nmax, atom_size, "mca/links:atom_state");
}

/* ----------------------------------------------------------------------
   new, empty tables of maxlinks links for nmax atoms
------------------------------------------------------------------------- */

void FixMCALinks::allocate_links(int nmax)
{
  memory->destroy(partner);
  memory->destroy(slot);
  memory->create(partner, nmax, maxlinks, "mca/links:partner");
  memory->create(slot, nmax, maxlinks, "mca/links:slot");
}

// room for n rows in the pool, keeping those in use
void FixMCALinks::grow_pool(int n)
{
  rows = static_cast<double *>(memory->srealloc(
      rows, static_cast<bigint>(n) * stored_size * sizeof(double), "mca/links:rows"));
  maxrows = n;
}

/* ---------------------------------------------------------------------- */

double *FixMCALinks::new_row(int i, int m)
{
  if (nrows == maxrows) grow_pool(MAX(1024, nrows + nrows / 4));
  slot[i][m] = nrows;
  double *row = pool_row(nrows++);
  // (zeros: a mixed row may have a float of padding)
  for (int k = 0; k < stored_size; k++) row[k] = 0.0;
  return row;
}

void FixMCALinks::add_row(int i, int m, const double *h)
{
  encode_row(model.layout(), h, new_row(i, m));
}

const double *FixMCALinks::read_row(int i, int m, double *work) const
{
  return MCAKernels::read_row(model.layout(), stored_row(i, m), work);
}

void FixMCALinks::reserve_rows(bigint n)
{
  if (n > MAXSMALLINT)
    error->one(FLERR, "Fix MCA_LINKS: {} link rows on one processor are too many", n);
  if (n > maxrows) grow_pool(static_cast<int>(n));
}

/* ----------------------------------------------------------------------
   the pool after LAMMPS reneighbored: the row of each link that its end i
   evaluates (partner_index[i][m] >= nlocal, or a local partner of higher
   ID: the passes' ownership rule) is kept, at the place of that end in
   the order of atoms and links, and a local partner's end shares it.  The
   rows no end evaluates are dropped: a local partner's own copy of the
   link (that of an atom that came from another processor or a restart
   file, a contact row both ends made), the rows of atoms that left.  Two
   ends that evaluate one row (a link between local automata whose closest
   images became ghost atoms when the box remapped them) each get a copy.
   The rows move in place, each once along its chain of places, so the
   pool needs no second copy; when every row is at its place already,
   nothing moves
------------------------------------------------------------------------- */

bool FixMCALinks::share_rows(int nlocal, const tagint *tag, int *const *partner_index,
                             tagint *apart)
{
  to_host();
  const MCALinkOwners owners{nlocal, tag};
  auto evaluates = [&](int i, int m) {
    return !partner_evaluates(owners, i, partner_index[i][m]);
  };

  // the new place of each row that is kept (-1: dropped); a second end
  // that evaluates a row takes a copy of it
  std::vector<int> place(nrows, -1);
  int kept = 0;
  bool in_place = true;
  for (int i = 0; i < nlocal; i++)
    for (int m = 0; m < nlinks[i]; m++) {
      if (!evaluates(i, m)) continue;
      int s = slot[i][m];
      if (place[s] >= 0) {
        const int shared = s;
        double *copy = new_row(i, m);
        std::copy(pool_row(shared), pool_row(shared) + stored_size, copy);
        s = slot[i][m];
        place.push_back(-1);
      }
      place[s] = kept;
      if (s != kept) in_place = false;
      kept++;
    }

  // move each kept row to its place: a chain ends at a place that is free
  // (its row dropped or moved already)
  if (!in_place) {
    std::vector<char> moved(nrows, 0);
    std::vector<double> carry(stored_size);
    for (int s = 0; s < nrows; s++) {
      if (place[s] < 0 || moved[s]) continue;
      moved[s] = 1;
      if (place[s] == s) continue;
      std::copy(pool_row(s), pool_row(s) + stored_size, carry.data());
      int at = place[s];
      while (place[at] >= 0 && !moved[at]) {
        std::swap_ranges(carry.begin(), carry.end(), pool_row(at));
        moved[at] = 1;
        at = place[at];
      }
      std::copy(carry.begin(), carry.end(), pool_row(at));
    }
    for (int i = 0; i < nlocal; i++)
      for (int m = 0; m < nlinks[i]; m++)
        if (evaluates(i, m)) slot[i][m] = place[slot[i][m]];
  }
  // (every link to a local partner is in the partner's table too, and
  // the partner sees this automaton, not a periodic image of it: else the
  // two would each take the link for one the other evaluates, or for one
  // to a ghost, and its forces would be lost or counted twice.  Closest
  // images differ only where the image of the partner that continues the
  // link is not a ghost atom here, i.e. the link is longer than the ghost
  // cutoff, or where the link is half a periodic box length, whose two
  // images are equally close up to round-off: the caller stops the run)
  for (int i = 0; i < nlocal; i++)
    for (int m = 0; m < nlinks[i]; m++) {
      const int j = partner_index[i][m];
      if (j >= nlocal) continue;
      int k = 0;
      while (k < nlinks[j] && partner[j][k] != tag[i]) k++;
      if (k == nlinks[j])
        error->one(FLERR, "Fix MCA_LINKS: automaton {} is linked to {} but not the other way",
                   tag[i], tag[j]);
      if (partner_index[j][k] != i) {
        apart[0] = tag[i];
        apart[1] = tag[j];
        return false;
      }
      if (!evaluates(i, m)) slot[i][m] = slot[j][k];
    }
  nrows = kept;
  // (the rows of atoms that came with copies of both ends, or from a
  // restart file, are given back)
  if (maxrows > 2 * nrows + 1024) grow_pool(nrows + nrows / 4);
  host_changed();
  return true;
}

/* ---------------------------------------------------------------------- */

double FixMCALinks::memory_usage()
{
  const double nmax = nmax_atoms;
  return nmax *
      (sizeof(int) + maxlinks * (sizeof(tagint) + sizeof(int)) + atom_size * sizeof(double)) +
      (double) maxrows * stored_size * sizeof(double);
}

/* ---------------------------------------------------------------------- */

// (atom->nmax grew: the tables follow the local atoms only, reserve_atoms)
void FixMCALinks::grow_arrays(int /*nmax*/)
{
  reserve_atoms(atom->nlocal + 1);
}

/* ----------------------------------------------------------------------
   a new atom (create_atoms, read_data, fix deposit, ...): no links
------------------------------------------------------------------------- */

void FixMCALinks::set_arrays(int i)
{
  reserve_atoms(i + 1);
  to_host();
  clear_atom(i);
  host_changed();
}

/* ----------------------------------------------------------------------
   (the rows stay where they are: atom j takes atom i's)
------------------------------------------------------------------------- */

void FixMCALinks::copy_arrays(int i, int j, int /*delflag*/)
{
  reserve_atoms(j + 1);
  to_host();
  nlinks[j] = nlinks[i];
  for (int m = 0; m < nlinks[i]; m++) {
    partner[j][m] = partner[i][m];
    slot[j][m] = slot[i][m];
  }
  for (int k = 0; k < atom_size; k++) atom_state[j][k] = atom_state[i][k];
  host_changed();
}

/* ----------------------------------------------------------------------
   pack the links of atom i for a move to another processor
------------------------------------------------------------------------- */

int FixMCALinks::pack_exchange(int i, double *buf)
{
  return pack_record(i, buf, RECORD_STORED);
}

// the record of atom i, with its rows as they are stored (a move to
// another processor) or as the law reads them (a restart file)
int FixMCALinks::pack_record(int i, double *buf, RecordRows record)
{
  to_host();
  int m = 0;
  buf[m++] = nlinks[i];
  for (int k = 0; k < atom_size; k++) buf[m++] = atom_state[i][k];
  for (int k = 0; k < nlinks[i]; k++) {
    buf[m++] = ubuf(partner[i][k]).d;
    if (record == RECORD_STORED) {
      memcpy(&buf[m], stored_row(i, k), stored_size * sizeof(double));
      m += stored_size;
    } else {
      decode_row(model.layout(), stored_row(i, k), &buf[m]);
      m += row_size;
    }
  }
  return m;
}

/* ---------------------------------------------------------------------- */

int FixMCALinks::unpack_exchange(int nlocal, double *buf)
{
  return unpack_record(nlocal, buf, RECORD_STORED);
}

/* ----------------------------------------------------------------------
   the links and law state of a new local atom from its record: its rows
   as they are stored (from another processor), as the law reads them (a
   restart file), or in history layout 1 (a restart file of an earlier
   version: converted)
------------------------------------------------------------------------- */

int FixMCALinks::unpack_record(int nlocal, const double *buf, RecordRows from)
{
  to_host();
  int width = row_size;
  if (from == RECORD_STORED) width = stored_size;
  if (from == RECORD_LAYOUT1) width = layout1_file.layout().row_size;
  reserve_atoms(nlocal + 1);
  int m = 0;
  nlinks[nlocal] = static_cast<int>(buf[m++]);
  for (int k = 0; k < atom_size; k++) atom_state[nlocal][k] = buf[m++];
  for (int k = 0; k < nlinks[nlocal]; k++) {
    partner[nlocal][k] = (tagint) ubuf(buf[m++]).i;
    if (from == RECORD_STORED) {
      memcpy(new_row(nlocal, k), &buf[m], stored_size * sizeof(double));
    } else if (from == RECORD_LAYOUT1) {
      double h[MAX_ROW_SIZE] = {};
      convert_layout1_row(&buf[m], h);
      add_row(nlocal, k, h);
    } else {
      add_row(nlocal, k, &buf[m]);
    }
    m += width;
  }
  host_changed();
  return m;
}

/* ----------------------------------------------------------------------
   global restart data: a negative marker (files of earlier versions begin
   with the capacity), capacity, whether the links exist, the order of the
   elastic block (1000 H_LAYOUT + H_SIZE, as those files had it), the
   blocks of the model by size and then by name
------------------------------------------------------------------------- */

void FixMCALinks::write_restart(FILE *fp)
{
  to_host();
  if (comm->me == 0) {
    std::vector<double> list = {NAMED_BLOCKS, (double) maxlinks, (double) created,
                                (double) (1000 * H_LAYOUT + H_SIZE),
                                (double) model.blocks().size()};
    for (const auto &b : model.blocks()) {
      list.push_back(b.link_size);
      list.push_back(b.atom_size);
    }
    const std::string names = model.names();
    const int size = list.size() * sizeof(double) + names.size() + 1;
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(list.data(), sizeof(double), list.size(), fp);
    fwrite(names.c_str(), sizeof(char), names.size() + 1, fp);
  }
}

/* ----------------------------------------------------------------------
   a file is read if its blocks are those of the model (files of earlier
   versions: the elastic block alone), else refused
------------------------------------------------------------------------- */

void FixMCALinks::restart(char *buf)
{
  auto list = (double *) buf;
  const bool named = list[0] == NAMED_BLOCKS;
  if (named) list++;
  const int format = static_cast<int>(list[2]);
  const bool layout1 = format == 1000 * LAYOUT1 + LAYOUT1_SIZE;
  if (format != 1000 * H_LAYOUT + H_SIZE && !layout1)
    error->all(FLERR,
               "Restart file holds MCA links in history layout {} with {} values each; this "
               "version reads layout {} with {}",
               format / 1000, format % 1000, static_cast<int>(H_LAYOUT), static_cast<int>(H_SIZE));

  MCALinkModel file;
  if (named) {
    const int nblocks = static_cast<int>(list[3]);
    auto names = utils::split_words(std::string((char *) &list[4 + 2 * nblocks]));
    if ((int) names.size() != nblocks) error->all(FLERR, "Invalid MCA links in restart file");
    for (int b = 0; b < nblocks; b++)
      file.add_part(-1, names[b], static_cast<int>(list[4 + 2 * b]),
                    static_cast<int>(list[5 + 2 * b]));
  } else {
    const MCALinkPartInfo &elastic = MCA_LINK_PARTS[PART_ELASTIC];
    file.add_part(elastic.part, elastic.name, format % 1000, elastic.atom_size);
  }
  // (a file of layout 1 has the blocks of the model in their sizes then)
  MCALinkModel expected;
  if (layout1) {
    for (const auto &b : model.blocks()) {
      int size = b.link_size;
      if (b.name == MCA_LINK_PARTS[PART_ELASTIC].name) size = LAYOUT1_SIZE;
      if (b.name == MCA_LINK_PARTS[PART_PLASTICITY].name) size = LAYOUT1_PLASTICITY_SIZE;
      expected.add_part(link_part_id(b.name), b.name, size, b.atom_size);
    }
  } else {
    expected = model;
  }
  if (!expected.same_blocks(file))
    error->all(FLERR,
               "Restart file holds MCA links with the blocks ({}) as name, values per link, "
               "values per automaton; the link model of the pair style has ({}){}",
               file.describe(), expected.describe(),
               layout1 ? " in the file's history layout 1" : "");
  layout1_file = layout1 ? file : MCALinkModel();

  set_capacity(static_cast<int>(list[0]));
  created = static_cast<int>(list[1]);
}

/* ----------------------------------------------------------------------
   per-atom restart data; buf[0] is the record length, as other fixes
   skip records by it
------------------------------------------------------------------------- */

int FixMCALinks::pack_restart(int i, double *buf)
{
  const int n = pack_record(i, &buf[1], RECORD_LAW);
  buf[0] = n + 1;
  return n + 1;
}

/* ---------------------------------------------------------------------- */

void FixMCALinks::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;

  // skip to the nth record of this atom
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  m++;

  const int n = static_cast<int>(extra[nlocal][m]);
  if (n > maxlinks)
    error->one(FLERR, "Restart file holds {} links for an automaton, more than the capacity {}", n,
               maxlinks);
  unpack_record(nlocal, &extra[nlocal][m],
                layout1_file.blocks().empty() ? RECORD_LAW : RECORD_LAYOUT1);
}

/* ----------------------------------------------------------------------
   a row of history layout 1 in the present layout.  Layout 1 kept a
   couple in each half; they were equal where the model has no plasticity
   (one is kept), and the plasticity block now keeps hi's
------------------------------------------------------------------------- */

void FixMCALinks::convert_layout1_row(const double *old, double *row) const
{
  // the elastic block of layout 1: the halves of lo and hi, 8 values each
  // (sigma, eps, t(3), couple(3)), between the half lengths and r0
  constexpr int OLD_LO = 4, OLD_HI = 12, OLD_COUPLE = 5, OLD_R0 = 20;
  for (int k = 0; k < H_LO; k++) row[k] = old[k];
  for (int k = 0; k < HALF_SIZE; k++) {
    row[H_LO + k] = old[OLD_LO + k];
    row[H_HI + k] = old[OLD_HI + k];
  }
  for (int k = 0; k < 3; k++) row[H_COUPLE + k] = old[OLD_LO + OLD_COUPLE + k];
  for (int k = 0; k < LAYOUT1_SIZE - OLD_R0; k++) row[H_R0 + k] = old[OLD_R0 + k];
  // the other blocks, in the same order (the plasticity block then had
  // its first values only)
  const auto &to_blocks = model.blocks(), &from_blocks = layout1_file.blocks();
  int from = from_blocks[0].link_size, to = to_blocks[0].link_size;
  for (std::size_t b = 1; b < to_blocks.size(); b++) {
    for (int k = 0; k < from_blocks[b].link_size; k++) row[to + k] = old[from + k];
    if (to_blocks[b].name == MCA_LINK_PARTS[PART_PLASTICITY].name)
      for (int k = 0; k < 3; k++) row[to + P_COUPLE_HI + k] = old[OLD_HI + OLD_COUPLE + k];
    from += from_blocks[b].link_size;
    to += to_blocks[b].link_size;
  }
}

/* ---------------------------------------------------------------------- */

int FixMCALinks::size_restart(int nlocal)
{
  to_host();
  return 1 + values_per_atom(nlinks[nlocal], row_size);
}

/* ---------------------------------------------------------------------- */

int FixMCALinks::maxsize_restart()
{
  return 1 + values_per_atom(maxlinks, row_size);
}
