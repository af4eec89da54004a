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

#ifndef LMP_PAIR_MCA_LINKED_H
#define LMP_PAIR_MCA_LINKED_H

#include "fix_mca_links.h"
#include "mca_link_model.h"
#include "pair.h"

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   the link table as the passes of mca_link_passes.h read it on the host
   (the Kokkos styles read the same names from their views)
------------------------------------------------------------------------- */

struct MCAHostLinks {
  int nlocal;
  MCAKernels::MCALinkLayout layout;
  const tagint *tag_;
  const int *nlinks_;
  int **partner_;    // local or ghost index of each link's partner
  int **slot_;       // the row of each link in the pool (both ends of a local link: one row)
  double *rows_;     // the pool, row_stride_ doubles a row
  int row_stride_;
  int nrows;    // rows of the pool in use
  double **atom_state_;

  tagint tag(int i) const { return tag_[i]; }
  int nlinks(int i) const { return nlinks_[i]; }
  int partner(int i, int m) const { return partner_[i][m]; }
  int slot(int i, int m) const { return slot_[i][m]; }
  double *history_row(int i, int m) const
  {
    return rows_ + static_cast<std::size_t>(slot_[i][m]) * row_stride_;
  }
  double &atom_state(int i, int k) const { return atom_state_[i][k]; }
};

/* ----------------------------------------------------------------------
   base of the pair styles whose automata keep persistent links (the
   links fix): the fix made with the blocks of the style's link model,
   the links made at the first run, the index of every link's partner,
   one row for each link between local automata, and the warning
   for links longer than the cutoff.  A derived style says which pairs
   link (linkable) and what a new link's row holds (init_link_row)
------------------------------------------------------------------------- */

class PairMCALinked : public Pair {
 public:
  PairMCALinked(class LAMMPS *, const char *label);
  ~PairMCALinked() override;

  class FixMCALinks *links;

 protected:
  const char *label;    // "Pair mca": how error messages name the style
  int capacity_user;    // links per automaton given by the user, else 0
  double cut_global;

  int **partner_cache;    // local or ghost index of each link's partner
  int cache_rows, cache_cols, cache_nlocal;
  bigint nstretched;    // links longer than the cutoff at the last step

  MCALinkModel model;    // the parts of the link law and their blocks
  // the links fix with the blocks of the model (made or found)
  void init_links();
  // style of the internal fix that keeps the links
  virtual const char *links_fix_style() const { return "MCA_LINKS"; }

  void create_links();
  virtual bool linkable(int i, int j) = 0;
  virtual void init_link_row(int i, int j, double *row) = 0;

  // the partner cache after LAMMPS reneighbored (or atoms moved): true
  // if it was made again (and the rows of local links shared)
  bool partners_outdated() const;
  bool refresh_partners();
  void build_partner_cache();
  virtual void allocate_partner_cache();
  // rows of an array of the local automata, with room for the changes of
  // their number at reneighboring (the partner cache, the pair styles' sums)
  static int local_rows(int nlocal) { return nlocal + nlocal / 64 + 16; }
  int partner_index(int i, tagint partner_tag);
  // how far the ghost atoms reach: the neighbour lists' cutoff, or the
  // comm_modify cutoff where it is larger (what the lost-link errors name)
  double comm_cutoff() const;
  MCAHostLinks host_links() const;
  void stretched_warning();
  // what a blow-up message adds about the time step (pair mca: how it
  // compares with the stable time step), or nothing
  virtual std::string timestep_hint() { return {}; }
};

}    // namespace LAMMPS_NS

#endif
