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
PairStyle(gp/eam/alloy,PairGPEAMAlloy);
// clang-format on
#else

#ifndef LMP_PAIR_GP_EAM_ALLOY_H
#define LMP_PAIR_GP_EAM_ALLOY_H

#include "gp_eam_style.h"
#include "mca_config.h"
#include "pair_eam_alloy.h"

namespace LAMMPS_NS {

// pair_style gp/eam/alloy: the EAM potential of a setfl file at the GP
// scale levels (gp_eam_style.h, doc/src/pair_gp.rst)
using PairGPEAMAlloy = PairGPEAMStyle<PairEAMAlloy, GPEAMAlloy, GPEAMHostTables>;

#ifdef MCA_HAVE_EAM_VIRTUAL_BASE
// (LAMMPS 2021: PairEAMAlloy derives virtually from PairEAM, which the
// constructor then initialises)
template <>
PairGPEAMStyle<PairEAMAlloy, GPEAMAlloy, GPEAMHostTables>::PairGPEAMStyle(class LAMMPS *);
#endif

}    // namespace LAMMPS_NS

#endif
#endif
