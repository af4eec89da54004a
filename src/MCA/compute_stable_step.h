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

#ifndef LMP_COMPUTE_STABLE_STEP_H
#define LMP_COMPUTE_STABLE_STEP_H

#include "compute.h"

#include <string>

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   the frame of compute beam/timestep and mlp/timestep: no arguments, a
   global vector whose first element (the stable time step) is also the
   scalar, made again at each invocation by the style's estimate
------------------------------------------------------------------------- */

class ComputeStableStep : public Compute {
 public:
  ComputeStableStep(class LAMMPS *, int, char **, int nvalues);
  ~ComputeStableStep() override;
  double compute_scalar() override;
  void compute_vector() override;

 protected:
  // fills the vector; false before the style has the state it needs
  virtual bool estimate(double *values) = 0;
  // what to do when estimate() is false (the error's text after the style)
  std::string not_ready;
};

}    // namespace LAMMPS_NS

#endif
