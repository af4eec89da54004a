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
FixStyle(mlp/traction,FixMLPTraction);
// clang-format on
#else

#ifndef LMP_FIX_MLP_TRACTION_H
#define LMP_FIX_MLP_TRACTION_H

#include "fix.h"

#include <vector>

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   fix mlp/traction: the compensating surface forces of pair_style mlp
   (doc/src/fix_mlp_traction.rst; digest B.4, option c).  At the first
   run it keeps each atom's lattice neighbours (the pairs within the
   return force's cutoff) and the surface vector S of its missing bonds;
   at every step it gives the atoms of the group f = cof(A) S
   (mlp_kernels.h surface_compensation), A the least-squares displacement
   gradient over their neighbours, taken in the atom's lattice frame when
   the pair style has one.  The free surfaces then carry the tractions of
   the isotropic medium of the lattice's wave moduli.  After each
   neighbour list build the surface atoms and the local indices of their
   neighbours are listed once (the plan), which the step reads
------------------------------------------------------------------------- */

class FixMLPTraction : public Fix {
 public:
  FixMLPTraction(class LAMMPS *, int, char **);
  ~FixMLPTraction() override;
  int setmask() override;
  void init() override;
  void init_list(int, class NeighList *) override;
  void setup(int) override;
  void min_setup(int) override;
  void post_neighbor() override;
  void min_post_neighbor() override;
  void post_force(int) override;
  void min_post_force(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  double compute_vector(int) override;
  double memory_usage() override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;

  static constexpr int MAXREF = 12;    // lattice neighbours an atom may keep

 protected:
  class PairMLP *pair;
  class NeighList *list;
  int made;          // the reference is made (at the first setup or from a restart file)
  double **ref;      // per atom: count, S (2), then per neighbour its ID and X (2)
  double **out;      // per atom: S (2), the force (2): the fix's per-atom array
  int counts[2];     // local: atoms given a force, atoms without a gradient
  bigint counted;    // the step of counts_all
  double counts_all[2];

  // the plan: the surface atoms of the group (S != 0) in this local numbering
  static constexpr int PLAN_REF = 3 + 2 * MAXREF;    // S (2), count, X (2 per neighbour)
  int nplan;
  std::vector<int> plan_atom;       // local index
  std::vector<int> plan_body;       // body in the lattice frame (-1: none)
  std::vector<int> plan_partner;    // [m MAXREF + k]: the closest image of neighbour k
  std::vector<double> plan_ref;     // [m PLAN_REF + ...]

  void make_reference();
  virtual void build_plan();
  // the forces of the plan's atoms (added to f, written to out)
  virtual void apply();
  int record_size(int i) const { return 3 + 3 * static_cast<int>(ref[i][0]); }
};

}    // namespace LAMMPS_NS

#endif
#endif
