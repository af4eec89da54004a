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

/* ----------------------------------------------------------------------
   Prescribed velocities of grips (fix mca/setvelocity).
------------------------------------------------------------------------- */

#ifndef LMP_MCA_PRESCRIBE_H
#define LMP_MCA_PRESCRIBE_H

#include "mca_inline.h"

#include <cmath>

namespace LAMMPS_NS {
namespace MCAKernels {

  /* a velocity component of a grip (fix mca/setvelocity): the force that
     acted on it is the reaction (returned); a prescribed component then
     moves at the target velocity and its force is removed, so that the
     time integrator keeps it there                                       */

  MCA_INLINE double prescribe_velocity(bool prescribed, double target, double &v, double &f)
  {
    const double reaction = f;
    if (prescribed) {
      v = target;
      f = 0.0;
    }
    return reaction;
  }

}    // namespace MCAKernels
}    // namespace LAMMPS_NS

#endif
