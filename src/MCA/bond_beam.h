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

#ifdef BOND_CLASS
// clang-format off
BondStyle(beam,BondBeam);
// clang-format on
#else

#ifndef LMP_BOND_BEAM_H
#define LMP_BOND_BEAM_H

#include "beam_kernels.h"
#include "bond.h"

#include <vector>

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   bond_style beam: the co-rotational beam of the NUMFRAC lattice, 2-D
   or 3-D (beam_kernels.h), between particles of atom_style mca, whose
   quaternions carry the orientations.  The reference state of each bond
   lives in the internal fix BEAM_STATE; the style copies it into an array
   parallel to the bond list whenever the list is built.
------------------------------------------------------------------------- */

class BondBeam : public Bond {
 public:
  // what the style keeps for each entry of the bond list: whether the
  // order lower atom ID first is the list's order reversed, the strength
  // factor of the bond, and its reference state (nrec values in all)
  enum { REC_SWAP, REC_STRENGTH, REC_REF };

  BondBeam(class LAMMPS *);
  ~BondBeam() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double equilibrium_distance(int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_data(FILE *) override;
  double single(int, double, int, int, double &) override;
  double memory_usage() override;

  // the stable time step of the listed bonds (Gershgorin's bound of the
  // fastest mode, beam_kernels.h; doc/src/bond_beam.rst): made at the setup
  // of each run and when compute beam/timestep asks (the Kokkos variant
  // brings the state to the host first).  Needs the records of a bond list
  // (a first run); returns whether it could be made
  struct StableStep {
    double dt;       // the stable time step (infinite: no bonds act)
    double omega;    // the bound of the fastest angular frequency
    double zeta;     // its damping ratio (bond damping)
    tagint atom;     // the particle whose row gives the bound (0: none)
    bigint nbonds;
  };
  virtual bool stable_timestep(StableStep &out);

  // the special weights leave bonded pairs out of the pair style (1-2 lj
  // weight 0, 1-3 and 1-4 weights 1: lj/coul 0 1 1 or lj 0 1 1 coul 1 1 1),
  // so that a broken bond's particles come back into it
  static bool bonded_pairs_excluded(const class Force *force);

 protected:
  BeamKernels::BeamCoeff *coeffs;    // by bond type
  class FixBeamState *fix_state;
  double L0_max;    // longest reference length seen (communication cutoff check)
  int nrec;         // values per record: REC_REF + the reference state of the dimension

  // the records of every entry of a bond list (i1, i2, type) into
  // records[n * nrec], when the list was built again since the last call;
  // entry (n, k) of the list is list[n * row_stride + k * column_stride]
  bigint built_at;
  int built_n;
  bool references_stale(int nlist) const;
  void fill_records(int nlist, const int *list, long row_stride, long column_stride,
                    double *records);

  // breaking: any type breakable; bonds broken this step (entries i1 i2)
  int breaking;
  // damping: any type with damp (reads v and omega; the power goes to BEAM_STATE's tally)
  int damping;
  // melting: any type with melt (a bond melts with a probability per step;
  // with refreeze it may freeze again, stress-free); melt_now: in dynamics,
  // not at a run's setup (whose step was evaluated by the run before)
  int melting;
  bool melt_now() const;
  // radii: any type with its sections from the particles' radii (reads radius)
  int radii;
  // particle: any type broken by the particle criterion (the fix's sums
  // and states; reads radius); particle_now: this evaluation applies the
  // decisions of the last one (not at a run's setup, which decides again
  // from the same state: a run continued or restarted breaks as one run)
  int particle;
  bool particle_now() const;
  // update_special: bonded pairs are left out of the pair style (special
  // weights 0 for 1-2, 1 for 1-3 and 1-4): a broken bond leaves the special
  // lists of its atoms on every rank and the neighbor lists are built again
  // at the next step, so that the two particles interact through the pair
  // style from then on (BPM's fix update/special/bonds)
  int update_special;
  // returns whether the special lists of local atoms changed
  bool remove_broken(int nbroken, const int *pairs);
  bool forget_broken_pairs(int nbroken, const int *pairs);
  // before the special lists change on the host (a bond broke on some
  // rank): the Kokkos variant brings them there first
  virtual void specials_to_host() {}

  StableStep stable_timestep_of(int nlist, const int *list, long row_stride, long column_stride,
                                const double *records);
  bool records_current() const;
  // at a dynamics run's setup: the estimate in the log, a warning above it
  void check_stable_timestep();

  void allocate();
  void estimate_longest_bond();
  void find_state();

 private:
  double *records;
  int maxrecords;
  template <int DIM> void evaluate(int nlist, int **bondlist, std::vector<int> &broken);
  void tally(int i, int j, int nlocal, int newton_bond, double ebond, const double *f,
             const double *d);
};

}    // namespace LAMMPS_NS

#endif
#endif
