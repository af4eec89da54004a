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
PairStyle(gp/lj/cut/kk,PairGPLJCutKokkos<LMPDeviceType>);
PairStyle(gp/lj/cut/kk/device,PairGPLJCutKokkos<LMPDeviceType>);
PairStyle(gp/lj/cut/kk/host,PairGPLJCutKokkos<LMPHostType>);
// clang-format on
#else

#ifndef LMP_PAIR_GP_LJ_CUT_KOKKOS_H
#define LMP_PAIR_GP_LJ_CUT_KOKKOS_H

#include "pair_gp_lj_cut.h"
#include "pair_lj_cut_kokkos.h"

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   pair_style gp/lj/cut/kk: the kernels of lj/cut/kk with the parameters of
   the GP scale levels (gp_pair_style.h), so that it matches gp/lj/cut as
   lj/cut/kk matches lj/cut
------------------------------------------------------------------------- */

template <class DeviceType>
class PairGPLJCutKokkos : public PairGPStyle<PairLJCutKokkos<DeviceType>, GPLJCut> {
 public:
  PairGPLJCutKokkos(class LAMMPS *lmp) : PairGPStyle<PairLJCutKokkos<DeviceType>, GPLJCut>(lmp) {}
};

}    // namespace LAMMPS_NS

#endif
#endif
