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

#ifdef FIX_CLASS
// clang-format off
FixStyle(mca/damping,FixMCADamping);
// clang-format on
#else

#ifndef LMP_FIX_MCA_DAMPING_H
#define LMP_FIX_MCA_DAMPING_H

#include "fix.h"
#include "mca_damping_fix.h"

namespace LAMMPS_NS {

// global damping of automata for quasi-static loading: F -= gamma m v,
// T -= gamma_r J omega, with the energy it takes out as its scalar (and in
// ecouple, so that econserve stays constant)
class FixMCADamping : public Fix {
 public:
  FixMCADamping(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;
  double compute_scalar() override;
  void write_restart(FILE *) override;
  void restart(char *) override;

 protected:
  double gamma, gamma_r;        // damping rates of translation and spin (1/time)
  MCAEnergyTally dissipated;    // energy taken out so far
  class MCAAtomFields *avec;    // the fields of atom_style mca
  // the power taken out at this call; tallied times dt in a step of a run
  // (a setup applies the forces and tallies nothing)
  virtual double apply();
};

}    // namespace LAMMPS_NS

#endif
#endif
