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

#include "fix_nve_damped_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "atom_vec_mca_kokkos.h"
#include "error.h"
#include "mca_integration.h"

using namespace LAMMPS_NS;

namespace {
// one half step (HALF: before the forces, with the drift) or full step
// (after them), with the sums m |v|^2 and J |omega|^2 of the full-step
// velocities (mca_integration.h)
template <class DeviceType, bool HALF> struct DampedVerletStep {
  typedef DeviceType device_type;
  typedef double value_type[];
  template <class DualViewType> using view = MCAKokkos::view_of<DualViewType, DeviceType>;

  view<decltype(AtomKokkos::k_x)> x;
  view<decltype(AtomKokkos::k_v)> v;
  view<decltype(AtomKokkos::k_f)> f;
  view<decltype(AtomKokkos::k_omega)> omega;
  view<decltype(AtomKokkos::k_torque)> torque;
  view<decltype(AtomKokkos::k_radius)> radius;
  view<decltype(AtomKokkos::k_rmass)> rmass;
  view<decltype(AtomKokkos::k_mass)> mass;
  view<decltype(AtomKokkos::k_type)> type;
  view<decltype(AtomKokkos::k_mask)> mask;
  MCAKokkos::double_1d<DeviceType> inertia;    // automata (atom_style mca/kk)
  MCAKokkos::double_2d<DeviceType> quat;
  unsigned value_count;
  int groupbit, spin, per_atom_mass, automata;
  double dtf, dtv, a, a_r, inertia_factor;

  KOKKOS_INLINE_FUNCTION void operator()(const int i, value_type sums) const
  {
    if (!(mask(i) & groupbit)) return;
    const double m = per_atom_mass ? rmass(i) : mass(type(i));
    double vi[3] = {v(i, 0), v(i, 1), v(i, 2)};
    const double fi[3] = {f(i, 0), f(i, 1), f(i, 2)};
    if (HALF) {
      sums[0] += m * MCAKernels::damped_half_step(vi, fi, dtf / m, a);
      for (int k = 0; k < 3; k++) x(i, k) += dtv * vi[k];
    } else {
      sums[0] += m * MCAKernels::damped_full_step(vi, fi, dtf / m, a);
    }
    for (int k = 0; k < 3; k++) v(i, k) = vi[k];
    if (!spin) return;
    const double j = automata ? inertia(i) : inertia_factor * m * radius(i) * radius(i);
    double wi[3] = {omega(i, 0), omega(i, 1), omega(i, 2)};
    const double ti[3] = {torque(i, 0), torque(i, 1), torque(i, 2)};
    if (HALF)
      sums[1] += j * MCAKernels::damped_half_step(wi, ti, dtf / j, a_r);
    else
      sums[1] += j * MCAKernels::damped_full_step(wi, ti, dtf / j, a_r);
    for (int k = 0; k < 3; k++) omega(i, k) = wi[k];
    if (HALF && automata) {
      double qi[4] = {quat(i, 0), quat(i, 1), quat(i, 2), quat(i, 3)};
      MCAKernels::rotate_quaternion(qi, wi, dtv);
      for (int k = 0; k < 4; k++) quat(i, k) = qi[k];
    }
  }
};
}    // namespace

/* ---------------------------------------------------------------------- */

template <class DeviceType>
FixNVEDampedKokkos<DeviceType>::FixNVEDampedKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixNVEDamped(lmp, narg, arg)
{
  MCAKokkos::require_kokkos(lmp, "Fix nve/damped/kk");
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = MCAKokkos::space_of<DeviceType>();
  // (the kernels sync and mark what they read and write themselves)
  datamask_read = EMPTY_MASK;
  datamask_modify = EMPTY_MASK;
}

/* ----------------------------------------------------------------------
   per-type masses live in a DualView of their own, set on the host
------------------------------------------------------------------------- */

template <class DeviceType> void FixNVEDampedKokkos<DeviceType>::init()
{
  FixNVEDamped::init();
  atomKK->k_mass.modify_host();
  atomKK->k_mass.template sync<DeviceType>();
}

/* ---------------------------------------------------------------------- */

template <class DeviceType>
template <bool HALF>
void FixNVEDampedKokkos<DeviceType>::integrate(double &mvsq, double &jwsq)
{
  MCAKokkos::mask_t read = X_MASK | V_MASK | F_MASK | MASK_MASK | TYPE_MASK;
  read |= atom->rmass ? RMASS_MASK : EMPTY_MASK;
  if (spin) read |= OMEGA_MASK | TORQUE_MASK | RADIUS_MASK;
  auto *avecKK = automata ? dynamic_cast<AtomVecMCAKokkos *>(atom->avec) : nullptr;
  if (automata && !avecKK)
    error->all(FLERR, "Fix nve/damped/kk with automata requires atom_style mca/kk, not {}",
               atom->atom_style);
  if (avecKK) read |= MCA_GEOMETRY_MASK | MCA_QUAT_MASK;
  atomKK->sync(execution_space, read);

  DampedVerletStep<DeviceType, HALF> step;
  step.x = atomKK->k_x.template view<DeviceType>();
  step.v = atomKK->k_v.template view<DeviceType>();
  step.f = atomKK->k_f.template view<DeviceType>();
  if (spin) {
    step.omega = atomKK->k_omega.template view<DeviceType>();
    step.torque = atomKK->k_torque.template view<DeviceType>();
    step.radius = atomKK->k_radius.template view<DeviceType>();
  }
  step.automata = avecKK ? 1 : 0;
  if (avecKK) {
    step.inertia = avecKK->k_inertia.template view<DeviceType>();
    step.quat = avecKK->k_quat.template view<DeviceType>();
  }
  step.per_atom_mass = atom->rmass ? 1 : 0;
  if (atom->rmass)
    step.rmass = atomKK->k_rmass.template view<DeviceType>();
  else
    step.mass = atomKK->k_mass.template view<DeviceType>();
  step.type = atomKK->k_type.template view<DeviceType>();
  step.mask = atomKK->k_mask.template view<DeviceType>();
  step.value_count = 2;
  step.groupbit = groupbit;
  step.spin = spin;
  step.dtf = dtf;
  step.dtv = dtv;
  step.a = 0.5 * gamma * dtv;
  step.a_r = 0.5 * gamma_r * dtv;
  step.inertia_factor = inertia_factor;

  int nlocal = atom->nlocal;
  if (igroup == atom->firstgroup) nlocal = atom->nfirst;
  // (an array, not a pointer: Kokkos 5 takes an array reduction's result
  // as an array or a view)
  double result[2] = {0.0, 0.0};
  Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType>(0, nlocal), step, result);
  mvsq += result[0];
  jwsq += result[1];

  MCAKokkos::mask_t modified = V_MASK | (HALF ? X_MASK : EMPTY_MASK);
  if (spin) modified |= OMEGA_MASK;
  if (avecKK && HALF) modified |= MCA_QUAT_MASK;
  atomKK->modified(execution_space, modified);
}

template <class DeviceType>
void FixNVEDampedKokkos<DeviceType>::half_step(double &mvsq, double &jwsq)
{
  integrate<true>(mvsq, jwsq);
}

template <class DeviceType>
void FixNVEDampedKokkos<DeviceType>::full_step(double &mvsq, double &jwsq)
{
  integrate<false>(mvsq, jwsq);
}

namespace LAMMPS_NS {
template class FixNVEDampedKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixNVEDampedKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
