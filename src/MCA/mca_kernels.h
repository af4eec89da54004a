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
   Physics of the Movable Cellular Automata method, written once.

   Plain arithmetic on doubles, no LAMMPS or STL objects, so that the CPU
   styles and the Kokkos styles (host or device) call the same functions.
   In a Kokkos translation unit Kokkos_Core.hpp is included first and
   MCA_INLINE becomes KOKKOS_INLINE_FUNCTION.
------------------------------------------------------------------------- */

#ifndef LMP_MCA_KERNELS_H
#define LMP_MCA_KERNELS_H

#include <cmath>

#ifndef MCA_INLINE
#if defined(KOKKOS_INLINE_FUNCTION)
#define MCA_INLINE KOKKOS_INLINE_FUNCTION
#else
#define MCA_INLINE inline
#endif
#endif

namespace LAMMPS_NS {
namespace MCAKernels {

  /* ----------------------------------------------------------------------
     packing of the automata = number of nearest neighbours N_c.
     The virtual cell of an automaton of radius R (half the nearest-neighbour
     distance) is the Voronoi cell of its lattice:
       sc    cube of edge 2R                    volume 8 R^3
       fcc   rhombic dodecahedron, inradius R   volume 4 sqrt(2) R^3
       hcp   trapezo-rhombic dodecahedron: same volume and face area as fcc
     An unpacked automaton (packing 0) is a sphere of radius R.
  ------------------------------------------------------------------------- */

  enum Packing { PACKING_NONE = 0, PACKING_SC = 6, PACKING_FCC = 12 };

  MCA_INLINE bool valid_packing(int packing)
  {
    return packing == PACKING_NONE || packing == PACKING_SC || packing == PACKING_FCC;
  }

  // volume of the virtual cell
  MCA_INLINE double cell_volume(int packing, double radius)
  {
    const double r3 = radius * radius * radius;
    if (packing == PACKING_SC) return 8.0 * r3;
    if (packing == PACKING_FCC) return 4.0 * 1.4142135623730951 * r3;
    return 4.0 / 3.0 * 3.14159265358979323846 * r3;
  }

  /* moment of inertia of the cell about any axis through its centre, in
     units of m R^2 (isotropic for the cube and the rhombic dodecahedron):
       cube of edge 2R:                      (2R)^2/6 = 2/3
       rhombic dodecahedron of inradius R:   1/2
       sphere:                               2/5                           */

  MCA_INLINE double inertia_factor(int packing)
  {
    if (packing == PACKING_SC) return 2.0 / 3.0;
    if (packing == PACKING_FCC) return 0.5;
    return 0.4;
  }

  MCA_INLINE double cell_inertia(int packing, double mass, double radius)
  {
    return inertia_factor(packing) * mass * radius * radius;
  }

  /* ----------------------------------------------------------------------
     rigid rotation of an orientation quaternion q = (w,x,y,z) by the
     space-frame angular velocity omega held constant over dt:
       q <- exp(dt/2 omega) * q
     This is exact for the torque-free motion of a body with isotropic
     inertia, which MCA automata are.  The result is renormalised so that
     round-off cannot accumulate into a non-unit quaternion.
  ------------------------------------------------------------------------- */

  MCA_INLINE void rotate_quaternion(double *q, const double *omega, double dt)
  {
    const double wsq = omega[0] * omega[0] + omega[1] * omega[1] + omega[2] * omega[2];
    const double half_angle_sq = 0.25 * wsq * dt * dt;
    double c, s;    // dq = (c, s*omega)
    if (half_angle_sq < 1.0e-8) {
      // Taylor series; error below 1e-24 relative
      c = 1.0 - 0.5 * half_angle_sq + half_angle_sq * half_angle_sq / 24.0;
      s = 0.5 * dt * (1.0 - half_angle_sq / 6.0 + half_angle_sq * half_angle_sq / 120.0);
    } else {
      const double w = sqrt(wsq);
      const double half_angle = 0.5 * w * dt;
      c = cos(half_angle);
      s = sin(half_angle) / w;
    }
    const double dx = s * omega[0], dy = s * omega[1], dz = s * omega[2];
    const double qw = c * q[0] - dx * q[1] - dy * q[2] - dz * q[3];
    const double qx = c * q[1] + dx * q[0] + dy * q[3] - dz * q[2];
    const double qy = c * q[2] + dy * q[0] + dz * q[1] - dx * q[3];
    const double qz = c * q[3] + dz * q[0] + dx * q[2] - dy * q[1];
    const double inv = 1.0 / sqrt(qw * qw + qx * qx + qy * qy + qz * qz);
    q[0] = qw * inv;
    q[1] = qx * inv;
    q[2] = qy * inv;
    q[3] = qz * inv;
  }

  // half-step kick of velocity and angular velocity (velocity Verlet)
  MCA_INLINE void kick(double *v, double *omega, const double *f, const double *torque, double dtf,
                       double mass, double inertia)
  {
    const double dtfm = dtf / mass;
    const double dtfi = dtf / inertia;
    v[0] += dtfm * f[0];
    v[1] += dtfm * f[1];
    v[2] += dtfm * f[2];
    omega[0] += dtfi * torque[0];
    omega[1] += dtfi * torque[1];
    omega[2] += dtfi * torque[2];
  }

  // full-step drift of position and orientation
  MCA_INLINE void drift(double *x, double *q, const double *v, const double *omega, double dtv)
  {
    x[0] += dtv * v[0];
    x[1] += dtv * v[1];
    x[2] += dtv * v[2];
    rotate_quaternion(q, omega, dtv);
  }

}    // namespace MCAKernels
}    // namespace LAMMPS_NS

#endif
