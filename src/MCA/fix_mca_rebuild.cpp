// clang-format off
/* ----------------------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   LAMMPS development team: developers@lammps.org

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */
// clang-format on

#include "fix_mca_rebuild.h"

#include "atom_masks.h"
#include "domain.h"
#include "error.h"
#include "neighbor.h"
#include "update.h"

#include <cmath>

using namespace LAMMPS_NS;
using namespace FixConst;

/* ---------------------------------------------------------------------- */

FixMCARebuild::FixMCARebuild(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), boxcheck(0), forced(0)
{
  if (narg != 3) error->all(FLERR, "Illegal fix MCA_REBUILD command: takes no arguments");
  force_reneighbor = 1;
  next_reneighbor = -1;
  scalar_flag = 1;
  extscalar = 0;
  global_freq = 1;
  // it reads no per-atom data: the Kokkos styles need not sync any for it
  datamask_read = EMPTY_MASK;
  datamask_modify = EMPTY_MASK;
  for (int k = 0; k < 3; k++) lo_hold[k] = hi_hold[k] = 0.0;
  for (auto &c : corners_hold) c[0] = c[1] = c[2] = 0.0;
}

/* ---------------------------------------------------------------------- */

int FixMCARebuild::setmask()
{
  return PRE_NEIGHBOR | POST_INTEGRATE;
}

/* ---------------------------------------------------------------------- */

void FixMCARebuild::init()
{
  // as Neighbor::init decides whether to check the box
  boxcheck = domain->box_change &&
      (domain->xperiodic || domain->yperiodic || (domain->dimension == 3 && domain->zperiodic));
}

/* ----------------------------------------------------------------------
   the box at each build of the neighbor lists
------------------------------------------------------------------------- */

void FixMCARebuild::setup_pre_neighbor()
{
  pre_neighbor();
}

void FixMCARebuild::pre_neighbor()
{
  if (!boxcheck) return;
  if (!domain->triclinic) {
    for (int k = 0; k < 3; k++) {
      lo_hold[k] = domain->boxlo[k];
      hi_hold[k] = domain->boxhi[k];
    }
  } else {
    domain->box_corners();
    for (int c = 0; c < 8; c++)
      for (int k = 0; k < 3; k++) corners_hold[c][k] = domain->corners[c][k];
  }
}

/* ----------------------------------------------------------------------
   after the positions moved, before LAMMPS decides whether to rebuild:
   the CPU check's allowed displacement 0.5 (skin - (d1 + d2)), with d1, d2
   the two largest moves of the box corners; below zero the lists are
   rebuilt now (the CPU check does so for any atom that moved at all)
------------------------------------------------------------------------- */

void FixMCARebuild::post_integrate()
{
  if (!boxcheck) return;
  double delta1 = 0.0, delta2 = 0.0;
  if (!domain->triclinic) {
    double dlo = 0.0, dhi = 0.0;
    for (int k = 0; k < 3; k++) {
      dlo += (domain->boxlo[k] - lo_hold[k]) * (domain->boxlo[k] - lo_hold[k]);
      dhi += (domain->boxhi[k] - hi_hold[k]) * (domain->boxhi[k] - hi_hold[k]);
    }
    delta1 = sqrt(dlo);
    delta2 = sqrt(dhi);
  } else {
    domain->box_corners();
    for (int c = 0; c < 8; c++) {
      double d = 0.0;
      for (int k = 0; k < 3; k++)
        d += (domain->corners[c][k] - corners_hold[c][k]) *
            (domain->corners[c][k] - corners_hold[c][k]);
      d = sqrt(d);
      if (d > delta1)
        delta1 = d;
      else if (d > delta2)
        delta2 = d;
    }
  }
  if (0.5 * (neighbor->skin - (delta1 + delta2)) < 0.0) {
    next_reneighbor = update->ntimestep;
    forced++;
  }
}

/* ----------------------------------------------------------------------
   the rebuilds it asked for (the same on every rank: it reads the box)
------------------------------------------------------------------------- */

double FixMCARebuild::compute_scalar()
{
  return static_cast<double>(forced);
}
