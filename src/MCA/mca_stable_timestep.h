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

#ifndef LMP_MCA_STABLE_TIMESTEP_H
#define LMP_MCA_STABLE_TIMESTEP_H

#include "mca_material.h"
#include "mca_stability.h"
#include "pair_mca_linked.h"
#include "pointers.h"

#include <vector>

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   the stable time step of a scene of linked automata: the largest
   eigenvalue omega^2 of the mass-scaled tangent stiffness of its links
   (mca_stability.h), found by the Lanczos iteration on all automata and
   their translations and rotations, and the damping ratio of that mode;
   then dt_c = 2 (sqrt(1 + zeta^2) - zeta) / omega.  Run on the host at a
   setup (and when the stiffness may have grown) by pair mca and mca/kk
   alike; see doc/src/pair_mca.rst, "Stable time step"
------------------------------------------------------------------------- */

class MCAStableTimestep : protected Pointers {
 public:
  // who sends the estimate's per-atom values to the ghost atoms: the pair
  // style, through its forward communication (comm_size values per atom)
  class Comm {
   public:
    virtual void estimate_forward_comm() = 0;

   protected:
    ~Comm() = default;
  };

  // what the estimate reads, on the host
  struct Input {
    MCAHostLinks links;    // the link table and the partners
    const int *type, *packing;
    const double *rmass, *inertia;
    const MCAKernels::MCAMaterial *material;    // by type
    bool damping;                               // the link model has viscous damping
    bool friction;                              // and friction (contacts coulomb)
  };

  struct Result {
    double dt;         // critical time step (inf without links)
    double omega;      // angular frequency of the fastest mode
    double zeta;       // its damping ratio (0 without damping)
    int iterations;    // Lanczos steps
    bigint nlinks;     // links that act (linked, or broken and pushing)
  };

  // the monitor: the largest stiffnesses of a link, mass-scaled by the
  // automaton that meets them (normal kn/m, shear kt/m, spin kt q^2/J,
  // bending kb/J: when one of them grows, the estimate may fall); the
  // automaton with the largest trace of its mass-scaled block of the
  // stiffness, its type and its stiffest link (lowest IDs among equals)
  static constexpr int NMONITOR = 4;
  struct Monitor {
    double value[NMONITOR];
    tagint atom, link_i, link_j;
    int atom_type;
  };

  MCAStableTimestep(class LAMMPS *);
  ~MCAStableTimestep() override;

  Result estimate(const Input &, Comm *);
  // (all ranks) it follows the stiffness through deformation, at the cost
  // of one pass over the links
  Monitor monitor(const Input &);

  static constexpr int comm_size = 7;
  int pack_forward_comm(int n, int *list, double *buf);
  void unpack_forward_comm(int n, int first, double *buf);

 private:
  enum Stage { STAGE_SETUP, STAGE_MOTION, STAGE_SUMS };
  int stage;
  int nmax;
  // per atom, local and ghost: inverse fabric tensor, predictor
  // stiffness and whether the mean stress is predicted (sent once), the
  // displacement and rotation of the vector the operator is applied to,
  // and the two mean-stress sums s and r of each automaton (flat arrays
  // of 6, 1, 1, 6 and 2 values per atom: no arrays of row pointers)
  double *finv, *hpred, *predicted, *motion, *sums;
  double *finv_of(int i) const { return finv + 6 * static_cast<std::size_t>(i); }
  double *motion_of(int i) const { return motion + 6 * static_cast<std::size_t>(i); }
  double *sums_of(int i) const { return sums + 2 * static_cast<std::size_t>(i); }
  // local: the right-hand sides and the diagonal of the mean-stress
  // systems, the next Jacobi iterate
  std::vector<double> rhs_fwd, rhs_tr, diag, next;

  // what the Jacobi steps of the mean-stress systems read of a link, kept
  // for the steps of one estimate in single precision (an estimate to 1e-4
  // needs no more) at the index of the link's row in the pool of the links
  // fix: both ends of a link between local automata share that row, so
  // they find the entry there.  It is made by the end that evaluates the
  // link (the lower ID of two local automata, the local automaton of a
  // link to a ghost); the other end reads it swapped.  A link that is not
  // linked has weights 0, and adding 0 x s (s finite) to a sum that starts
  // at +0 leaves it as it is, bit for bit: the steps take every end and
  // need no test.  The rest of a link's tangent is made again from its row
  // where a pass needs it, once for both ends (for_each_acting): that is
  // faster than reading a table of it at each end, and 64 bytes a link less
  struct JacobiEntry {
    float fwd, tr;    // weights of the partner's mean stress in the two systems
  };
  std::vector<JacobiEntry> jacobi;

  void grow(int n);
  // the per-automaton arrays and the link table live only while an
  // estimate or a check runs (at a setup or a reneighbouring): freed after
  void release();
  Result lanczos_estimate(const Input &, Comm *);
  void prepare(const Input &, Comm *);
  void cache_jacobi_weights(const Input &);
  // f(i, j, tangent) for each link that acts (a link, or a broken pair
  // that pushes) once, from the local automaton i that evaluates it (in
  // the order of the local automata and their rows): its partner and its
  // tangent seen from i, made from its row (f may swap its sides)
  template <class F> void for_each_acting(const Input &, F f) const;
  // the partner's mean-stress weights (forward, transposed) of the link of
  // local automaton i at row m
  void jacobi_weights(const MCAHostLinks &, int i, int m, double &fwd, double &tr) const;
  // the share of a link that a local automaton evaluates, with partner j,
  // in sums over the local automata: 1 for a local partner, 1/2 for a
  // ghost (counted half by each of the two processors that own its
  // automata)
  static double link_weight(int nlocal, int j);
  // the unit start vector of the Lanczos steps (it depends only on the IDs)
  void start_vector(const Input &, std::vector<double> &v) const;
  // y <- M^-1/2 K_s M^-1/2 x - keep y on the local automata (6 per
  // automaton; keep y: the Lanczos step's beta v_old, in y already)
  void apply(const Input &, Comm *, const double *x, double keep, double *y);
  // the motion of the local automata for a mass-scaled vector, sent to the ghosts
  void set_motion(const Input &, Comm *, const double *x);
  double dot(const std::vector<double> &a, const std::vector<double> &b) const;
  // the link of local automaton i at row m seen from i, and its partner
  void tangent_of(const Input &, int i, int m, int &j, MCAKernels::MCALinkTangent &t) const;
  double damping_ratio(const Input &, Comm *, const std::vector<double> &x, double omega);
};

}    // namespace LAMMPS_NS

#endif
