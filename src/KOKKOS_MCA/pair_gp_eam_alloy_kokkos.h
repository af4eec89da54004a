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
PairStyle(gp/eam/alloy/kk,PairGPEAMAlloyKokkos<LMPDeviceType>);
PairStyle(gp/eam/alloy/kk/device,PairGPEAMAlloyKokkos<LMPDeviceType>);
PairStyle(gp/eam/alloy/kk/host,PairGPEAMAlloyKokkos<LMPHostType>);
// clang-format on
#else

#ifndef LMP_PAIR_GP_EAM_ALLOY_KOKKOS_H
#define LMP_PAIR_GP_EAM_ALLOY_KOKKOS_H

#include "gp_eam_kokkos.h"
#include "pair_eam_alloy_kokkos.h"
#include "pair_gp_eam_alloy.h"

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   pair_style gp/eam/alloy/kk: the kernels of eam/alloy/kk with the tables of
   the GP scale levels (gp_eam_style.h), so that it matches gp/eam/alloy as
   eam/alloy/kk matches eam/alloy
------------------------------------------------------------------------- */

template <class DeviceType>
class PairGPEAMAlloyKokkos :
    public PairGPEAMStyle<PairEAMAlloyKokkos<DeviceType>, GPEAMAlloy, GPEAMKokkosTables> {
 public:
  PairGPEAMAlloyKokkos(class LAMMPS *lmp) :
      PairGPEAMStyle<PairEAMAlloyKokkos<DeviceType>, GPEAMAlloy, GPEAMKokkosTables>(lmp)
  {
  }
};

}    // namespace LAMMPS_NS

#endif
#endif
