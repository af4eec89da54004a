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

#include "fix_nve_mca_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "atom_vec_mca_kokkos.h"
#include "error.h"
#include "mca_integration.h"

using namespace LAMMPS_NS;

namespace {
template <class DeviceType, bool INITIAL> struct MCAVerletStep {
  typedef DeviceType device_type;
  template <class DualViewType> using view = MCAKokkos::view_of<DualViewType, DeviceType>;

  view<decltype(AtomKokkos::k_x)> x;
  view<decltype(AtomKokkos::k_v)> v;
  view<decltype(AtomKokkos::k_f)> f;
  view<decltype(AtomKokkos::k_omega)> omega;
  view<decltype(AtomKokkos::k_torque)> torque;
  view<decltype(AtomKokkos::k_rmass)> rmass;
  view<decltype(AtomKokkos::k_mask)> mask;
  MCAKokkos::double_1d<DeviceType> inertia;
  MCAKokkos::double_2d<DeviceType> quat;
  int groupbit;
  double dtf, dtv;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    if (!(mask(i) & groupbit)) return;
    double vi[3], wi[3], fi[3], ti[3];
    for (int k = 0; k < 3; k++) {
      vi[k] = v(i, k);
      wi[k] = omega(i, k);
      fi[k] = f(i, k);
      ti[k] = torque(i, k);
    }
    MCAKernels::kick(vi, wi, fi, ti, dtf, rmass(i), inertia(i));
    if (INITIAL) {
      double xi[3] = {x(i, 0), x(i, 1), x(i, 2)};
      double qi[4] = {quat(i, 0), quat(i, 1), quat(i, 2), quat(i, 3)};
      MCAKernels::drift(xi, qi, vi, wi, dtv);
      for (int k = 0; k < 3; k++) x(i, k) = xi[k];
      for (int k = 0; k < 4; k++) quat(i, k) = qi[k];
    }
    for (int k = 0; k < 3; k++) {
      v(i, k) = vi[k];
      omega(i, k) = wi[k];
    }
  }
};
}    // namespace

/* ---------------------------------------------------------------------- */

template <class DeviceType>
FixNVEMCAKokkos<DeviceType>::FixNVEMCAKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixNVEMCA(lmp, narg, arg), avecKK(nullptr)
{
  MCAKokkos::require_kokkos(lmp, "Fix nve/mca/kk");
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = MCAKokkos::space_of<DeviceType>();
  datamask_read = EMPTY_MASK;
  datamask_modify = EMPTY_MASK;
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void FixNVEMCAKokkos<DeviceType>::init()
{
  avecKK = dynamic_cast<AtomVecMCAKokkos *>(atom->avec);
  if (!avecKK)
    error->all(FLERR, "Fix nve/mca/kk requires atom_style mca/kk, not atom_style {}",
               atom->atom_style);
  avecKK->sync_host();    // the base class checks masses on the host
  FixNVEMCA::init();
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> template <bool INITIAL> void FixNVEMCAKokkos<DeviceType>::integrate()
{
  const MCAKokkos::mask_t read = X_MASK | V_MASK | F_MASK | OMEGA_MASK | TORQUE_MASK | RMASS_MASK |
      MASK_MASK | MCA_GEOMETRY_MASK | MCA_QUAT_MASK;
  atomKK->sync(execution_space, read);

  MCAVerletStep<DeviceType, INITIAL> step;
  step.x = atomKK->k_x.template view<DeviceType>();
  step.v = atomKK->k_v.template view<DeviceType>();
  step.f = atomKK->k_f.template view<DeviceType>();
  step.omega = atomKK->k_omega.template view<DeviceType>();
  step.torque = atomKK->k_torque.template view<DeviceType>();
  step.rmass = atomKK->k_rmass.template view<DeviceType>();
  step.mask = atomKK->k_mask.template view<DeviceType>();
  step.inertia = avecKK->k_inertia.template view<DeviceType>();
  step.quat = avecKK->k_quat.template view<DeviceType>();
  step.groupbit = groupbit;
  step.dtf = dtf;
  step.dtv = dtv;

  int nlocal = atom->nlocal;
  if (igroup == atom->firstgroup) nlocal = atom->nfirst;
  Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, nlocal), step);

  atomKK->modified(execution_space,
                   INITIAL ? (X_MASK | V_MASK | OMEGA_MASK | MCA_QUAT_MASK)
                           : (V_MASK | OMEGA_MASK));
}

template <class DeviceType> void FixNVEMCAKokkos<DeviceType>::initial_integrate(int /*vflag*/)
{
  integrate<true>();
}

template <class DeviceType> void FixNVEMCAKokkos<DeviceType>::final_integrate()
{
  integrate<false>();
}

namespace LAMMPS_NS {
template class FixNVEMCAKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixNVEMCAKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
