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
FixStyle(gp/link,FixGPLink);
// clang-format on
#else

#ifndef LMP_FIX_GP_LINK_H
#define LMP_FIX_GP_LINK_H

#include "fix.h"
#include "gp_link.h"

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   fix ID imaginary-group gp/link real-group [keyword value ...]: the
   imaginary particles of the GP method follow the real particles they
   are linked to (gp_link.h, doc/src/fix_gp_link.rst).  The links are
   made once, at the first setup: the nearest real particles of the
   adjacent levels (interfaces) or of the same level (surface images)
   within the search distance, their tags and weights kept per particle,
   moved with it and written to restart files.  After every drift the
   linked particles are put where their members say, before the forces;
   their forces and velocities are set to zero (they are not integrated)
------------------------------------------------------------------------- */

class FixGPLink : public Fix {
 public:
  static constexpr int MAX_MEMBERS = GPKernels::MAX_LINK_MEMBERS;

  FixGPLink(class LAMMPS *, int, char **);
  ~FixGPLink() override;
  int setmask() override;
  void init() override;
  void setup_pre_force(int) override;
  void pre_force(int) override {}
  void post_integrate() override;
  void post_force(int) override;
  void setup(int) override;
  void min_setup(int) override;
  void min_pre_force(int) override;
  void min_post_force(int) override;
  double compute_vector(int) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;

  void write_restart(FILE *) override;
  void restart(char *) override;
  double memory_usage() override;
  void grow_arrays(int) override;
  void set_arrays(int) override;
  void copy_arrays(int, int, int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;

 private:
  int real_group, real_bit;
  int max_members;        // members per imaginary particle, 4..12
  double cutoff;          // search distance for members (0: the pair cutoff)
  int same_level;         // 1: members of the same level (surface images)
  int energy_coupling;    // 1: the forces on the linked particles go to their members
  int quadratic_fit;      // 1: weights exact for quadratic motions too (fit quadratic)
  int linked;             // the links exist (made or read from a restart file)
  const int *level;       // the level of each atom type (the GP pair style's)
  double stats[4];        // linked particles, members per particle, largest member distance,
                          // largest sum of |weights|
  int nmax_arrays;        // allocated per-atom entries

  int *nmembers;        // per atom: 0 for all but the linked particles
  tagint **members;     // per atom: [MAX_MEMBERS] tags
  double **weights;     // per atom: [MAX_MEMBERS] weights
  double **returned;    // per atom (owned and ghost): forces returned to members
  int nmax_returned;

  void link();
  void update();
  int member_index(int i, int k);
  void follow(bool ghosts_current);
  void zero_motion();
  void return_forces(int vflag);
};

}    // namespace LAMMPS_NS

#endif
#endif
