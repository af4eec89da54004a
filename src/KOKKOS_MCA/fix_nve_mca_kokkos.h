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
FixStyle(nve/mca/kk,FixNVEMCAKokkos<LMPDeviceType>);
FixStyle(nve/mca/kk/device,FixNVEMCAKokkos<LMPDeviceType>);
FixStyle(nve/mca/kk/host,FixNVEMCAKokkos<LMPHostType>);
// clang-format on
#else

#ifndef LMP_FIX_NVE_MCA_KOKKOS_H
#define LMP_FIX_NVE_MCA_KOKKOS_H

#include "fix_nve_mca.h"
#include "mca_kokkos_compat.h"

namespace LAMMPS_NS {

// velocity Verlet of fix nve/mca as one Kokkos kernel per half step,
// calling the same kick and drift functions (mca_integration.h)
template <class DeviceType> class FixNVEMCAKokkos : public FixNVEMCA {
 public:
  FixNVEMCAKokkos(class LAMMPS *, int, char **);
  void init() override;
  void initial_integrate(int) override;
  void final_integrate() override;

 private:
  class AtomKokkos *atomKK;
  class AtomVecMCAKokkos *avecKK;
  template <bool INITIAL> void integrate();
};

}    // namespace LAMMPS_NS

#endif
#endif
