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
FixStyle(nve/damped/kk,FixNVEDampedKokkos<LMPDeviceType>);
FixStyle(nve/damped/kk/device,FixNVEDampedKokkos<LMPDeviceType>);
FixStyle(nve/damped/kk/host,FixNVEDampedKokkos<LMPHostType>);
// clang-format on
#else

#ifndef LMP_FIX_NVE_DAMPED_KOKKOS_H
#define LMP_FIX_NVE_DAMPED_KOKKOS_H

#include "fix_nve_damped.h"
#include "mca_kokkos_compat.h"

namespace LAMMPS_NS {

// fix nve/damped as two Kokkos kernels, each with a reduction of the
// kinetic energies of the full-step velocities
template <class DeviceType> class FixNVEDampedKokkos : public FixNVEDamped {
 public:
  FixNVEDampedKokkos(class LAMMPS *, int, char **);
  void init() override;

 protected:
  void half_step(double &, double &) override;
  void full_step(double &, double &) override;

 private:
  class AtomKokkos *atomKK;
  template <bool HALF> void integrate(double &mvsq, double &jwsq);
};

}    // namespace LAMMPS_NS

#endif
#endif
