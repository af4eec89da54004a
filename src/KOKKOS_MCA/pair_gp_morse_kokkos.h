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
PairStyle(gp/morse/kk,PairGPMorseKokkos<LMPDeviceType>);
PairStyle(gp/morse/kk/device,PairGPMorseKokkos<LMPDeviceType>);
PairStyle(gp/morse/kk/host,PairGPMorseKokkos<LMPHostType>);
// clang-format on
#else

#ifndef LMP_PAIR_GP_MORSE_KOKKOS_H
#define LMP_PAIR_GP_MORSE_KOKKOS_H

#include "pair_gp_morse.h"
#include "pair_morse_kokkos.h"

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   pair_style gp/morse/kk: the kernels of morse/kk with the parameters of
   the GP scale levels (gp_pair_style.h), so that it matches gp/morse as
   morse/kk matches morse
------------------------------------------------------------------------- */

template <class DeviceType>
class PairGPMorseKokkos : public PairGPStyle<PairMorseKokkos<DeviceType>, GPMorse> {
 public:
  PairGPMorseKokkos(class LAMMPS *lmp) : PairGPStyle<PairMorseKokkos<DeviceType>, GPMorse>(lmp) {}
};

}    // namespace LAMMPS_NS

#endif
#endif
