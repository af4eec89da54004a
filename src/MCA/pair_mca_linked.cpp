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

#include "pair_mca_linked.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "mca_compat.h"
#include "mca_link_passes.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <cctype>
#include <string>

using namespace LAMMPS_NS;
using namespace MCAKernels;

// the links fix has a fixed ID, so that restart files find it again
static const char FIX_LINKS_ID[] = "MCA_LINKS";

/* ---------------------------------------------------------------------- */

PairMCALinked::PairMCALinked(LAMMPS *lmp, const char *label_) :
    Pair(lmp), links(nullptr), label(label_), capacity_user(0), cut_global(0.0),
    partner_cache(nullptr), cache_rows(0), cache_cols(0), cache_nlocal(-1), nstretched(0)
{
}

/* ---------------------------------------------------------------------- */

PairMCALinked::~PairMCALinked()
{
  if (copymode) return;
  memory->destroy(partner_cache);
  // the links fix is kept: a pair style command issued again (e.g. to
  // change a setting) finds the links and their history; clear removes it
}

/* ---------------------------------------------------------------------- */

void PairMCALinked::init_links()
{
  links = dynamic_cast<FixMCALinks *>(MCACompat::fix_by_id(modify, FIX_LINKS_ID));
  if (!links)
    links = dynamic_cast<FixMCALinks *>(modify->add_fix(
        fmt::format("{} all {} {}", FIX_LINKS_ID, links_fix_style(), model.fix_arguments())));
  if (!links->model.same_blocks(model))
    error->all(FLERR,
               "{}: the link model ({}) differs from the one the links were made with ({}); "
               "write a restart file and read it with the new model",
               label, model.describe(), links->model.describe());
  if (links->model.mixed() != model.mixed())
    error->all(FLERR,
               "{}: precision {} differs from the precision the links are stored in ({}); "
               "write a restart file and read it with the new precision",
               label, model.precision(), links->model.precision());
}

/* ----------------------------------------------------------------------
   at the first run: link the pairs the style says are linkable, from a
   full neighbor list
------------------------------------------------------------------------- */

void PairMCALinked::create_links()
{
  NeighList *full = links->build_full_list();
  const int inum = full->inum;
  const int *ilist = full->ilist;
  const int *numneigh = full->numneigh;
  int **firstneigh = full->firstneigh;
  const tagint *tag = atom->tag;

  // a row for each link the end i evaluates (the ownership rule of the
  // passes: a ghost partner or a local one of higher ID); the other end of
  // a link between local automata shares the partner's row (below)
  const int nlocal = atom->nlocal;
  const MCALinkOwners owners{nlocal, tag};
  auto evaluates = [&](int i, int j) {
    return !partner_evaluates(owners, i, j);
  };

  // capacity: the user's, or the largest number of links of an automaton;
  // the rows of this rank
  int nmost = 0;
  tagint worst = 0;
  bigint nrows = 0;
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    int n = 0;
    for (int jj = 0; jj < numneigh[i]; jj++) {
      const int j = firstneigh[i][jj] & NEIGHMASK;
      if (!linkable(i, j)) continue;
      n++;
      if (evaluates(i, j)) nrows++;
    }
    if (n > nmost) {
      nmost = n;
      worst = tag[i];
    }
  }
  int nmostall;
  MPI_Allreduce(&nmost, &nmostall, 1, MPI_INT, MPI_MAX, world);
  if (capacity_user > 0 && nmostall > capacity_user) {
    tagint worst_local = (nmost == nmostall) ? worst : MAXTAGINT, worst_all;
    MPI_Allreduce(&worst_local, &worst_all, 1, MPI_LMP_TAGINT, MPI_MIN, world);
    error->all(FLERR,
               "{}: automaton {} has {} neighbours to link, more than the capacity "
               "{} (pair_style mca capacity); reduce the link tolerance or raise the capacity",
               label, worst_all, nmostall, capacity_user);
  }
  links->set_capacity(capacity_user > 0 ? capacity_user : MAX(nmostall, 1));

  links->to_host();
  links->reserve_rows(nrows);
  bigint nlocal_links = 0;
  int duplicate = 0;
  // how far the lengths of the new links are from the sums of the radii
  // (a link is stress-free at the length it is made with)
  double misfit = 0.0;
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    int &n = links->nlinks[i];
    n = 0;
    for (int jj = 0; jj < numneigh[i]; jj++) {
      const int j = firstneigh[i][jj] & NEIGHMASK;
      if (!linkable(i, j)) continue;
      // two images of one partner: the periodic box is too small
      for (int k = 0; k < n; k++)
        if (links->partner[i][k] == tag[j]) duplicate = 1;
      if (evaluates(i, j)) {
        double row[MAX_ROW_SIZE] = {};
        init_link_row(i, j, row);
        links->add_row(i, n, row);
      } else {
        links->slot[i][n] = -1;
      }
      const double sum = atom->radius[i] + atom->radius[j];
      const double dx = atom->x[j][0] - atom->x[i][0], dy = atom->x[j][1] - atom->x[i][1],
                   dz = atom->x[j][2] - atom->x[i][2];
      misfit = MAX(misfit, fabs(sqrt(dx * dx + dy * dy + dz * dz) - sum) / sum);
      links->partner[i][n] = tag[j];
      n++;
    }
    nlocal_links += n;
  }
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    for (int m = 0; m < links->nlinks[i]; m++) {
      if (links->slot[i][m] >= 0) continue;
      const int j = atom->map(links->partner[i][m]);
      for (int k = 0; k < links->nlinks[j]; k++)
        if (links->partner[j][k] == tag[i]) links->slot[i][m] = links->slot[j][k];
      // (not linked the other way: a row of its own, and the partner cache
      // stops the run)
      if (links->slot[i][m] < 0) {
        double row[MAX_ROW_SIZE] = {};
        init_link_row(i, j, row);
        links->add_row(i, m, row);
      }
    }
  }
  int duplicate_all;
  MPI_Allreduce(&duplicate, &duplicate_all, 1, MPI_INT, MPI_MAX, world);
  if (duplicate_all)
    error->all(FLERR,
               "{}: an automaton would link to two periodic images of the same "
               "automaton; every periodic box length must exceed twice the link length "
               "(2 (1 + tolerance) (R_i + R_j))",
               label);
  links->created = 1;
  links->host_changed();

  bigint nall_links;
  MPI_Allreduce(&nlocal_links, &nall_links, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  double misfit_all;
  MPI_Allreduce(&misfit, &misfit_all, 1, MPI_DOUBLE, MPI_MAX, world);
  if (comm->me == 0) {
    std::string name(label);
    name[0] = tolower(name[0]);
    utils::logmesg(lmp,
                   "{}: {} links made, at most {} per automaton; stress-free at their lengths, "
                   "which differ from R_i + R_j by up to {:.3g} %\n",
                   name, nall_links / 2, nmostall, 100.0 * misfit_all);
  }
}

/* ----------------------------------------------------------------------
   local and ghost indices change only when LAMMPS reneighbors (and atoms
   move or are sorted)
------------------------------------------------------------------------- */

bool PairMCALinked::partners_outdated() const
{
  return neighbor->ago == 0 || cache_nlocal != atom->nlocal;
}

bool PairMCALinked::refresh_partners()
{
  if (!partners_outdated()) return false;
  build_partner_cache();
  return true;
}

/* ----------------------------------------------------------------------
   index of every link's partner (closest image); then the two ends of a
   link between local automata share one row (FixMCALinks::share_rows)
------------------------------------------------------------------------- */

void PairMCALinked::build_partner_cache()
{
  // (rows for the local automata only)
  const int nlocal = atom->nlocal;
  // the links fix's tables grow where LAMMPS gives an atom an index (its
  // hooks); one that came by another path gets an entry without links,
  // not a read past the tables' end
  links->reserve_atoms(nlocal + 1);
  if (cache_rows < nlocal || cache_cols < links->maxlinks) {
    cache_rows = local_rows(nlocal);
    cache_cols = links->maxlinks;
    allocate_partner_cache();
  }
  for (int i = 0; i < nlocal; i++)
    for (int m = 0; m < links->nlinks[i]; m++)
      partner_cache[i][m] = partner_index(i, links->partner[i][m]);
  cache_nlocal = nlocal;
  tagint apart[2];
  if (!links->share_rows(nlocal, atom->tag, partner_cache, apart))
    error->one(FLERR,
               "{}: the link of automaton {} to automaton {} is lost: {} sees another periodic "
               "image of {} (the link is longer than the communication cutoff {:.6g}, or half a "
               "periodic box length){}",
               label, apart[0], apart[1], apart[1], apart[0], comm_cutoff(), timestep_hint());
}

void PairMCALinked::allocate_partner_cache()
{
  memory->destroy(partner_cache);
  memory->create(partner_cache, cache_rows, cache_cols, "pair:partner_cache");
}

/* ----------------------------------------------------------------------
   index of automaton partner_tag as seen from i: the image closest to i;
   a link whose partner is not a local or ghost atom cannot be computed
------------------------------------------------------------------------- */

int PairMCALinked::partner_index(int i, tagint partner_tag)
{
  const int j = atom->map(partner_tag);
  if (j < 0)
    error->one(
        FLERR,
        "{}: the link of automaton {} to automaton {} is lost: the partner is "
        "farther than the communication cutoff {:.6g} (stretched link, or a deleted automaton); "
        "increase it with comm_modify cutoff or pair_style mca cutoff{}",
        label, atom->tag[i], partner_tag, comm_cutoff(), timestep_hint());
  return domain->closest_image(i, j);
}

double PairMCALinked::comm_cutoff() const
{
  return MAX(comm->cutghostuser, neighbor->cutneighmax);
}

/* ---------------------------------------------------------------------- */

MCAHostLinks PairMCALinked::host_links() const
{
  MCAHostLinks d;
  d.nlocal = atom->nlocal;
  d.layout = model.layout();
  d.tag_ = atom->tag;
  d.nlinks_ = links->nlinks;
  d.partner_ = partner_cache;
  d.slot_ = links->slot;
  d.rows_ = links->rows;
  d.row_stride_ = links->stored_size;
  d.nrows = links->nrows;
  d.atom_state_ = links->atom_state;
  return d;
}

/* ----------------------------------------------------------------------
   a link longer than the cutoff still acts (its partner is found through
   the atom map) but may be lost when it stretches beyond the ghost shell;
   reported on reneighboring steps (and at setup)
------------------------------------------------------------------------- */

void PairMCALinked::stretched_warning()
{
  bigint nall;
  MPI_Allreduce(&nstretched, &nall, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (nall > 0 && comm->me == 0)
    error->warning(FLERR,
                   "{}: {} links are longer than the cutoff {} at step {}; a link "
                   "whose partner leaves the ghost atoms stops the run{}",
                   label, nall / 2, cut_global, update->ntimestep, timestep_hint());
}
