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
   The pair interaction of the movable lattice particles (MLP, Popov and
   Filippov; doc/src/pair_mlp.rst), written once for pair_style mlp and
   mlp/kk: plain arithmetic on doubles (mca_inline.h).

   A pair (i, j) in 2-D, d = x_i - x_j, r = |d|, phi = arg(d):
     central part   E = s(r) U(r), U harmonic, Morse or LJ
     return force   on i: -f0 s(r) sin(n (phi - theta0)) e_phi   ("literal")
                    or the force of E = s(r) (f0 r_ref / n)
                    (1 - cos(n (phi - theta0)))              ("conservative")
   with e_phi = (-sin phi, cos phi), n = 4 or 6, s(r) a taper (1 below
   rc - w, a C2 quintic down to 0 at rc; w = 0: a plain cut).  The force
   on j is minus the force on i (n is even: evaluating the pair from j
   reverses d, keeps sin(n phi) and reverses e_phi), so linear momentum
   is conserved; angular momentum is not: the return force couples the
   lattice to the fixed directions theta0 (the method's point).
   sin and cos of n (phi - theta0) come from the complex power
   (d / r)^n e^{-i n theta0}: no atan2.
------------------------------------------------------------------------- */

#ifndef LMP_MLP_KERNELS_H
#define LMP_MLP_KERNELS_H

#include "mca_inline.h"

#include <cmath>

namespace LAMMPS_NS {
namespace MLPKernels {

  enum MLPCentral { MLP_HARMONIC = 0, MLP_MORSE = 1, MLP_LJ = 2 };
  enum MLPReturn { MLP_LITERAL = 0, MLP_CONSERVATIVE = 1 };

  // the coefficients of one type pair (plain record: copied to a device)
  struct MLPCoeff {
    int central;       // MLPCentral
    int n;             // order of the return force (4 or 6), 0: no return force
    double a, b, c;    // harmonic: K r0 -; Morse: D0 alpha r0; LJ: epsilon sigma -
    double f0;         // amplitude of the return force (force units)
    double theta0;     // direction of the lattice axes as given (degrees)
    double cos_nt0;    // cos(n theta0), sin(n theta0)
    double sin_nt0;
    double r_ref;    // equilibrium distance of U (conservative return energy)
    double cutsq;    // cutoff squared
    double cut;
    double taper_start;    // rc - w: where the taper begins (= rc: none)
  };

  // what a pair gives atom i
  struct MLPPairForce {
    double fx, fy;    // total force on i
    double rx, ry;    // its return-force part
    double energy;    // pair energy (central + conservative return)
  };

  // central potential U(r) and dU/dr
  MCA_INLINE void central_potential(const MLPCoeff &p, double r, double &u, double &du)
  {
    if (p.central == MLP_HARMONIC) {
      const double dr = r - p.b;
      u = 0.5 * p.a * dr * dr;
      du = p.a * dr;
    } else if (p.central == MLP_MORSE) {
      const double e = exp(-p.b * (r - p.c));
      u = p.a * (e * e - 2.0 * e);
      du = 2.0 * p.a * p.b * (e - e * e);
    } else {
      const double sr2 = p.b * p.b / (r * r);
      const double sr6 = sr2 * sr2 * sr2;
      u = 4.0 * p.a * (sr6 * sr6 - sr6);
      du = -24.0 * p.a * (2.0 * sr6 * sr6 - sr6) / r;
    }
  }

  // U''(r_ref): the pair's longitudinal stiffness at its equilibrium distance
  MCA_INLINE double central_stiffness(const MLPCoeff &p)
  {
    if (p.central == MLP_HARMONIC) return p.a;
    if (p.central == MLP_MORSE) return 2.0 * p.a * p.b * p.b;
    // LJ at r_ref = 2^(1/6) sigma: 72 epsilon / (2^(1/3) sigma^2)
    return 72.0 * p.a / (cbrt(2.0) * p.b * p.b);
  }

  // the taper s(r) and ds/dr: 1 below taper_start, 1 - 10t^3 + 15t^4 - 6t^5
  // on [taper_start, cut] (value, slope and curvature continuous)
  MCA_INLINE void taper(const MLPCoeff &p, double r, double &s, double &ds)
  {
    if (r <= p.taper_start) {
      s = 1.0;
      ds = 0.0;
      return;
    }
    const double w = p.cut - p.taper_start;
    const double t = (r - p.taper_start) / w;
    s = 1.0 - t * t * t * (10.0 - 15.0 * t + 6.0 * t * t);
    ds = -30.0 * t * t * (1.0 - t) * (1.0 - t) / w;
  }

  // z^n of a unit complex number z = (re, im), n = 4 or 6 (z^2, z^4, z^6)
  MCA_INLINE void unit_power(int n, double zr, double zi, double &re, double &im)
  {
    const double re2 = zr * zr - zi * zi, im2 = 2.0 * zr * zi;
    re = re2 * re2 - im2 * im2;
    im = 2.0 * re2 * im2;
    if (n == 6) {
      const double re6 = re * re2 - im * im2;
      im = re * im2 + im * re2;
      re = re6;
    }
  }

  // sin and cos of n (phi - theta) for the unit vector (ux, uy) = d / r,
  // with (cos_nt, sin_nt) = (cos n theta, sin n theta) of the pair's axes
  MCA_INLINE void return_angle(const MLPCoeff &p, double ux, double uy, double cos_nt,
                               double sin_nt, double &sn, double &cn)
  {
    double re, im;
    unit_power(p.n, ux, uy, re, im);
    // times e^{-i n theta}
    cn = re * cos_nt + im * sin_nt;
    sn = im * cos_nt - re * sin_nt;
  }

  // a body's lattice frame: each atom carries (cos a/2, sin a/2) of the
  // angle a its body has turned (fix mlp/frame); a pair's axes turn by the
  // mean (a_i + a_j)/2, i.e. e^{i n theta} becomes e^{i n theta0} (z_i z_j)^n.
  // For the even n of the style the two means of a pair of angles, which
  // differ by pi, give the same axes, so the angles need no unwrapping
  MCA_INLINE void turned_axes(const MLPCoeff &p, double ci, double si, double cj, double sj,
                              double &cos_nt, double &sin_nt)
  {
    double re, im;
    unit_power(p.n, ci * cj - si * sj, ci * sj + si * cj, re, im);
    cos_nt = p.cos_nt0 * re - p.sin_nt0 * im;
    sin_nt = p.sin_nt0 * re + p.cos_nt0 * im;
  }

  // the force of pair (i, j) on i, d = x_i - x_j, rsq = |d|^2 < cutsq;
  // factor: the special-bond factor; (cos_nt, sin_nt): the pair's axes
  MCA_INLINE MLPPairForce pair_force(const MLPCoeff &p, int return_style, double dx, double dy,
                                     double rsq, double factor, double cos_nt, double sin_nt)
  {
    MLPPairForce out;
    const double r = sqrt(rsq);
    const double ux = dx / r, uy = dy / r;
    double u, du, s, ds;
    central_potential(p, r, u, du);
    taper(p, r, s, ds);
    // radial force on i (along +d) and tangential one (along e_phi)
    double radial = -(s * du + ds * u);
    double tangential = 0.0, e_return = 0.0, radial_return = 0.0;
    if (p.n > 0 && p.f0 != 0.0) {
      double sn, cn;
      return_angle(p, ux, uy, cos_nt, sin_nt, sn, cn);
      if (return_style == MLP_LITERAL) {
        tangential = -p.f0 * s * sn;
      } else {
        const double v = p.f0 * p.r_ref / p.n * (1.0 - cn);
        e_return = s * v;
        radial_return = -ds * v;
        // -(1/r) dE/dphi, dV/dphi = f0 r_ref sin
        tangential = -s * p.f0 * p.r_ref / r * sn;
      }
    }
    radial += radial_return;
    out.rx = factor * (radial_return * ux - tangential * uy);
    out.ry = factor * (radial_return * uy + tangential * ux);
    out.fx = factor * (radial * ux - tangential * uy);
    out.fy = factor * (radial * uy + tangential * ux);
    out.energy = factor * (s * u + e_return);
    return out;
  }

  /* --------------------------------------------------------------------
     the stable time step (doc/src/pair_mlp.rst, "Stable time step"):
     Gershgorin's bound of the fastest mode, omega^2 <= max over rows r of
     sum_c |S_rc|, S = M^-1/2 K M^-1/2, K = -dF/dx the pairs' stiffness at
     the present positions (and lattice axes).  The pair force on i is a
     function of d = x_i - x_j alone, so K_ij = J and K_ii = -sum_j J with
     J = df_i/dd; the row sums of atom i come from its own (full) list
  -------------------------------------------------------------------- */

  // U''(r)
  MCA_INLINE double central_curvature(const MLPCoeff &p, double r)
  {
    if (p.central == MLP_HARMONIC) return p.a;
    if (p.central == MLP_MORSE) {
      const double e = exp(-p.b * (r - p.c));
      return 2.0 * p.a * p.b * p.b * (2.0 * e * e - e);
    }
    const double sr2 = p.b * p.b / (r * r);
    const double sr6 = sr2 * sr2 * sr2;
    return 24.0 * p.a * (26.0 * sr6 * sr6 - 7.0 * sr6) / (r * r);
  }

  // s''(r) of the taper
  MCA_INLINE double taper_curvature(const MLPCoeff &p, double r)
  {
    if (r <= p.taper_start) return 0.0;
    const double w = p.cut - p.taper_start;
    const double t = (r - p.taper_start) / w;
    return -60.0 * t * (1.0 - t) * (1.0 - 2.0 * t) / (w * w);
  }

  // J = df_i/dd of pair_force (row-major 2x2).  With f = F_r u + F_t e_phi
  // (u = d/r, e_phi = (-u_y, u_x)), in the basis (u, e_phi):
  //   J_uu = dF_r/dr          J_ue = (dF_r/dphi - F_t) / r
  //   J_eu = dF_t/dr          J_ee = (F_r + dF_t/dphi) / r
  // (symmetric for the conservative variant: the Hessian of -E)
  MCA_INLINE void pair_jacobian(const MLPCoeff &p, int return_style, double dx, double dy,
                                double rsq, double factor, double cos_nt, double sin_nt,
                                double *jac)
  {
    const double r = sqrt(rsq);
    const double ux = dx / r, uy = dy / r;
    double u, du, s, ds;
    central_potential(p, r, u, du);
    taper(p, r, s, ds);
    const double dds = taper_curvature(p, r);
    double fr = -(s * du + ds * u);
    double dfr_dr = -(s * central_curvature(p, r) + 2.0 * ds * du + dds * u);
    double dfr_dphi = 0.0, ft = 0.0, dft_dr = 0.0, dft_dphi = 0.0;
    if (p.n > 0 && p.f0 != 0.0) {
      double sn, cn;
      return_angle(p, ux, uy, cos_nt, sin_nt, sn, cn);
      if (return_style == MLP_LITERAL) {
        ft = -p.f0 * s * sn;
        dft_dr = -p.f0 * ds * sn;
        dft_dphi = -p.f0 * s * p.n * cn;
      } else {
        const double v = p.f0 * p.r_ref / p.n * (1.0 - cn), dv = p.f0 * p.r_ref * sn;
        fr -= ds * v;
        dfr_dr -= dds * v;
        dfr_dphi = -ds * dv;
        ft = -s * dv / r;
        dft_dr = -dv * (ds / r - s / rsq);
        dft_dphi = -s * p.f0 * p.r_ref * p.n * cn / r;
      }
    }
    const double juu = dfr_dr, jue = (dfr_dphi - ft) / r;
    const double jeu = dft_dr, jee = (fr + dft_dphi) / r;
    // R [[juu, jue], [jeu, jee]] R^T with R = [u e_phi]
    const double m00 = ux * juu - uy * jeu, m01 = ux * jue - uy * jee;
    const double m10 = uy * juu + ux * jeu, m11 = uy * jue + ux * jee;
    jac[0] = factor * (m00 * ux - m01 * uy);
    jac[1] = factor * (m00 * uy + m01 * ux);
    jac[2] = factor * (m10 * ux - m11 * uy);
    jac[3] = factor * (m10 * uy + m11 * ux);
  }

  // the row sums of one atom: the diagonal block sum_j J (its absolute
  // values are taken at the end) and sum_j |J_rc| / sqrt(m_j) per row
  struct MLPRowSums {
    double diag[4];
    double off[2];
  };

  MCA_INLINE void gershgorin_clear(MLPRowSums &g)
  {
    for (int k = 0; k < 4; k++) g.diag[k] = 0.0;
    g.off[0] = g.off[1] = 0.0;
  }

  MCA_INLINE void gershgorin_add(const double *jac, double inv_sqrt_mass_j, MLPRowSums &g)
  {
    for (int k = 0; k < 4; k++) g.diag[k] += jac[k];
    g.off[0] += (fabs(jac[0]) + fabs(jac[1])) * inv_sqrt_mass_j;
    g.off[1] += (fabs(jac[2]) + fabs(jac[3])) * inv_sqrt_mass_j;
  }

  // the bound of omega^2 from atom i's rows
  MCA_INLINE double gershgorin_bound(const MLPRowSums &g, double mass_i)
  {
    const double inv_sqrt = 1.0 / sqrt(mass_i);
    const double row0 = (fabs(g.diag[0]) + fabs(g.diag[1])) / mass_i + g.off[0] * inv_sqrt;
    const double row1 = (fabs(g.diag[2]) + fabs(g.diag[3])) / mass_i + g.off[1] * inv_sqrt;
    return row0 > row1 ? row0 : row1;
  }

  // the body of an atom in a lattice frame (fix mlp/frame): its group's one
  // body, or its molecule's (IDs 1 to nbody); -1: none (its axes stay put)
  MCA_INLINE int frame_body(int mask, int groupbit, int by_molecule, long long molecule, int nbody)
  {
    if (!(mask & groupbit)) return -1;
    if (!by_molecule) return 0;
    return (molecule >= 1 && molecule <= nbody) ? static_cast<int>(molecule - 1) : -1;
  }

  /* --------------------------------------------------------------------
     the compensating surface force (fix mlp/traction; doc/src/
     fix_mlp_traction.rst, digest B.4 (c)).  The return force's transverse
     spring k1 carries the null Lagrangian kappa det(grad u) (kappa =
     sqrt3 k1 on the hex lattice), which adds nothing in the bulk but the
     traction -kappa cof(grad u) n on a free surface.  An atom short of
     lattice neighbours gets it back: f_i = cof(A_i) S_i, with A_i its
     displacement gradient and S_i = sum over its missing bonds of (k1 c) e
     = -sum over its present ones of (k1 r) e_ij (e_ij from i towards j;
     kappa l n of the surface it carries: on a close-packed facet of the
     hex lattice l = c, its spacing).  For a rigid rotation this is the
     return force of each missing bond to first order, so a turned body
     feels no torque
  -------------------------------------------------------------------- */

  // (k1 r) of a pair at distance r: the transverse stiffness of its
  // return force, d F_t / d(r dphi), times r: n f0 s(r) (literal) or
  // n f0 s(r) r_ref / r (conservative)
  MCA_INLINE double return_stiffness_length(const MLPCoeff &p, int return_style, double r)
  {
    if (p.n == 0 || p.f0 == 0.0) return 0.0;
    double s, ds;
    taper(p, r, s, ds);
    const double k1r = p.n * p.f0 * s;
    return return_style == MLP_LITERAL ? k1r : k1r * p.r_ref / r;
  }

  // the least-squares deformation gradient F = B C^-1 (row-major 2x2) of
  // the neighbour vectors x_ij (now) and X_ij (reference), B = sum x X^T,
  // C = sum X X^T; false if the X_ij do not span the plane
  MCA_INLINE bool least_squares_gradient(const double *B, const double *C, double *F)
  {
    const double det = C[0] * C[3] - C[1] * C[2];
    const double trace = C[0] + C[3];
    if (!(det > 1.0e-6 * trace * trace)) return false;
    const double i00 = C[3] / det, i01 = -C[1] / det, i10 = -C[2] / det, i11 = C[0] / det;
    F[0] = B[0] * i00 + B[1] * i10;
    F[1] = B[0] * i01 + B[1] * i11;
    F[2] = B[2] * i00 + B[3] * i10;
    F[3] = B[2] * i01 + B[3] * i11;
    return true;
  }

  // the compensating force R cof(R^T F - I) S of an atom whose lattice
  // frame has turned by a, (ca, sa) = (cos a, sin a); S in the reference.
  // cof of a 2x2 A is [[A11, -A10], [-A01, A00]]
  MCA_INLINE void surface_compensation(const double *F, double ca, double sa, double sx, double sy,
                                       double &fx, double &fy)
  {
    // A = R^T F - I
    const double a00 = ca * F[0] + sa * F[2] - 1.0, a01 = ca * F[1] + sa * F[3];
    const double a10 = -sa * F[0] + ca * F[2], a11 = -sa * F[1] + ca * F[3] - 1.0;
    const double gx = a11 * sx - a10 * sy, gy = -a01 * sx + a00 * sy;
    fx = ca * gx - sa * gy;
    fy = sa * gx + ca * gy;
  }

  // the compensating force of the surface atom i, entry m of a plan: the
  // local indices of its lattice neighbours partner(m, k) (closest images),
  // ref(m, .) = S (2), their count, then X_ij (2 per neighbour); x(j, d) the
  // positions; (ca, sa) its frame's turn.  False: no gradient
  template <class Positions, class Partners, class Refs>
  MCA_INLINE bool surface_force(const Positions &x, const Partners &partner, const Refs &ref, int m,
                                int i, double ca, double sa, double &fx, double &fy)
  {
    double B[4] = {0.0, 0.0, 0.0, 0.0}, C[4] = {0.0, 0.0, 0.0, 0.0}, F[4];
    const double xi = x(i, 0), yi = x(i, 1);
    const int count = static_cast<int>(ref(m, 2));
    for (int k = 0; k < count; k++) {
      const int j = partner(m, k);
      const double dx = x(j, 0) - xi, dy = x(j, 1) - yi;
      const double X = ref(m, 3 + 2 * k), Y = ref(m, 4 + 2 * k);
      B[0] += dx * X;
      B[1] += dx * Y;
      B[2] += dy * X;
      B[3] += dy * Y;
      C[0] += X * X;
      C[1] += X * Y;
      C[3] += Y * Y;
    }
    C[2] = C[1];
    if (!least_squares_gradient(B, C, F)) return false;
    surface_compensation(F, ca, sa, ref(m, 0), ref(m, 1), fx, fy);
    return true;
  }

  // ... with the axes of the type pair (no lattice frame)
  MCA_INLINE MLPPairForce pair_force(const MLPCoeff &p, int return_style, double dx, double dy,
                                     double rsq, double factor)
  {
    return pair_force(p, return_style, dx, dy, rsq, factor, p.cos_nt0, p.sin_nt0);
  }

}    // namespace MLPKernels
}    // namespace LAMMPS_NS

#endif
