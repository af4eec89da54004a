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
FixStyle(mca/damping/kk,FixMCADampingKokkos<LMPDeviceType>);
FixStyle(mca/damping/kk/device,FixMCADampingKokkos<LMPDeviceType>);
FixStyle(mca/damping/kk/host,FixMCADampingKokkos<LMPHostType>);
// clang-format on
#else

#ifndef LMP_FIX_MCA_DAMPING_KOKKOS_H
#define LMP_FIX_MCA_DAMPING_KOKKOS_H

#include "fix_mca_damping.h"
#include "mca_kokkos_compat.h"

namespace LAMMPS_NS {

// fix mca/damping as one Kokkos kernel (a reduction of the power)
template <class DeviceType> class FixMCADampingKokkos : public FixMCADamping {
 public:
  FixMCADampingKokkos(class LAMMPS *, int, char **);
  void init() override;

 protected:
  double apply() override;

 private:
  class AtomKokkos *atomKK;
  class AtomVecMCAKokkos *avecKK;
};

}    // namespace LAMMPS_NS

#endif
#endif
