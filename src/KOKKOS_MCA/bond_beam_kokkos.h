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

#ifdef BOND_CLASS
// clang-format off
BondStyle(beam/kk,BondBeamKokkos<LMPDeviceType>);
BondStyle(beam/kk/device,BondBeamKokkos<LMPDeviceType>);
BondStyle(beam/kk/host,BondBeamKokkos<LMPHostType>);
// clang-format on
#else

#ifndef LMP_BOND_BEAM_KOKKOS_H
#define LMP_BOND_BEAM_KOKKOS_H

#include "bond_beam.h"
#include "mca_kokkos_compat.h"

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   bond_style beam/kk: bond_style beam as one Kokkos kernel over the bond
   list (an instance per dimension), calling the same element
   (beam_kernels.h).  Forces and torques are added atomically (a bond adds
   to two atoms); the reference states of the listed bonds go to the
   device when the list is built again.  The particle criterion's sums
   are added atomically too (the candidate in a second pass: the largest
   measure, then the lowest partner ID among the bonds that have it) and
   go to the host, where the fix communicates them and decides
------------------------------------------------------------------------- */

template <class DeviceType>
class BondBeamKokkos : private MCAKokkos::RequiresKokkos, public BondBeam {
 public:
  BondBeamKokkos(class LAMMPS *);
  ~BondBeamKokkos() override;
  void compute(int, int) override;
  void init_style() override;
  bool stable_timestep(StableStep &out) override;

 private:
  class AtomKokkos *atomKK;
  class AtomVecMCAKokkos *avecKK;
  MCAKokkos::PairTally tally;    // per-atom energy and virial
  MCAKokkos::dual_double_2d k_records;
  Kokkos::View<BeamKernels::BeamCoeff *, DeviceType> d_coeff;
  MCAKokkos::int_2d<DeviceType> d_broken;
  Kokkos::View<int, DeviceType> d_nbroken;
  // the particle criterion: the fix's states and sums (PSTATE_*, PSUM_*
  // of local and ghost atoms) and each listed bond's measure on the device
  MCAKokkos::double_2d<DeviceType> d_pstate, d_psum;
  MCAKokkos::double_1d<DeviceType> d_bond_measure;
  // melting: the list entries of the bonds that froze again at this step
  MCAKokkos::int_1d<DeviceType> d_frozen;
  Kokkos::View<int, DeviceType> d_nfrozen;
  void refrozen_to_host();
  void specials_to_host() override;
  template <int DIM> void launch(int nlist, class NeighborKokkos *neighborKK);
  void particle_states_to_device(int nall);
  void find_candidates(int nlist, class NeighborKokkos *neighborKK);
  void particle_sums_to_host(int nall);
};

}    // namespace LAMMPS_NS

#endif
#endif
