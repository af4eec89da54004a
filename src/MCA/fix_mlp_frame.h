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
FixStyle(mlp/frame,FixMLPFrame);
// clang-format on
#else

#ifndef LMP_FIX_MLP_FRAME_H
#define LMP_FIX_MLP_FRAME_H

#include "fix.h"

#include <vector>

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   fix mlp/frame: a co-rotating lattice frame for pair_style mlp
   (doc/src/fix_mlp_frame.rst; digest B.4, option a).  Every N steps it
   measures the angle each body has turned from its reference (the
   positions at the fix's definition) as the best-fit rotation of its
   atoms, atan2(sum m X x x', sum m X . x') about the centroids, and in
   between extrapolates it at the rate of the last two; pair mlp
   turns the lattice axes of a pair by the mean angle of its two atoms'
   bodies, so that a body turned as a whole keeps no surface torque.
------------------------------------------------------------------------- */

class FixMLPFrame : public Fix {
 public:
  FixMLPFrame(class LAMMPS *, int, char **);
  ~FixMLPFrame() override;
  int setmask() override;
  void setup_pre_force(int) override;
  void pre_force(int) override;
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

  // what pair mlp reads: the bodies (MLPKernels::frame_body) and the angle
  // each has turned (radians, continuous over turns)
  int by_molecule;
  int nbody;
  const double *body_angles() const { return angle.data(); }
  // the body of atom i (-1: none) and the angle it has turned (0 outside the bodies)
  int body_of(int) const;
  double atom_angle(int i) const
  {
    const int b = body_of(i);
    return b < 0 ? 0.0 : angle[b];
  }

 private:
  double **xref;                   // per atom: position in the reference relative to its
                                   // body's centroid, and 1 where it has one (0: atoms
                                   // created after the definition)
  std::vector<double> angle;       // in use at this step (radians)
  std::vector<double> measured;    // at the last measurement
  std::vector<double> rate;        // per step, between the last two
  bigint step_measured;            // -1: none yet
  int rate_known;                  // the rate is from an interval

  void measure();
};

}    // namespace LAMMPS_NS

#endif
#endif
