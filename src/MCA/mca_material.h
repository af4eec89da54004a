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
   Material of an atom type: the record every style reads (one plain,
   trivially copyable struct) and the moduli derived from its input.
------------------------------------------------------------------------- */

#ifndef LMP_MCA_MATERIAL_H
#define LMP_MCA_MATERIAL_H

#include "mca_inline.h"

#include <cmath>

namespace LAMMPS_NS {
namespace MCAKernels {

  /* ----------------------------------------------------------------------
     isotropic material: shear and bulk modulus from E and nu, and the
     coupling factor of the mean stress in the normal law,
       D = 1 - 2G/(3K) = lambda/K = 3 nu/(1 + nu)
     (the source prints 1 - 2G/K; only 1 - 2G/(3K) reproduces Hooke's law)
  ------------------------------------------------------------------------- */

  MCA_INLINE double shear_modulus(double E, double nu)
  {
    return E / (2.0 * (1.0 + nu));
  }

  MCA_INLINE double bulk_modulus(double E, double nu)
  {
    return E / (3.0 * (1.0 - 2.0 * nu));
  }

  MCA_INLINE double mean_stress_coupling(double G, double K)
  {
    return 1.0 - 2.0 * G / (3.0 * K);
  }

  // P-wave speed sqrt((K + 4G/3)/rho)
  MCA_INLINE double p_wave_speed(double G, double K, double rho)
  {
    return sqrt((K + 4.0 * G / 3.0) / rho);
  }

  /* ----------------------------------------------------------------------
     the material of an atom type: the input (pair_coeff, parsed and
     checked in MCAMaterials) and what every kernel derives from it once.
     A new parameter is a field here, its line in MCAMaterials' keyword
     table and its line in doc/src/pair_mca.rst
  ------------------------------------------------------------------------- */

  struct MCAMaterial {
    // input
    double youngs;       // Young's modulus E
    double poisson;      // Poisson's ratio nu
    double density;      // mass density rho
    double viscosity;    // eta of the link damping (damping viscous; 0: none)
    double yield;        // yield stress sigma_y (plasticity mises; 0: elastic)
    double hardening;    // linear hardening modulus H = d sigma_y / d eps_p
    // derived (derive_material)
    double shear;       // G
    double bulk;        // K
    double coupling;    // D = 1 - 2G/(3K)
  };

  MCA_INLINE void derive_material(MCAMaterial &m)
  {
    m.shear = shear_modulus(m.youngs, m.poisson);
    m.bulk = bulk_modulus(m.youngs, m.poisson);
    m.coupling = mean_stress_coupling(m.shear, m.bulk);
  }

}    // namespace MCAKernels
}    // namespace LAMMPS_NS

#endif
