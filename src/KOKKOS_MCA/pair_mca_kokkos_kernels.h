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
   the kernels of pair_style mca/kk (included by pair_mca_kokkos.cpp only):
   the views a kernel reads (MCAPairViews, the data policy of the passes
   of mca_link_passes.h), where a link adds to its automata (direct,
   per-chunk or atomic sums), the energy tally, and the functors, each a
   call of a pass of mca_link_passes.h
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_MCA_KOKKOS_KERNELS_H
#define LMP_PAIR_MCA_KOKKOS_KERNELS_H

#include "atom_kokkos.h"
#include "mca_geometry.h"
#include "mca_link_batch.h"
#include "mca_link_passes.h"
#include "pair_mca_kokkos.h"

namespace LAMMPS_NS {
using namespace MCAKernels;

// per-atom sums of the predictor (PS_*) and the link pass (LS_*): see
// mca_link_passes.h; per-atom energy and virial, when asked for
enum AtomTally { AT_ENERGY = 0, AT_VIRIAL = 1, AT_SIZE = 7 };

/* ----------------------------------------------------------------------
   everything a kernel reads or writes, copied into each functor
------------------------------------------------------------------------- */

template <class DeviceType> struct MCAPairViews {
  template <class DualViewType> using view = MCAKokkos::view_of<DualViewType, DeviceType>;
  typedef MCAKokkos::double_1d<DeviceType> double_1d;
  typedef MCAKokkos::double_2d<DeviceType> double_2d;
  typedef MCAKokkos::int_1d<DeviceType> int_1d;
  typedef MCAKokkos::int_2d<DeviceType> int_2d;

  view<decltype(AtomKokkos::k_x)> x;
  view<decltype(AtomKokkos::k_omega)> omega;
  view<decltype(AtomKokkos::k_f)> f;
  view<decltype(AtomKokkos::k_torque)> torque;
  view<decltype(AtomKokkos::k_type)> type;
  view<decltype(AtomKokkos::k_tag)> tag;
  int_1d packing;
  double_2d stress;
  double_1d smean, seq, eeq;

  int_1d nlinks;
  int_2d slot, partner;    // each link's row in the pool, its partner's local or ghost index
  double_2d rows, atom_state;
  MCALinkLayout layout;

  double_1d pred_stiffness, dsmean, smean_pred;
  // plasticity: hardening curves by type, plastic strain and cell volume
  // of the automata, their return factor and trial mean stress
  Kokkos::View<MCAHardening *, DeviceType> hardening;
  double_1d epsp, volume, return_scale, return_smean;
  // fracture: rules by type pair (row stride break_stride), damage
  Kokkos::View<MCABreakRule *, DeviceType> break_rules;
  int break_stride;
  double_1d damage;
  // contacts: rules by type pair (the same stride)
  Kokkos::View<MCAContactRule *, DeviceType> contact_rules;
  int_1d link_count, foreign;
  double_2d fabric, predictor_sums, link_sums, atom_tally;
  Kokkos::View<MCAMaterial *, DeviceType> material;
  double_1d eatom;
  double_2d vatom;

  int nlocal;

  // a row of x or omega as 3 contiguous doubles (the views' layout may be
  // LayoutLeft on a device)
  template <class View>
  KOKKOS_INLINE_FUNCTION static const double *copy_row(const View &v, int i, double *scratch)
  {
    for (int k = 0; k < 3; k++) scratch[k] = v(i, k);
    return scratch;
  }
  KOKKOS_INLINE_FUNCTION const double *x_row(int i, double *scratch) const
  {
    return copy_row(x, i, scratch);
  }
  KOKKOS_INLINE_FUNCTION const double *omega_row(int i, double *scratch) const
  {
    return copy_row(omega, i, scratch);
  }

  KOKKOS_INLINE_FUNCTION double *history_row(int i, int m) const { return &rows(slot(i, m), 0); }
  KOKKOS_INLINE_FUNCTION const MCABreakRule &break_rule(int ti, int tj) const
  {
    return break_rules(ti * break_stride + tj);
  }
  KOKKOS_INLINE_FUNCTION const MCAContactRule &contact_rule(int ti, int tj) const
  {
    return contact_rules(ti * break_stride + tj);
  }
};

/* ----------------------------------------------------------------------
   energy, virial and count of over-long links of the link pass
------------------------------------------------------------------------- */

struct MCALinkSums {
  double energy;
  double virial[6];
  bigint nlong;
  int nhealed;    // contacts that became links (healing weld)

  KOKKOS_INLINE_FUNCTION MCALinkSums() : energy(0.0), virial{0, 0, 0, 0, 0, 0}, nlong(0), nhealed(0)
  {
  }
  KOKKOS_INLINE_FUNCTION void operator+=(const MCALinkSums &rhs)
  {
    energy += rhs.energy;
    for (int k = 0; k < 6; k++) virial[k] += rhs.virial[k];
    nlong += rhs.nlong;
    nhealed += rhs.nhealed;
  }
#if MCA_KK_VOLATILE_JOIN
  KOKKOS_INLINE_FUNCTION void operator+=(const volatile MCALinkSums &rhs) volatile
  {
    energy += rhs.energy;
    for (int k = 0; k < 6; k++) virial[k] += rhs.virial[k];
    nlong += rhs.nlong;
    nhealed += rhs.nhealed;
  }
#endif
};

// the virial of a pair force f on atom i at separation del = x_i - x_j,
// in the order of Pair::ev_tally_xyz
KOKKOS_INLINE_FUNCTION void pair_virial(const double *del, const double *f, double *v)
{
  MCAKernels::virial_terms(del, f, v);
}

/* ----------------------------------------------------------------------
   kernel: number of interacting links of each automaton and its
   stiffness in the predictor
------------------------------------------------------------------------- */

template <class DeviceType> struct MCACountLinks {
  typedef DeviceType device_type;
  MCAPairViews<DeviceType> d;
  int chunk_size;    // 0: the sums have no chunks

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    count_links_of(d, i);
    if (chunk_size == 0) return;
    // a partner that evaluates a link from another chunk adds its
    // contribution to i in its chunk's copy
    int foreign = 0;
    for (int m = 0; m < d.nlinks(i); m++) {
      const int j = d.partner(i, m);
      if (partner_evaluates(d, i, j) && j / chunk_size != i / chunk_size) foreign = 1;
    }
    d.foreign(i) = foreign;
  }
};

// the rows of the copies: where MCACountLinks marked an automaton (1),
// the number of marked automata before it; else -1
template <class DeviceType> struct MCAForeignRows {
  typedef DeviceType device_type;
  typedef int value_type;
  MCAKokkos::int_1d<DeviceType> foreign;

  KOKKOS_INLINE_FUNCTION void operator()(const int i, int &count, const bool final) const
  {
    const int marked = foreign(i);
    if (final) foreign(i) = marked ? count : -1;
    count += marked;
  }
};

/* ----------------------------------------------------------------------
   where a kernel adds what a link gives its two automata: the automaton
   it runs for (own) and a local partner.  DirectSums: into the sums
   themselves, in the loop order (one host thread: the order of the CPU
   style; GPU: atomic).  ChunkSums (several host threads): the local
   automata are cut into one contiguous chunk per thread, each run by one
   thread in order (MCAChunkedFor/Reduce); the automaton and a partner in
   the same chunk get their parts in the sums themselves, a partner in
   another chunk in this chunk's copy, which the kernel that reads the
   sums adds (load_sums) for the automata marked as having such partners
   (MCACountLinks).  No two threads write the same element, and the order
   of the additions depends only on the number of threads.  (Summing the
   own part in registers, or choosing the target per added value, cost 6
   to 9 % more cycles than the direct sums on one thread; this costs none.)
------------------------------------------------------------------------- */

template <class DeviceType> struct MCADirectSums {
  typename MCAScatter<DeviceType>::direct sums;
  typedef decltype(sums.access()) Thread;

  KOKKOS_INLINE_FUNCTION Thread begin(int) const { return sums.access(); }
  KOKKOS_INLINE_FUNCTION void own(Thread &add, int i, int k, double value) const
  {
    add(i, k) += value;
  }
  KOKKOS_INLINE_FUNCTION int partner_of(Thread &, int j) const { return j; }
  KOKKOS_INLINE_FUNCTION void partner(Thread &add, int j, int k, double value) const
  {
    add(j, k) += value;
  }
};

template <class DeviceType> struct MCAChunkSums {
  MCAKokkos::double_2d<DeviceType> sums;
  MCAKokkos::double_3d<DeviceType> copies;
  MCAKokkos::int_1d<DeviceType> foreign;    // an automaton's row in the copies
  int chunk_size;
  struct Thread {
    double *own;    // the automaton's row of the sums
    int chunk, first, last;
  };

  KOKKOS_INLINE_FUNCTION Thread begin(int i) const
  {
    Thread thread;
    thread.own = &sums(i, 0);
    thread.chunk = i / chunk_size;
    thread.first = thread.chunk * chunk_size;
    thread.last = thread.first + chunk_size;
    return thread;
  }
  KOKKOS_INLINE_FUNCTION void own(Thread &thread, int, int k, double value) const
  {
    thread.own[k] += value;
  }
  // the row a partner's part goes to (rows are contiguous: LayoutRight)
  KOKKOS_INLINE_FUNCTION double *partner_of(Thread &thread, int j) const
  {
    return (j >= thread.first && j < thread.last) ? &sums(j, 0)
                                                  : &copies(thread.chunk, foreign(j), 0);
  }
  KOKKOS_INLINE_FUNCTION void partner(Thread &, double *row, int k, double value) const
  {
    row[k] += value;
  }
};

// one past the last automaton of chunk c
KOKKOS_INLINE_FUNCTION int chunk_end(int c, int chunk_size, int nlocal)
{
  return (c + 1) * chunk_size < nlocal ? (c + 1) * chunk_size : nlocal;
}

// a kernel over the automata of one chunk per call, in order
template <class Pass> struct MCAChunkedFor {
  typedef typename Pass::device_type device_type;
  Pass pass;
  int nlocal, chunk_size;

  KOKKOS_INLINE_FUNCTION void operator()(const int c) const
  {
    const int last = chunk_end(c, chunk_size, nlocal);
    for (int i = c * chunk_size; i < last; i++) pass(i);
  }
};

template <class Pass> struct MCAChunkedReduce {
  typedef typename Pass::device_type device_type;
  typedef typename Pass::value_type value_type;
  Pass pass;
  int nlocal, chunk_size;

  KOKKOS_INLINE_FUNCTION void operator()(const int c, value_type &sum) const
  {
    const int last = chunk_end(c, chunk_size, nlocal);
    for (int i = c * chunk_size; i < last; i++) pass(i, sum);
  }
};

// the first n sums of an automaton plus, where other chunks add to it,
// the copies of all chunks (none with DirectSums); all are left zero for
// the next pass
template <class DeviceType>
KOKKOS_INLINE_FUNCTION void load_sums(const MCAKokkos::double_2d<DeviceType> &sums,
                                      const MCAKokkos::double_3d<DeviceType> &copies,
                                      const MCAKokkos::int_1d<DeviceType> &foreign, int i, int n,
                                      double *out)
{
  for (int k = 0; k < n; k++) {
    out[k] = sums(i, k);
    sums(i, k) = 0.0;
  }
  if (copies.extent(0) == 0 || foreign(i) < 0) return;
  const int row = foreign(i);
  for (int t = 0; t < static_cast<int>(copies.extent(0)); t++)
    for (int k = 0; k < n; k++) {
      out[k] += copies(t, row, k);
      copies(t, row, k) = 0.0;
    }
}

/* ----------------------------------------------------------------------
   kernel: the links of the mean-stress predictor, each computed once, by
   the lower ID of two local automata or by the local owner of a link to
   a ghost atom (whose rows are current), added to both local automata
------------------------------------------------------------------------- */

template <class DeviceType, class Sums> struct MCAPredictorLinks {
  typedef DeviceType device_type;
  MCAPairViews<DeviceType> d;
  Sums sums;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const { predictor_links_of(d, sums, i); }
};

/* ----------------------------------------------------------------------
   kernel: the mean stress each automaton's normal law applies this step
------------------------------------------------------------------------- */

template <class DeviceType> struct MCAPredictorFinish {
  typedef DeviceType device_type;
  MCAPairViews<DeviceType> d;
  MCAKokkos::double_3d<DeviceType> copies;
  bool setup_pass;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    double sums[PS_SIZE];
    load_sums(d.predictor_sums, copies, d.foreign, i, PS_SIZE, sums);
    predictor_finish_of(d, i, sums, setup_pass);
  }
};

/* ----------------------------------------------------------------------
   energy and virial of a link: the whole pair, or this owner's half of
   it; per atom, each automaton of the pair gets half (as ev_tally_xyz)
------------------------------------------------------------------------- */

template <class TallyScatter> struct MCAKokkosTally {
  TallyScatter tally;
  bool eflag_global, vflag_global, eflag_atom, vflag_atom;

  KOKKOS_INLINE_FUNCTION bool wanted() const
  {
    return eflag_global || vflag_global || eflag_atom || vflag_atom;
  }

  template <class D>
  KOKKOS_INLINE_FUNCTION void link(MCALinkSums &ev, const D &d, int i, int j, bool jlocal,
                                   double sign, double work, const double *fpair) const
  {
    const double share = jlocal ? 1.0 : 0.5;
    if (eflag_global) ev.energy += share * work;
    double v[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    if (vflag_global || vflag_atom) {
      const double del[3] = {d.x(i, 0) - d.x(j, 0), d.x(i, 1) - d.x(j, 1), d.x(i, 2) - d.x(j, 2)};
      const double fi[3] = {sign * fpair[0], sign * fpair[1], sign * fpair[2]};
      pair_virial(del, fi, v);
      if (vflag_global)
        for (int k = 0; k < 6; k++) ev.virial[k] += share * v[k];
    }
    if (eflag_atom || vflag_atom) {
      auto tally_add = tally.access();
      for (int n = 0; n < (jlocal ? 2 : 1); n++) {
        const int owner = n ? j : i;
        tally_add(owner, AT_ENERGY) += 0.5 * work;
        for (int k = 0; k < 6; k++) tally_add(owner, AT_VIRIAL + k) += 0.5 * v[k];
      }
    }
  }
};

/* ----------------------------------------------------------------------
   kernel: the links, each computed once as in the predictor: tractions,
   forces, torques and history; force, torque and traction moment added
   to both local automata
------------------------------------------------------------------------- */

template <class DeviceType, class Sums, class TallyScatter, int Law> struct MCALinkPass {
  typedef DeviceType device_type;
  typedef MCALinkSums value_type;
  MCAPairViews<DeviceType> d;
  Sums sums;
  MCAKokkosTally<TallyScatter> tally;
  MCALinkPassFlags flags;

  KOKKOS_INLINE_FUNCTION void operator()(const int i, MCALinkSums &ev) const
  {
    link_pass_of<Law>(d, sums, tally, flags, i, ev);
  }
};

// the link pass of a law as a template of (device, sums, tally), as
// MCAPushingPassOf (PairMCAKokkos::link_kernel)
template <int Law> struct MCALinkPassOf {
  template <class DeviceType, class Sums, class TallyScatter>
  using type = MCALinkPass<DeviceType, Sums, TallyScatter, Law>;
};

/* ----------------------------------------------------------------------
   the elastic link pass on batches of links (mca_link_batch.h), on host
   threads only: the same numbers as MCALinkPass<LAW_ELASTIC>, a chunk of
   automata per call (all of them where one thread adds to the sums
   directly: chunk_size 0).  A host function: the kernel never runs on a
   GPU (MCABatchedLinkKernel)
------------------------------------------------------------------------- */

template <class DeviceType, class Sums, class TallyScatter> struct MCALinkPassBatched {
  typedef DeviceType device_type;
  typedef MCALinkSums value_type;
  MCAPairViews<DeviceType> d;
  Sums sums;
  MCAKokkosTally<TallyScatter> tally;
  MCALinkPassFlags flags;
  int nlocal, chunk_size;

  void operator()(const int c, MCALinkSums &ev) const
  {
    const int first = chunk_size > 0 ? c * chunk_size : 0;
    const int last = chunk_size > 0 ? chunk_end(c, chunk_size, nlocal) : nlocal;
    MCALinkBatch batch;
    link_pass_batched(evaluate_link_batch, batch, d, sums, tally, flags, ev, first, last);
  }
};

// a kernel that takes a chunk of automata per call (else one automaton)
template <class Pass> struct MCAPassPerChunk : std::false_type {
};
template <class DeviceType, class Sums, class TallyScatter>
struct MCAPassPerChunk<MCALinkPassBatched<DeviceType, Sums, TallyScatter>> : std::true_type {
};

/* ----------------------------------------------------------------------
   kernels of a model with plasticity: the elastic trial of the links
   (their traction moment B in the LS_BMAT columns of the link sums),
   then the return of each automaton from its trial stress
------------------------------------------------------------------------- */

template <class DeviceType, class Sums> struct MCATrialPass {
  typedef DeviceType device_type;
  MCAPairViews<DeviceType> d;
  Sums sums;
  MCALinkPassFlags flags;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const { trial_pass_of(d, sums, flags, i); }
};

template <class DeviceType> struct MCAPlasticReturnPass {
  typedef DeviceType device_type;
  MCAPairViews<DeviceType> d;
  MCAKokkos::double_3d<DeviceType> copies;
  bool commit;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    double sums[LS_SIZE];
    load_sums(d.link_sums, copies, d.foreign, i, LS_SIZE, sums);
    plastic_return_of(d, i, sums + LS_BMAT, commit);
  }
};

/* ----------------------------------------------------------------------
   kernels of a model with fracture: the force of the broken pairs (into
   the link sums, before MCALinkFinish), the links that break after the
   stress of the step is known, the damage of each automaton
------------------------------------------------------------------------- */

template <class DeviceType, class Sums, class TallyScatter, int State> struct MCAPushingPass {
  typedef DeviceType device_type;
  typedef MCALinkSums value_type;
  MCAPairViews<DeviceType> d;
  Sums sums;
  MCAKokkosTally<TallyScatter> tally;
  MCALinkPassFlags flags;

  KOKKOS_INLINE_FUNCTION void operator()(const int i, MCALinkSums &ev) const
  {
    pushing_pass_of<State>(d, sums, tally, flags, i, ev);
  }
};

// the pass of the pairs that push in one state (LINK_BROKEN: the broken
// pairs; LINK_CONTACT: the contacts, mca_contact.h) as a template of
// (device, sums, tally) (PairMCAKokkos::link_kernel)
template <int State> struct MCAPushingPassOf {
  template <class DeviceType, class Sums, class TallyScatter>
  using type = MCAPushingPass<DeviceType, Sums, TallyScatter, State>;
};

template <class DeviceType> struct MCAFracturePass {
  typedef DeviceType device_type;
  typedef int value_type;    // links broken
  MCAPairViews<DeviceType> d;
  MCABreakFlags flags;

  KOKKOS_INLINE_FUNCTION void operator()(const int i, int &nbroke) const
  {
    nbroke += fracture_pass_of(d, flags, i);
  }
};

template <class DeviceType> struct MCADamagePass {
  typedef DeviceType device_type;
  typedef double value_type;    // energy released at break_step (halves)
  MCAPairViews<DeviceType> d;
  double break_step;
  bool eflag_atom;

  KOKKOS_INLINE_FUNCTION void operator()(const int i, double &released) const
  {
    const double released_i = damage_of(d, i, break_step);
    if (eflag_atom) d.eatom(i) -= released_i;
    released += released_i;
  }
};

// healing weld: the contacts that heal, then what they left (halves)
template <class DeviceType> struct MCAHealPass {
  typedef DeviceType device_type;
  MCAPairViews<DeviceType> d;
  MCABreakFlags flags;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const { heal_pass_of(d, flags, i); }
};

template <class DeviceType> struct MCAHealedPass {
  typedef DeviceType device_type;
  MCAPairViews<DeviceType> d;
  double heal_step;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const { healed_of(d, i, heal_step); }
};

/* ----------------------------------------------------------------------
   kernel: each automaton's forces, torques and stress from its sums
------------------------------------------------------------------------- */

template <class DeviceType> struct MCALinkFinish {
  typedef DeviceType device_type;
  MCAPairViews<DeviceType> d;
  MCAKokkos::double_3d<DeviceType> copies;
  bool commit, eflag_atom, vflag_atom;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    double sums[LS_SIZE];
    load_sums(d.link_sums, copies, d.foreign, i, LS_SIZE, sums);
    add_link_forces(d, i, sums);
    automaton_outputs_of(d, i, sums + LS_BMAT, commit);
    if (eflag_atom) d.eatom(i) += d.atom_tally(i, AT_ENERGY);
    if (vflag_atom)
      for (int k = 0; k < 6; k++) d.vatom(i, k) += d.atom_tally(i, AT_VIRIAL + k);
  }
};

/* ----------------------------------------------------------------------
   kernels: forward communication of the predictor values
------------------------------------------------------------------------- */

// a stage sends a, then b (if nb == 1), then the ncols columns of c
template <class DeviceType> struct MCAPackForward {
  typedef DeviceType device_type;
  MCAKokkos::double_1d<DeviceType> a, b;
  MCAKokkos::double_2d<DeviceType> c;
  MCAKokkos::view_of<MCA_KK_SENDLIST_VIEW, DeviceType> list;
  MCAKokkos::view_of<MCA_KK_COMM_BUFFER, DeviceType> buf;
  int iswap, stride, nb, ncols;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    const int j = MCA_KK_SENDLIST(list, iswap, i);
    int m = stride * i;
    buf(m++) = a(j);
    if (nb) buf(m++) = b(j);
    for (int k = 0; k < ncols; k++) buf(m++) = c(j, k);
  }
};

template <class DeviceType> struct MCAUnpackForward {
  typedef DeviceType device_type;
  MCAKokkos::double_1d<DeviceType> a, b;
  MCAKokkos::double_2d<DeviceType> c;
  MCAKokkos::view_of<MCA_KK_COMM_BUFFER, DeviceType> buf;
  int first, stride, nb, ncols;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    int m = stride * i;
    a(first + i) = buf(m++);
    if (nb) b(first + i) = buf(m++);
    for (int k = 0; k < ncols; k++) c(first + i, k) = buf(m++);
  }
};

}    // namespace LAMMPS_NS

#endif
