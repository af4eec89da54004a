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
PairStyle(mlp/kk,PairMLPKokkos<LMPDeviceType>);
PairStyle(mlp/kk/device,PairMLPKokkos<LMPDeviceType>);
PairStyle(mlp/kk/host,PairMLPKokkos<LMPHostType>);
// clang-format on
#else

#ifndef LMP_PAIR_MLP_KOKKOS_H
#define LMP_PAIR_MLP_KOKKOS_H

#include "mca_kokkos_compat.h"
#include "pair_mlp.h"

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   pair_style mlp/kk: pair_style mlp as one Kokkos kernel over the local
   atoms with a full neighbour list, calling the same pair function
   (mlp_kernels.h).  Each atom sums its own force, energy and virial
   share: no atomic additions, and the order of the sums is that of the
   CPU style for the same list
------------------------------------------------------------------------- */

template <class DeviceType>
class PairMLPKokkos : private MCAKokkos::RequiresKokkos, public PairMLP {
 public:
  PairMLPKokkos(class LAMMPS *);
  ~PairMLPKokkos() override;

  void compute(int, int) override;
  void init_style() override;
  double init_one(int, int) override;
  bool stable_timestep(StableStep &out) override;

 private:
  class AtomKokkos *atomKK;
  Kokkos::View<MLPKernels::MLPCoeff *, DeviceType> d_coeff;
  MCAKokkos::PairTally tally;    // per-atom energy and virial
  MCAKokkos::dual_double_1d k_freturn;
  int kk_nmax;
  MCAKokkos::double_2d<DeviceType> d_half_turn;
  MCAKokkos::dual_double_1d k_body_angle;
  MCAKokkos::double_2d<DeviceType> frame_half_turns_on_device();
  MCAKokkos::dual_double_1d k_row_bound;    // the stable time step's rows
};

}    // namespace LAMMPS_NS

#endif
#endif
