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

#ifdef PAIR_CLASS
// clang-format off
PairStyle(mca,PairMCA);
// clang-format on
#else

#ifndef LMP_PAIR_MCA_H
#define LMP_PAIR_MCA_H

#include "mca_link_passes.h"
#include "mca_materials.h"
#include "mca_stable_timestep.h"
#include "pair_mca_linked.h"

namespace LAMMPS_NS {

struct MCAHostTotals;

class PairMCA : public PairMCALinked, public MCAStableTimestep::Comm {
 public:
  PairMCA(class LAMMPS *);
  ~PairMCA() override;

  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void setup() override;

  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;

  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  void *extract(const char *, int &) override;
  double memory_usage() override;

  // the mean-stress predictor: a separate pass with its own forward
  // communication, called by compute() (and by the Kokkos variant)
  virtual void predict_mean_stress();

  // the stable time step of the scene (made again first if the links,
  // the masses, the materials or the stiffness changed since); nullptr
  // before the links are made
  const MCAStableTimestep::Result *stable_timestep();
  // the time step pair mca recommends: a fraction of the stable one
  static constexpr double RECOMMENDED_FRACTION = 0.7;
  void estimate_forward_comm() override;

 protected:
  MCAMaterials materials;    // per type
  // per type pair: linking rules
  int **link_allowed;
  double **link_tolerance;

  // fracture links: the criterion of each type pair ((ntypes + 1)^2,
  // symmetric), the strength scatter and its seed
  std::vector<MCAKernels::MCABreakRule> break_rules;
  double break_scatter;
  int break_seed;

  // contacts: the friction and healing criterion of each type pair
  // ((ntypes + 1)^2, symmetric) and whether pair_coeff gave the friction
  // (else mixed from the types' own)
  std::vector<MCAKernels::MCAContactRule> contact_rules;
  std::vector<int> friction_given;

  double tolerance_default;    // relative distance tolerance for links
  bool batch_links;            // the elastic link pass over batches of links (pair_mca_batch.cpp)
  double cutoff_user;          // pair cutoff given by the user, else < 0

  // per-atom work arrays (local + ghost)
  int nmax;
  int *link_count;           // interacting links of each local automaton
  double *pred_stiffness;    // its stiffness in the mean-stress predictor (communicated)
  double *dsmean;            // mean-stress increment the normal law applies this step
  double *smean_pred;        // predicted mean stress of this step
  double *return_scale;      // plasticity: return factor M of each automaton (communicated)
  double *return_smean;      // and the mean stress of its trial (communicated)
  void destroy_peratom();
  // the sums of the passes, for the local automata only (a pass adds to a
  // local partner, never to a ghost; nsums rows).  Two arrays: B's dense
  // rows of 9 keep the link pass on fewer cache lines than rows shared
  // with the predictor's sums, whose strain moments are dead by then (one
  // array of 15 columns cost 3-4 % of the step at 265721 automata, 2-5 %
  // measured again on 7 Dec 2026; F in rows of its own and M then B in
  // rows of 9 cost the predictor 15 %: bench/README.md)
  int nsums;
  double **predictor_sums;    // predictor pass: PS_* columns (mca_link_passes.h); the
                              // first six, sum n n^T, are the fabric tensor of the stress
  double **bmat;              // link pass: sum of T n^T (LS_BMAT columns)
  void grow_sums();
  // what the forward communication sends: the predictor stiffness, the
  // mean-stress increment and prediction, or the return of the automata
  // or (fracture) the stress and plastic strain of the step
  enum CommStage { STAGE_COUNT, STAGE_MEAN, STAGE_RETURN, STAGE_BREAK, STAGE_ESTIMATE };
  int comm_stage;
  int restart_named;       // the restart file being read names its material keywords
  int restart_tables;      // and holds hardening tables
  int restart_fracture;    // and fracture rules

  class MCAAtomFields *avec;

  void allocate();
  void grow_peratom();
  bool linkable(int i, int j) override;
  void init_link_row(int i, int j, double *row) override;
  void init_contact_row(int i, int j, double *row);
  void init_pair_row(int i, int j, int state, double *row);
  void init_contacts(double rmax);    // (rmax: the largest radius)
  void check_rigid_bodies();
  void count_links();
  void set_masses();
  static const char *link_slot(const char *keyword);
  void select_parts(const std::vector<std::string> &chosen);
  void check_parts();
  bool plastic() const;
  bool fractured() const;
  bool contacts() const;
  bool healing() const;
  // contacts: the friction of the type pairs pair_coeff left unset (mixed)
  void mix_friction();
  // at reneighboring, before the partners are found again: drop the
  // contact rows of pairs that moved apart beyond reach, add one for every
  // unlinked pair within reach (from the contact neighbor list)
  void update_contacts();
  void keep_dropped_energy(const double *row, double *state) const;
  class NeighList *contact_list;
  void init_list(int, class NeighList *) override;
  int restart_contacts;    // the restart file being read holds contact rules
  int restart_healing;     // and healing criteria
  void parse_heal(int ilo, int ihi, int jlo, int jhi, int narg, char **arg, int &iarg);
  void parse_break(int ilo, int ihi, int jlo, int jhi, int narg, char **arg, int &iarg);
  // drop broken pairs farther apart than the cutoff from the link tables
  // (at reneighboring, before the partners are found again)
  void forget_broken_links();
  MCAKernels::MCABreakFlags break_flags() const;
  MCAKernels::MCALinkPassFlags link_pass_flags(bool commit) const;
  int links_broke;    // links broke at the last step (on some processor)
  void note_breaks(int nbroke_local);
  int links_healed;    // contacts healed at the last step (on some processor)
  void note_heals(int nhealed_local);
  // ghost automata need the plastic strain of the step (STAGE_BREAK)
  bool heal_reads_epsp() const;

  // the stable time step: its estimate, and what it was made from (the
  // monitor value of the stiffness, a checksum of the masses and
  // materials, the link changes counted since)
  MCAStableTimestep *stability;
  MCAStableTimestep::Result dt_estimate;
  MCAStableTimestep::Monitor dt_monitor;
  int dt_estimated;
  double dt_warned_ratio;    // time step / estimate of the last warning during a run
  std::vector<double> dt_inputs;
  int links_changed;    // links broke or were forgotten here since the estimate
  enum EstimateWhen { ESTIMATE_SETUP, ESTIMATE_RENEIGHBOR, ESTIMATE_QUERY };
  // at a setup and when LAMMPS reneighbors (from compute(), where the host
  // copies of the table are current): make the estimate again if needed,
  // print it and warn about the time step
  void check_stable_timestep(EstimateWhen when);
  // (when: what a warning during a run adds, or nothing)
  void timestep_warning(const std::string &when);
  // bring the host copies of what the estimate reads up to date (kk)
  virtual void estimate_host_state() {}
  MCAStableTimestep::Input stability_input();
  std::vector<double> stability_inputs();
  std::string timestep_hint() override;

  struct HostData;
  struct HostSums;
  struct HostLinkSums;
  struct HostTally;
  HostData host_data();
  // the elastic link pass over batches of links (pair_mca_batch.cpp), for
  // the models it applies to (batched_link_pass_applies)
  bool batched_link_pass_applies() const;
  void batched_link_pass(const HostData &, const HostLinkSums &, const HostTally &,
                         const MCAKernels::MCALinkPassFlags &, MCAHostTotals &);
};

}    // namespace LAMMPS_NS

#endif
#endif
