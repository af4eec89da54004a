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

#include "fix_mca_links.h"
#include "pair.h"

namespace LAMMPS_NS {

class PairMCA : public Pair, public MCALinkRowSync {
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

  double recommended_timestep();
  class FixMCALinks *links;

  // a link between two local automata is advanced in the row of the
  // lower ID only; the partner's row is brought up to date on request
  void sync_link_rows() override;

 protected:
  // per type: material
  double *youngs, *poisson, *density;    // E, nu, rho
  double *shear, *bulk, *coupling;       // G, K, D = 1 - 2G/(3K)
  int *material_set;
  // per type pair: linking rules
  int **link_allowed;
  double **link_tolerance;

  double tolerance_default;    // relative distance tolerance for links
  double cutoff_user;          // pair cutoff given by the user, else < 0
  int capacity_user;           // links per automaton given by the user, else 0
  double cut_global;

  // per-atom work arrays (local + ghost)
  int nmax;
  double *link_count;        // interacting links of each local automaton
  double *pred_stiffness;    // its stiffness in the mean-stress predictor (communicated)
  double *dsmean;            // mean-stress increment the normal law applies this step
  double *smean_pred;        // predicted mean stress of this step
  double **bmat_atom;        // sum of T n^T of each local automaton
  double **fabric_atom;      // sum of n n^T of each local automaton at the current
                             // positions: made by the predictor, used by the stress too
  double **pred_strain;      // sum of de n n^T of the predicted strains
  int **partner_cache;       // local or ghost index of each link's partner
  int **row_cache;           // row of the same link in a local partner's table
  int cache_rows, cache_cols, cache_nlocal;
  void destroy_peratom();
  int partner_rows_stale;    // rows of local links behind their partner's copy
  // what the forward communication sends: the predictor stiffness, or the
  // mean-stress increment and prediction
  enum CommStage { STAGE_COUNT, STAGE_MEAN };
  int comm_stage;
  bigint nstretched;    // links longer than the cutoff at the last step

  class MCAAtomFields *avec;

  void allocate();
  void grow_peratom();
  void create_links();
  void count_links();
  void build_partner_cache();
  virtual void allocate_partner_cache();
  // style of the internal fix that keeps the links
  virtual const char *links_fix_style() const { return "MCA_LINKS"; }
  void set_masses();
  int partner_index(int i, tagint partner_tag);
  void stretched_warning();
};

}    // namespace LAMMPS_NS

#endif
#endif
