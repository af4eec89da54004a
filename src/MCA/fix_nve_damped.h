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
FixStyle(nve/damped,FixNVEDamped);
// clang-format on
#else

#ifndef LMP_FIX_NVE_DAMPED_H
#define LMP_FIX_NVE_DAMPED_H

#include "fix.h"
#include "mca_damping_fix.h"

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   fix nve/damped: NUMFRAC's damped integrator (mca_integration.h,
   doc/src/fix_nve_damped.rst): velocity Verlet with the mass-proportional
   damping force -gamma m v(n) at the centred velocity, stable for
   omega dt < 2 at any damping; the spin of finite-size spheres likewise
   (-gamma_r J omega), and that of automata (atom_style mca: their own J,
   the orientation turned as fix nve/mca does).  The energy it takes out
   is its scalar (ecouple).
------------------------------------------------------------------------- */

class FixNVEDamped : public Fix {
 public:
  FixNVEDamped(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void initial_integrate(int) override;
  void final_integrate() override;
  void reset_dt() override;
  double compute_scalar() override;
  void write_restart(FILE *) override;
  void restart(char *) override;

 protected:
  double gamma, gamma_r;            // damping rates of translation and spin (1/time)
  double inertia_factor;            // J = inertia_factor m r^2 (0.4 sphere, 0.5 disc)
  int spin;                         // integrate the spin of finite-size spheres
  class MCAAtomFields *automata;    // atom_style mca: its J and orientations
  double dtv, dtf;
  MCAEnergyTally dissipated;    // energy taken out so far

  // the two half steps over the group's atoms, each adding to the sums
  // m |v|^2 and J |omega|^2 of the full-step velocities it starts from (the
  // first) or ends at (the second)
  virtual void half_step(double &mvsq, double &jwsq);
  virtual void full_step(double &mvsq, double &jwsq);
  void tally(double mvsq, double jwsq);
};

}    // namespace LAMMPS_NS

#endif
#endif
