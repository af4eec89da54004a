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
PairStyle(gp/morse,PairGPMorse);
// clang-format on
#else

#ifndef LMP_PAIR_GP_MORSE_H
#define LMP_PAIR_GP_MORSE_H

#include "gp_pair_style.h"
#include "pair_morse.h"

namespace LAMMPS_NS {

// pair_style gp/morse: the Morse potential of the GP scale levels
// (gp_pair_style.h, doc/src/pair_gp.rst)
class PairGPMorse : public PairGPStyle<PairMorse, GPMorse> {
 public:
  PairGPMorse(class LAMMPS *lmp) : PairGPStyle<PairMorse, GPMorse>(lmp) {}
};

}    // namespace LAMMPS_NS

#endif
#endif
