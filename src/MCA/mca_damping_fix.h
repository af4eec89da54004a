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

#ifndef LMP_MCA_DAMPING_FIX_H
#define LMP_MCA_DAMPING_FIX_H

#include "error.h"
#include "lammps.h"
#include "utils.h"

#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <cstring>

/* ----------------------------------------------------------------------
   what the damping fixes (fix mca/damping, fix nve/damped) share
------------------------------------------------------------------------- */

namespace LAMMPS_NS {

// a damping rate argument (1/time units): >= 0 and finite, or an error
// naming the fix, the argument and the range
inline double damping_rate(LAMMPS *lmp, const char *fix, const char *name, const char *arg)
{
  const double rate = utils::numeric(FLERR, arg, false, lmp);
  if (!(rate >= 0.0) || !std::isfinite(rate))
    lmp->error->all(FLERR, "Fix {}: {} must be >= 0 and finite (1/time units), got {}", fix, name,
                    arg);
  return rate;
}

/* ----------------------------------------------------------------------
   the energy a damping fix has taken out so far (its scalar, counted in
   ecouple): summed on each rank, reduced on request, and carried by the
   fix's global restart record so that a restarted run continues it
   (rank 0 holds the restored total)
------------------------------------------------------------------------- */

class MCAEnergyTally {
 public:
  double local = 0.0;

  double total(MPI_Comm world) const
  {
    // a copy: the MPI stubs of a serial build take a non-const send buffer
    double mine = local, all = 0.0;
    MPI_Allreduce(&mine, &all, 1, MPI_DOUBLE, MPI_SUM, world);
    return all;
  }

  // a Fix::write_restart() record: its size, then the total
  void write_restart(FILE *fp, MPI_Comm world, int me) const
  {
    const double all = total(world);
    if (me == 0) {
      const int size = sizeof(double);
      fwrite(&size, sizeof(int), 1, fp);
      fwrite(&all, sizeof(double), 1, fp);
    }
  }

  void restart(const char *buf, int me)
  {
    double all = 0.0;
    memcpy(&all, buf, sizeof(double));
    local = (me == 0) ? all : 0.0;
  }
};

}    // namespace LAMMPS_NS

#endif
