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

#include "fix_mlp_traction_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "fix_mlp_frame.h"
#include "mlp_kernels.h"
#include "pair_mlp.h"

#include <cmath>

using namespace LAMMPS_NS;

// what the host part (the reference, the plan) reads
#define MLP_TRACTION_HOST_MASK (X_MASK | TYPE_MASK | MASK_MASK | TAG_MASK | MOLECULE_MASK)

namespace {

template <class DeviceType> struct MLPSurfaceForce {
  typedef DeviceType device_type;
  typedef int value_type;
  template <class DualViewType> using view = MCAKokkos::view_of<DualViewType, DeviceType>;

  view<decltype(AtomKokkos::k_x)> x;
  view<decltype(AtomKokkos::k_f)> f;
  MCAKokkos::int_1d<DeviceType> atom, body;
  MCAKokkos::int_2d<DeviceType> partner;
  MCAKokkos::double_2d<DeviceType> ref, force;
  MCAKokkos::double_1d<DeviceType> angles;
  int framed;

  // counts the atoms without a gradient
  KOKKOS_INLINE_FUNCTION void operator()(const int m, int &missing) const
  {
    const int i = atom(m);
    const bool turned = framed && body(m) >= 0;
    const double a = turned ? angles(body(m)) : 0.0;
    const double ca = turned ? cos(a) : 1.0, sa = turned ? sin(a) : 0.0;
    double fx, fy;
    if (!MLPKernels::surface_force(x, partner, ref, m, i, ca, sa, fx, fy)) {
      force(m, 0) = force(m, 1) = 0.0;
      missing++;
      return;
    }
    f(i, 0) += fx;
    f(i, 1) += fy;
    force(m, 0) = fx;
    force(m, 1) = fy;
  }
};
}    // namespace

/* ---------------------------------------------------------------------- */

template <class DeviceType>
FixMLPTractionKokkos<DeviceType>::FixMLPTractionKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixMLPTraction(lmp, narg, arg), capacity(0)
{
  MCAKokkos::require_kokkos(lmp, "Fix mlp/traction/kk");
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = MCAKokkos::space_of<DeviceType>();
  // (each part syncs what it reads)
  datamask_read = EMPTY_MASK;
  datamask_modify = EMPTY_MASK;
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void FixMLPTractionKokkos<DeviceType>::setup(int vflag)
{
  atomKK->sync(Host, MLP_TRACTION_HOST_MASK);
  FixMLPTraction::setup(vflag);
}

/* ----------------------------------------------------------------------
   the plan on the host (FixMLPTraction::build_plan), then on the device
------------------------------------------------------------------------- */

template <class DeviceType> void FixMLPTractionKokkos<DeviceType>::build_plan()
{
  atomKK->sync(Host, MLP_TRACTION_HOST_MASK);
  FixMLPTraction::build_plan();
  if (nplan > capacity || capacity == 0) {
    capacity = MAX(nplan, 1);
    d_atom = MCAKokkos::int_1d<DeviceType>("mlp/traction:atom", capacity);
    d_body = MCAKokkos::int_1d<DeviceType>("mlp/traction:body", capacity);
    d_partner = MCAKokkos::int_2d<DeviceType>("mlp/traction:partner", capacity, MAXREF);
    d_ref = MCAKokkos::double_2d<DeviceType>("mlp/traction:ref", capacity, PLAN_REF);
    d_force = MCAKokkos::double_2d<DeviceType>("mlp/traction:force", capacity, 2);
  }
  auto h_atom = Kokkos::create_mirror_view(d_atom);
  auto h_body = Kokkos::create_mirror_view(d_body);
  auto h_partner = Kokkos::create_mirror_view(d_partner);
  auto h_ref = Kokkos::create_mirror_view(d_ref);
  for (int m = 0; m < nplan; m++) {
    h_atom(m) = plan_atom[m];
    h_body(m) = plan_body[m];
    for (int k = 0; k < MAXREF; k++) h_partner(m, k) = plan_partner[m * MAXREF + k];
    for (int k = 0; k < PLAN_REF; k++) h_ref(m, k) = plan_ref[m * PLAN_REF + k];
  }
  Kokkos::deep_copy(d_atom, h_atom);
  Kokkos::deep_copy(d_body, h_body);
  Kokkos::deep_copy(d_partner, h_partner);
  Kokkos::deep_copy(d_ref, h_ref);
}

/* ----------------------------------------------------------------------
   the forces on the device; the plan's forces back to the per-atom output
------------------------------------------------------------------------- */

template <class DeviceType> void FixMLPTractionKokkos<DeviceType>::apply()
{
  const FixMLPFrame *frame = pair->lattice_frame();
  MLPSurfaceForce<DeviceType> kernel;
  kernel.framed = frame ? 1 : 0;
  if (frame) {
    if ((int) d_angles.extent(0) < frame->nbody)
      d_angles = MCAKokkos::double_1d<DeviceType>("mlp/traction:angles", frame->nbody);
    auto h_angles = Kokkos::create_mirror_view(d_angles);
    for (int b = 0; b < frame->nbody; b++) h_angles(b) = frame->body_angles()[b];
    Kokkos::deep_copy(d_angles, h_angles);
  }
  atomKK->sync(execution_space, X_MASK | F_MASK);
  kernel.x = atomKK->k_x.template view<DeviceType>();
  kernel.f = atomKK->k_f.template view<DeviceType>();
  kernel.atom = d_atom;
  kernel.body = d_body;
  kernel.partner = d_partner;
  kernel.ref = d_ref;
  kernel.force = d_force;
  kernel.angles = d_angles;
  int missing = 0;
  Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType>(0, nplan), kernel, missing);
  atomKK->modified(execution_space, F_MASK);
  counts[0] = nplan - missing;
  counts[1] = missing;

  auto h_force = Kokkos::create_mirror_view(d_force);
  Kokkos::deep_copy(h_force, d_force);
  for (int m = 0; m < nplan; m++) {
    out[plan_atom[m]][2] = h_force(m, 0);
    out[plan_atom[m]][3] = h_force(m, 1);
  }
}

namespace LAMMPS_NS {
template class FixMLPTractionKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixMLPTractionKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
