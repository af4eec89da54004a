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

#include "bond_beam_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "atom_vec_mca_kokkos.h"
#include "domain.h"
#include "error.h"
#include "fix_beam_state.h"
#include "force.h"
#include "memory_kokkos.h"
#include "neighbor_kokkos.h"
#include "update.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

using namespace LAMMPS_NS;
using namespace BeamKernels;

namespace {

template <class View>
using atomic_view = Kokkos::View<typename View::data_type, typename View::array_layout,
                                 typename View::device_type, Kokkos::MemoryTraits<Kokkos::Atomic>>;

// the force kernel: one bond per call (BondBeam::evaluate)
template <class DeviceType, int DIM> struct BeamForceKernel {
  template <class DualViewType> using view = MCAKokkos::view_of<DualViewType, DeviceType>;
  view<decltype(AtomKokkos::k_x)> x;
  view<decltype(AtomKokkos::k_v)> v;    // (read with damping only)
  view<decltype(AtomKokkos::k_omega)> omega;
  view<decltype(AtomKokkos::k_radius)> radius;    // (read with radii only)
  atomic_view<view<decltype(AtomKokkos::k_f)>> f;
  atomic_view<view<decltype(AtomKokkos::k_torque)>> torque;
  MCAKokkos::double_2d<DeviceType> quat, records;
  view<decltype(NeighborKokkos::k_bondlist)> bondlist;
  Kokkos::View<BeamCoeff *, DeviceType> coeff;
  atomic_view<MCAKokkos::double_1d<DeviceType>> eatom;
  atomic_view<MCAKokkos::double_2d<DeviceType>> vatom;
  MCAKokkos::int_2d<DeviceType> broken;    // entries (i1, i2, n) broken this step
  Kokkos::View<int, DeviceType> nbroken;
  // the particle criterion (read with it only): the tags, the particles'
  // states of the last evaluation, their sums, each bond's measure
  view<decltype(AtomKokkos::k_tag)> tag;
  MCAKokkos::double_2d<DeviceType> pstate;
  MCAKokkos::double_2d<DeviceType> psum;    // (atomic add and max)
  MCAKokkos::double_1d<DeviceType> bond_measure;
  int particle, particle_now;
  // melting (tag bound with it): the step and its length; the entries n
  // of the bonds that froze again (their new references in records)
  int melt_now;
  double dt;
  long long step;
  MCAKokkos::int_1d<DeviceType> frozen;
  Kokkos::View<int, DeviceType> nfrozen;
  int nlocal, newton_bond;
  int damp_now;    // damping in dynamics only
  int eflag_global, eflag_atom, vflag_global, vflag_atom;

  // a bond broken: its record says so until the list is built again
  KOKKOS_INLINE_FUNCTION void report_broken(const int n) const
  {
    records(n, BondBeam::REC_STRENGTH) = -1.0;
    const int k = Kokkos::atomic_fetch_add(&nbroken(), 1);
    if (k < (int) broken.extent(0)) {
      broken(k, 0) = bondlist(n, 0);
      broken(k, 1) = bondlist(n, 1);
      broken(k, 2) = n;
    }
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int n, EV_FLOAT &ev) const
  {
    const int type = bondlist(n, 2);
    // (a bond broken since the list was built: its strength set to -1)
    if (type <= 0 || records(n, BondBeam::REC_STRENGTH) < 0.0) return;
    const bool swap = records(n, BondBeam::REC_SWAP) != 0.0;
    const int i = swap ? bondlist(n, 1) : bondlist(n, 0);
    const int j = swap ? bondlist(n, 0) : bondlist(n, 1);
    constexpr int NVALUES = (DIM == 3) ? NREF_3D : NREF_2D;
    double ref[NVALUES];
    for (int k = 0; k < NVALUES; k++) ref[k] = records(n, BondBeam::REC_REF + k);
    const double qi[4] = {quat(i, 0), quat(i, 1), quat(i, 2), quat(i, 3)};
    const double qj[4] = {quat(j, 0), quat(j, 1), quat(j, 2), quat(j, 3)};
    const double d[3] = {x(j, 0) - x(i, 0), x(j, 1) - x(i, 1), DIM == 3 ? x(j, 2) - x(i, 2) : 0.0};
    BeamCoeff sized;
    const BeamCoeff &c =
        coeff(type).radii ? bond_coeff(coeff(type), DIM, radius(i), radius(j), sized) : coeff(type);
    // (the particle criterion's decision of the last evaluation)
    if (particle_now && c.particle) {
      const ParticleState si = {pstate(i, PSTATE_SIGMA), pstate(i, PSTATE_TAU),
                                pstate(i, PSTATE_PARTNER)};
      const ParticleState sj = {pstate(j, PSTATE_SIGMA), pstate(j, PSTATE_TAU),
                                pstate(j, PSTATE_PARTNER)};
      if (particle_breaks(c, si, sj, (double) tag(i), (double) tag(j),
                          records(n, BondBeam::REC_STRENGTH))) {
        report_broken(n);
        return;
      }
    }
    BeamBond out;
    if (damp_now && c.beta > 0.0) {
      BeamRates rates;
      for (int k = 0; k < 3; k++) {
        rates.w[k] = v(j, k) - v(i, k);
        rates.oi[k] = omega(i, k);
        rates.oj[k] = omega(j, k);
      }
      out = beam_bond<DIM>(c, ref, d, qi, qj, records(n, BondBeam::REC_STRENGTH), &rates);
    } else
      out = beam_bond<DIM>(c, ref, d, qi, qj, records(n, BondBeam::REC_STRENGTH));
    if (out.measure >= 1.0 && !c.particle) {
      report_broken(n);
      return;
    }
    if (melt_now && c.melt) {
      const int fate = melt_fate(c, DIM, out.energy, ref[REF_L0], d, dt, step, (long long) tag(i),
                                 (long long) tag(j));
      if (fate == FATE_BREAK) {
        report_broken(n);
        return;
      }
      if (fate == FATE_REFREEZE) {
        // stress-free from now on: no loads at this step (BondBeam::evaluate)
        double fresh[NVALUES];
        fresh_reference(DIM, d, qi, qj, fresh);
        for (int k = 0; k < NVALUES; k++) records(n, BondBeam::REC_REF + k) = fresh[k];
        const int m = Kokkos::atomic_fetch_add(&nfrozen(), 1);
        if (m < (int) frozen.extent(0)) frozen(m) = n;
        return;
      }
    }
    const bool own_i = newton_bond || i < nlocal, own_j = newton_bond || j < nlocal;
    if (particle) {
      // FixBeamState::add_share; the candidate found by find_candidates
      double w[6];
      virial_share(d, out.fe, w);
      for (int k = 0; k < 6; k++) {
        if (own_i) Kokkos::atomic_add(&psum(i, PSUM_VIRIAL + k), w[k]);
        if (own_j) Kokkos::atomic_add(&psum(j, PSUM_VIRIAL + k), w[k]);
      }
      if (c.particle) {
        bond_measure(n) = out.measure;
        if (own_i) Kokkos::atomic_fetch_max(&psum(i, PSUM_MEASURE), out.measure);
        if (own_j) Kokkos::atomic_fetch_max(&psum(j, PSUM_MEASURE), out.measure);
      }
    }
    if (own_i) {
      f(i, 0) -= out.f[0];
      f(i, 1) -= out.f[1];
      if (DIM == 3) {
        f(i, 2) -= out.f[2];
        torque(i, 0) += out.ti[0];
        torque(i, 1) += out.ti[1];
      }
      torque(i, 2) += out.ti[2];
    }
    if (own_j) {
      f(j, 0) += out.f[0];
      f(j, 1) += out.f[1];
      if (DIM == 3) {
        f(j, 2) += out.f[2];
        torque(j, 0) += out.tj[0];
        torque(j, 1) += out.tj[1];
      }
      torque(j, 2) += out.tj[2];
    }
    // BondBeam::tally
    const double share = bond_share(newton_bond, i, j, nlocal);
    if (eflag_global) ev.evdwl += share * out.energy;
    if (damp_now) ev.ecoul += share * out.dissipation;    // the damping's power
    if (eflag_atom) {
      if (own_i) eatom(i) += 0.5 * out.energy;
      if (own_j) eatom(j) += 0.5 * out.energy;
    }
    if (vflag_global || vflag_atom) {
      double vir[6];
      virial_terms(d, out.f, vir);
      if (vflag_global)
        for (int k = 0; k < 6; k++) ev.v[k] += share * vir[k];
      if (vflag_atom)
        for (int k = 0; k < 6; k++) {
          if (own_i) vatom(i, k) += 0.5 * vir[k];
          if (own_j) vatom(j, k) += 0.5 * vir[k];
        }
    }
  }
};

// the particle criterion's candidates: of the bonds with an end's largest
// measure, the one to the lowest partner ID (FixBeamState::add_share's
// order, whatever order the threads ran in)
template <class DeviceType> struct BeamCandidateKernel {
  template <class DualViewType> using view = MCAKokkos::view_of<DualViewType, DeviceType>;
  view<decltype(NeighborKokkos::k_bondlist)> bondlist;
  view<decltype(AtomKokkos::k_tag)> tag;
  MCAKokkos::double_1d<DeviceType> bond_measure;
  MCAKokkos::double_2d<DeviceType> psum;
  int nlocal, newton_bond;

  KOKKOS_INLINE_FUNCTION void operator()(const int n) const
  {
    const double measure = bond_measure(n);
    if (measure < 0.0) return;    // broken, or not of a particle-criterion type
    const int i = bondlist(n, 0), j = bondlist(n, 1);
    if ((newton_bond || i < nlocal) && measure == psum(i, PSUM_MEASURE))
      Kokkos::atomic_fetch_min(&psum(i, PSUM_PARTNER), (double) tag(j));
    if ((newton_bond || j < nlocal) && measure == psum(j, PSUM_MEASURE))
      Kokkos::atomic_fetch_min(&psum(j, PSUM_PARTNER), (double) tag(i));
  }
};

// Bond::kokkosable (since 2023: Verlet syncs for a bond style without it)
template <class Style>
auto mark_kokkosable(Style *style, int) -> decltype(style->kokkosable = 1, void())
{
  style->kokkosable = 1;
}
template <class Style> void mark_kokkosable(Style *, long) {}

}    // namespace

/* ---------------------------------------------------------------------- */

template <class DeviceType>
BondBeamKokkos<DeviceType>::BondBeamKokkos(LAMMPS *lmp) :
    MCAKokkos::RequiresKokkos(lmp, "Bond style beam/kk"), BondBeam(lmp), avecKK(nullptr),
    d_nbroken("bond:beam_nbroken"), d_nfrozen("bond:beam_nfrozen")
{
  mark_kokkosable(this, 0);
  atomKK = (AtomKokkos *) atom;
  execution_space = MCAKokkos::space_of<DeviceType>();
  datamask_read = X_MASK | F_MASK | TORQUE_MASK | ENERGY_MASK | VIRIAL_MASK;
  datamask_modify = F_MASK | TORQUE_MASK | ENERGY_MASK | VIRIAL_MASK;
}

template <class DeviceType> BondBeamKokkos<DeviceType>::~BondBeamKokkos()
{
  if (copymode) return;
  // the base destructor then finds null pointers
  tally.destroy(memoryKK, eatom, vatom);
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void BondBeamKokkos<DeviceType>::init_style()
{
  BondBeam::init_style();
  avecKK = dynamic_cast<AtomVecMCAKokkos *>(atom->avec);
  if (!avecKK)
    error->all(FLERR, "Bond style beam/kk requires atom_style mca/kk, not atom_style {}",
               atom->atom_style);
  d_coeff = MCAKokkos::copy_to_device<DeviceType>(coeffs, atom->nbondtypes + 1, "bond:beam_coeff");
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void BondBeamKokkos<DeviceType>::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag, 0);
  tally.make(memoryKK, eatom, vatom, eflag_atom, vflag_atom, maxeatom, maxvatom);

  auto *neighborKK = static_cast<NeighborKokkos *>(neighbor);
  const int nlist = neighbor->nbondlist;

  // the records of the listed bonds, made on the host (the fix keeps the
  // reference states there) after each build of the list
  if (references_stale(nlist)) {
    atomKK->sync(Host, X_MASK | TAG_MASK | BOND_MASK | MCA_QUAT_MASK | (radii ? RADIUS_MASK : 0));
    neighborKK->k_bondlist.sync_host();
    auto list = neighborKK->k_bondlist.view_host();
    if ((int) k_records.extent(0) < nlist)
      k_records = MCAKokkos::dual_double_2d("bond:beam_records", nlist + nlist / 4 + 16, nrec);
    fill_records(nlist, list.data(), (long) list.stride(0), (long) list.stride(1),
                 k_records.view_host().data());
    k_records.modify_host();
    k_records.template sync<DeviceType>();
  }
  if (update->setupflag && update->whichflag == 1) check_stable_timestep();

  const int nall = atom->nlocal + atom->nghost;
  if (particle) particle_states_to_device(nall);
  atomKK->sync(execution_space,
               datamask_read | MCA_QUAT_MASK | (damping ? V_MASK | OMEGA_MASK : 0) |
                   (radii ? RADIUS_MASK : 0) | ((particle || melting) ? TAG_MASK : 0));
  atomKK->modified(execution_space, datamask_modify);

  if (domain->dimension == 3)
    launch<3>(nlist, neighborKK);
  else
    launch<2>(nlist, neighborKK);
  tally.to_host<DeviceType>(eflag_atom, vflag_atom);
  if (particle) {
    find_candidates(nlist, neighborKK);
    particle_sums_to_host(nall);
  }

  if (melt_now()) refrozen_to_host();

  // broken bonds leave the bond arrays on the host (on the device their
  // records say so until the list is built again); in the order of the
  // list entries, as the CPU style removes them, whatever order the
  // threads found them in
  if (breaking) {
    int nbroken = 0;
    Kokkos::deep_copy(nbroken, d_nbroken);
    std::vector<int> pairs;
    if (nbroken) {
      auto found = Kokkos::create_mirror_view(d_broken);
      Kokkos::deep_copy(found, d_broken);
      std::vector<std::array<int, 3>> entries(nbroken);
      for (int k = 0; k < nbroken; k++) entries[k] = {found(k, 2), found(k, 0), found(k, 1)};
      std::sort(entries.begin(), entries.end());
      for (const auto &e : entries) {
        pairs.push_back(e[1]);
        pairs.push_back(e[2]);
      }
      atomKK->sync(Host, TAG_MASK | BOND_MASK);
    }
    // (another rank's broken bonds can change the special lists here:
    // specials_to_host() at the steps where some rank broke a bond)
    const bool specials_changed = remove_broken(nbroken, pairs.data());
    if (nbroken) atomKK->modified(Host, BOND_MASK);
    if (specials_changed) atomKK->modified(Host, SPECIAL_MASK);
  }
  if (particle) {
    atomKK->sync(Host, RADIUS_MASK);
    fix_state->decide_particles(force->newton_bond);
  }
}

/* ----------------------------------------------------------------------
   the stable time step: the CPU style's, on the host copies of the state
   and of the records and bond list
------------------------------------------------------------------------- */

template <class DeviceType> bool BondBeamKokkos<DeviceType>::stable_timestep(StableStep &out)
{
  if (!records_current()) return false;
  atomKK->sync(Host,
               X_MASK | TAG_MASK | RMASS_MASK | MCA_QUAT_MASK | MCA_GEOMETRY_MASK |
                   (radii ? RADIUS_MASK : 0));
  auto *neighborKK = static_cast<NeighborKokkos *>(neighbor);
  neighborKK->k_bondlist.sync_host();
  k_records.sync_host();
  auto list = neighborKK->k_bondlist.view_host();
  out = stable_timestep_of(neighbor->nbondlist, list.data(), (long) list.stride(0),
                           (long) list.stride(1), k_records.view_host().data());
  return true;
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void BondBeamKokkos<DeviceType>::specials_to_host()
{
  atomKK->sync(Host, TAG_MASK | SPECIAL_MASK);
}

/* ----------------------------------------------------------------------
   the particle criterion: the states the fix kept (and sent to the
   ghosts) to the device, the sums cleared; after the kernels, the sums to
   the fix (host), which communicates them and decides
------------------------------------------------------------------------- */

namespace {
using HostRows = Kokkos::View<double **, Kokkos::LayoutRight, Kokkos::HostSpace,
                              Kokkos::MemoryTraits<Kokkos::Unmanaged>>;
}

template <class DeviceType> void BondBeamKokkos<DeviceType>::particle_states_to_device(int nall)
{
  if ((int) d_psum.extent(0) < nall) {
    d_psum = MCAKokkos::double_2d<DeviceType>("bond:beam_psum", atom->nmax, (int) NPSUM);
    d_pstate = MCAKokkos::double_2d<DeviceType>("bond:beam_pstate", atom->nmax, (int) NPSTATE);
  }
  if (nall == 0) return;
  const auto rows = std::make_pair(0, nall);
  Kokkos::deep_copy(Kokkos::subview(d_pstate, rows, Kokkos::ALL),
                    HostRows(fix_state->pstate[0], nall, (int) NPSTATE));
  Kokkos::deep_copy(Kokkos::subview(d_psum, rows, std::make_pair(0, 6)), 0.0);
  // no candidate yet (a measure is >= 0)
  Kokkos::deep_copy(Kokkos::subview(d_psum, rows, (int) PSUM_MEASURE), -1.0);
  Kokkos::deep_copy(Kokkos::subview(d_psum, rows, (int) PSUM_PARTNER), HUGE_VAL);
}

template <class DeviceType>
void BondBeamKokkos<DeviceType>::find_candidates(int nlist, NeighborKokkos *neighborKK)
{
  BeamCandidateKernel<DeviceType> kernel;
  kernel.bondlist = neighborKK->k_bondlist.template view<DeviceType>();
  kernel.tag = atomKK->k_tag.template view<DeviceType>();
  kernel.bond_measure = d_bond_measure;
  kernel.psum = d_psum;
  kernel.nlocal = atom->nlocal;
  kernel.newton_bond = force->newton_bond;
  Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, nlist), kernel);
}

template <class DeviceType> void BondBeamKokkos<DeviceType>::particle_sums_to_host(int nall)
{
  if (nall == 0) return;
  Kokkos::deep_copy(HostRows(fix_state->sums[0], nall, (int) NPSUM),
                    Kokkos::subview(d_psum, std::make_pair(0, nall), Kokkos::ALL));
}

/* ----------------------------------------------------------------------
   melting: the new reference states of the bonds that froze again (in
   the device's records) to the fix's slots on the host, where the records
   are made again when the bond list is built (on a GPU the records come
   to the host at steps where a bond froze again)
------------------------------------------------------------------------- */

template <class DeviceType> void BondBeamKokkos<DeviceType>::refrozen_to_host()
{
  int nfrozen = 0;
  Kokkos::deep_copy(nfrozen, d_nfrozen);
  if (!nfrozen) return;
  auto entries = Kokkos::create_mirror_view(d_frozen);
  Kokkos::deep_copy(entries, d_frozen);
  k_records.template modify<DeviceType>();
  k_records.sync_host();
  auto records = k_records.view_host();
  auto *neighborKK = static_cast<NeighborKokkos *>(neighbor);
  neighborKK->k_bondlist.sync_host();
  auto list = neighborKK->k_bondlist.view_host();
  atomKK->sync(Host, TAG_MASK | BOND_MASK);
  for (int k = 0; k < nfrozen; k++) {
    const int n = entries(k);
    fix_state->set_reference(list(n, 0), list(n, 1), force->newton_bond,
                             &records(n, BondBeam::REC_REF));
  }
}

/* ----------------------------------------------------------------------
   the force kernel over the bond list, for beams of dimension DIM
------------------------------------------------------------------------- */

template <class DeviceType>
template <int DIM>
void BondBeamKokkos<DeviceType>::launch(int nlist, NeighborKokkos *neighborKK)
{
  BeamForceKernel<DeviceType, DIM> kernel;
  kernel.x = atomKK->k_x.template view<DeviceType>();
  if (damping) {
    // (bound whenever a type damps; read in dynamics only)
    kernel.v = atomKK->k_v.template view<DeviceType>();
    kernel.omega = atomKK->k_omega.template view<DeviceType>();
  }
  if (radii) kernel.radius = atomKK->k_radius.template view<DeviceType>();
  kernel.particle = particle;
  kernel.particle_now = particle_now();
  kernel.melt_now = melt_now();
  if (kernel.melt_now) {
    kernel.dt = update->dt;
    kernel.step = update->ntimestep;
    if ((int) d_frozen.extent(0) < nlist)
      d_frozen = MCAKokkos::int_1d<DeviceType>("bond:beam_frozen", nlist);
    Kokkos::deep_copy(d_nfrozen, 0);
    kernel.frozen = d_frozen;
    kernel.nfrozen = d_nfrozen;
  }
  if (particle || kernel.melt_now) kernel.tag = atomKK->k_tag.template view<DeviceType>();
  if (particle) {
    if ((int) d_bond_measure.extent(0) < nlist)
      d_bond_measure =
          MCAKokkos::double_1d<DeviceType>("bond:beam_measure", nlist + nlist / 4 + 16);
    Kokkos::deep_copy(d_bond_measure, -2.0);    // (no candidate unless set)
    kernel.pstate = d_pstate;
    kernel.psum = d_psum;
    kernel.bond_measure = d_bond_measure;
  }
  kernel.f = atomKK->k_f.template view<DeviceType>();
  kernel.torque = atomKK->k_torque.template view<DeviceType>();
  kernel.quat = avecKK->k_quat.template view<DeviceType>();
  kernel.records = k_records.template view<DeviceType>();
  // (built on the host where no device neighbor list is requested)
  neighborKK->k_bondlist.template sync<DeviceType>();
  kernel.bondlist = neighborKK->k_bondlist.template view<DeviceType>();
  kernel.coeff = d_coeff;
  if (breaking) {
    if ((int) d_broken.extent(0) < nlist)
      d_broken = MCAKokkos::int_2d<DeviceType>("bond:beam_broken", nlist, 3);
    Kokkos::deep_copy(d_nbroken, 0);
    kernel.broken = d_broken;
    kernel.nbroken = d_nbroken;
  }
  if (eflag_atom) {
    kernel.eatom = tally.k_eatom.template view<DeviceType>();
    Kokkos::deep_copy(tally.k_eatom.template view<DeviceType>(), 0.0);
  }
  if (vflag_atom) {
    kernel.vatom = tally.k_vatom.template view<DeviceType>();
    Kokkos::deep_copy(tally.k_vatom.template view<DeviceType>(), 0.0);
  }
  kernel.nlocal = atom->nlocal;
  kernel.damp_now = damping && update->whichflag == 1;
  kernel.newton_bond = force->newton_bond;
  kernel.eflag_global = eflag_global;
  kernel.eflag_atom = eflag_atom;
  kernel.vflag_global = vflag_global;
  kernel.vflag_atom = vflag_atom;

  EV_FLOAT ev;
  Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType>(0, nlist), kernel, ev);

  if (eflag_global) energy += ev.evdwl;
  if (vflag_global)
    for (int k = 0; k < 6; k++) virial[k] += ev.v[k];
  if (kernel.damp_now && !update->setupflag) fix_state->dissipated.local += ev.ecoul * update->dt;
}

namespace LAMMPS_NS {
template class BondBeamKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class BondBeamKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
