/* -*- c++ -*- ----------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   LAMMPS development team: developers@lammps.org

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(MCA_LINKS,FixMCALinks);
// clang-format on
#else

#ifndef LMP_FIX_MCA_LINKS_H
#define LMP_FIX_MCA_LINKS_H

#include "fix.h"
#include "mca_link_model.h"

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   internal fix created by pair_style mca: the persistent table of links
   of each automaton, independent of neighbor lists.  Row m of atom i holds
   the partner's atom ID and the whole link history (both halves, in the
   canonical order lower ID first), so the two owners of a link hold
   identical copies and never need each other's data (between the
   exchanges of atoms: see MCALinkRowSync).  Each automaton also keeps the
   law state of the link model.  Rows and state move with their atom
   between processors and are written to restart files.

   The fix knows no law: the pair style passes the blocks of its link
   model (MCALinkModel) as arguments, "name link_size atom_size" each, and
   the widths of a row and of the state follow from them.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   a style that advances a local link in the row of one of its automata
   only (leaving the partner's copy behind during a run) brings the copies
   up to date when asked: before atoms move between processors, at the end
   of a run and before a restart file is written
------------------------------------------------------------------------- */

class MCALinkRowSync {
 public:
  virtual void sync_link_rows() = 0;

 protected:
  ~MCALinkRowSync() = default;    // not deleted through this interface
};

class FixMCALinks : public Fix {
 public:
  FixMCALinks(class LAMMPS *, int, char **);
  ~FixMCALinks() override;
  int setmask() override;
  void init() override;
  void pre_exchange() override;
  void min_pre_exchange() override;
  void post_run() override;
  void init_list(int, class NeighList *) override;

  double memory_usage() override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;

  // link table, maxlinks rows per atom
  int maxlinks;           // capacity per automaton
  int *nlinks;            // number of links of each atom
  tagint **partner;       // atom ID of the partner of each link
  double **history;       // row_size doubles per link (see mca_link_layout.h)
  double **atom_state;    // atom_size doubles of law state per automaton

  MCALinkModel model;    // the blocks of a row and of the state
  int row_size, atom_size;

  int created;    // 1 once the links have been made (kept in restart files)

  // who brings the partner copies up to date (pair mca), and whether it
  // may leave them behind during this run: not if a fix that acts before
  // this one at pre-exchange could move atoms first
  MCALinkRowSync *row_sync;
  int lazy_rows;
  void sync_rows()
  {
    if (row_sync) row_sync->sync_link_rows();
  }

  void set_capacity(int);
  // drop row m of local atom i: the last row takes its place (host)
  void remove_row(int i, int m);
  class NeighList *build_full_list();

  // the host copy of the table is current / was changed on the host (the
  // Kokkos variant keeps the table in DualViews; here both do nothing)
  virtual void to_host() {}
  virtual void host_changed() {}

 protected:
  virtual void allocate_rows(int nmax);

 private:
  class NeighList *list;
  // values of an automaton's exchange record (a restart record has one more: its length)
  int values_per_atom(int nlink) const { return 1 + atom_size + nlink * (1 + row_size); }
};

}    // namespace LAMMPS_NS

#endif
#endif
