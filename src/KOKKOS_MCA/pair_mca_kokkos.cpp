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
#include "pair_mca_kokkos_kernels.h"

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

using namespace LAMMPS_NS;
using namespace MCAKernels;

/* ---------------------------------------------------------------------- */

template <class DeviceType>
PairMCAKokkos<DeviceType>::PairMCAKokkos(LAMMPS *lmp) :
    MCAKokkos::RequiresKokkos(lmp, "Pair style mca/kk"), PairMCA(lmp), avecKK(nullptr),
    linksKK(nullptr), kk_nmax(0), kk_nsums(0), tally_nmax(0), chunk_size(0)
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
  memoryKK->destroy_kokkos(k_return_scale, return_scale);
  memoryKK->destroy_kokkos(k_return_smean, return_smean);
  memoryKK->destroy_kokkos(k_partner_cache, partner_cache);
  tally.destroy(memoryKK, eatom, vatom);
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
  d_material =
      MCAKokkos::copy_to_device<DeviceType>(materials.type, atom->ntypes + 1, "pair:material");
  d_hardening = MCAKokkos::copy_to_device<DeviceType>(materials.hardening, atom->ntypes + 1,
                                                      "pair:hardening");
  d_break_rules = MCAKokkos::copy_to_device<DeviceType>(
      break_rules.data(), (atom->ntypes + 1) * (atom->ntypes + 1), "pair:break_rules");
  d_contact_rules = MCAKokkos::copy_to_device<DeviceType>(
      contact_rules.data(), (atom->ntypes + 1) * (atom->ntypes + 1), "pair:contact_rules");
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
    if (plastic()) {
      memoryKK->destroy_kokkos(k_return_scale, return_scale);
      memoryKK->destroy_kokkos(k_return_smean, return_smean);
      memoryKK->create_kokkos(k_return_scale, return_scale, kk_nmax, "pair:return_scale");
      memoryKK->create_kokkos(k_return_smean, return_smean, kk_nmax, "pair:return_smean");
    }
  }
  // the arrays of the local automata only (a pass adds to a local partner,
  // never to a ghost), grown with some room: the number of local automata
  // changes at each reneighboring (then count_links_kk runs next)
  if (atom->nlocal > kk_nsums) {
    kk_nsums = local_rows(atom->nlocal);
    d_link_count = MCAKokkos::int_1d<DeviceType>("pair:link_count", kk_nsums);
    d_foreign = MCAKokkos::int_1d<DeviceType>("pair:foreign", kk_nsums);
    // (no row in the copies until count_links_kk gives the rows)
    Kokkos::deep_copy(d_foreign, -1);
    d_fabric = MCAKokkos::double_2d<DeviceType>("pair:fabric", kk_nsums, 6);
    // the predictor and the link passes share their sums (and copies): the
    // predictor's are read (and left zero) before the link pass adds to
    // them, and it uses the first PS_SIZE columns only
    static_assert(PS_SIZE <= LS_SIZE, "the predictor's sums fit in the link sums");
    d_link_sums = MCAKokkos::double_2d<DeviceType>("pair:sums", kk_nsums, LS_SIZE);
    d_predictor_sums = d_link_sums;
    // (the copies: count_links_kk, where their rows are given)
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
  memoryKK->create_kokkos(k_partner_cache, partner_cache, cache_rows, cache_cols,
                          "pair:partner_cache");
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
  d.slot = linksKK->k_slot.template view<DeviceType>();
  d.rows = linksKK->k_rows.template view<DeviceType>();
  d.atom_state = linksKK->k_atom_state.template view<DeviceType>();
  d.layout = model.layout();
  d.partner = k_partner_cache.template view<DeviceType>();
  d.pred_stiffness = k_pred_stiffness.template view<DeviceType>();
  d.dsmean = k_dsmean.template view<DeviceType>();
  d.smean_pred = k_smean_pred.template view<DeviceType>();
  d.link_count = d_link_count;
  d.foreign = d_foreign;
  d.fabric = d_fabric;
  d.predictor_sums = d_predictor_sums;
  d.link_sums = d_link_sums;
  d.atom_tally = d_atom_tally;
  d.material = d_material;
  d.hardening = d_hardening;
  d.epsp = avecKK->k_epsp.template view<DeviceType>();
  d.volume = avecKK->k_volume.template view<DeviceType>();
  d.return_scale = k_return_scale.template view<DeviceType>();
  d.return_smean = k_return_smean.template view<DeviceType>();
  d.break_rules = d_break_rules;
  d.break_stride = atom->ntypes + 1;
  d.damage = avecKK->k_damage.template view<DeviceType>();
  d.contact_rules = d_contact_rules;
  if (eflag_atom) d.eatom = tally.k_eatom.template view<DeviceType>();
  if (vflag_atom) d.vatom = tally.k_vatom.template view<DeviceType>();
  d.nlocal = atom->nlocal;
  return d;
}

/* ----------------------------------------------------------------------
   forward communication of a stage's per-atom values, device or host
------------------------------------------------------------------------- */

template <class DeviceType>
void PairMCAKokkos<DeviceType>::stage_views(int stage, MCAKokkos::dual_double_1d *&a,
                                            MCAKokkos::dual_double_1d *&b,
                                            MCAKokkos::dual_double_2d *&c)
{
  c = nullptr;
  if (stage == STAGE_BREAK) {
    // (the order of PairMCA::pack_forward_comm)
    a = &avecKK->k_epsp;
    b = nullptr;
    c = &avecKK->k_stress;
  } else if (stage == STAGE_COUNT) {
    a = &k_pred_stiffness;
    b = nullptr;
  } else if (stage == STAGE_RETURN) {
    a = &k_return_scale;
    b = &k_return_smean;
  } else {
    a = &k_dsmean;
    b = &k_smean_pred;
  }
}

template <class DeviceType> void PairMCAKokkos<DeviceType>::forward_comm_stage(int stage)
{
  comm_stage = stage;
  MCAKokkos::dual_double_1d *a, *b;
  MCAKokkos::dual_double_2d *c;
  stage_views(stage, a, b, c);
  a->template modify<DeviceType>();
  if (b) b->template modify<DeviceType>();
  if (c) c->template modify<DeviceType>();
  MCACompat::forward_comm(comm, this);
  a->template sync<DeviceType>();
  if (b) b->template sync<DeviceType>();
  if (c) c->template sync<DeviceType>();
}

template <class DeviceType>
int PairMCAKokkos<DeviceType>::pack_forward_comm_kokkos(MCA_KK_PACK_FORWARD_ARGS)
{
  (void) pbc_flag;
  (void) pbc;
  MCAKokkos::dual_double_1d *a, *b;
  MCAKokkos::dual_double_2d *c;
  stage_views(comm_stage, a, b, c);
  MCAPackForward<DeviceType> pack;
  pack.nb = b ? 1 : 0;
  pack.ncols = c ? static_cast<int>(c->extent(1)) : 0;
  pack.stride = 1 + pack.nb + pack.ncols;
  pack.a = a->template view<DeviceType>();
  if (b) pack.b = b->template view<DeviceType>();
  if (c) pack.c = c->template view<DeviceType>();
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
  MCAKokkos::dual_double_1d *a, *b;
  MCAKokkos::dual_double_2d *c;
  stage_views(comm_stage, a, b, c);
  MCAUnpackForward<DeviceType> unpack;
  unpack.nb = b ? 1 : 0;
  unpack.ncols = c ? static_cast<int>(c->extent(1)) : 0;
  unpack.stride = 1 + unpack.nb + unpack.ncols;
  unpack.a = a->template view<DeviceType>();
  if (b) unpack.b = b->template view<DeviceType>();
  if (c) unpack.c = c->template view<DeviceType>();
  unpack.buf = k_buf.template view<DeviceType>();
  unpack.first = first;
  Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, n), unpack);
}

template <class DeviceType>
int PairMCAKokkos<DeviceType>::pack_forward_comm(int n, int *list, double *buf, int pbc_flag,
                                                 int *pbc)
{
  if (comm_stage == STAGE_ESTIMATE) return PairMCA::pack_forward_comm(n, list, buf, pbc_flag, pbc);
  MCAKokkos::dual_double_1d *a, *b;
  MCAKokkos::dual_double_2d *c;
  stage_views(comm_stage, a, b, c);
  a->sync_host();
  if (b) b->sync_host();
  if (c) c->sync_host();
  return PairMCA::pack_forward_comm(n, list, buf, pbc_flag, pbc);
}

template <class DeviceType>
void PairMCAKokkos<DeviceType>::unpack_forward_comm(int n, int first, double *buf)
{
  if (comm_stage == STAGE_ESTIMATE) {
    PairMCA::unpack_forward_comm(n, first, buf);
    return;
  }
  MCAKokkos::dual_double_1d *a, *b;
  MCAKokkos::dual_double_2d *c;
  stage_views(comm_stage, a, b, c);
  a->sync_host();
  if (b) b->sync_host();
  if (c) c->sync_host();
  PairMCA::unpack_forward_comm(n, first, buf);
  a->modify_host();
  if (b) b->modify_host();
  if (c) c->modify_host();
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
  if (chunk_size > 0) {
    // a row of the copies for each automaton that other chunks add to
    // (those near the chunks' borders); the copies are all zero between
    // the passes, so their rows may be given again
    MCAForeignRows<DeviceType> rows;
    rows.foreign = d_foreign;
    int nforeign = 0;
    Kokkos::parallel_scan(Kokkos::RangePolicy<DeviceType>(0, nlocal), rows, nforeign);
    const int copies = typename DeviceType::execution_space().concurrency();
    if (static_cast<int>(d_link_copies.extent(0)) != copies ||
        nforeign > static_cast<int>(d_link_copies.extent(1)))
      d_link_copies = MCAKokkos::double_3d<DeviceType>("pair:sum_copies", copies,
                                                       nforeign + nforeign / 4 + 1, LS_SIZE);
  }
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
    chunked.pass.sums = chunk_sums();
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
  if (need_dup()) finish.copies = d_link_copies;
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

template <class DeviceType> MCAChunkSums<DeviceType> PairMCAKokkos<DeviceType>::chunk_sums() const
{
  MCAChunkSums<DeviceType> sums;
  sums.sums = d_link_sums;
  sums.copies = d_link_copies;
  sums.foreign = d_foreign;
  sums.chunk_size = chunk_size;
  return sums;
}

// a kernel of one automaton per call: over the chunks where threads share
// the sums (chunk_size > 0), else over the automata
template <class DeviceType, class Pass>
static void launch_link_kernel(const Pass &pass, int nlocal, int chunk_size, int nchunks,
                               MCALinkSums &out, std::false_type)
{
  if (chunk_size > 0) {
    MCAChunkedReduce<Pass> chunked;
    chunked.pass = pass;
    chunked.nlocal = nlocal;
    chunked.chunk_size = chunk_size;
    Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType>(0, nchunks), chunked, out);
  } else {
    Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType>(0, nlocal), pass, out);
  }
}

// a kernel of a chunk per call (MCALinkPassBatched): the chunks, or one
template <class DeviceType, class Pass>
static void launch_link_kernel(Pass pass, int nlocal, int chunk_size, int nchunks, MCALinkSums &out,
                               std::true_type)
{
  pass.nlocal = nlocal;
  pass.chunk_size = chunk_size;
  Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType>(0, chunk_size > 0 ? nchunks : 1), pass,
                          out);
}

/* ----------------------------------------------------------------------
   the batched elastic link pass (mca_link_batch.h) on host threads, for
   the models it applies to (PairMCA::batched_link_pass_applies); false
   where it does not run (a GPU: one link per thread there)
------------------------------------------------------------------------- */

namespace LAMMPS_NS {
template <class DeviceType, bool Host> struct MCABatchedLinkKernel {
  static bool run(PairMCAKokkos<DeviceType> &, bool, MCALinkSums &) { return false; }
};

template <class DeviceType> struct MCABatchedLinkKernel<DeviceType, true> {
  static bool run(PairMCAKokkos<DeviceType> &pair, bool commit, MCALinkSums &sums)
  {
    if (!pair.batched_link_pass_applies()) return false;
    pair.template batched_link_kernel<void>(commit, sums);
    return true;
  }
};

}    // namespace LAMMPS_NS

template <class DeviceType>
template <class Deferred>
void PairMCAKokkos<DeviceType>::batched_link_kernel(bool commit, MCALinkSums &sums)
{
  link_kernel<MCALinkPassBatched>(commit, sums);
}

/* ----------------------------------------------------------------------
   a kernel over the links with the link sums and the energy tally: the
   link pass of a law (MCALinkPassOf<Law>::type) or the pass of the pairs
   that push in a state (MCAPushingPassOf<State>::type); its energy and
   virial are added to sums
------------------------------------------------------------------------- */

template <class DeviceType>
template <class Pass>
void PairMCAKokkos<DeviceType>::run_link_kernel(Pass &pass, bool commit, MCALinkSums &sums)
{
  pass.d = views();
  pass.flags = link_pass_flags(commit);
  pass.tally.eflag_global = eflag_global;
  pass.tally.vflag_global = vflag_global;
  pass.tally.eflag_atom = eflag_atom;
  pass.tally.vflag_atom = vflag_atom;
  // (a reduction sets its result)
  MCALinkSums kernel_sums;
  launch_link_kernel<DeviceType>(pass, atom->nlocal, need_dup() ? chunk_size : 0, chunks(),
                                 kernel_sums, MCAPassPerChunk<Pass>());
  sums += kernel_sums;
}

template <class DeviceType>
template <template <class, class, class> class Pass>
void PairMCAKokkos<DeviceType>::link_kernel(bool commit, MCALinkSums &sums)
{
  const bool atom_tally = eflag_atom || vflag_atom;
  if (need_dup()) {
    if (atom_tally) dup_tally.reset();
    Pass<DeviceType, MCAChunkSums<DeviceType>, dup_type> pass;
    pass.sums = chunk_sums();
    pass.tally.tally = dup_tally;
    run_link_kernel(pass, commit, sums);
    if (atom_tally) Kokkos::Experimental::contribute(d_atom_tally, dup_tally);
  } else {
    Pass<DeviceType, MCADirectSums<DeviceType>, direct_type> pass;
    pass.sums.sums = direct_type(d_link_sums);
    pass.tally.tally = direct_type(d_atom_tally);
    run_link_kernel(pass, commit, sums);
  }
}

/* ----------------------------------------------------------------------
   plasticity: the elastic trial of the links, the return of each
   automaton from its trial stress, sent to the ghosts (see
   PairMCA::compute())
------------------------------------------------------------------------- */

template <class DeviceType> void PairMCAKokkos<DeviceType>::plastic_return(bool commit)
{
  const int nlocal = atom->nlocal;
  const MCAPairViews<DeviceType> d = views();
  const MCALinkPassFlags flags = link_pass_flags(commit);
  if (need_dup()) {
    MCAChunkedFor<MCATrialPass<DeviceType, MCAChunkSums<DeviceType>>> chunked;
    chunked.pass.d = d;
    chunked.pass.sums = chunk_sums();
    chunked.pass.flags = flags;
    chunked.nlocal = nlocal;
    chunked.chunk_size = chunk_size;
    Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, chunks()), chunked);
  } else {
    MCATrialPass<DeviceType, MCADirectSums<DeviceType>> trial;
    trial.d = d;
    trial.sums.sums = direct_type(d_link_sums);
    trial.flags = flags;
    Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, nlocal), trial);
  }
  MCAPlasticReturnPass<DeviceType> ret;
  ret.d = d;
  if (need_dup()) ret.copies = d_link_copies;
  ret.commit = commit;
  Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, nlocal), ret);
  forward_comm_stage(STAGE_RETURN);
}

/* ----------------------------------------------------------------------
   fracture and healing, after the stress of the step: the links that
   break, the contacts that heal and the damage (see PairMCA::compute())
------------------------------------------------------------------------- */

template <class DeviceType> void PairMCAKokkos<DeviceType>::change_links(bool commit, int nhealed)
{
  const int nlocal = atom->nlocal;
  const MCAPairViews<DeviceType> d = views();
  const MCABreakFlags flags = break_flags();
  if (commit && (fractured() || heal_reads_epsp())) forward_comm_stage(STAGE_BREAK);
  if (commit && fractured()) {
    MCAFracturePass<DeviceType> pass;
    pass.d = d;
    pass.flags = flags;
    int nbroke = 0;
    Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType>(0, nlocal), pass, nbroke);
    note_breaks(nbroke);
  }
  if (commit && healing()) {
    note_heals(nhealed);
    if (links_healed) {
      MCAHealedPass<DeviceType> healed;
      healed.d = d;
      healed.heal_step = flags.step;
      Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, nlocal), healed);
    }
    // (without a work criterion the contact pass marked them)
    if (heal_reads_epsp()) {
      MCAHealPass<DeviceType> pass;
      pass.d = d;
      pass.flags = flags;
      Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, nlocal), pass);
    }
  }
  if (!fractured() || (!links_broke && !links_healed && commit)) return;
  MCADamagePass<DeviceType> damage;
  damage.d = d;
  damage.break_step = commit ? flags.step : -1.0;
  damage.eflag_atom = eflag_atom;
  double released = 0.0;
  Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType>(0, nlocal), damage, released);
  if (eflag_global) eng_vdwl -= released;
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void PairMCAKokkos<DeviceType>::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag, 0);
  if (!links->created) error->all(FLERR, "Pair mca/kk: compute() before the links were made");

  tally.make(memoryKK, eatom, vatom, eflag_atom, vflag_atom, maxeatom, maxvatom);

  atomKK->sync(execution_space, datamask_read);
  atomKK->modified(execution_space, datamask_modify);
  grow_kk_peratom();
  // the table may have changed on the host (exchange, restart, setup); the
  // partner cache below only reads the host copy, which stays current
  linksKK->to_device();

  // the partner cache is made on the host when LAMMPS reneighbors (the
  // atom map and the closest images live there)
  if (partners_outdated()) {
    atomKK->sync(Host, X_MASK | TAG_MASK);
    links->to_host();
    if (fractured()) forget_broken_links();
    if (contacts() && neighbor->ago == 0) {
      // (new contact rows read the radii, types and cells of the automata)
      atomKK->sync(Host, RADIUS_MASK | TYPE_MASK | MCA_GEOMETRY_MASK);
      update_contacts();
    }
    refresh_partners();
    linksKK->to_device();
    k_partner_cache.modify_host();
    k_partner_cache.template sync<DeviceType>();
    count_links_kk();
    // (the host copies of the table are current here)
    check_stable_timestep(update->setupflag ? ESTIMATE_SETUP : ESTIMATE_RENEIGHBOR);
  } else if (links_broke || links_healed) {
    // links broke or contacts healed at the last step (see PairMCA::compute())
    count_links_kk();
  }
  links_broke = links_healed = 0;

  const bool commit = (update->setupflag == 0);

  predict_mean_stress();

  const int nlocal = atom->nlocal;
  const bool atom_tally = eflag_atom || vflag_atom;
  if (atom_tally) Kokkos::deep_copy(d_atom_tally, 0.0);
  const MCAPairViews<DeviceType> d = views();
  MCALinkSums sums;
  if (!plastic()) {
    if (!MCABatchedLinkKernel<DeviceType>::run(*this, commit, sums))
      link_kernel<MCALinkPassOf<LAW_ELASTIC>::template type>(commit, sums);
  } else if (commit) {
    plastic_return(commit);
    link_kernel<MCALinkPassOf<LAW_PLASTIC>::template type>(commit, sums);
  } else {
    // a setup returns no automaton (see PairMCA::compute())
    link_kernel<MCALinkPassOf<LAW_PLASTIC_SETUP>::template type>(commit, sums);
  }
  // broken pairs: their compressive force (and friction) only
  if (fractured()) link_kernel<MCAPushingPassOf<LINK_BROKEN>::template type>(commit, sums);
  if (contacts()) link_kernel<MCAPushingPassOf<LINK_CONTACT>::template type>(commit, sums);

  MCALinkFinish<DeviceType> finish;
  finish.d = d;
  if (need_dup()) finish.copies = d_link_copies;
  finish.commit = commit;
  finish.eflag_atom = eflag_atom;
  finish.vflag_atom = vflag_atom;
  Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, nlocal), finish);
  if (fractured() || healing()) change_links(commit, sums.nhealed);

  linksKK->device_changed();

  if (eflag_global) eng_vdwl += sums.energy;
  if (vflag_global)
    for (int k = 0; k < 6; k++) virial[k] += sums.virial[k];
  tally.to_host<DeviceType>(eflag_atom, vflag_atom);

  nstretched = sums.nlong;
  if (neighbor->ago == 0) stretched_warning();
}

/* ----------------------------------------------------------------------
   the stable time step is estimated on the host (PairMCA, the same code
   and so the same estimate as the CPU style): the host copies of what it
   reads, and its communication through the host buffers
------------------------------------------------------------------------- */

template <class DeviceType> void PairMCAKokkos<DeviceType>::estimate_host_state()
{
  atomKK->sync(Host, TAG_MASK | TYPE_MASK | RMASS_MASK | MCA_GEOMETRY_MASK);
  links->to_host();
}

template <class DeviceType> void PairMCAKokkos<DeviceType>::estimate_forward_comm()
{
  const ExecutionSpace space = execution_space;
  execution_space = Host;
  PairMCA::estimate_forward_comm();
  execution_space = space;
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> double PairMCAKokkos<DeviceType>::memory_usage()
{
  double bytes = PairMCA::memory_usage();
  // per automaton: 3 communicated values (5 with plasticity); per local
  // automaton: fabric, the sums the two passes share, link count and row
  // in the copies of the sums (one copy per thread on the host)
  typedef typename DeviceType::memory_space memory_space;
  const double copies = Kokkos::SpaceAccessibility<Kokkos::HostSpace, memory_space>::accessible
      ? typename DeviceType::execution_space().concurrency()
      : 0.0;
  bytes += (plastic() ? 5.0 : 3.0) * kk_nmax * sizeof(double) +
      ((6.0 + LS_SIZE) * sizeof(double) + 2.0 * sizeof(int)) * kk_nsums +
      (need_dup() ? copies : 0.0) * d_link_copies.extent(1) * LS_SIZE * sizeof(double);
  return bytes;
}

namespace LAMMPS_NS {
template class PairMCAKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class PairMCAKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
