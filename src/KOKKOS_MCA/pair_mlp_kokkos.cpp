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

#include "pair_mlp_kokkos.h"

#include "fix_mlp_frame.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory_kokkos.h"
#include "neigh_list_kokkos.h"
#include "neighbor.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace MLPKernels;

namespace {

// the force kernel: one local atom per call, its whole neighbour list
// (the passes of mlp_passes.h read the atoms and the list from its members)
template <class DeviceType> struct MLPForceKernel {
  template <class DualViewType> using view = MCAKokkos::view_of<DualViewType, DeviceType>;
  view<decltype(AtomKokkos::k_x)> x;
  view<decltype(AtomKokkos::k_f)> f;
  view<decltype(AtomKokkos::k_type)> type;
  Kokkos::View<MLPCoeff *, DeviceType> coeff;
  MCAKokkos::double_2d<DeviceType> half_turn;    // with a lattice frame
  typename ArrayTypes<DeviceType>::t_int_1d ilist, numneigh;
  typename ArrayTypes<DeviceType>::t_neighbors_2d neighbors;
  MCAKokkos::double_1d<DeviceType> eatom, freturn;
  MCAKokkos::double_2d<DeviceType> vatom;
  double special_lj[4];
  int ntypes1, return_style;
  int eflag_global, eflag_atom, vflag_global, vflag_atom, freturn_flag;

  template <int FRAME> KOKKOS_INLINE_FUNCTION void eval(const int ii, EV_FLOAT &ev) const
  {
    const int i = ilist(ii);
    const MLPAtomSums s = atom_forces<FRAME>(*this, i);
    f(i, 0) += s.fx;
    f(i, 1) += s.fy;
    if (eflag_global) ev.evdwl += s.energy;
    if (eflag_atom) eatom(i) += s.energy;
    if (vflag_global)
      for (int k = 0; k < 6; k++) ev.v[k] += s.v[k];
    if (vflag_atom)
      for (int k = 0; k < 6; k++) vatom(i, k) += s.v[k];
    if (freturn_flag) freturn(i) = sqrt(s.rx * s.rx + s.ry * s.ry);
  }
};

template <class DeviceType, int FRAME> struct MLPForceCall {
  MLPForceKernel<DeviceType> kernel;
  KOKKOS_INLINE_FUNCTION void operator()(const int ii, EV_FLOAT &ev) const
  {
    kernel.template eval<FRAME>(ii, ev);
  }
};

// the stable time step: the Gershgorin bound of omega^2 from each local
// atom's rows (PairMLP::row_bounds), and the number of pairs counted
template <class DeviceType, int FRAME> struct MLPRowBoundKernel {
  template <class DualViewType> using view = MCAKokkos::view_of<DualViewType, DeviceType>;
  view<decltype(AtomKokkos::k_x)> x;
  view<decltype(AtomKokkos::k_type)> type;
  view<decltype(AtomKokkos::k_rmass)> rmass;
  view<decltype(AtomKokkos::k_mass)> mass;
  Kokkos::View<MLPCoeff *, DeviceType> coeff;
  MCAKokkos::double_2d<DeviceType> half_turn;
  typename ArrayTypes<DeviceType>::t_int_1d ilist, numneigh;
  typename ArrayTypes<DeviceType>::t_neighbors_2d neighbors;
  MCAKokkos::double_1d<DeviceType> bound;
  double special_lj[4];
  int ntypes1, return_style, per_atom_mass;

  KOKKOS_INLINE_FUNCTION double mass_of(const int i) const
  {
    return per_atom_mass ? rmass(i) : mass(type(i));
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int ii, bigint &pairs) const
  {
    const int i = ilist(ii);
    bound(i) = atom_row_bound<FRAME>(*this, i, pairs);
  }
};

// (cos a/2, sin a/2) of each atom's body angle a (fix mlp/frame)
template <class DeviceType> struct MLPHalfTurnKernel {
  template <class DualViewType> using view = MCAKokkos::view_of<DualViewType, DeviceType>;
  view<decltype(AtomKokkos::k_mask)> mask;
  view<decltype(AtomKokkos::k_molecule)> molecule;
  MCAKokkos::double_1d<DeviceType> angle;
  MCAKokkos::double_2d<DeviceType> half_turn;
  int groupbit, by_molecule, nbody;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    const int b = frame_body(mask(i), groupbit, by_molecule, by_molecule ? molecule(i) : 0, nbody);
    const double a = (b < 0) ? 0.0 : angle(b);
    half_turn(i, 0) = cos(0.5 * a);
    half_turn(i, 1) = sin(0.5 * a);
  }
};

}    // namespace

/* ---------------------------------------------------------------------- */

template <class DeviceType>
PairMLPKokkos<DeviceType>::PairMLPKokkos(LAMMPS *lmp) :
    MCAKokkos::RequiresKokkos(lmp, "Pair style mlp/kk"), PairMLP(lmp), kk_nmax(0)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = MCAKokkos::space_of<DeviceType>();
  datamask_read = X_MASK | F_MASK | TYPE_MASK | ENERGY_MASK | VIRIAL_MASK;
  datamask_modify = F_MASK | ENERGY_MASK | VIRIAL_MASK;
}

template <class DeviceType> PairMLPKokkos<DeviceType>::~PairMLPKokkos()
{
  if (copymode) return;
  // the base destructor then finds null pointers
  tally.destroy(memoryKK, eatom, vatom);
  memoryKK->destroy_kokkos(k_freturn, freturn);
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void PairMLPKokkos<DeviceType>::init_style()
{
  if (domain->dimension != 2)
    error->all(FLERR,
               "Pair style mlp/kk requires dimension 2 (the return force toward the lattice "
               "axes is defined in the plane; doc/src/pair_mlp.rst)");
  MCAKokkos::request_kokkos_full_list<DeviceType>(neighbor, this, instance_me);
  find_frame();
}

/* ----------------------------------------------------------------------
   the coefficients of each type pair, both orders, on the device (the
   last init_one() call of a run is that of ntypes ntypes)
------------------------------------------------------------------------- */

template <class DeviceType> double PairMLPKokkos<DeviceType>::init_one(int i, int j)
{
  const double cut = PairMLP::init_one(i, j);
  if (i == atom->ntypes && j == atom->ntypes)
    d_coeff = MCAKokkos::copy_to_device<DeviceType>(coeff_table.data(), (int) coeff_table.size(),
                                                    "pair:mlp_coeff");
  return cut;
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void PairMLPKokkos<DeviceType>::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag, 0);
  tally.make(memoryKK, eatom, vatom, eflag_atom, vflag_atom, maxeatom, maxvatom);
  if (freturn_flag && atom->nmax > kk_nmax) {
    kk_nmax = atom->nmax;
    memoryKK->destroy_kokkos(k_freturn, freturn);
    memoryKK->create_kokkos(k_freturn, freturn, kk_nmax, "pair:freturn");
    nmax_freturn = kk_nmax;
  }

  atomKK->sync(execution_space, datamask_read);
  atomKK->modified(execution_space, datamask_modify);

  auto *klist = static_cast<NeighListKokkos<DeviceType> *>(list);
  MLPForceKernel<DeviceType> kernel;
  kernel.x = atomKK->k_x.template view<DeviceType>();
  kernel.f = atomKK->k_f.template view<DeviceType>();
  kernel.type = atomKK->k_type.template view<DeviceType>();
  kernel.coeff = d_coeff;
  kernel.ilist = klist->d_ilist;
  kernel.numneigh = klist->d_numneigh;
  kernel.neighbors = klist->d_neighbors;
  if (eflag_atom) {
    kernel.eatom = tally.k_eatom.template view<DeviceType>();
    Kokkos::deep_copy(kernel.eatom, 0.0);
  }
  if (vflag_atom) {
    kernel.vatom = tally.k_vatom.template view<DeviceType>();
    Kokkos::deep_copy(kernel.vatom, 0.0);
  }
  if (freturn_flag) kernel.freturn = k_freturn.template view<DeviceType>();
  for (int k = 0; k < 4; k++) kernel.special_lj[k] = force->special_lj[k];
  kernel.ntypes1 = atom->ntypes + 1;
  kernel.return_style = return_style;
  kernel.eflag_global = eflag_global;
  kernel.eflag_atom = eflag_atom;
  kernel.vflag_global = vflag_global;
  kernel.vflag_atom = vflag_atom;
  kernel.freturn_flag = freturn_flag;

  EV_FLOAT ev;
  if (frame) {
    kernel.half_turn = frame_half_turns_on_device();
    MLPForceCall<DeviceType, 1> call{kernel};
    Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType>(0, klist->inum), call, ev);
  } else {
    MLPForceCall<DeviceType, 0> call{kernel};
    Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType>(0, klist->inum), call, ev);
  }

  if (eflag_global) eng_vdwl += ev.evdwl;
  if (vflag_global)
    for (int k = 0; k < 6; k++) virial[k] += ev.v[k];
  tally.to_host<DeviceType>(eflag_atom, vflag_atom);
  if (freturn_flag) {
    k_freturn.template modify<DeviceType>();
    k_freturn.sync_host();
  }
  if (update->setupflag && update->whichflag == 1) check_stable_timestep();
}

/* ----------------------------------------------------------------------
   the stable time step: the rows on the device, the reduction on the host
------------------------------------------------------------------------- */

template <class DeviceType> bool PairMLPKokkos<DeviceType>::stable_timestep(StableStep &out)
{
  if (!list || neighbor->lastcall < 0) return false;
  const int per_atom_mass = atom->rmass ? 1 : 0;
  atomKK->sync(execution_space, X_MASK | TYPE_MASK | (per_atom_mass ? RMASS_MASK : EMPTY_MASK));
  if (!per_atom_mass) {
    atomKK->k_mass.modify_host();
    atomKK->k_mass.template sync<DeviceType>();
  }
  const int nlocal = atom->nlocal;
  if ((int) k_row_bound.extent(0) < nlocal)
    k_row_bound = MCAKokkos::dual_double_1d("pair:mlp_row_bound", atom->nmax);

  auto *klist = static_cast<NeighListKokkos<DeviceType> *>(list);
  auto fill = [&](auto &kernel) {
    kernel.x = atomKK->k_x.template view<DeviceType>();
    kernel.type = atomKK->k_type.template view<DeviceType>();
    if (per_atom_mass)
      kernel.rmass = atomKK->k_rmass.template view<DeviceType>();
    else
      kernel.mass = atomKK->k_mass.template view<DeviceType>();
    kernel.coeff = d_coeff;
    kernel.ilist = klist->d_ilist;
    kernel.numneigh = klist->d_numneigh;
    kernel.neighbors = klist->d_neighbors;
    kernel.bound = k_row_bound.template view<DeviceType>();
    for (int k = 0; k < 4; k++) kernel.special_lj[k] = force->special_lj[k];
    kernel.ntypes1 = atom->ntypes + 1;
    kernel.return_style = return_style;
    kernel.per_atom_mass = per_atom_mass;
  };
  Kokkos::deep_copy(k_row_bound.template view<DeviceType>(), 0.0);
  bigint pairs = 0;
  if (frame) {
    MLPRowBoundKernel<DeviceType, 1> kernel;
    fill(kernel);
    kernel.half_turn = frame_half_turns_on_device();
    Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType>(0, klist->inum), kernel, pairs);
  } else {
    MLPRowBoundKernel<DeviceType, 0> kernel;
    fill(kernel);
    Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType>(0, klist->inum), kernel, pairs);
  }
  k_row_bound.template modify<DeviceType>();
  k_row_bound.sync_host();
  out = reduce_stable_timestep(k_row_bound.view_host().data(), pairs);
  return true;
}

/* ----------------------------------------------------------------------
   the half turns of the owned and ghost atoms, from the body angles of the
   frame fix (a host fix: its few angles are copied each step)
------------------------------------------------------------------------- */

template <class DeviceType>
MCAKokkos::double_2d<DeviceType> PairMLPKokkos<DeviceType>::frame_half_turns_on_device()
{
  const int nall = atom->nlocal + atom->nghost;
  if ((int) d_half_turn.extent(0) < nall)
    d_half_turn = MCAKokkos::double_2d<DeviceType>("pair:mlp_half_turn", atom->nmax, 2);
  if ((int) k_body_angle.extent(0) != frame->nbody)
    k_body_angle = MCAKokkos::dual_double_1d("pair:mlp_body_angle", frame->nbody);
  for (int b = 0; b < frame->nbody; b++) k_body_angle.view_host()(b) = frame->body_angles()[b];
  k_body_angle.modify_host();
  k_body_angle.template sync<DeviceType>();
  MCAKokkos::mask_t mask = MASK_MASK;
  if (frame->by_molecule) mask |= MOLECULE_MASK;
  atomKK->sync(execution_space, mask);
  MLPHalfTurnKernel<DeviceType> turn;
  turn.mask = atomKK->k_mask.template view<DeviceType>();
  if (frame->by_molecule) turn.molecule = atomKK->k_molecule.template view<DeviceType>();
  turn.angle = k_body_angle.template view<DeviceType>();
  turn.half_turn = d_half_turn;
  turn.groupbit = frame->groupbit;
  turn.by_molecule = frame->by_molecule;
  turn.nbody = frame->nbody;
  Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, nall), turn);
  return d_half_turn;
}

namespace LAMMPS_NS {
template class PairMLPKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class PairMLPKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
