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
PairStyle(gp/eam/fs,PairGPEAMFS);
// clang-format on
#else

#ifndef LMP_PAIR_GP_EAM_FS_H
#define LMP_PAIR_GP_EAM_FS_H

#include "gp_eam_style.h"
#include "mca_config.h"
#include "pair_eam_fs.h"

namespace LAMMPS_NS {

// pair_style gp/eam/fs: the EAM potential of a Finnis-Sinclair setfl file at the GP
// scale levels (gp_eam_style.h, doc/src/pair_gp.rst)
using PairGPEAMFS = PairGPEAMStyle<PairEAMFS, GPEAMFS, GPEAMHostTables>;

#ifdef MCA_HAVE_EAM_VIRTUAL_BASE
// (LAMMPS 2021: PairEAMFS derives virtually from PairEAM, which the
// constructor then initialises)
template <> PairGPEAMStyle<PairEAMFS, GPEAMFS, GPEAMHostTables>::PairGPEAMStyle(class LAMMPS *);
#endif

}    // namespace LAMMPS_NS

#endif
#endif
