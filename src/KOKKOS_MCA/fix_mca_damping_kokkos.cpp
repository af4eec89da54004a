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

#include "fix_mca_damping_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "atom_vec_mca_kokkos.h"

#include "mca_integration.h"

using namespace LAMMPS_NS;

namespace {
template <class DeviceType> struct MCAGlobalDamping {
  typedef DeviceType device_type;
  typedef double value_type;
  template <class DualViewType> using view = MCAKokkos::view_of<DualViewType, DeviceType>;

  view<decltype(AtomKokkos::k_v)> v;
  view<decltype(AtomKokkos::k_f)> f;
  view<decltype(AtomKokkos::k_omega)> omega;
  view<decltype(AtomKokkos::k_torque)> torque;
  view<decltype(AtomKokkos::k_rmass)> rmass;
  view<decltype(AtomKokkos::k_mask)> mask;
  MCAKokkos::double_1d<DeviceType> inertia;
  int groupbit;
  double gamma, gamma_r;

  KOKKOS_INLINE_FUNCTION void operator()(const int i, double &power) const
  {
    if (!(mask(i) & groupbit)) return;
    const double vi[3] = {v(i, 0), v(i, 1), v(i, 2)};
    const double wi[3] = {omega(i, 0), omega(i, 1), omega(i, 2)};
    double fi[3] = {f(i, 0), f(i, 1), f(i, 2)};
    double ti[3] = {torque(i, 0), torque(i, 1), torque(i, 2)};
    power += MCAKernels::global_damping(gamma, gamma_r, rmass(i), inertia(i), vi, wi, fi, ti);
    for (int k = 0; k < 3; k++) {
      f(i, k) = fi[k];
      torque(i, k) = ti[k];
    }
  }
};
}    // namespace

/* ---------------------------------------------------------------------- */

template <class DeviceType>
FixMCADampingKokkos<DeviceType>::FixMCADampingKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixMCADamping(lmp, narg, arg), avecKK(nullptr)
{
  MCAKokkos::require_kokkos(lmp, "Fix mca/damping/kk");
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = MCAKokkos::space_of<DeviceType>();
  datamask_read = EMPTY_MASK;
  datamask_modify = EMPTY_MASK;
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void FixMCADampingKokkos<DeviceType>::init()
{
  avecKK = dynamic_cast<AtomVecMCAKokkos *>(atom->avec);
  if (!avecKK) error->all(FLERR, "Fix mca/damping/kk requires atom_style mca/kk");
  FixMCADamping::init();
}

/* ----------------------------------------------------------------------
   as FixMCADamping::apply(), on the device
------------------------------------------------------------------------- */

template <class DeviceType> double FixMCADampingKokkos<DeviceType>::apply()
{
  atomKK->sync(execution_space,
               V_MASK | F_MASK | OMEGA_MASK | TORQUE_MASK | RMASS_MASK | MASK_MASK |
                   MCA_GEOMETRY_MASK);
  MCAGlobalDamping<DeviceType> damp;
  damp.v = atomKK->k_v.template view<DeviceType>();
  damp.f = atomKK->k_f.template view<DeviceType>();
  damp.omega = atomKK->k_omega.template view<DeviceType>();
  damp.torque = atomKK->k_torque.template view<DeviceType>();
  damp.rmass = atomKK->k_rmass.template view<DeviceType>();
  damp.mask = atomKK->k_mask.template view<DeviceType>();
  damp.inertia = avecKK->k_inertia.template view<DeviceType>();
  damp.groupbit = groupbit;
  damp.gamma = gamma;
  damp.gamma_r = gamma_r;
  double power = 0.0;
  Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType>(0, atom->nlocal), damp, power);
  atomKK->modified(execution_space, F_MASK | TORQUE_MASK);
  return power;
}

namespace LAMMPS_NS {
template class FixMCADampingKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixMCADampingKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
