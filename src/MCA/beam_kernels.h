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
   The beam element of the NUMFRAC lattice (digest A.3; doc/src/bond_beam.rst),
   written once for bond_style beam and beam/kk: plain arithmetic on doubles
   (mca_inline.h).

   2-D total co-rotational Euler-Bernoulli beam between particles i and j
   (orientation angles t_i, t_j), d = x_j - x_i = L (cos a, sin a).  The
   reference state, taken when the bond is first seen: L0 and the chord
   direction seen from each particle, b_i = a0 - t_i0, b_j = a0 - t_j0.
   The element's rigid turn is a - a0; what bends it is each particle's
   turn beyond it,
     q_i = wrap(t_i + b_i - a),   q_j = wrap(t_j + b_j - a),
   and with u = L - L0, k = EI / (L0 (1 + Phi)),
     N = EA u / L0,
     M_i = k ((4 + Phi) q_i + (2 - Phi) q_j),
     M_j = k ((2 - Phi) q_i + (4 + Phi) q_j),
     V = (M_i + M_j) / L                       (current length: see below)
     E = EA u^2 / (2 L0) + (q_i M_i + q_j M_j) / 2.
   Forces and torques are minus the gradient of E: on i  N e - V e_perp
   and -M_i, on j the opposite force and -M_j (e = d / L, e_perp = e turned
   by +90 degrees; da/dx_j = e_perp / L gives V with the current L), so the
   element conserves linear and angular momentum and energy, and a rigid
   motion of any size gives zero force.  Phi = 12 EI / (k_s G A L0^2) is the
   Timoshenko shear correction (0: Euler-Bernoulli).  The shear beam
   (MODEL_SPRINGS) is the same element with N = k_n u, M_i = k_r q_i,
   M_j = k_r q_j: E = k_n u^2 / 2 + k_r (q_i^2 + q_j^2) / 2.
------------------------------------------------------------------------- */

#ifndef LMP_BEAM_KERNELS_H
#define LMP_BEAM_KERNELS_H

#include "mca_inline.h"

#include <cmath>

namespace LAMMPS_NS {
namespace BeamKernels {

  enum BeamScatter { SCATTER_NONE = 0, SCATTER_UNIFORM = 1, SCATTER_WEIBULL = 2 };

  // the end moments of a bond: the Euler-Bernoulli beam, or the shear
  // beam of NUMFRAC's ice lattices (digest A.4): a normal spring k_n and a
  // rotational spring k_r at each end, M_i = k_r q_i, M_j = k_r q_j
  enum BeamModel { MODEL_BEAM = 0, MODEL_SPRINGS = 1 };

  // the section and strength of one bond type (plain record: copied to a device)
  struct BeamCoeff {
    int model;         // BeamModel
    double kn, kr;     // springs: normal and rotational stiffness
    double E, A, I;    // Young's modulus, area, second moment of area (springs: A = I = 1)
    double G, ks;      // shear modulus and shear coefficient (G = 0: Euler-Bernoulli)
    double EA, EI;
    double shear;      // 12 EI / (ks G A): Phi = shear / L0^2
    int breakable;     // 1: the elliptic criterion below
    int mohr;          // 1: Mohr-Coulomb branch in compression
    double sigma0;     // tensile strength
    double tau0;       // shear strength
    double fibre;      // distance of the outer fibre (0: no bending stress)
    double tan_phi;    // friction of the Mohr-Coulomb branch
    double phi_deg;    // its angle as given (degrees)
    int scatter;       // BeamScatter of the strengths from bond to bond
    int seed;
    double scatter_width;    // uniform: half width; Weibull: modulus m
  };

  // the reference state of a bond, in the order of the particle that stores it
  enum { REF_L0, REF_BI, REF_BJ, NREF };

  // what the element gives
  struct BeamForce {
    double fx, fy;          // force on j (on i: the opposite)
    double ti, tj;          // torques (about z) on i and on j
    double energy;          // elastic energy of the element
    double N, V, Mi, Mj;    // axial and shear force, end moments
  };

  MCA_INLINE double wrap_angle(double a)
  {
    return remainder(a, 2.0 * M_PI);
  }

  // the turn about z of an orientation quaternion (w, x, y, z): 2-D particles
  MCA_INLINE double planar_angle(const double w, const double z)
  {
    return 2.0 * atan2(z, w);
  }

  MCA_INLINE void set_coeff(BeamCoeff &c)
  {
    c.EA = c.E * c.A;
    c.EI = c.E * c.I;
    c.shear = (c.G > 0.0) ? 12.0 * c.EI / (c.ks * c.G * c.A) : 0.0;
  }

  // the reference state of a bond from the present geometry (stress-free)
  MCA_INLINE void reference_state(const double dx, const double dy, const double ti,
                                  const double tj, double *ref)
  {
    const double a = atan2(dy, dx);
    ref[REF_L0] = sqrt(dx * dx + dy * dy);
    ref[REF_BI] = wrap_angle(a - ti);
    ref[REF_BJ] = wrap_angle(a - tj);
  }

  // the stiffness of a bond of reference length L0: N = axial u,
  // M_i = own q_i + cross q_j, M_j = cross q_i + own q_j
  MCA_INLINE void end_stiffness(const BeamCoeff &c, const double L0, double &axial, double &own,
                                double &cross)
  {
    if (c.model == MODEL_SPRINGS) {
      axial = c.kn;
      own = c.kr;
      cross = 0.0;
      return;
    }
    const double phi = c.shear / (L0 * L0);
    const double k = c.EI / (L0 * (1.0 + phi));
    axial = c.EA / L0;
    own = k * (4.0 + phi);
    cross = k * (2.0 - phi);
  }

  MCA_INLINE BeamForce beam_force_2d(const BeamCoeff &c, const double *ref, const double dx,
                                     const double dy, const double ti, const double tj)
  {
    BeamForce out;
    const double L0 = ref[REF_L0];
    const double L = sqrt(dx * dx + dy * dy);
    const double ex = dx / L, ey = dy / L;
    const double a = atan2(dy, dx);
    const double qi = wrap_angle(ti + ref[REF_BI] - a);
    const double qj = wrap_angle(tj + ref[REF_BJ] - a);
    const double u = L - L0;
    double axial, own, cross;
    end_stiffness(c, L0, axial, own, cross);
    out.Mi = own * qi + cross * qj;
    out.Mj = cross * qi + own * qj;
    out.N = axial * u;
    out.V = (out.Mi + out.Mj) / L;
    out.energy = 0.5 * out.N * u + 0.5 * (qi * out.Mi + qj * out.Mj);
    // on j: -(N e - V e_perp), e_perp = (-ey, ex)
    out.fx = -out.N * ex - out.V * ey;
    out.fy = -out.N * ey + out.V * ex;
    out.ti = -out.Mi;
    out.tj = -out.Mj;
    return out;
  }

  /* --------------------------------------------------------------------
     breaking (digest A.5): the elliptic criterion
       (sigma / sigma0)^2 + (tau / tau0)^2 >= 1,
     sigma = N / A + fibre max(|M_i|, |M_j|) / I (the most stretched fibre),
     tau = |V| / A; in tension only (sigma < 0 counts as 0), or with the
     Mohr-Coulomb branch: in compression tau0 grows to tau0 - sigma tan(phi)
     and sigma drops out.  strength: the bond's factor on sigma0 and tau0
  -------------------------------------------------------------------- */

  MCA_INLINE double break_measure(const BeamCoeff &c, const BeamForce &f, const double strength)
  {
    const double mi = fabs(f.Mi), mj = fabs(f.Mj);
    const double sigma = f.N / c.A + c.fibre * (mi > mj ? mi : mj) / c.I;
    const double tau = fabs(f.V) / c.A;
    const double s0 = strength * c.sigma0, t0 = strength * c.tau0;
    if (sigma < 0.0 && c.mohr) {
      const double t = tau / (t0 - sigma * c.tan_phi);
      return t * t;
    }
    const double s = (sigma > 0.0 ? sigma : 0.0) / s0, t = tau / t0;
    return s * s + t * t;
  }

  // the strength factor of the bond between atoms tag_lo < tag_hi: a
  // function of the two IDs and the seed (the same on every rank, in every
  // restart), uniform in [1 - w, 1 + w] or Weibull of modulus m with mean 1
  MCA_INLINE double strength_factor(const BeamCoeff &c, const long long tag_lo,
                                    const long long tag_hi)
  {
    if (c.scatter == SCATTER_NONE) return 1.0;
    // splitmix64 of the seed and the two IDs
    unsigned long long z = (unsigned long long) c.seed * 0x9E3779B97F4A7C15ULL;
    z ^= (unsigned long long) tag_lo + 0x632BE59BD9B4E019ULL + (z << 6) + (z >> 2);
    z ^= (unsigned long long) tag_hi + 0x85157AF5ULL + (z << 6) + (z >> 2);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    // (0, 1): the middle of one of 2^53 bins (u = 0 would give a Weibull strength 0)
    const double u = ((double) (z >> 11) + 0.5) * (1.0 / 9007199254740992.0);
    if (c.scatter == SCATTER_UNIFORM) return 1.0 + c.scatter_width * (2.0 * u - 1.0);
    const double m = c.scatter_width;
    return pow(-log(1.0 - u), 1.0 / m) / tgamma(1.0 + 1.0 / m);
  }

}    // namespace BeamKernels
}    // namespace LAMMPS_NS

#endif
