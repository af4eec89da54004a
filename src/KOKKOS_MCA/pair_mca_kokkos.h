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
PairStyle(mca/kk,PairMCAKokkos<LMPDeviceType>);
PairStyle(mca/kk/device,PairMCAKokkos<LMPDeviceType>);
PairStyle(mca/kk/host,PairMCAKokkos<LMPHostType>);
// clang-format on
#else

#ifndef LMP_PAIR_MCA_KOKKOS_H
#define LMP_PAIR_MCA_KOKKOS_H

#include "kokkos_base.h"
#include "mca_kokkos_compat.h"
#include "pair_mca.h"

namespace LAMMPS_NS {

template <class DeviceType> struct MCAPairViews;

/* ----------------------------------------------------------------------
   pair_style mca/kk: the passes of pair_style mca as Kokkos kernels over
   the local automata, calling the same functions of mca_kernels.h.

   Race-free without atomics, and deterministic (the same bits for any
   number of threads): a link between two local automata is computed
   once, by the lower ID, which updates its row and writes what the
   partner needs (force, torque, traction) into the slot of that row in a
   result buffer; a second kernel lets every automaton gather the slots of
   its lower-ID partners, in the order of its own rows.  A link to a ghost atom is computed by its local owner.
   Only the owner of an automaton writes its force, torque, stress and
   energy.  The predictor and the link counts are sums over the rows of
   each automaton (each owner reads the current copy of the row).
------------------------------------------------------------------------- */

template <class DeviceType> class PairMCAKokkos : public PairMCA, public KokkosBase {
 public:
  PairMCAKokkos(class LAMMPS *);
  ~PairMCAKokkos() override;

  void compute(int, int) override;
  void init_style() override;
  void setup() override;
  void predict_mean_stress() override;
  void sync_link_rows() override;

  int pack_forward_comm_kokkos(MCA_KK_PACK_FORWARD_ARGS) override;
  void unpack_forward_comm_kokkos(int, int, MCA_KK_COMM_BUFFER &) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  double memory_usage() override;

 protected:
  void allocate_partner_cache() override;
  const char *links_fix_style() const override { return "MCA_LINKS/kk"; }

 private:
  class AtomKokkos *atomKK;
  class AtomVecMCAKokkos *avecKK;
  class FixMCALinksKokkos *linksKK;

  // per automaton (local + ghost): predictor values sent to the ghosts
  MCAKokkos::dual_double_1d k_pred_stiffness, k_dsmean, k_smean_pred;
  // per local automaton
  MCAKokkos::int_1d<DeviceType> d_link_count;
  MCAKokkos::double_2d<DeviceType> d_fabric, d_bmat;
  // what the lower ID of a local link leaves for its partner, by its own
  // row: force and torque on the partner, traction, normal, energy, and
  // the link's predictor record for the next step
  MCAKokkos::double_2d<DeviceType> d_result;
  // the caches of the base class, in DualViews
  MCAKokkos::dual_int_2d k_partner_cache, k_row_cache;
  // materials by type
  MCAKokkos::double_1d<DeviceType> d_shear, d_bulk, d_coupling;
  // per-atom energy and virial
  MCAKokkos::dual_double_1d k_eatom;
  MCAKokkos::dual_double_2d k_vatom;

  int kk_nmax, result_rows, result_cols;
  // the result buffer holds the predictor records of the last committed
  // step in the current order of the atoms
  bool slots_current;

  void grow_kk_peratom();
  void count_links_kk();
  void forward_comm_stage(int stage);
  MCAPairViews<DeviceType> views();
};

}    // namespace LAMMPS_NS

#endif
#endif
