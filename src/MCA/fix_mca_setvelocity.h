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
FixStyle(mca/setvelocity,FixMCASetVelocity);
// clang-format on
#else

#ifndef LMP_FIX_MCA_SETVELOCITY_H
#define LMP_FIX_MCA_SETVELOCITY_H

#include "fix.h"

namespace LAMMPS_NS {

class FixMCASetVelocity : public Fix {
 public:
  FixMCASetVelocity(class LAMMPS *, int, char **);
  ~FixMCASetVelocity() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;
  void post_force_respa(int, int, int) override;
  double compute_vector(int) override;
  double memory_usage() override;

 protected:
  enum { NONE, CONSTANT, EQUAL, ATOM };
  int style[3];       // per component: NONE (free), CONSTANT, EQUAL or ATOM variable
  double value[3];    // constant or current equal-style value
  char *varname[3];
  int ivar[3];
  double reaction[3], reaction_all[3];    // force on the group before it is removed
  int reaction_flag;
  int ilevel_respa;
  int maxatom;
  double **vatom;    // values of atom-style variables

  void evaluate_targets();
};

}    // namespace LAMMPS_NS

#endif
#endif
