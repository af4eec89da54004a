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

#include "pair_mca_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "atom_vec_mca_kokkos.h"
#include "comm.h"
#include "error.h"
#include "fix_mca_links_kokkos.h"
#include "force.h"
#include "memory_kokkos.h"
#include "neighbor.h"
#include "update.h"

#include "mca_kernels.h"

using namespace LAMMPS_NS;
using namespace MCAKernels;

// per-automaton sums of the two link passes (columns): the predictor's
// fabric tensor F and strain moment M, and the
// link pass's force, torque and traction moment B (see PairMCA)
constexpr int PS_FABRIC = 0, PS_STRAIN = 6, PS_SIZE = 12;
constexpr int LS_FORCE = 0, LS_TORQUE = 3, LS_BMAT = 6, LS_SIZE = 15;
// per-atom energy and virial, when asked for
enum AtomTally { AT_ENERGY = 0, AT_VIRIAL = 1, AT_SIZE = 7 };

namespace LAMMPS_NS {

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
  double_2d history;
  double_1d smean_step, smean_law;
  int_2d partner, row;

  double_1d pred_stiffness, dsmean, smean_pred;
  int_1d link_count, foreign;
  double_2d fabric, predictor_sums, link_sums, atom_tally;
  double_1d shear, bulk, coupling;
  double_1d eatom;
  double_2d vatom;

  int nlocal;

  // a link between local automata is evaluated by, and advances in the
  // row of, the lower ID: is that the partner j of i?
  KOKKOS_INLINE_FUNCTION bool partner_evaluates(int i, int j) const
  {
    return j < nlocal && tag(j) < tag(i);
  }

  // the history row of link m of automaton i that is current
  KOKKOS_INLINE_FUNCTION const double *current_row(int i, int m) const
  {
    const int j = partner(i, m);
    if (partner_evaluates(i, j)) return &history(j, row(i, m) * H_SIZE);
    return &history(i, m * H_SIZE);
  }
};

/* ----------------------------------------------------------------------
   energy, virial and count of over-long links of the link pass
------------------------------------------------------------------------- */

struct MCALinkSums {
  double energy;
  double virial[6];
  bigint nlong;

  KOKKOS_INLINE_FUNCTION MCALinkSums() : energy(0.0), virial{0, 0, 0, 0, 0, 0}, nlong(0) {}
  KOKKOS_INLINE_FUNCTION void operator+=(const MCALinkSums &rhs)
  {
    energy += rhs.energy;
    for (int k = 0; k < 6; k++) virial[k] += rhs.virial[k];
    nlong += rhs.nlong;
  }
#if MCA_KK_VOLATILE_JOIN
  KOKKOS_INLINE_FUNCTION void operator+=(const volatile MCALinkSums &rhs) volatile
  {
    energy += rhs.energy;
    for (int k = 0; k < 6; k++) virial[k] += rhs.virial[k];
    nlong += rhs.nlong;
  }
#endif
};

// the virial of a pair force f on atom i at separation del = x_i - x_j,
// in the order of Pair::ev_tally_xyz
KOKKOS_INLINE_FUNCTION void pair_virial(const double *del, const double *f, double *v)
{
  v[0] = del[0] * f[0];
  v[1] = del[1] * f[1];
  v[2] = del[2] * f[2];
  v[3] = del[0] * f[1];
  v[4] = del[0] * f[2];
  v[5] = del[1] * f[2];
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
    int n = 0;
    int foreign = 0;
    for (int m = 0; m < d.nlinks(i); m++) {
      if (static_cast<int>(d.current_row(i, m)[H_STATE]) == LINK_LINKED) n++;
      // a partner that evaluates the link from another chunk adds its
      // contribution to i in its chunk's copy
      const int j = d.partner(i, m);
      if (chunk_size > 0 && d.partner_evaluates(i, j) && j / chunk_size != i / chunk_size)
        foreign = 1;
    }
    d.link_count(i) = n;
    if (chunk_size > 0) d.foreign(i) = foreign;
    const int it = d.type(i);
    const int nc = d.packing(i);
    d.pred_stiffness(i) = (nc > 0) ? predictor_stiffness(d.shear(it), d.bulk(it), nc, n) : 0.0;
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
    return (j >= thread.first && j < thread.last) ? &sums(j, 0) : &copies(thread.chunk, j, 0);
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

// an automaton's sums plus, where other chunks add to it, the copies of
// all chunks (none with DirectSums); all are left zero for the next pass
template <class DeviceType>
KOKKOS_INLINE_FUNCTION void load_sums(const MCAKokkos::double_2d<DeviceType> &sums,
                                      const MCAKokkos::double_3d<DeviceType> &copies,
                                      const MCAKokkos::int_1d<DeviceType> &foreign, int i,
                                      double *out)
{
  const int n = sums.extent(1);
  for (int k = 0; k < n; k++) {
    out[k] = sums(i, k);
    sums(i, k) = 0.0;
  }
  if (copies.extent(0) == 0 || !foreign(i)) return;
  for (int t = 0; t < static_cast<int>(copies.extent(0)); t++)
    for (int k = 0; k < n; k++) {
      out[k] += copies(t, i, k);
      copies(t, i, k) = 0.0;
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

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    auto add = sums.begin(i);
    for (int m = 0; m < d.nlinks(i); m++) {
      const int j = d.partner(i, m);
      const bool jlocal = j < d.nlocal;
      const bool ilo = d.tag(i) < d.tag(j);
      if (jlocal && !ilo) continue;
      const double *h = &d.history(i, m * H_SIZE);
      if (static_cast<int>(h[H_STATE]) != LINK_LINKED) continue;
      const double del[3] = {d.x(j, 0) - d.x(i, 0), d.x(j, 1) - d.x(i, 1), d.x(j, 2) - d.x(i, 2)};
      double nn[6], de_i, de_j;
      link_prediction(h, del, ilo, d.pred_stiffness(i), d.pred_stiffness(j), nn, de_i, de_j);
      for (int k = 0; k < 6; k++) {
        sums.own(add, i, PS_FABRIC + k, nn[k]);
        sums.own(add, i, PS_STRAIN + k, de_i * nn[k]);
      }
      if (jlocal) {
        const auto to = sums.partner_of(add, j);
        for (int k = 0; k < 6; k++) {
          sums.partner(add, to, PS_FABRIC + k, nn[k]);
          sums.partner(add, to, PS_STRAIN + k, de_j * nn[k]);
        }
      }
    }
  }
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
    load_sums(d.predictor_sums, copies, d.foreign, i, sums);
    const double *fab = sums + PS_FABRIC, *mstrain = sums + PS_STRAIN;
    for (int k = 0; k < 6; k++) d.fabric(i, k) = fab[k];
    const bool interacting = d.link_count(i) > 0 && d.packing(i) != PACKING_NONE;
    double smean_pred, dsmean;
    mean_stress_prediction(interacting, setup_pass, d.smean_step(i), d.smean_law(i), fab, mstrain,
                           d.bulk(d.type(i)), smean_pred, dsmean);
    d.smean_pred(i) = smean_pred;
    d.dsmean(i) = dsmean;
  }
};

/* ----------------------------------------------------------------------
   kernel: the links, each computed once as in the predictor: tractions,
   forces, torques and history; force, torque and traction moment added
   to both local automata
------------------------------------------------------------------------- */

template <class DeviceType, class Sums, class TallyScatter> struct MCALinkPass {
  typedef DeviceType device_type;
  typedef MCALinkSums value_type;
  MCAPairViews<DeviceType> d;
  Sums sums;
  TallyScatter tally;
  bool commit, eager, eflag_global, vflag_global, eflag_atom, vflag_atom;
  double dt, cutsq;

  KOKKOS_INLINE_FUNCTION void operator()(const int i, MCALinkSums &ev) const
  {
    auto add = sums.begin(i);
    for (int m = 0; m < d.nlinks(i); m++) {
      const int j = d.partner(i, m);
      const bool jlocal = j < d.nlocal;
      const bool ilo = d.tag(i) < d.tag(j);
      if (jlocal && !ilo) continue;    // the partner computes it
      double *row = &d.history(i, m * H_SIZE);
      if (static_cast<int>(row[H_STATE]) != LINK_LINKED) continue;
      const int lo = ilo ? i : j, hi = ilo ? j : i;
      const int tlo = d.type(lo), thi = d.type(hi);

      // a step updates the row in place; a setup works on a copy
      double copy[H_SIZE];
      double *h = row;
      if (!commit) {
        for (int k = 0; k < H_SIZE; k++) copy[k] = row[k];
        h = copy;
      }
      const double x_lo[3] = {d.x(lo, 0), d.x(lo, 1), d.x(lo, 2)};
      const double x_hi[3] = {d.x(hi, 0), d.x(hi, 1), d.x(hi, 2)};
      const double w_lo[3] = {d.omega(lo, 0), d.omega(lo, 1), d.omega(lo, 2)};
      const double w_hi[3] = {d.omega(hi, 0), d.omega(hi, 1), d.omega(hi, 2)};
      double fpair[3], tq_lo[3], tq_hi[3], trac[3], nvec[3], sig, r;
      linked_pair(h, x_lo, x_hi, w_lo, w_hi, d.shear(tlo), d.shear(thi), d.coupling(tlo),
                  d.coupling(thi), d.bulk(tlo), d.bulk(thi), d.dsmean(lo), d.dsmean(hi),
                  d.smean_pred(lo), d.smean_pred(hi), face_moment_factor(d.packing(lo)), dt, fpair,
                  tq_lo, tq_hi, sig, trac, r, nvec);
      if (r * r > cutsq) ev.nlong += jlocal ? 2 : 1;

      // force on lo is fpair, on hi -fpair; T n^T is the same for both
      const double sign = ilo ? 1.0 : -1.0;
      const double *tq = ilo ? tq_lo : tq_hi;
      for (int k = 0; k < 3; k++) {
        sums.own(add, i, LS_FORCE + k, sign * fpair[k]);
        sums.own(add, i, LS_TORQUE + k, tq[k]);
      }
      for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) sums.own(add, i, LS_BMAT + 3 * a + b, trac[a] * nvec[b]);
      if (jlocal) {
        const auto to = sums.partner_of(add, j);
        for (int k = 0; k < 3; k++) {
          sums.partner(add, to, LS_FORCE + k, -fpair[k]);
          sums.partner(add, to, LS_TORQUE + k, tq_hi[k]);
        }
        for (int a = 0; a < 3; a++)
          for (int b = 0; b < 3; b++) sums.partner(add, to, LS_BMAT + 3 * a + b, trac[a] * nvec[b]);
        if (commit && eager) {
          double *partner_row = &d.history(j, d.row(i, m) * H_SIZE);
          for (int k = 0; k < H_SIZE; k++) partner_row[k] = row[k];
        }
      }

      // energy and virial: the whole pair, or this owner's half of it;
      // per atom, each automaton of the pair gets half (as ev_tally_xyz)
      const double share = jlocal ? 1.0 : 0.5;
      if (eflag_global) ev.energy += share * h[H_WORK];
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
          tally_add(owner, AT_ENERGY) += 0.5 * h[H_WORK];
          for (int k = 0; k < 6; k++) tally_add(owner, AT_VIRIAL + k) += 0.5 * v[k];
        }
      }
    }
  }
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
    load_sums(d.link_sums, copies, d.foreign, i, sums);
    for (int k = 0; k < 3; k++) {
      d.f(i, k) += sums[LS_FORCE + k];
      d.torque(i, k) += sums[LS_TORQUE + k];
    }
    if (eflag_atom) d.eatom(i) += d.atom_tally(i, AT_ENERGY);
    if (vflag_atom)
      for (int k = 0; k < 6; k++) d.vatom(i, k) += d.atom_tally(i, AT_VIRIAL + k);

    double fab[6], stress[6], smean, seq, eeq;
    for (int k = 0; k < 6; k++) fab[k] = d.fabric(i, k);
    automaton_stress(sums + LS_BMAT, fab, d.shear(d.type(i)), stress, smean, seq, eeq);
    for (int k = 0; k < 6; k++) d.stress(i, k) = stress[k];
    d.smean(i) = smean;
    d.seq(i) = seq;
    d.eeq(i) = eeq;
    if (commit) {
      d.smean_step(i) = smean;
      d.smean_law(i) = d.smean_pred(i);
    }
  }
};

/* ----------------------------------------------------------------------
   kernel: copy the current row of each local link to the partner's row
------------------------------------------------------------------------- */

template <class DeviceType> struct MCASyncRows {
  typedef DeviceType device_type;
  MCAPairViews<DeviceType> d;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    for (int m = 0; m < d.nlinks(i); m++) {
      const int j = d.partner(i, m);
      if (!d.partner_evaluates(i, j)) continue;
      const double *from = &d.history(j, d.row(i, m) * H_SIZE);
      double *to = &d.history(i, m * H_SIZE);
      for (int k = 0; k < H_SIZE; k++) to[k] = from[k];
    }
  }
};

/* ----------------------------------------------------------------------
   kernels: forward communication of the predictor values
------------------------------------------------------------------------- */

template <class DeviceType> struct MCAPackForward {
  typedef DeviceType device_type;
  MCAKokkos::double_1d<DeviceType> a, b;    // b unused when stride is 1
  MCAKokkos::view_of<MCA_KK_SENDLIST_VIEW, DeviceType> list;
  MCAKokkos::view_of<MCA_KK_COMM_BUFFER, DeviceType> buf;
  int iswap, stride;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    const int j = MCA_KK_SENDLIST(list, iswap, i);
    buf(stride * i) = a(j);
    if (stride == 2) buf(2 * i + 1) = b(j);
  }
};

template <class DeviceType> struct MCAUnpackForward {
  typedef DeviceType device_type;
  MCAKokkos::double_1d<DeviceType> a, b;
  MCAKokkos::view_of<MCA_KK_COMM_BUFFER, DeviceType> buf;
  int first, stride;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    a(first + i) = buf(stride * i);
    if (stride == 2) b(first + i) = buf(2 * i + 1);
  }
};

}    // namespace LAMMPS_NS

/* ---------------------------------------------------------------------- */

template <class DeviceType>
PairMCAKokkos<DeviceType>::PairMCAKokkos(LAMMPS *lmp) :
    MCAKokkos::RequiresKokkos(lmp, "Pair style mca/kk"), PairMCA(lmp), avecKK(nullptr),
    linksKK(nullptr), kk_nmax(0), tally_nmax(0), chunk_size(0)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = MCAKokkos::space_of<DeviceType>();
  // the state fields are read too: the kernels write only some of them
  // (stress, mean stress, equivalent values), and marking the others
  // modified on the device without a sync would lose host changes
  datamask_read = X_MASK | F_MASK | TORQUE_MASK | OMEGA_MASK | TYPE_MASK | TAG_MASK |
      MCA_GEOMETRY_MASK | MCA_STATE_MASK | ENERGY_MASK | VIRIAL_MASK;
  datamask_modify = F_MASK | TORQUE_MASK | MCA_STATE_MASK | ENERGY_MASK | VIRIAL_MASK;
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> PairMCAKokkos<DeviceType>::~PairMCAKokkos()
{
  if (copymode) return;
  // the base destructor then finds null pointers
  memoryKK->destroy_kokkos(k_pred_stiffness, pred_stiffness);
  memoryKK->destroy_kokkos(k_dsmean, dsmean);
  memoryKK->destroy_kokkos(k_smean_pred, smean_pred);
  memoryKK->destroy_kokkos(k_partner_cache, partner_cache);
  memoryKK->destroy_kokkos(k_row_cache, row_cache);
  memoryKK->destroy_kokkos(k_eatom, eatom);
  memoryKK->destroy_kokkos(k_vatom, vatom);
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void PairMCAKokkos<DeviceType>::init_style()
{
  avecKK = dynamic_cast<AtomVecMCAKokkos *>(atom->avec);
  if (!avecKK)
    error->all(FLERR, "Pair style mca/kk requires atom_style mca/kk, not {}", atom->atom_style);

  PairMCA::init_style();

  linksKK = dynamic_cast<FixMCALinksKokkos *>(links);
  if (!linksKK)
    error->all(FLERR,
               "Pair style mca/kk: the links of this system were made by pair_style mca "
               "without the Kokkos suffix; use the same variant throughout a simulation or "
               "go through a restart file");

  // on a GPU, keep the reneighbouring check on the device (see the function)
  if (!MCAScatter<DeviceType>::host) MCAKokkos::request_device_list(neighbor, this, instance_me);

  if (comm->me == 0)
    utils::logmesg(lmp, "pair mca/kk: link passes as Kokkos kernels in the {} execution space\n",
                   execution_space == Device ? "device" : "host");

  // materials by type, on the device
  const int n = atom->ntypes + 1;
  d_shear = MCAKokkos::double_1d<DeviceType>("pair:shear", n);
  d_bulk = MCAKokkos::double_1d<DeviceType>("pair:bulk", n);
  d_coupling = MCAKokkos::double_1d<DeviceType>("pair:coupling", n);
  auto h_shear = Kokkos::create_mirror_view(d_shear);
  auto h_bulk = Kokkos::create_mirror_view(d_bulk);
  auto h_coupling = Kokkos::create_mirror_view(d_coupling);
  for (int t = 0; t < n; t++) {
    h_shear(t) = shear[t];
    h_bulk(t) = bulk[t];
    h_coupling(t) = coupling[t];
  }
  Kokkos::deep_copy(d_shear, h_shear);
  Kokkos::deep_copy(d_bulk, h_bulk);
  Kokkos::deep_copy(d_coupling, h_coupling);
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void PairMCAKokkos<DeviceType>::grow_kk_peratom()
{
  if (atom->nmax > kk_nmax) {
    kk_nmax = atom->nmax;
    memoryKK->destroy_kokkos(k_pred_stiffness, pred_stiffness);
    memoryKK->destroy_kokkos(k_dsmean, dsmean);
    memoryKK->destroy_kokkos(k_smean_pred, smean_pred);
    memoryKK->create_kokkos(k_pred_stiffness, pred_stiffness, kk_nmax, "pair:pred_stiffness");
    memoryKK->create_kokkos(k_dsmean, dsmean, kk_nmax, "pair:dsmean");
    memoryKK->create_kokkos(k_smean_pred, smean_pred, kk_nmax, "pair:smean_pred");
    d_link_count = MCAKokkos::int_1d<DeviceType>("pair:link_count", kk_nmax);
    d_foreign = MCAKokkos::int_1d<DeviceType>("pair:foreign", kk_nmax);
    d_fabric = MCAKokkos::double_2d<DeviceType>("pair:fabric", kk_nmax, 6);
    d_predictor_sums = MCAKokkos::double_2d<DeviceType>("pair:predictor_sums", kk_nmax, PS_SIZE);
    d_link_sums = MCAKokkos::double_2d<DeviceType>("pair:link_sums", kk_nmax, LS_SIZE);
    if (need_dup()) {
      const int copies = typename DeviceType::execution_space().concurrency();
      d_predictor_copies =
          MCAKokkos::double_3d<DeviceType>("pair:predictor_copies", copies, kk_nmax, PS_SIZE);
      d_link_copies =
          MCAKokkos::double_3d<DeviceType>("pair:link_copies", copies, kk_nmax, LS_SIZE);
    }
  }
  if ((eflag_atom || vflag_atom) && atom->nmax > tally_nmax) {
    tally_nmax = atom->nmax;
    d_atom_tally = MCAKokkos::double_2d<DeviceType>("pair:atom_tally", tally_nmax, AT_SIZE);
    if (need_dup()) dup_tally = dup_type(d_atom_tally);
  }
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void PairMCAKokkos<DeviceType>::allocate_partner_cache()
{
  memoryKK->destroy_kokkos(k_partner_cache, partner_cache);
  memoryKK->destroy_kokkos(k_row_cache, row_cache);
  memoryKK->create_kokkos(k_partner_cache, partner_cache, cache_rows, cache_cols,
                          "pair:partner_cache");
  memoryKK->create_kokkos(k_row_cache, row_cache, cache_rows, cache_cols, "pair:row_cache");
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> MCAPairViews<DeviceType> PairMCAKokkos<DeviceType>::views()
{
  MCAPairViews<DeviceType> d;
  d.x = atomKK->k_x.template view<DeviceType>();
  d.omega = atomKK->k_omega.template view<DeviceType>();
  d.f = atomKK->k_f.template view<DeviceType>();
  d.torque = atomKK->k_torque.template view<DeviceType>();
  d.type = atomKK->k_type.template view<DeviceType>();
  d.tag = atomKK->k_tag.template view<DeviceType>();
  d.packing = avecKK->k_packing.template view<DeviceType>();
  d.stress = avecKK->k_stress.template view<DeviceType>();
  d.smean = avecKK->k_smean.template view<DeviceType>();
  d.seq = avecKK->k_seq.template view<DeviceType>();
  d.eeq = avecKK->k_eeq.template view<DeviceType>();
  d.nlinks = linksKK->k_nlinks.template view<DeviceType>();
  d.history = linksKK->k_history.template view<DeviceType>();
  d.smean_step = linksKK->k_smean_step.template view<DeviceType>();
  d.smean_law = linksKK->k_smean_law.template view<DeviceType>();
  d.partner = k_partner_cache.template view<DeviceType>();
  d.row = k_row_cache.template view<DeviceType>();
  d.pred_stiffness = k_pred_stiffness.template view<DeviceType>();
  d.dsmean = k_dsmean.template view<DeviceType>();
  d.smean_pred = k_smean_pred.template view<DeviceType>();
  d.link_count = d_link_count;
  d.foreign = d_foreign;
  d.fabric = d_fabric;
  d.predictor_sums = d_predictor_sums;
  d.link_sums = d_link_sums;
  d.atom_tally = d_atom_tally;
  d.shear = d_shear;
  d.bulk = d_bulk;
  d.coupling = d_coupling;
  if (eflag_atom) d.eatom = k_eatom.template view<DeviceType>();
  if (vflag_atom) d.vatom = k_vatom.template view<DeviceType>();
  d.nlocal = atom->nlocal;
  return d;
}

/* ----------------------------------------------------------------------
   forward communication of a stage's per-atom values, device or host
------------------------------------------------------------------------- */

template <class DeviceType> void PairMCAKokkos<DeviceType>::forward_comm_stage(int stage)
{
  comm_stage = stage;
  k_pred_stiffness.template modify<DeviceType>();
  k_dsmean.template modify<DeviceType>();
  k_smean_pred.template modify<DeviceType>();
  MCACompat::forward_comm(comm, this);
  k_pred_stiffness.template sync<DeviceType>();
  k_dsmean.template sync<DeviceType>();
  k_smean_pred.template sync<DeviceType>();
}

template <class DeviceType>
int PairMCAKokkos<DeviceType>::pack_forward_comm_kokkos(MCA_KK_PACK_FORWARD_ARGS)
{
  (void) pbc_flag;
  (void) pbc;
  MCAPackForward<DeviceType> pack;
  pack.stride = (comm_stage == STAGE_COUNT) ? 1 : 2;
  pack.a = (comm_stage == STAGE_COUNT) ? k_pred_stiffness.template view<DeviceType>()
                                       : k_dsmean.template view<DeviceType>();
  pack.b = k_smean_pred.template view<DeviceType>();
  pack.list = k_sendlist.template view<DeviceType>();
  pack.buf = k_buf.template view<DeviceType>();
#ifdef MCA_HAVE_KK_FLOAT
  pack.iswap = 0;
#else
  pack.iswap = iswap;
#endif
  Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, n), pack);
  return n * pack.stride;
}

template <class DeviceType>
void PairMCAKokkos<DeviceType>::unpack_forward_comm_kokkos(int n, int first,
                                                           MCA_KK_COMM_BUFFER &k_buf)
{
  MCAUnpackForward<DeviceType> unpack;
  unpack.stride = (comm_stage == STAGE_COUNT) ? 1 : 2;
  unpack.a = (comm_stage == STAGE_COUNT) ? k_pred_stiffness.template view<DeviceType>()
                                         : k_dsmean.template view<DeviceType>();
  unpack.b = k_smean_pred.template view<DeviceType>();
  unpack.buf = k_buf.template view<DeviceType>();
  unpack.first = first;
  Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, n), unpack);
}

template <class DeviceType>
int PairMCAKokkos<DeviceType>::pack_forward_comm(int n, int *list, double *buf, int pbc_flag,
                                                 int *pbc)
{
  k_pred_stiffness.sync_host();
  k_dsmean.sync_host();
  k_smean_pred.sync_host();
  return PairMCA::pack_forward_comm(n, list, buf, pbc_flag, pbc);
}

template <class DeviceType>
void PairMCAKokkos<DeviceType>::unpack_forward_comm(int n, int first, double *buf)
{
  k_pred_stiffness.sync_host();
  k_dsmean.sync_host();
  k_smean_pred.sync_host();
  PairMCA::unpack_forward_comm(n, first, buf);
  k_pred_stiffness.modify_host();
  k_dsmean.modify_host();
  k_smean_pred.modify_host();
}

/* ----------------------------------------------------------------------
   number of interacting links per automaton, sent to the ghosts
------------------------------------------------------------------------- */

template <class DeviceType> void PairMCAKokkos<DeviceType>::count_links_kk()
{
  // one chunk of local automata per thread for the sums (see ChunkSums)
  const int nlocal = atom->nlocal;
  chunk_size = 0;
  if (need_dup()) {
    const int threads = typename DeviceType::execution_space().concurrency();
    chunk_size = nlocal > threads ? (nlocal + threads - 1) / threads : 1;
  }
  MCACountLinks<DeviceType> count;
  count.d = views();
  count.chunk_size = chunk_size;
  Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, nlocal), count);
  forward_comm_stage(STAGE_COUNT);
}

/* ----------------------------------------------------------------------
   the mean-stress kernel (see PairMCA::predict_mean_stress())
------------------------------------------------------------------------- */

template <class DeviceType> void PairMCAKokkos<DeviceType>::predict_mean_stress()
{
  const int nlocal = atom->nlocal;
  const MCAPairViews<DeviceType> d = views();
  // the sums start at zero: the kernels that read them leave them so
  if (need_dup()) {
    MCAChunkedFor<MCAPredictorLinks<DeviceType, MCAChunkSums<DeviceType>>> chunked;
    chunked.pass.d = d;
    chunked.pass.sums.sums = d_predictor_sums;
    chunked.pass.sums.copies = d_predictor_copies;
    chunked.pass.sums.chunk_size = chunk_size;
    chunked.nlocal = nlocal;
    chunked.chunk_size = chunk_size;
    Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, chunks()), chunked);
  } else {
    MCAPredictorLinks<DeviceType, MCADirectSums<DeviceType>> links_pass;
    links_pass.d = d;
    links_pass.sums.sums = direct_type(d_predictor_sums);
    Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, nlocal), links_pass);
  }

  MCAPredictorFinish<DeviceType> finish;
  finish.d = d;
  if (need_dup()) finish.copies = d_predictor_copies;
  finish.setup_pass = (update->setupflag != 0);
  Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, nlocal), finish);
  forward_comm_stage(STAGE_MEAN);
}

/* ----------------------------------------------------------------------
   one copy of the sums per thread only where threads share them
------------------------------------------------------------------------- */

template <class DeviceType> bool PairMCAKokkos<DeviceType>::need_dup() const
{
  return MCAScatter<DeviceType>::host && typename DeviceType::execution_space().concurrency() > 1;
}

// number of chunks of the local automata (ChunkSums)
template <class DeviceType> int PairMCAKokkos<DeviceType>::chunks() const
{
  return (atom->nlocal + chunk_size - 1) / chunk_size;
}

template <class DeviceType>
template <class Pass>
void PairMCAKokkos<DeviceType>::link_pass(Pass &pass, bool commit, bool lazy, MCALinkSums &sums)
{
  pass.commit = commit;
  pass.eager = !lazy;
  pass.eflag_global = eflag_global;
  pass.vflag_global = vflag_global;
  pass.eflag_atom = eflag_atom;
  pass.vflag_atom = vflag_atom;
  // spins turn the automata only in steps of a run (see PairMCA::compute)
  pass.dt = commit ? update->dt : 0.0;
  pass.cutsq = cut_global * cut_global;
  if (need_dup()) {
    MCAChunkedReduce<Pass> chunked;
    chunked.pass = pass;
    chunked.nlocal = atom->nlocal;
    chunked.chunk_size = chunk_size;
    Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType>(0, chunks()), chunked, sums);
  } else {
    Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType>(0, atom->nlocal), pass, sums);
  }
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void PairMCAKokkos<DeviceType>::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag, 0);
  if (!links->created) error->all(FLERR, "Pair mca/kk: compute() before the links were made");

  if (eflag_atom) {
    memoryKK->destroy_kokkos(k_eatom, eatom);
    memoryKK->create_kokkos(k_eatom, eatom, maxeatom, "pair:eatom");
  }
  if (vflag_atom) {
    memoryKK->destroy_kokkos(k_vatom, vatom);
    memoryKK->create_kokkos(k_vatom, vatom, maxvatom, 6, "pair:vatom");
  }

  atomKK->sync(execution_space, datamask_read);
  atomKK->modified(execution_space, datamask_modify);
  grow_kk_peratom();
  // the table may have changed on the host (exchange, restart, setup); the
  // partner cache below only reads the host copy, which stays current
  linksKK->to_device();

  // the partner cache is made on the host when LAMMPS reneighbors (the
  // atom map and the closest images live there)
  if (neighbor->ago == 0 || cache_nlocal != atom->nlocal) {
    if (partner_rows_stale)
      error->one(FLERR, "Pair mca/kk: atoms were reordered while link rows were out of date");
    atomKK->sync(Host, X_MASK | TAG_MASK);
    links->to_host();
    build_partner_cache();
    k_partner_cache.modify_host();
    k_row_cache.modify_host();
    k_partner_cache.template sync<DeviceType>();
    k_row_cache.template sync<DeviceType>();
    count_links_kk();
  }

  const bool commit = (update->setupflag == 0);
  const bool lazy = links->lazy_rows && links->row_sync == this;

  predict_mean_stress();

  const int nlocal = atom->nlocal;
  const bool atom_tally = eflag_atom || vflag_atom;
  if (atom_tally) Kokkos::deep_copy(d_atom_tally, 0.0);
  const MCAPairViews<DeviceType> d = views();
  MCALinkSums sums;
  if (need_dup()) {
    if (atom_tally) dup_tally.reset();
    MCALinkPass<DeviceType, MCAChunkSums<DeviceType>, dup_type> pass;
    pass.d = d;
    pass.sums.sums = d_link_sums;
    pass.sums.copies = d_link_copies;
    pass.sums.chunk_size = chunk_size;
    pass.tally = dup_tally;
    link_pass(pass, commit, lazy, sums);
    if (atom_tally) Kokkos::Experimental::contribute(d_atom_tally, dup_tally);
  } else {
    MCALinkPass<DeviceType, MCADirectSums<DeviceType>, direct_type> pass;
    pass.d = d;
    pass.sums.sums = direct_type(d_link_sums);
    pass.tally = direct_type(d_atom_tally);
    link_pass(pass, commit, lazy, sums);
  }

  MCALinkFinish<DeviceType> finish;
  finish.d = d;
  if (need_dup()) finish.copies = d_link_copies;
  finish.commit = commit;
  finish.eflag_atom = eflag_atom;
  finish.vflag_atom = vflag_atom;
  Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, nlocal), finish);

  linksKK->device_changed();
  if (commit && lazy) partner_rows_stale = 1;

  if (eflag_global) eng_vdwl += sums.energy;
  if (vflag_global)
    for (int k = 0; k < 6; k++) virial[k] += sums.virial[k];
  if (eflag_atom) {
    k_eatom.template modify<DeviceType>();
    k_eatom.sync_host();
  }
  if (vflag_atom) {
    k_vatom.template modify<DeviceType>();
    k_vatom.sync_host();
  }

  nstretched = sums.nlong;
  if (neighbor->ago == 0) stretched_warning();
}

/* ----------------------------------------------------------------------
   partner copies of the local links (see PairMCA::sync_link_rows())
------------------------------------------------------------------------- */

template <class DeviceType> void PairMCAKokkos<DeviceType>::sync_link_rows()
{
  if (!partner_rows_stale) return;
  if (cache_nlocal != atom->nlocal)
    error->one(FLERR, "Pair mca/kk: atoms were reordered while link rows were out of date");
  linksKK->to_device();
  MCASyncRows<DeviceType> rows;
  rows.d = views();
  Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, atom->nlocal), rows);
  linksKK->device_changed();
  partner_rows_stale = 0;
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> double PairMCAKokkos<DeviceType>::memory_usage()
{
  double bytes = PairMCA::memory_usage();
  // per automaton: 3 communicated values, fabric, the sums of both passes
  // and their copies (one per thread on the host), link count and flag
  typedef typename DeviceType::memory_space memory_space;
  const double copies = Kokkos::SpaceAccessibility<Kokkos::HostSpace, memory_space>::accessible
      ? typename DeviceType::execution_space().concurrency()
      : 0.0;
  bytes += (3.0 + 6.0 + (1.0 + (need_dup() ? copies : 0.0)) * (PS_SIZE + LS_SIZE)) * kk_nmax *
          sizeof(double) +
      2.0 * kk_nmax * sizeof(int);
  return bytes;
}

namespace LAMMPS_NS {
template class PairMCAKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class PairMCAKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
