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

#ifdef ATOM_CLASS
// clang-format off
AtomStyle(mca/kk,AtomVecMCAKokkos);
AtomStyle(mca/kk/device,AtomVecMCAKokkos);
AtomStyle(mca/kk/host,AtomVecMCAKokkos);
// clang-format on
#else

#ifndef LMP_ATOM_VEC_MCA_KOKKOS_H
#define LMP_ATOM_VEC_MCA_KOKKOS_H

#include "atom_vec_kokkos.h"
#include "atom_vec_mca.h"
#include "mca_kokkos_compat.h"

namespace LAMMPS_NS {

// sync masks of the MCA fields: bits no field of atom_style mca uses
// otherwise (those of the DPD styles in 2021; unused bits above 2023's)
#ifdef MCA_HAVE_KK_AVEC_VIRTUAL
enum : uint64_t {
  MCA_GEOMETRY_MASK = 0x0100000000000000,    // packing, volume, inertia, given
  MCA_STATE_MASK = 0x0200000000000000,       // smean, stress, seq, eeq, epsp, damage
  MCA_QUAT_MASK = 0x0400000000000000         // orientation
};
#else
enum : unsigned int {
  MCA_GEOMETRY_MASK = 0x02000000,
  MCA_STATE_MASK = 0x04000000,
  MCA_QUAT_MASK = 0x08000000
};
#endif

/* ----------------------------------------------------------------------
   atom_style mca/kk: the fields of atom_style mca in DualViews.  Positions,
   velocities and spins of the ghosts are sent on the device every step
   (by this class in 2021, by the mask-driven packing of AtomVecKokkos
   since 2023); atoms and ghost shells are exchanged through the host
   ("classic" or "legacy") communication with the generic field lists of
   atom_style mca, because the link table that travels with each
   automaton lives in a fix, which the KOKKOS communication cannot send
   on the device
------------------------------------------------------------------------- */

class AtomVecMCAKokkos : public AtomVecMCAStyle<AtomVecKokkos> {
 public:
  AtomVecMCAKokkos(class LAMMPS *);
  ~AtomVecMCAKokkos() override;

  void init() override;
  void grow(int) override;
  void grow_pointers() override;

  void sync(ExecutionSpace space, MCAKokkos::mask_t mask) override;
  void modified(ExecutionSpace space, MCAKokkos::mask_t mask) override;
  void sync_host() override;
  void modified_host() override;
  void orientation_to_host() override;
  void orientation_changed_on_host() override;

#ifdef MCA_HAVE_KK_AVEC_VIRTUAL
  void sync_pinned(ExecutionSpace space, uint64_t mask, int async_flag = 0) override;
  void sort_kokkos(Kokkos::BinSort<KeyViewType, BinOp> &Sorter) override;
#else
  void sync_overlapping_device(ExecutionSpace space, unsigned int mask) override;

  // host communication: the generic field lists (AtomVecKokkos packs x, v, f only)
  int pack_comm_vel(int, int *, double *, int, int *) override;
  void unpack_comm_vel(int, int, double *) override;
  int pack_reverse(int, int, double *) override;
  void unpack_reverse(int, int *, double *) override;
  void data_vel(int, char **) override;
  void pack_vel(double **) override;
  void write_vel(FILE *, int, double **) override;

  int pack_comm_vel_kokkos(const int &n, const DAT::tdual_int_2d &list, const int &iswap,
                           const DAT::tdual_xfloat_2d &buf, const int &pbc_flag,
                           const int pbc[]) override;
  void unpack_comm_vel_kokkos(const int &n, const int &nfirst,
                              const DAT::tdual_xfloat_2d &buf) override;

  int pack_border_kokkos(int n, DAT::tdual_int_2d k_sendlist, DAT::tdual_xfloat_2d buf, int iswap,
                         int pbc_flag, int *pbc, ExecutionSpace space) override;
  void unpack_border_kokkos(const int &n, const int &nfirst, const DAT::tdual_xfloat_2d &buf,
                            ExecutionSpace space) override;
  int pack_exchange_kokkos(const int &nsend, DAT::tdual_xfloat_2d &buf,
                           DAT::tdual_int_1d k_sendlist, DAT::tdual_int_1d k_copylist,
                           ExecutionSpace space, int dim, X_FLOAT lo, X_FLOAT hi) override;
  int unpack_exchange_kokkos(DAT::tdual_xfloat_2d &k_buf, int nrecv, int nlocal, int dim,
                             X_FLOAT lo, X_FLOAT hi, ExecutionSpace space) override;
#endif

  // the MCA fields; the host pointers of MCAAtomFields alias their host views
  MCAKokkos::dual_int_1d k_packing, k_given;
  MCAKokkos::dual_double_1d k_volume, k_inertia, k_smean, k_seq, k_eeq, k_epsp, k_damage;
  MCAKokkos::dual_double_2d k_stress, k_quat;

 private:
  template <class Apply> void for_each_view(MCAKokkos::mask_t mask, Apply apply);
  void host_only(const char *what);
#ifndef MCA_HAVE_KK_AVEC_VIRTUAL
  template <class DeviceType>
  int pack_comm_vel_on(int n, const DAT::tdual_int_2d &list, int iswap,
                       const DAT::tdual_xfloat_2d &buf, int pbc_flag, const int pbc[]);
  template <class DeviceType>
  void unpack_comm_vel_on(int n, int first, const DAT::tdual_xfloat_2d &buf);
#endif
};

}    // namespace LAMMPS_NS

#endif
#endif
