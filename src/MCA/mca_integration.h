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
   Time integration of an automaton (fix nve/mca): velocity Verlet for
   translation and spin, exact rotation of the orientation quaternion.
------------------------------------------------------------------------- */

#ifndef LMP_MCA_INTEGRATION_H
#define LMP_MCA_INTEGRATION_H

#include "mca_inline.h"

#include <cmath>

namespace LAMMPS_NS {
namespace MCAKernels {

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

  // global damping of one automaton (fix mca/damping): forces proportional
  // to its mass and moment of inertia, F -= gamma m v, T -= gamma_r J omega,
  // so that every automaton's motion decays at the same rate whatever its
  // size; returns the power the damping takes out (>= 0)
  MCA_INLINE double global_damping(double gamma, double gamma_r, double mass, double inertia,
                                   const double *v, const double *omega, double *f, double *torque)
  {
    const double cv = gamma * mass, cw = gamma_r * inertia;
    double power = 0.0;
    for (int k = 0; k < 3; k++) {
      f[k] -= cv * v[k];
      torque[k] -= cw * omega[k];
      power += cv * v[k] * v[k] + cw * omega[k] * omega[k];
    }
    return power;
  }

  /* ----------------------------------------------------------------------
     NUMFRAC's damped integrator (central differences with the centred
     damping velocity, Eq. 4 of the NUMFRAC notes, digest A.6) split into
     the half steps of velocity Verlet.  With a = c dt / (2 m) (c = gamma m:
     a = gamma dt / 2) and the kick h = dt / (2 m) F:
       v(n+1/2) = (1 - a) v(n) + h(n)              before the forces
       v(n+1)   = (v(n+1/2) + h(n+1)) / (1 + a)    after them
     so that v(n+1) - v(n) = dt/m [(F(n) + F(n+1))/2 - c (v(n) + v(n+1))/2]
     and, in leapfrog form, (1 + a) v(n+1/2) = (1 - a) v(n-1/2) + dt F(n)/m:
     stable for omega dt < 2 whatever the damping.  a = 0 is velocity
     Verlet.  Both return |v|^2 at the full step they start or end at: the
     energy the damping takes out over a step, c dt (|v(n)|^2 +
     |v(n+1)|^2) / 2, is the change of the full-step kinetic energy to
     O((a)^2) (exactly c dt |(v(n) + v(n+1))/2|^2)
  ------------------------------------------------------------------------- */

  MCA_INLINE double damped_half_step(double *v, const double *f, double dtfm, double a)
  {
    double vsq = 0.0;
    for (int k = 0; k < 3; k++) {
      vsq += v[k] * v[k];
      v[k] = (1.0 - a) * v[k] + dtfm * f[k];
    }
    return vsq;
  }

  MCA_INLINE double damped_full_step(double *v, const double *f, double dtfm, double a)
  {
    const double inv = 1.0 / (1.0 + a);
    double vsq = 0.0;
    for (int k = 0; k < 3; k++) {
      v[k] = (v[k] + dtfm * f[k]) * inv;
      vsq += v[k] * v[k];
    }
    return vsq;
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
