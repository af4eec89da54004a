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

#ifdef PAIR_CLASS
// clang-format off
PairStyle(gp/lj/cut,PairGPLJCut);
// clang-format on
#else

#ifndef LMP_PAIR_GP_LJ_CUT_H
#define LMP_PAIR_GP_LJ_CUT_H

#include "gp_pair_style.h"
#include "pair_lj_cut.h"

namespace LAMMPS_NS {

// pair_style gp/lj/cut: the Lennard-Jones potential of the GP scale levels
// (gp_pair_style.h, doc/src/pair_gp.rst)
class PairGPLJCut : public PairGPStyle<PairLJCut, GPLJCut> {
 public:
  PairGPLJCut(class LAMMPS *lmp) : PairGPStyle<PairLJCut, GPLJCut>(lmp) {}
};

}    // namespace LAMMPS_NS

#endif
#endif
