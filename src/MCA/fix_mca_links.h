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
#include "mca_row_codec.h"

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   internal fix created by pair_style mca: the persistent table of links
   of each automaton, independent of neighbor lists.  Link m of atom i has
   the partner's atom ID and a row of its history (both halves, in the
   canonical order lower ID first) in a pool of rows.  A link between two
   local automata has one row, which both ends share (share_rows(), after
   atoms moved or rows were added); a link to a ghost atom has a row on
   each processor that owns one of its automata.  The rows of the pool are
   kept in the order in which the pair style's passes walk them.  An atom
   that moves to another processor, and a restart file, take a copy of
   each of its rows, so the two owners of a link never need each other's
   data.  Each automaton also keeps the law state of the link model.

   The fix knows no law: the pair style passes the blocks of its link
   model (MCALinkModel) as arguments, "name link_size atom_size" each,
   and "precision mixed" where its rows are stored so (mca_row_codec.h);
   the widths of a row and of the state follow from them.  Rows move to
   other processors as they are stored and go to restart files as
   doubles, whatever the precision.
------------------------------------------------------------------------- */

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
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;

  // link table, up to maxlinks links per atom, for the local atoms only
  // (nothing reads the links of a ghost atom)
  int maxlinks;           // capacity per automaton
  int nmax_atoms;         // atoms the per-atom tables hold
  int *nlinks;            // number of links of each atom
  tagint **partner;       // atom ID of the partner of each link
  int **slot;             // the row of each link in the pool
  double *rows;           // the pool: maxrows rows of stored_size doubles (mca_row_codec.h)
  int nrows, maxrows;     // rows in use, allocated
  double **atom_state;    // atom_size doubles of law state per automaton

  MCALinkModel model;    // the blocks of a row and of the state
  int row_size, atom_size;
  int stored_size;    // doubles of a stored row (row_size in precision double)

  int created;    // 1 once the links have been made (kept in restart files)

  // the stored row of link m of atom i (mca_row_codec.h), and its state
  // (LinkState) without decoding the rest
  double *stored_row(int i, int m) const { return pool_row(slot[i][m]); }
  // row s of the pool (flat: no array of row pointers, 8 bytes a row)
  double *pool_row(int s) const { return rows + static_cast<std::size_t>(s) * stored_size; }
  int link_state(int i, int m) const
  {
    return MCAKernels::stored_state(model.layout(), stored_row(i, m));
  }
  // the row of link m of atom i as the law reads it: the stored row, or
  // decoded into work (MAX_ROW_SIZE doubles)
  const double *read_row(int i, int m, double *work) const;
  // a new stored row for link m of local atom i (zeros)
  double *new_row(int i, int m);
  // a new row for link m of local atom i, from the law's row h
  void add_row(int i, int m, const double *h);
  // room for n rows in all (new_row() grows the pool by a quarter)
  void reserve_rows(bigint n);
  // one row for each link between local atoms (the row of the end that
  // evaluates it: partner_index[i][m] >= nlocal or the lower ID), the
  // rows in the order of those ends.  After every reneighboring: the box
  // may have remapped a local partner's closest image to a ghost atom.
  // False, with the IDs of i and j in apart, where local automaton i sees
  // local j but j sees another image of i: the link is lost (longer than
  // the ghost cutoff, or half a periodic box length)
  bool share_rows(int nlocal, const tagint *tag, int *const *partner_index, tagint *apart);

  void set_capacity(int);
  // room in the per-atom tables for atoms 0..n-1 (new entries: no links,
  // a law state of zeros)
  void reserve_atoms(int n);
  // drop link m of local atom i: the last link takes its place (host)
  void remove_row(int i, int m);
  class NeighList *build_full_list();

  // the host copy of the table is current / was changed on the host (the
  // Kokkos variant keeps the table in DualViews; here both do nothing)
  virtual void to_host() {}
  virtual void host_changed() {}

 protected:
  virtual void allocate_links(int nmax);
  virtual void resize_atom_tables(int nmax);
  virtual void grow_pool(int n);

 private:
  class NeighList *list;
  // atom i without links, its law state zeros (host)
  void clear_atom(int i);
  // values of an automaton's record, its rows width doubles each: stored
  // rows when it moves, rows as the law reads them in restart files (a
  // restart record has one more value: its length)
  int values_per_atom(int nlink, int width) const { return 1 + atom_size + nlink * (1 + width); }
  enum RecordRows { RECORD_STORED, RECORD_LAW, RECORD_LAYOUT1 };
  int pack_record(int i, double *buf, RecordRows record);
  // the blocks of the restart file being read, where its rows are in
  // history layout 1 (converted as they are read); empty otherwise
  MCALinkModel layout1_file;
  int unpack_record(int nlocal, const double *buf, RecordRows from);
  void convert_layout1_row(const double *old, double *row) const;
};

}    // namespace LAMMPS_NS

#endif
#endif
