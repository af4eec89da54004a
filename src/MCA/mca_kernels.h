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
   Physics of the Movable Cellular Automata method, written once for the
   CPU and the Kokkos styles, one header per topic (see
   doc/src/Developer_mca.rst):
     mca_inline.h        how the kernels are declared (host and device)
     mca_geometry.h      packing, cells, faces, fabric, homogenised stress
     mca_integration.h   velocity Verlet and quaternion rotation
     mca_prescribe.h     prescribed grip velocities
     mca_material.h      the material record of an atom type
     mca_link_layout.h   blocks of a link row and of the automaton state
     mca_mean_stress.h   mean-stress predictor and automaton stress
     mca_plasticity.h    hardening curves, radial return, plastic correction
     mca_link_law.h      the link law, step by step
     mca_link_passes.h   the passes over the links, for both dispatchers
     mca_stability.h     the linearised link law, for the stable time step
------------------------------------------------------------------------- */

#ifndef LMP_MCA_KERNELS_H
#define LMP_MCA_KERNELS_H

#include "mca_geometry.h"
#include "mca_integration.h"
#include "mca_link_law.h"
#include "mca_link_layout.h"
#include "mca_link_passes.h"
#include "mca_material.h"
#include "mca_mean_stress.h"
#include "mca_plasticity.h"
#include "mca_prescribe.h"
#include "mca_stability.h"

#endif
