// clang-format off
/* ----------------------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   LAMMPS development team: developers@lammps.org

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */
// clang-format on

/* ----------------------------------------------------------------------
   Contributing authors: MCA package developers
------------------------------------------------------------------------- */

#include "fix_mca_setvelocity_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "memory_kokkos.h"

#include "mca_prescribe.h"

using namespace LAMMPS_NS;

namespace {
struct Reaction {
  double f[3];
  KOKKOS_INLINE_FUNCTION Reaction() : f{0.0, 0.0, 0.0} {}
  KOKKOS_INLINE_FUNCTION void operator+=(const Reaction &rhs)
  {
    for (int k = 0; k < 3; k++) f[k] += rhs.f[k];
  }
#if MCA_KK_VOLATILE_JOIN
  KOKKOS_INLINE_FUNCTION void operator+=(const volatile Reaction &rhs) volatile
  {
    for (int k = 0; k < 3; k++) f[k] += rhs.f[k];
  }
#endif
};

template <class DeviceType> struct MCASetVelocity {
  typedef DeviceType device_type;
  typedef Reaction value_type;
  template <class DualViewType> using view = MCAKokkos::view_of<DualViewType, DeviceType>;

  view<decltype(AtomKokkos::k_v)> v;
  view<decltype(AtomKokkos::k_f)> f;
  view<decltype(AtomKokkos::k_mask)> mask;
  MCAKokkos::double_2d<DeviceType> vatom;
  int groupbit;
  int prescribed[3], per_atom[3];
  double value[3];

  KOKKOS_INLINE_FUNCTION void operator()(const int i, Reaction &reaction) const
  {
    if (!(mask(i) & groupbit)) return;
    for (int k = 0; k < 3; k++) {
      const double target = per_atom[k] ? vatom(i, k) : value[k];
      double vk = v(i, k), fk = f(i, k);
      reaction.f[k] += MCAKernels::prescribe_velocity(prescribed[k], target, vk, fk);
      v(i, k) = vk;
      f(i, k) = fk;
    }
  }
};
}    // namespace

/* ---------------------------------------------------------------------- */

template <class DeviceType>
FixMCASetVelocityKokkos<DeviceType>::FixMCASetVelocityKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixMCASetVelocity(lmp, narg, arg)
{
  MCAKokkos::require_kokkos(lmp, "Fix mca/setvelocity/kk");
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = MCAKokkos::space_of<DeviceType>();
  datamask_read = EMPTY_MASK;
  datamask_modify = EMPTY_MASK;
}

template <class DeviceType> FixMCASetVelocityKokkos<DeviceType>::~FixMCASetVelocityKokkos()
{
  if (copymode) return;
  // the base destructor then finds a null pointer
  memoryKK->destroy_kokkos(k_vatom, vatom);
}

/* ----------------------------------------------------------------------
   as FixMCASetVelocity::post_force(), on the device
------------------------------------------------------------------------- */

template <class DeviceType> void FixMCASetVelocityKokkos<DeviceType>::post_force(int /*vflag*/)
{
  bool any_atom_style = false;
  for (int k = 0; k < 3; k++) any_atom_style |= (style[k] == ATOM);

  if (any_atom_style && atom->nmax > maxatom) {
    maxatom = atom->nmax;
    memoryKK->destroy_kokkos(k_vatom, vatom);
    memoryKK->create_kokkos(k_vatom, vatom, maxatom, 3, "mca/setvelocity:vatom");
  }
  if (any_atom_style) atomKK->sync(Host, ALL_MASK);    // what the variables may read
  evaluate_targets();
  if (any_atom_style) {
    k_vatom.modify_host();
    k_vatom.template sync<DeviceType>();
  }

  atomKK->sync(execution_space, V_MASK | F_MASK | MASK_MASK);
  MCASetVelocity<DeviceType> set;
  set.v = atomKK->k_v.template view<DeviceType>();
  set.f = atomKK->k_f.template view<DeviceType>();
  set.mask = atomKK->k_mask.template view<DeviceType>();
  if (any_atom_style) set.vatom = k_vatom.template view<DeviceType>();
  set.groupbit = groupbit;
  for (int k = 0; k < 3; k++) {
    set.prescribed[k] = (style[k] != NONE);
    set.per_atom[k] = (style[k] == ATOM);
    set.value[k] = value[k];
  }
  Reaction sum;
  Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType>(0, atom->nlocal), set, sum);
  atomKK->modified(execution_space, V_MASK | F_MASK);

  for (int k = 0; k < 3; k++) reaction[k] = sum.f[k];
  reaction_flag = 0;
}

namespace LAMMPS_NS {
template class FixMCASetVelocityKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixMCASetVelocityKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
