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
FixStyle(MCA_REBUILD,FixMCARebuild);
// clang-format on
#else

#ifndef LMP_FIX_MCA_REBUILD_H
#define LMP_FIX_MCA_REBUILD_H

#include "fix.h"

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   internal fix created by pair_style mca with contacts: the neighbor
   lists are rebuilt when the box has moved so far since the last build
   that an automaton may have come within reach of one it has no row for.
   LAMMPS's CPU check (Neighbor::check_distance) then rebuilds as soon as
   any atom moved; the Kokkos check lacks the clamp of the allowed
   displacement at zero and never rebuilds (a sheared or compressed box
   that moves more than the skin).  This fix asks for the rebuild with the
   CPU criterion on both paths; it reads the box only.
------------------------------------------------------------------------- */

class FixMCARebuild : public Fix {
 public:
  FixMCARebuild(class LAMMPS *, int, char **);

  int setmask() override;
  void init() override;
  void setup_pre_neighbor() override;
  void pre_neighbor() override;
  void post_integrate() override;
  double compute_scalar() override;

 private:
  int boxcheck;                     // the box can move (as Neighbor decides)
  double lo_hold[3], hi_hold[3];    // box bounds at the last build
  double corners_hold[8][3];        // triclinic: box corners then
  bigint forced;                    // rebuilds this fix asked for
};

}    // namespace LAMMPS_NS

#endif
#endif
