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
FixStyle(mlp/traction/kk,FixMLPTractionKokkos<LMPDeviceType>);
FixStyle(mlp/traction/kk/device,FixMLPTractionKokkos<LMPDeviceType>);
FixStyle(mlp/traction/kk/host,FixMLPTractionKokkos<LMPHostType>);
// clang-format on
#else

#ifndef LMP_FIX_MLP_TRACTION_KOKKOS_H
#define LMP_FIX_MLP_TRACTION_KOKKOS_H

#include "fix_mlp_traction.h"
#include "mca_kokkos_compat.h"

namespace LAMMPS_NS {

// fix mlp/traction with the step's forces as one Kokkos kernel over the
// plan (mlp_kernels.h surface_force); the plan is made on the host after
// each neighbour list build, as the reference at the first setup
template <class DeviceType> class FixMLPTractionKokkos : public FixMLPTraction {
 public:
  FixMLPTractionKokkos(class LAMMPS *, int, char **);
  void setup(int) override;

 protected:
  void build_plan() override;
  void apply() override;

 private:
  class AtomKokkos *atomKK;
  int capacity;    // rows of the device plan
  MCAKokkos::int_1d<DeviceType> d_atom, d_body;
  MCAKokkos::int_2d<DeviceType> d_partner;
  MCAKokkos::double_2d<DeviceType> d_ref, d_force;
  MCAKokkos::double_1d<DeviceType> d_angles;
};

}    // namespace LAMMPS_NS

#endif
#endif
