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
PairStyle(mlp,PairMLP);
// clang-format on
#else

#ifndef LMP_PAIR_MLP_H
#define LMP_PAIR_MLP_H

#include "mca_compat.h"
#include "mlp_passes.h"
#include "pair.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   pair_style mlp: movable lattice particles in 2-D (Popov and Filippov),
   a central potential plus the return force toward the lattice axes
   (mlp_kernels.h, doc/src/pair_mlp.rst).  A full neighbour list: each
   atom sums its own force, so that the per-atom return force needs no
   reverse communication and results do not depend on newton_pair
------------------------------------------------------------------------- */

class PairMLP : public Pair {
 public:
  PairMLP(class LAMMPS *);
  ~PairMLP() override;

  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  void write_data(FILE *) override;
  void write_data_all(FILE *) override;
  void *extract(const char *, int &) override;
  // "freturn": |F_return| per atom (fix pair; LAMMPS 2022 and later)
  void *extract_peratom(const char *, int &) MCA_EXTRACT_PERATOM_OVERRIDE;
  double memory_usage() override;

  // the stable time step (Gershgorin's bound; doc/src/pair_mlp.rst): false
  // before the first neighbour list
  struct StableStep {
    double dt;       // 2 / omega (velocity Verlet); infinite if no pair acts
    double omega;    // the bound of the fastest angular frequency
    tagint atom;     // the atom of the largest row sum (lowest ID of ties)
    bigint pairs;    // pairs within their cutoff (each once)
  };
  virtual bool stable_timestep(StableStep &out);

  // what fix mlp/traction reads (after init): the coefficients of a type
  // pair, the return force's variant, the lattice frame (nullptr: none)
  const MLPKernels::MLPCoeff &coefficients(int i, int j) const;
  int return_variant() const { return return_style; }
  class FixMLPFrame *lattice_frame() const { return frame; }

 protected:
  double cut_global, taper_width;
  int return_style;    // MLPKernels::MLPReturn
  // coefficients of each type pair as given (the I <= J record is used
  // for both orders); the kernels read coeff_table, [i * (ntypes+1) + j]
  std::vector<MLPKernels::MLPCoeff> coeff_table;
  // per-atom |F_return| (computed when freturn_flag is set, by fix pair)
  int freturn_flag, nmax_freturn;
  double *freturn;

  virtual void allocate();
  MLPKernels::MLPCoeff &coeff_of(int i, int j);
  void set_derived(MLPKernels::MLPCoeff &, double cut);
  std::string coeff_args(int i, int j);
  void grow_freturn();

  // a co-rotating lattice frame (fix mlp/frame): (cos a/2, sin a/2) of the
  // angle a each atom's body has turned, owned and ghost atoms
  std::string frame_id;
  class FixMLPFrame *frame;
  std::vector<double> half_turn;
  void find_frame();
  void frame_half_turns();

  // the bound of omega^2 of each local atom's rows -> the estimate
  StableStep reduce_stable_timestep(const double *bound, bigint pairs_twice);
  void check_stable_timestep();

 private:
  // the atoms and the list as the passes read them (mlp_passes.h)
  struct HostAtoms {
    double **xp;
    const int *typep;
    const double *rmass, *mass;
    const MLPKernels::MLPCoeff *table;
    const int *numneighp;
    int **firstneigh;
    const double *special_lj;
    const double *turn;    // half_turn
    int ntypes1, return_style;
    double x(int i, int k) const { return xp[i][k]; }
    int type(int i) const { return typep[i]; }
    const MLPKernels::MLPCoeff &coeff(int k) const { return table[k]; }
    int numneigh(int i) const { return numneighp[i]; }
    int neighbors(int i, int jj) const { return firstneigh[i][jj]; }
    double half_turn(int i, int k) const { return turn[2 * i + k]; }
    double mass_of(int i) const { return rmass ? rmass[i] : mass[typep[i]]; }
  };
  HostAtoms host_atoms() const;
  void tally_atom(int i, const MLPKernels::MLPAtomSums &);
  template <int FRAME> void eval();
  template <int FRAME> bigint row_bounds(std::vector<double> &bound);
};

}    // namespace LAMMPS_NS

#endif
#endif
