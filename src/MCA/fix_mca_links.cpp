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
#include "mca_link_law.h"
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

/* ----------------------------------------------------------------------
   fix ID group MCA_LINKS name link_size atom_size [name link_size atom_size ...]
------------------------------------------------------------------------- */

FixMCALinks::FixMCALinks(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), nlinks(nullptr), partner(nullptr), history(nullptr), atom_state(nullptr),
    row_sync(nullptr), lazy_rows(0), list(nullptr)
{
  if (narg < 6 || (narg - 3) % 3 != 0)
    error->all(FLERR,
               "Illegal fix MCA_LINKS command (internal fix of pair mca: the blocks of its "
               "link model as name link_size atom_size)");
  for (int iarg = 3; iarg < narg; iarg += 3)
    model.add_part(link_part_id(arg[iarg]), arg[iarg],
                   utils::inumeric(FLERR, arg[iarg + 1], false, lmp),
                   utils::inumeric(FLERR, arg[iarg + 2], false, lmp));
  row_size = model.layout().row_size;
  atom_size = model.layout().atom_size;
  if (row_size > MAX_ROW_SIZE)
    error->all(FLERR, "Fix MCA_LINKS: a link row of {} values is longer than the {} supported",
               row_size, static_cast<int>(MAX_ROW_SIZE));

  restart_global = 1;
  restart_peratom = 1;
  stores_ids = 1;
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
  memory->destroy(history);
  memory->destroy(atom_state);
}

/* ---------------------------------------------------------------------- */

int FixMCALinks::setmask()
{
  return PRE_EXCHANGE | MIN_PRE_EXCHANGE | POST_RUN;
}

/* ----------------------------------------------------------------------
   the links are made once, from an occasional full neighbor list.
   Partner copies may be left behind during a run only if no fix acts at
   pre-exchange before this one (e.g. fix balance, which moves atoms)
------------------------------------------------------------------------- */

void FixMCALinks::init()
{
  if (!created) MCACompat::request_full_occasional(neighbor, this, 0);
  lazy_rows = 1;
  for (int i = 0; i < modify->nfix && modify->fix[i] != this; i++)
    if (modify->fmask[i] & (PRE_EXCHANGE | MIN_PRE_EXCHANGE)) lazy_rows = 0;
}

/* ----------------------------------------------------------------------
   atoms are about to move between processors or be sorted
------------------------------------------------------------------------- */

void FixMCALinks::pre_exchange()
{
  sync_rows();
  to_host();
  host_changed();    // by the exchange and sorting of atoms that follow
}

void FixMCALinks::min_pre_exchange()
{
  pre_exchange();
}

void FixMCALinks::post_run()
{
  sync_rows();
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
   change the number of rows per atom, keeping the existing links
------------------------------------------------------------------------- */

void FixMCALinks::set_capacity(int capacity)
{
  if (capacity == maxlinks) return;
  to_host();
  const int nlocal = atom->nlocal;

  // keep the links of the local atoms while the rows are reallocated
  std::vector<tagint> kept_partner;
  std::vector<double> kept_history;
  if (partner) {
    for (int i = 0; i < nlocal; i++) {
      if (nlinks[i] > capacity)
        error->one(FLERR, "Cannot reduce the link capacity of pair mca below {} links", nlinks[i]);
      kept_partner.insert(kept_partner.end(), partner[i], partner[i] + nlinks[i]);
      kept_history.insert(kept_history.end(), history[i], history[i] + nlinks[i] * row_size);
    }
  }
  maxlinks = capacity;
  allocate_rows(atom->nmax);
  if (!nlinks) {
    grow_arrays(atom->nmax);
    for (int i = 0; i < atom->nmax; i++) {
      nlinks[i] = 0;
      for (int k = 0; k < atom_size; k++) atom_state[i][k] = 0.0;
    }
  }
  size_t p = 0, h = 0;
  for (int i = 0; i < nlocal && !kept_partner.empty(); i++) {
    std::copy(kept_partner.data() + p, kept_partner.data() + p + nlinks[i], partner[i]);
    std::copy(kept_history.data() + h, kept_history.data() + h + nlinks[i] * row_size, history[i]);
    p += nlinks[i];
    h += nlinks[i] * row_size;
  }
  host_changed();

  // largest record an atom sends when it moves to another processor
  maxexchange = values_per_atom(maxlinks);
}

/* ---------------------------------------------------------------------- */

void FixMCALinks::remove_row(int i, int m)
{
  const int last = nlinks[i] - 1;
  if (m != last) {
    partner[i][m] = partner[i][last];
    memcpy(&history[i][m * row_size], &history[i][last * row_size], row_size * sizeof(double));
  }
  nlinks[i] = last;
}

/* ----------------------------------------------------------------------
   new, empty rows of maxlinks links for nmax atoms
------------------------------------------------------------------------- */

void FixMCALinks::allocate_rows(int nmax)
{
  memory->destroy(partner);
  memory->destroy(history);
  memory->create(partner, nmax, maxlinks, "mca/links:partner");
  memory->create(history, nmax, maxlinks * row_size, "mca/links:history");
}

/* ---------------------------------------------------------------------- */

double FixMCALinks::memory_usage()
{
  const double nmax = atom->nmax;
  return nmax *
      (sizeof(int) + maxlinks * (sizeof(tagint) + row_size * sizeof(double)) +
       atom_size * sizeof(double));
}

/* ---------------------------------------------------------------------- */

void FixMCALinks::grow_arrays(int nmax)
{
  memory->grow(nlinks, nmax, "mca/links:nlinks");
  memory->grow(partner, nmax, maxlinks, "mca/links:partner");
  memory->grow(history, nmax, maxlinks * row_size, "mca/links:history");
  memory->grow(atom_state, nmax, atom_size, "mca/links:atom_state");
}

/* ---------------------------------------------------------------------- */

void FixMCALinks::copy_arrays(int i, int j, int /*delflag*/)
{
  to_host();
  nlinks[j] = nlinks[i];
  for (int m = 0; m < nlinks[i]; m++) partner[j][m] = partner[i][m];
  memcpy(history[j], history[i], nlinks[i] * row_size * sizeof(double));
  for (int k = 0; k < atom_size; k++) atom_state[j][k] = atom_state[i][k];
  host_changed();
}

/* ----------------------------------------------------------------------
   pack the links of atom i for a move to another processor
------------------------------------------------------------------------- */

int FixMCALinks::pack_exchange(int i, double *buf)
{
  to_host();
  int m = 0;
  buf[m++] = nlinks[i];
  for (int k = 0; k < atom_size; k++) buf[m++] = atom_state[i][k];
  for (int k = 0; k < nlinks[i]; k++) {
    buf[m++] = ubuf(partner[i][k]).d;
    memcpy(&buf[m], &history[i][k * row_size], row_size * sizeof(double));
    m += row_size;
  }
  return m;
}

/* ---------------------------------------------------------------------- */

int FixMCALinks::unpack_exchange(int nlocal, double *buf)
{
  to_host();
  int m = 0;
  nlinks[nlocal] = static_cast<int>(buf[m++]);
  for (int k = 0; k < atom_size; k++) atom_state[nlocal][k] = buf[m++];
  for (int k = 0; k < nlinks[nlocal]; k++) {
    partner[nlocal][k] = (tagint) ubuf(buf[m++]).i;
    memcpy(&history[nlocal][k * row_size], &buf[m], row_size * sizeof(double));
    m += row_size;
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
  // every processor comes here before the per-atom records are packed
  sync_rows();
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
  if (format != 1000 * H_LAYOUT + H_SIZE)
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
    file.add_part(elastic.part, elastic.name, elastic.link_size, elastic.atom_size);
  }
  if (!model.same_blocks(file))
    error->all(FLERR,
               "Restart file holds MCA links with the blocks ({}) as name, values per link, "
               "values per automaton; the link model of the pair style has ({})",
               file.describe(), model.describe());

  set_capacity(static_cast<int>(list[0]));
  created = static_cast<int>(list[1]);
}

/* ----------------------------------------------------------------------
   per-atom restart data; buf[0] is the record length, as other fixes
   skip records by it
------------------------------------------------------------------------- */

int FixMCALinks::pack_restart(int i, double *buf)
{
  const int n = pack_exchange(i, &buf[1]);
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
  unpack_exchange(nlocal, &extra[nlocal][m]);
}

/* ---------------------------------------------------------------------- */

int FixMCALinks::size_restart(int nlocal)
{
  to_host();
  return 1 + values_per_atom(nlinks[nlocal]);
}

/* ---------------------------------------------------------------------- */

int FixMCALinks::maxsize_restart()
{
  return 1 + values_per_atom(maxlinks);
}
