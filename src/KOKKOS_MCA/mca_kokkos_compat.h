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

/* ----------------------------------------------------------------------
   The one place where KOKKOS_MCA deals with differences between the
   KOKKOS packages of the supported LAMMPS versions (the CPU half of the
   package has its own, ../MCA/mca_compat.h).

   - Views the package owns are declared here with explicit element types
     and layouts (LayoutRight: row i of a 2d view is contiguous, as the
     host pointer arrays made by memoryKK require), so that they do not
     depend on the precision typedefs that changed names (F_FLOAT ... in
     2021, KK_FLOAT later).
   - DualViews are accessed with view_host(), template view<D>(),
     sync_host(), modify_host(), which exist from Kokkos 3.4 on.
   - The views of AtomKokkos are taken with decltype of what
     k_x.view<D>() returns, never by their typedef names.
   - Interfaces whose signatures changed (forward communication of pair
     styles, the switch for the host "classic" exchange) have one macro
     each below, selected by the probe MCA_HAVE_KK_FLOAT (KOKKOS of 2023
     and later) written by cmake/Modules/Packages/MCA.cmake.
   - The atom style base class changed more: since 2023 AtomVecKokkos
     derives virtually from AtomVec, syncs with 64-bit masks and packs
     the fields AtomKokkos knows itself (probe MCA_HAVE_KK_AVEC_VIRTUAL);
     mask_t, sync_view, modify_view, MCA_KK_ATOMVEC_BASE and
     use_host_exchange below cover what atom_style mca/kk needs.
------------------------------------------------------------------------- */

#ifndef LMP_MCA_KOKKOS_COMPAT_H
#define LMP_MCA_KOKKOS_COMPAT_H

#include "error.h"
#include "kokkos_type.h"
#include "lammps.h"
#include "mca_config.h"
#include "memory_kokkos.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "pair.h"

#include <type_traits>
#include <utility>

namespace LAMMPS_NS {
namespace MCAKokkos {

  template <class DeviceType> using double_1d = Kokkos::View<double *, DeviceType>;
  template <class DeviceType>
  using double_2d = Kokkos::View<double **, Kokkos::LayoutRight, DeviceType>;
  template <class DeviceType>
  using double_3d = Kokkos::View<double ***, Kokkos::LayoutRight, DeviceType>;
  template <class DeviceType> using int_1d = Kokkos::View<int *, DeviceType>;
  template <class DeviceType> using int_2d = Kokkos::View<int **, Kokkos::LayoutRight, DeviceType>;

  typedef Kokkos::DualView<double *, LMPDeviceType> dual_double_1d;
  typedef Kokkos::DualView<double **, Kokkos::LayoutRight, LMPDeviceType> dual_double_2d;
  typedef Kokkos::DualView<int *, LMPDeviceType> dual_int_1d;
  typedef Kokkos::DualView<int **, Kokkos::LayoutRight, LMPDeviceType> dual_int_2d;
  typedef Kokkos::DualView<tagint **, Kokkos::LayoutRight, LMPDeviceType> dual_tagint_2d;

  // the view of a DualView member of AtomKokkos on DeviceType, whatever its typedef name
  template <class DualViewType, class DeviceType>
  using view_of = typename std::decay<
      decltype(std::declval<DualViewType &>().template view<DeviceType>())>::type;

  // the Kokkos styles construct only in a Kokkos-enabled run: a restart
  // file written by one holds their names (LAMMPS 2021 keeps the suffix)
  inline void require_kokkos(LAMMPS *lmp, const char *what)
  {
    if (!lmp->kokkos)
      lmp->error->all(FLERR,
                      "{} requires the KOKKOS package enabled with the command-line switch "
                      "'-k on' (a restart file written by a run with -sf kk names the /kk "
                      "styles: read it with -k on -sf kk)",
                      what);
  }

  // first base class of a Kokkos style whose members need an initialized
  // Kokkos (a duplicated ScatterView constructs an execution space instance
  // since Kokkos 4): stops with require_kokkos's message before them
  struct RequiresKokkos {
    RequiresKokkos(LAMMPS *lmp, const char *what) { require_kokkos(lmp, what); }
  };

  // a perpetual full neighbour list built on the device.  pair mca/kk does
  // not read it (the links carry their partners), but without any device
  // request the KOKKOS neighbour class checks the displacements for
  // reneighbouring on the host, copying the positions there every step
  // (half the time of a GPU step, measured on an H100)
  inline void request_device_list(Neighbor *neighbor, Pair *pair, int instance)
  {
#ifdef MCA_HAVE_ADD_REQUEST
    (void) instance;
    auto request = neighbor->add_request(pair, NeighConst::REQ_FULL);
    request->set_kokkos_device(1);
    request->set_kokkos_host(0);
#else
    const int irequest = neighbor->request(pair, instance);
    neighbor->requests[irequest]->half = 0;
    neighbor->requests[irequest]->full = 1;
    neighbor->requests[irequest]->kokkos_device = 1;
    neighbor->requests[irequest]->kokkos_host = 0;
#endif
  }

  // a perpetual full neighbour list of a Kokkos pair style, built in the
  // style's execution space (its kernels read it there)
  template <class DeviceType>
  inline void request_kokkos_full_list(Neighbor *neighbor, Pair *pair, int instance)
  {
    const int on_host = std::is_same<DeviceType, LMPHostType>::value &&
        !std::is_same<DeviceType, LMPDeviceType>::value;
    const int on_device = std::is_same<DeviceType, LMPDeviceType>::value;
#ifdef MCA_HAVE_ADD_REQUEST
    (void) instance;
    auto request = neighbor->add_request(pair, NeighConst::REQ_FULL);
    request->set_kokkos_host(on_host);
    request->set_kokkos_device(on_device);
#else
    const int irequest = neighbor->request(pair, instance);
    neighbor->requests[irequest]->half = 0;
    neighbor->requests[irequest]->full = 1;
    neighbor->requests[irequest]->kokkos_host = on_host;
    neighbor->requests[irequest]->kokkos_device = on_device;
#endif
  }

  // the per-atom energy and virial of a Kokkos pair style: DualViews whose
  // host copies are the style's eatom and vatom
  class PairTally {
   public:
    dual_double_1d k_eatom;
    dual_double_2d k_vatom;

    // made again at a step that tallies them, at the sizes ev_setup() chose
    void make(MemoryKokkos *memoryKK, double *&eatom, double **&vatom, int eflag_atom,
              int vflag_atom, int maxeatom, int maxvatom)
    {
      if (eflag_atom) {
        memoryKK->destroy_kokkos(k_eatom, eatom);
        memoryKK->create_kokkos(k_eatom, eatom, maxeatom, "pair:eatom");
      }
      if (vflag_atom) {
        memoryKK->destroy_kokkos(k_vatom, vatom);
        memoryKK->create_kokkos(k_vatom, vatom, maxvatom, 6, "pair:vatom");
      }
    }

    // what a kernel on DeviceType wrote, to the host copies
    template <class DeviceType> void to_host(int eflag_atom, int vflag_atom)
    {
      if (eflag_atom) {
        k_eatom.template modify<DeviceType>();
        k_eatom.sync_host();
      }
      if (vflag_atom) {
        k_vatom.template modify<DeviceType>();
        k_vatom.sync_host();
      }
    }

    // (the style's destructor: Pair's then finds null pointers)
    void destroy(MemoryKokkos *memoryKK, double *&eatom, double **&vatom)
    {
      memoryKK->destroy_kokkos(k_eatom, eatom);
      memoryKK->destroy_kokkos(k_vatom, vatom);
    }
  };

  // sync masks of the atom styles
#ifdef MCA_HAVE_KK_AVEC_VIRTUAL
  typedef uint64_t mask_t;
#else
  typedef unsigned int mask_t;
#endif

  // sync or mark modified one DualView of an atom style for a LAMMPS
  // execution space.  Since 2023 the views of AtomKokkos are TransformViews
  // with a third copy, the Kokkos host view (HostKK), which differs from
  // the legacy host arrays only in mixed precision; other views have one
  // host copy for both
  namespace Detail {
    template <class View> auto sync_hostkk(View &view, int) -> decltype(view.sync_hostkk())
    {
      return view.sync_hostkk();
    }
    template <class View> void sync_hostkk(View &view, long)
    {
      view.sync_host();
    }
    template <class View> auto modify_hostkk(View &view, int) -> decltype(view.modify_hostkk())
    {
      return view.modify_hostkk();
    }
    template <class View> void modify_hostkk(View &view, long)
    {
      view.modify_host();
    }
  }    // namespace Detail

  template <class View> void sync_view(View &view, ExecutionSpace space)
  {
    if (space == Device) {
      view.sync_device();
      return;
    }
#ifdef MCA_HAVE_KK_AVEC_VIRTUAL
    if (space == HostKK) {
      Detail::sync_hostkk(view, 0);
      return;
    }
#endif
    view.sync_host();
  }

  template <class View> void modify_view(View &view, ExecutionSpace space)
  {
    if (space == Device) {
      view.modify_device();
      return;
    }
#ifdef MCA_HAVE_KK_AVEC_VIRTUAL
    if (space == HostKK) {
      Detail::modify_hostkk(view, 0);
      return;
    }
#endif
    view.modify_host();
  }

  // atoms and ghost shells through the host communication of LAMMPS
  // (CommBrick with the field lists of the atom style), which sends the
  // link table of the links fix with its atoms; since 2023 atoms are also
  // sorted on the host for the same reason
  template <class KokkosLMPType> void use_host_exchange(KokkosLMPType *kokkos)
  {
#ifdef MCA_HAVE_KK_AVEC_VIRTUAL
    kokkos->exchange_comm_legacy = 1;
    kokkos->sort_legacy = 1;
#else
    kokkos->exchange_comm_classic = 1;
#endif
  }

  // execution space tag of LAMMPS for a device type
  template <class DeviceType> inline ExecutionSpace space_of()
  {
    return ExecutionSpaceFromDevice<DeviceType>::space;
  }

  // a device copy of a host array of plain records (materials by type): one call
  template <class DeviceType, class T>
  Kokkos::View<T *, DeviceType> copy_to_device(const T *host, int n, const char *label)
  {
    Kokkos::View<T *, DeviceType> device(std::string(label), n);
    auto mirror = Kokkos::create_mirror_view(device);
    for (int i = 0; i < n; i++) mirror(i) = host[i];
    Kokkos::deep_copy(device, mirror);
    return device;
  }

}    // namespace MCAKokkos
}    // namespace LAMMPS_NS

// the AtomVec base of a Kokkos atom style is virtual since 2023: the most
// derived class constructs it
#ifdef MCA_HAVE_KK_AVEC_VIRTUAL
#define MCA_KK_ATOMVEC_BASE(lmp) AtomVec(lmp),
#else
#define MCA_KK_ATOMVEC_BASE(lmp)
#endif

// Kokkos 3 joins the values of a reduction through volatile references
// (a value type needs a volatile operator+=); Kokkos 4 and later do not,
// and C++20 deprecates compound assignment to volatile operands
#define MCA_KK_VOLATILE_JOIN (KOKKOS_VERSION < 40000)

// forward communication of per-atom data of a pair style, Kokkos path
#ifdef MCA_HAVE_KK_FLOAT
#define MCA_KK_COMM_BUFFER DAT::tdual_double_1d
#define MCA_KK_PACK_FORWARD_ARGS \
  int n, DAT::tdual_int_1d k_sendlist, MCA_KK_COMM_BUFFER &k_buf, int pbc_flag, int *pbc
#define MCA_KK_SENDLIST_VIEW DAT::tdual_int_1d
#define MCA_KK_SENDLIST(list, iswap, i) list(i)
#else
#define MCA_KK_COMM_BUFFER DAT::tdual_xfloat_1d
#define MCA_KK_PACK_FORWARD_ARGS \
  int n, DAT::tdual_int_2d k_sendlist, int iswap, MCA_KK_COMM_BUFFER &k_buf, int pbc_flag, int *pbc
#define MCA_KK_SENDLIST_VIEW DAT::tdual_int_2d
#define MCA_KK_SENDLIST(list, iswap, i) list(iswap, i)
#endif

#endif
