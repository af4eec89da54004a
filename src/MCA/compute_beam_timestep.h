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

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(beam/timestep,ComputeBeamTimestep);
// clang-format on
#else

#ifndef LMP_COMPUTE_BEAM_TIMESTEP_H
#define LMP_COMPUTE_BEAM_TIMESTEP_H

#include "compute_stable_step.h"

namespace LAMMPS_NS {

// the stable time step of bond_style beam's bonds (Gershgorin's bound)
class ComputeBeamTimestep : public ComputeStableStep {
 public:
  ComputeBeamTimestep(class LAMMPS *, int, char **);
  void init() override;

 protected:
  bool estimate(double *values) override;

 private:
  class BondBeam *bond;
};

}    // namespace LAMMPS_NS

#endif
#endif
