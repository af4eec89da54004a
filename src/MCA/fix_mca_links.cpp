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
#include "mca_kernels.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"

#include <algorithm>
#include <cstring>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;
using namespace MCAKernels;

// per-atom values besides the rows: nlinks, smean_step, smean_law
static constexpr int NPERATOM = 3;

/* ---------------------------------------------------------------------- */

FixMCALinks::FixMCALinks(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), nlinks(nullptr), partner(nullptr), history(nullptr), smean_step(nullptr),
    smean_law(nullptr), row_sync(nullptr), lazy_rows(0), list(nullptr)
{
  if (narg != 3) error->all(FLERR, "Illegal fix MCA_LINKS command (internal fix of pair mca)");

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
  memory->destroy(smean_step);
  memory->destroy(smean_law);
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
      kept_history.insert(kept_history.end(), history[i], history[i] + nlinks[i] * H_SIZE);
    }
  }
  maxlinks = capacity;
  allocate_rows(atom->nmax);
  if (!nlinks) {
    grow_arrays(atom->nmax);
    for (int i = 0; i < atom->nmax; i++) {
      nlinks[i] = 0;
      smean_step[i] = smean_law[i] = 0.0;
    }
  }
  size_t p = 0, h = 0;
  for (int i = 0; i < nlocal && !kept_partner.empty(); i++) {
    std::copy(kept_partner.data() + p, kept_partner.data() + p + nlinks[i], partner[i]);
    std::copy(kept_history.data() + h, kept_history.data() + h + nlinks[i] * H_SIZE, history[i]);
    p += nlinks[i];
    h += nlinks[i] * H_SIZE;
  }
  host_changed();

  // largest record an atom sends when it moves to another processor
  maxexchange = NPERATOM + maxlinks * (1 + H_SIZE);
}

/* ----------------------------------------------------------------------
   new, empty rows of maxlinks links for nmax atoms
------------------------------------------------------------------------- */

void FixMCALinks::allocate_rows(int nmax)
{
  memory->destroy(partner);
  memory->destroy(history);
  memory->create(partner, nmax, maxlinks, "mca/links:partner");
  memory->create(history, nmax, maxlinks * H_SIZE, "mca/links:history");
}

/* ---------------------------------------------------------------------- */

double FixMCALinks::memory_usage()
{
  const double nmax = atom->nmax;
  return nmax *
      (sizeof(int) + maxlinks * (sizeof(tagint) + H_SIZE * sizeof(double)) + 2.0 * sizeof(double));
}

/* ---------------------------------------------------------------------- */

void FixMCALinks::grow_arrays(int nmax)
{
  memory->grow(nlinks, nmax, "mca/links:nlinks");
  memory->grow(partner, nmax, maxlinks, "mca/links:partner");
  memory->grow(history, nmax, maxlinks * H_SIZE, "mca/links:history");
  memory->grow(smean_step, nmax, "mca/links:smean_step");
  memory->grow(smean_law, nmax, "mca/links:smean_law");
}

/* ---------------------------------------------------------------------- */

void FixMCALinks::copy_arrays(int i, int j, int /*delflag*/)
{
  to_host();
  nlinks[j] = nlinks[i];
  for (int m = 0; m < nlinks[i]; m++) partner[j][m] = partner[i][m];
  memcpy(history[j], history[i], nlinks[i] * H_SIZE * sizeof(double));
  smean_step[j] = smean_step[i];
  smean_law[j] = smean_law[i];
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
  buf[m++] = smean_step[i];
  buf[m++] = smean_law[i];
  for (int k = 0; k < nlinks[i]; k++) {
    buf[m++] = ubuf(partner[i][k]).d;
    memcpy(&buf[m], &history[i][k * H_SIZE], H_SIZE * sizeof(double));
    m += H_SIZE;
  }
  return m;
}

/* ---------------------------------------------------------------------- */

int FixMCALinks::unpack_exchange(int nlocal, double *buf)
{
  to_host();
  int m = 0;
  nlinks[nlocal] = static_cast<int>(buf[m++]);
  smean_step[nlocal] = buf[m++];
  smean_law[nlocal] = buf[m++];
  for (int k = 0; k < nlinks[nlocal]; k++) {
    partner[nlocal][k] = (tagint) ubuf(buf[m++]).i;
    memcpy(&history[nlocal][k * H_SIZE], &buf[m], H_SIZE * sizeof(double));
    m += H_SIZE;
  }
  host_changed();
  return m;
}

/* ----------------------------------------------------------------------
   global restart data: capacity, whether the links exist, and the layout
   of the history rows (files written before layouts were numbered hold
   H_SIZE, i.e. layout 0)
------------------------------------------------------------------------- */

static int history_format()
{
  return 1000 * H_LAYOUT + H_SIZE;
}

void FixMCALinks::write_restart(FILE *fp)
{
  // every processor comes here before the per-atom records are packed
  sync_rows();
  to_host();
  if (comm->me == 0) {
    double list[3] = {(double) maxlinks, (double) created, (double) history_format()};
    int size = 3 * sizeof(double);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(list, sizeof(double), 3, fp);
  }
}

/* ---------------------------------------------------------------------- */

void FixMCALinks::restart(char *buf)
{
  auto list = (double *) buf;
  const int format = static_cast<int>(list[2]);
  if (format != history_format())
    error->all(FLERR,
               "Restart file holds MCA links in history layout {} with {} values each; this "
               "version reads layout {} with {}",
               format / 1000, format % 1000, static_cast<int>(H_LAYOUT), static_cast<int>(H_SIZE));
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
  return 1 + NPERATOM + nlinks[nlocal] * (1 + H_SIZE);
}

/* ---------------------------------------------------------------------- */

int FixMCALinks::maxsize_restart()
{
  return 1 + NPERATOM + maxlinks * (1 + H_SIZE);
}
