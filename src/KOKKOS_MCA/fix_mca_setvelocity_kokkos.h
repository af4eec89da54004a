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
FixStyle(mca/setvelocity/kk,FixMCASetVelocityKokkos<LMPDeviceType>);
FixStyle(mca/setvelocity/kk/device,FixMCASetVelocityKokkos<LMPDeviceType>);
FixStyle(mca/setvelocity/kk/host,FixMCASetVelocityKokkos<LMPHostType>);
// clang-format on
#else

#ifndef LMP_FIX_MCA_SETVELOCITY_KOKKOS_H
#define LMP_FIX_MCA_SETVELOCITY_KOKKOS_H

#include "fix_mca_setvelocity.h"
#include "mca_kokkos_compat.h"

namespace LAMMPS_NS {

// fix mca/setvelocity as one Kokkos kernel: numbers and equal-style
// variables are evaluated on the host and passed to the kernel;
// atom-style variables are evaluated on the host (LAMMPS evaluates them
// there) and copied to the device
template <class DeviceType> class FixMCASetVelocityKokkos : public FixMCASetVelocity {
 public:
  FixMCASetVelocityKokkos(class LAMMPS *, int, char **);
  ~FixMCASetVelocityKokkos() override;
  void post_force(int) override;

 private:
  class AtomKokkos *atomKK;
  MCAKokkos::dual_double_2d k_vatom;
};

}    // namespace LAMMPS_NS

#endif
#endif
