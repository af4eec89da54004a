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

#ifndef LMP_MCA_LARGEST_ROW_H
#define LMP_MCA_LARGEST_ROW_H

#include "lmptype.h"

#include <mpi.h>

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   the largest of the local atoms' row bounds over all ranks and, of the
   atoms that hold it, the lowest ID (0 when no bound is > 0): the
   Gershgorin estimates of bond beam and pair mlp, the same on any number
   of ranks
------------------------------------------------------------------------- */

struct MCALargestRow {
  double value;
  tagint atom;
};

inline MCALargestRow mca_largest_row(MPI_Comm world, int n, const double *bound, const tagint *tag)
{
  double most = 0.0;
  tagint atom_most = MAXTAGINT;
  for (int i = 0; i < n; i++)
    if (bound[i] > most || (bound[i] == most && most > 0.0 && tag[i] < atom_most)) {
      most = bound[i];
      atom_most = tag[i];
    }
  MCALargestRow out;
  MPI_Allreduce(&most, &out.value, 1, MPI_DOUBLE, MPI_MAX, world);
  tagint mine = (most == out.value && out.value > 0.0) ? atom_most : MAXTAGINT;
  MPI_Allreduce(&mine, &out.atom, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  if (!(out.value > 0.0)) out.atom = 0;
  return out;
}

}    // namespace LAMMPS_NS

#endif
