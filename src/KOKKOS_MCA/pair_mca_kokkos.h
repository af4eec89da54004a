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

#include "Kokkos_ScatterView.hpp"
#include "kokkos_base.h"
#include "mca_kokkos_compat.h"
#include "pair_mca.h"

namespace LAMMPS_NS {

template <class DeviceType> struct MCAPairViews;
template <class DeviceType> struct MCAChunkSums;
struct MCALinkSums;

// ScatterViews of the per-automaton sums: direct (one host thread: plain
// additions in the loop order; GPU: atomic additions) and duplicated per
// host thread (used for the per-atom energy and virial)
template <class DeviceType> struct MCAScatter {
  typedef typename DeviceType::memory_space memory_space;
  static constexpr bool host =
      Kokkos::SpaceAccessibility<Kokkos::HostSpace, memory_space>::accessible;
  typedef Kokkos::Experimental::ScatterView<
      double **, Kokkos::LayoutRight, DeviceType, Kokkos::Experimental::ScatterSum,
      Kokkos::Experimental::ScatterNonDuplicated,
      typename std::conditional<host, Kokkos::Experimental::ScatterNonAtomic,
                                Kokkos::Experimental::ScatterAtomic>::type>
      direct;
  typedef typename std::conditional<
      host,
      Kokkos::Experimental::ScatterView<
          double **, Kokkos::LayoutRight, DeviceType, Kokkos::Experimental::ScatterSum,
          Kokkos::Experimental::ScatterDuplicated, Kokkos::Experimental::ScatterNonAtomic>,
      direct>::type duplicated;
};

/* ----------------------------------------------------------------------
   pair_style mca/kk: the passes of pair_style mca as Kokkos kernels over
   the local automata, calling the same functions of mca_kernels.h.

   Each link is computed once, as in the CPU style: by the lower ID of two
   local automata (whose row is current) or by the local owner of a link
   to a ghost atom.  What it adds to the two automata (fabric and strain
   moment in the predictor; force, torque and traction moment in the link
   pass) goes into per-automaton sums: on one host thread directly, in the
   CPU style's order (which gives its bits); on several host threads each
   thread runs one contiguous chunk of the automata, adding directly to
   the automata of its chunk and into a per-chunk copy for the others
   (added by the kernel that reads the sums); on a GPU by atomic
   additions.  Only the owner of an automaton writes its force, torque
   and stress.
------------------------------------------------------------------------- */

// the batched elastic link pass where the style runs on host threads
// (pair_mca_kokkos.cpp); nothing elsewhere.  (The execution space, not the
// memory space: a GPU's unified memory is accessible from the host too)
template <class DeviceType,
          bool Host = Kokkos::SpaceAccessibility<typename DeviceType::execution_space,
                                                 Kokkos::HostSpace>::accessible>
struct MCABatchedLinkKernel;

template <class DeviceType>
class PairMCAKokkos : private MCAKokkos::RequiresKokkos, public PairMCA, public KokkosBase {
  template <class, bool> friend struct MCABatchedLinkKernel;

 public:
  PairMCAKokkos(class LAMMPS *);
  ~PairMCAKokkos() override;

  void compute(int, int) override;
  void init_style() override;
  void predict_mean_stress() override;

  int pack_forward_comm_kokkos(MCA_KK_PACK_FORWARD_ARGS) override;
  void unpack_forward_comm_kokkos(int, int, MCA_KK_COMM_BUFFER &) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  void estimate_forward_comm() override;
  double memory_usage() override;

 protected:
  void allocate_partner_cache() override;
  const char *links_fix_style() const override { return "MCA_LINKS/kk"; }
  void estimate_host_state() override;

 private:
  class AtomKokkos *atomKK;
  class AtomVecMCAKokkos *avecKK;
  class FixMCALinksKokkos *linksKK;

  // per automaton (local + ghost): predictor values sent to the ghosts
  MCAKokkos::dual_double_1d k_pred_stiffness, k_dsmean, k_smean_pred;
  // plasticity: the return of each automaton, sent to the ghosts
  MCAKokkos::dual_double_1d k_return_scale, k_return_smean;
  Kokkos::View<MCAKernels::MCAHardening *, DeviceType> d_hardening;
  // fracture: the rules by type pair
  Kokkos::View<MCAKernels::MCABreakRule *, DeviceType> d_break_rules;
  Kokkos::View<MCAKernels::MCAContactRule *, DeviceType> d_contact_rules;
  // per local automaton: link count, fabric tensor, and the sums of the
  // predictor, of the link pass and of the per-atom energy and virial
  typedef typename MCAScatter<DeviceType>::direct direct_type;
  typedef typename MCAScatter<DeviceType>::duplicated dup_type;
  // d_foreign: where a partner in another chunk adds to the automaton,
  // its row in the copies below (else -1)
  MCAKokkos::int_1d<DeviceType> d_link_count, d_foreign;
  MCAKokkos::double_2d<DeviceType> d_fabric, d_predictor_sums, d_link_sums, d_atom_tally;
  // several host threads: per-chunk copies of the contributions to
  // automata of other chunks (chunk_size automata per chunk), a row for
  // each automaton that takes such contributions
  MCAKokkos::double_3d<DeviceType> d_link_copies;
  dup_type dup_tally;
  bool need_dup() const;
  int chunks() const;
  // the chunked sums of the predictor and link passes
  MCAChunkSums<DeviceType> chunk_sums() const;
  template <class Pass> void run_link_kernel(Pass &, bool commit, struct MCALinkSums &);
  // (a member template, so that only MCABatchedLinkKernel's use for host
  // threads makes it: Deferred is not used)
  template <class Deferred> void batched_link_kernel(bool commit, struct MCALinkSums &);
  // a kernel over the links with the link sums: Pass<DeviceType, Sums, TallyScatter>
  template <template <class, class, class> class Pass>
  void link_kernel(bool commit, struct MCALinkSums &);
  void plastic_return(bool commit);
  // (nhealed: contacts that became links in this step's contact pass)
  void change_links(bool commit, int nhealed);
  // the per-atom values a stage communicates: a, b (or none), the columns
  // of c (or none)
  void stage_views(int stage, MCAKokkos::dual_double_1d *&a, MCAKokkos::dual_double_1d *&b,
                   MCAKokkos::dual_double_2d *&c);
  // the caches of the base class, in DualViews
  MCAKokkos::dual_int_2d k_partner_cache;
  // materials by type
  Kokkos::View<MCAKernels::MCAMaterial *, DeviceType> d_material;
  // per-atom energy and virial
  MCAKokkos::PairTally tally;

  int kk_nmax, kk_nsums, tally_nmax, chunk_size;    // kk_nsums: rows of the local arrays

  void grow_kk_peratom();
  void count_links_kk();
  void forward_comm_stage(int stage);
  MCAPairViews<DeviceType> views();
};

}    // namespace LAMMPS_NS

#endif
#endif
