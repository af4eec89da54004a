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

   3-D: the 12 x 12 frame element (axial EA/L0, torsion GJ/L0, bending
   about the section's y and z axes with I_y and I_z) in the same total
   co-rotational form.  The section's axes y, z, normal to the chord,
   are fixed in each particle's body frame when the bond is first seen
   (stored in both particles' frames: y_i, z_i, y_j, z_j, which coincide
   at rest and under any rigid motion; x = y x z is the chord at rest).
   The ends' turns relative to the chord e = d / L and the twist of j
   against i are measured by
     about z:  a_i = -2 e.y_i / (1 + e.x_i),   about y:  c_i = 2 e.z_i / (1 + e.x_i)
     (and a_j, c_j),   twist:  p = 2 S / (1 + C),
     S = (z_i.y_j - y_i.z_j) / 2,  C = (y_i.y_j + z_i.z_j) / 2,
   in a plane 2 tan(q / 2) of the angle q (the angles to third order;
   monotone up to a half turn, where the energy grows without bound), so
     E = EA u^2 / (2 L0) + GJ p^2 / (2 L0)
         + [own_z (a_i^2 + a_j^2) + 2 cross_z a_i a_j] / 2   (own, cross: as
         + [own_y (c_i^2 + c_j^2) + 2 cross_y c_i c_j] / 2    in 2-D, I_z, I_y)
   depends on dot products of vectors that turn together under a rigid
   motion only (zero force for any rigid motion), its linearisation is the
   12 x 12 element (nodally exact: a cantilever of any number of elements
   gives PL^3/3EI), and forces and torques are its exact gradient
   (frame_state, frame_loads below).  In a planar motion the 3-D element
   is the 2-D one with 2 tan(q / 2) in place of q.
------------------------------------------------------------------------- */

#ifndef LMP_BEAM_KERNELS_H
#define LMP_BEAM_KERNELS_H

#include "mca_geometry.h"
#include "mca_inline.h"

#include <cmath>

namespace LAMMPS_NS {
namespace BeamKernels {

  using MCAKernels::cross3;
  using MCAKernels::dot3;
  using MCAKernels::virial_terms;    // of a bond: its force on j, d = x_j - x_i

  enum BeamScatter { SCATTER_NONE = 0, SCATTER_UNIFORM = 1, SCATTER_WEIBULL = 2 };

  // stochastic melting (keyword melt): a constant rate, or Glen's law
  enum BeamMelt { MELT_NONE = 0, MELT_RATE = 1, MELT_GLEN = 2 };

  // the end moments of a bond: the Euler-Bernoulli beam, or the shear
  // beam of NUMFRAC's ice lattices (digest A.4): a normal spring k_n and a
  // rotational spring k_r at each end, M_i = k_r q_i, M_j = k_r q_j
  enum BeamModel { MODEL_BEAM = 0, MODEL_SPRINGS = 1 };

  // the section and strength of one bond type (plain record: copied to a device)
  struct BeamCoeff {
    int model;           // BeamModel
    double kn, kr;       // springs: normal and rotational stiffness
    double kt;           // springs in 3-D: torsional stiffness
    double E, A, I;      // Young's modulus, area, second moment of area (springs: A = I = 1)
    double Iy, Iz, J;    // 3-D section: bending about its y and z axes, torsion
    double G, ks;        // shear modulus; shear coefficient (0: Euler-Bernoulli)
    double nu;           // Poisson's ratio when G was given as E / (2 (1 + nu))
    int G_from_nu;
    double EA, EI, EIy, EIz, GJ;
    double shear, shear_y, shear_z;    // 12 EI / (ks G A): Phi = shear / L0^2
    double beta;                       // stiffness-proportional damping: time constant (0: none)
    int breakable;                     // 1: the elliptic criterion below
    int mohr;                          // 1: Mohr-Coulomb branch in compression
    double sigma0;                     // tensile strength
    double tau0;                       // shear strength
    double fibre;                      // distance of the outer fibre (0: no bending stress)
    double tan_phi;                    // friction of the Mohr-Coulomb branch
    double phi_deg;                    // its angle as given (degrees)
    int scatter;                       // BeamScatter of the strengths from bond to bond
    int seed;
    double scatter_width;    // uniform: half width; Weibull: modulus m
    int radii;               // 1: the section from the particles' radii (radii_section)
    int fibre_rim;           // 1: the outer fibre at the rim of that section
    double lambda;           // its radius over the smaller particle radius
    int particle;            // 1: broken by its particles' averaged stress (particle_measure)
    int melt;                // BeamMelt: stochastic melting (melts)
    double melt_value;       // MELT_RATE: the rate lambda; MELT_GLEN: Glen's factor A
    int melt_seed;
    double capture;    // refreeze: a melted bond this short re-forms stress-free (0: breaks)
  };

  // the reference state of a bond, in the order lower atom ID first.
  // 2-D: L0 and the chord direction seen from each particle; 3-D: L0 and
  // the section's y and z axes in each particle's body frame
  enum {
    REF_L0 = 0,
    REF_BI = 1,    // 2-D
    REF_BJ = 2,
    NREF_2D = 3,
    REF_YI = 1,    // 3-D
    REF_ZI = 4,
    REF_YJ = 7,
    REF_ZJ = 10,
    NREF_3D = 13
  };

  MCA_INLINE int nref(const int dimension)
  {
    return dimension == 3 ? NREF_3D : NREF_2D;
  }

  // what the 2-D element gives
  struct BeamForce {
    double fx, fy;          // force on j (on i: the opposite)
    double ti, tj;          // torques (about z) on i and on j
    double energy;          // elastic energy of the element
    double N, V, Mi, Mj;    // axial and shear force, end moments
  };

  // what the 3-D element gives
  struct BeamForce3D {
    double f[3];            // force on j (on i: the opposite)
    double ti[3], tj[3];    // torques on i and on j
    double energy;          // elastic energy of the element
    double N, V, T;         // axial force, size of the shear force, twisting moment
    double bend;            // the larger end's sqrt((M_y / I_y)^2 + (M_z / I_z)^2)
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

  // v from a particle's body frame to space (q: body to space), and back
  MCA_INLINE void to_space(const double *q, const double *v, double *out)
  {
    // v + 2 w (u x v) + 2 u x (u x v), u = (q1, q2, q3)
    const double t0 = 2.0 * (q[2] * v[2] - q[3] * v[1]);
    const double t1 = 2.0 * (q[3] * v[0] - q[1] * v[2]);
    const double t2 = 2.0 * (q[1] * v[1] - q[2] * v[0]);
    out[0] = v[0] + q[0] * t0 + q[2] * t2 - q[3] * t1;
    out[1] = v[1] + q[0] * t1 + q[3] * t0 - q[1] * t2;
    out[2] = v[2] + q[0] * t2 + q[1] * t1 - q[2] * t0;
  }

  MCA_INLINE void to_body(const double *q, const double *v, double *out)
  {
    const double conj[4] = {q[0], -q[1], -q[2], -q[3]};
    to_space(conj, v, out);
  }

  MCA_INLINE void set_coeff(BeamCoeff &c)
  {
    c.EA = c.E * c.A;
    c.EI = c.E * c.I;
    c.EIy = c.E * c.Iy;
    c.EIz = c.E * c.Iz;
    c.GJ = c.G * c.J;
    c.shear = (c.ks > 0.0) ? 12.0 * c.EI / (c.ks * c.G * c.A) : 0.0;
    c.shear_y = (c.ks > 0.0) ? 12.0 * c.EIy / (c.ks * c.G * c.A) : 0.0;
    c.shear_z = (c.ks > 0.0) ? 12.0 * c.EIz / (c.ks * c.G * c.A) : 0.0;
  }

  /* --------------------------------------------------------------------
     keyword radii lambda: each bond's section from its particles' radii,
     R = lambda min(r_i, r_j) (the contact's radius; min: a small particle
     holds a thin beam whatever its neighbour):
       3-D  a round section of radius R:  A = pi R^2, I_y = I_z = pi R^4 / 4,
            J = pi R^4 / 2;
       2-D  a beam of height h = 2R per unit thickness:  A = h, I = h^3 / 12
            (lambda = h / L for touching particles of one radius);
     the outer fibre at R with bending rim.  sized: the type's record with
     the section of this bond (E, G, ks, strengths as the type's)
  -------------------------------------------------------------------- */

  MCA_INLINE void radii_section(BeamCoeff &c, const int dimension, const double ri, const double rj)
  {
    const double R = c.lambda * (ri < rj ? ri : rj);
    if (dimension == 3) {
      c.A = M_PI * R * R;
      c.I = c.Iy = c.Iz = 0.25 * M_PI * R * R * R * R;
      c.J = 2.0 * c.I;
    } else {
      c.A = 2.0 * R;
      c.I = c.Iy = c.Iz = 8.0 * R * R * R / 12.0;
      c.J = 2.0 * c.I;
    }
    if (c.fibre_rim) c.fibre = R;
    set_coeff(c);
  }

  // the record a bond uses: its type's, or with radii a copy in sized
  // with the bond's own section (only bonds of such types pay for it)
  MCA_INLINE const BeamCoeff &bond_coeff(const BeamCoeff &type_coeff, const int dimension,
                                         const double ri, const double rj, BeamCoeff &sized)
  {
    if (!type_coeff.radii) return type_coeff;
    sized = type_coeff;
    radii_section(sized, dimension, ri, rj);
    return sized;
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

  // 3-D: the section's z axis is particle i's body z axis made normal to
  // the chord, or its body x axis if the bond is within 45 degrees of body
  // z (a projection of at least 0.7: well conditioned); y = z x e.
  // (Quaternions of unit length, as the integrators and mca_set keep them.)
  MCA_INLINE void reference_state_3d(const double *d, const double *qi, const double *qj,
                                     double *ref)
  {
    const double L = sqrt(dot3(d, d));
    const double e[3] = {d[0] / L, d[1] / L, d[2] / L};
    const double body_z[3] = {0.0, 0.0, 1.0}, body_x[3] = {1.0, 0.0, 0.0};
    double axis[3], z[3], y[3];
    to_space(qi, body_z, axis);
    if (fabs(dot3(axis, e)) > 0.70710678118654752) to_space(qi, body_x, axis);
    const double along = dot3(axis, e);
    for (int k = 0; k < 3; k++) z[k] = axis[k] - along * e[k];
    const double size = sqrt(dot3(z, z));
    for (int k = 0; k < 3; k++) z[k] /= size;
    cross3(z, e, y);
    ref[REF_L0] = L;
    to_body(qi, y, ref + REF_YI);
    to_body(qi, z, ref + REF_ZI);
    to_body(qj, y, ref + REF_YJ);
    to_body(qj, z, ref + REF_ZJ);
  }

  // a stress-free reference state of either dimension (d = x_j - x_i, i
  // the lower atom ID): a new bond, or a melted one that freezes again
  MCA_INLINE void fresh_reference(const int dimension, const double *d, const double *qi,
                                  const double *qj, double *ref)
  {
    if (dimension == 3)
      reference_state_3d(d, qi, qj, ref);
    else
      reference_state(d[0], d[1], planar_angle(qi[0], qi[3]), planar_angle(qj[0], qj[3]), ref);
  }

  // the bending stiffness of a bond of reference length L0 in one plane
  // (EI, shear = 12 EI / (ks G A)): M_i = own q_i + cross q_j,
  // M_j = cross q_i + own q_j; the shear beam: M = k_r q at each end
  MCA_INLINE void bending_stiffness(const BeamCoeff &c, const double EI, const double shear,
                                    const double L0, double &own, double &cross)
  {
    if (c.model == MODEL_SPRINGS) {
      own = c.kr;
      cross = 0.0;
      return;
    }
    const double phi = shear / (L0 * L0);
    const double k = EI / (L0 * (1.0 + phi));
    own = k * (4.0 + phi);
    cross = k * (2.0 - phi);
  }

  MCA_INLINE double axial_stiffness(const BeamCoeff &c, const double L0)
  {
    return (c.model == MODEL_SPRINGS) ? c.kn : c.EA / L0;
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
    const double axial = axial_stiffness(c, L0);
    double own, cross;
    bending_stiffness(c, c.EI, c.shear, L0, own, cross);
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

  MCA_INLINE double torsion_stiffness(const BeamCoeff &c, const double L0)
  {
    return (c.model == MODEL_SPRINGS) ? c.kt : c.GJ / L0;
  }

  /* --------------------------------------------------------------------
     a 3-D element now: the chord e, L, the measures of the ends' turns
     and of the twist, and their gradients (see the top of the file):
       a_i = -2 e.y_i / (1 + e.x_i),  c_i = 2 e.z_i / (1 + e.x_i)
     (x_i = y_i x z_i; the same for j), p = 2 S / (1 + C) with
     S = (z_i.y_j - y_i.z_j) / 2, C = (y_i.y_j + z_i.z_j) / 2.
     A measure m of one end depends on e and that end's axes through dot
     products with e only, so a turn w of the particle changes it as
     turning e by -w would: dm/dw = (dm/de) x e.  dp/dw_j = -dp/dw_i.
  -------------------------------------------------------------------- */

  struct FrameState {
    double L, e[3];
    double ai, aj, ci, cj, p;    // the measures
    double gai[3], gaj[3];       // their gradients by e
    double gci[3], gcj[3];
    double gp[3];    // dp / d(turn of i)
  };

  // one end: the measures a (about z), c (about y) and their gradients by e
  MCA_INLINE void end_measures(const double *e, const double *y, const double *z, double &a,
                               double &c, double *ga, double *gc)
  {
    double x[3];
    cross3(y, z, x);
    const double sy = dot3(e, y), sz = dot3(e, z);
    const double inv = 1.0 / (1.0 + dot3(e, x));
    a = -2.0 * sy * inv;
    c = 2.0 * sz * inv;
    for (int k = 0; k < 3; k++) {
      ga[k] = -2.0 * inv * (y[k] + 0.5 * a * x[k]);
      gc[k] = 2.0 * inv * (z[k] - 0.5 * c * x[k]);
    }
  }

  MCA_INLINE FrameState frame_state(const double *ref, const double *d, const double *qi,
                                    const double *qj)
  {
    FrameState st;
    st.L = sqrt(dot3(d, d));
    for (int k = 0; k < 3; k++) st.e[k] = d[k] / st.L;
    double yi[3], zi[3], yj[3], zj[3];
    to_space(qi, ref + REF_YI, yi);
    to_space(qi, ref + REF_ZI, zi);
    to_space(qj, ref + REF_YJ, yj);
    to_space(qj, ref + REF_ZJ, zj);
    end_measures(st.e, yi, zi, st.ai, st.ci, st.gai, st.gci);
    end_measures(st.e, yj, zj, st.aj, st.cj, st.gaj, st.gcj);
    // twist: dS/dw_i = (z_i x y_j - y_i x z_j) / 2, dC/dw_i = (y_i x y_j + z_i x z_j) / 2
    const double S = 0.5 * (dot3(zi, yj) - dot3(yi, zj));
    const double inv = 1.0 / (1.0 + 0.5 * (dot3(yi, yj) + dot3(zi, zj)));
    st.p = 2.0 * S * inv;
    double zy[3], yz[3], yy[3], zz[3];
    cross3(zi, yj, zy);
    cross3(yi, zj, yz);
    cross3(yi, yj, yy);
    cross3(zi, zj, zz);
    for (int k = 0; k < 3; k++) st.gp[k] = inv * ((zy[k] - yz[k]) - 0.5 * st.p * (yy[k] + zz[k]));
    return st;
  }

  // the force on j and the torques of the generalised loads (the energy's
  // derivatives by the measures) N (axial u), T (p), M_iz, M_jz (a_i, a_j),
  // M_iy, M_jy (c_i, c_j): with g_i = M_iz ga_i + M_iy gc_i, g_j likewise,
  // f_j = -(N e + P (g_i + g_j) / L) (P: normal to e), t_i = -g_i x e - T gp,
  // t_j = -g_j x e + T gp; returns the shear force's size |P (g_i + g_j)| / L
  MCA_INLINE double frame_loads(const FrameState &st, const double N, const double T,
                                const double Miz, const double Mjz, const double Miy,
                                const double Mjy, double *f, double *ti, double *tj)
  {
    double gi[3], gj[3], shear[3];
    for (int k = 0; k < 3; k++) {
      gi[k] = Miz * st.gai[k] + Miy * st.gci[k];
      gj[k] = Mjz * st.gaj[k] + Mjy * st.gcj[k];
      shear[k] = gi[k] + gj[k];
    }
    const double along = dot3(shear, st.e);
    for (int k = 0; k < 3; k++) {
      shear[k] = (shear[k] - along * st.e[k]) / st.L;
      f[k] = -(N * st.e[k] + shear[k]);
    }
    double ge[3];
    cross3(gi, st.e, ge);
    for (int k = 0; k < 3; k++) ti[k] = -ge[k] - T * st.gp[k];
    cross3(gj, st.e, ge);
    for (int k = 0; k < 3; k++) tj[k] = -ge[k] + T * st.gp[k];
    return sqrt(dot3(shear, shear));
  }

  MCA_INLINE BeamForce3D beam_force_3d(const BeamCoeff &c, const double *ref, const FrameState &st)
  {
    BeamForce3D out;
    const double L0 = ref[REF_L0];
    const double u = st.L - L0;
    double own_z, cross_z, own_y, cross_y;
    bending_stiffness(c, c.EIz, c.shear_z, L0, own_z, cross_z);
    bending_stiffness(c, c.EIy, c.shear_y, L0, own_y, cross_y);
    const double Miz = own_z * st.ai + cross_z * st.aj, Mjz = cross_z * st.ai + own_z * st.aj;
    const double Miy = own_y * st.ci + cross_y * st.cj, Mjy = cross_y * st.ci + own_y * st.cj;
    out.N = axial_stiffness(c, L0) * u;
    out.T = torsion_stiffness(c, L0) * st.p;
    out.energy =
        0.5 * (out.N * u + st.ai * Miz + st.aj * Mjz + st.ci * Miy + st.cj * Mjy + st.p * out.T);
    out.V = frame_loads(st, out.N, out.T, Miz, Mjz, Miy, Mjy, out.f, out.ti, out.tj);
    const double bi = sqrt((Miy / c.Iy) * (Miy / c.Iy) + (Miz / c.Iz) * (Miz / c.Iz));
    const double bj = sqrt((Mjy / c.Iy) * (Mjy / c.Iy) + (Mjz / c.Iz) * (Mjz / c.Iz));
    out.bend = bi > bj ? bi : bj;
    return out;
  }

  /* --------------------------------------------------------------------
     bond damping (keyword damp beta): stiffness-proportional (Rayleigh)
     damping of the element, the elastic loads of the deformation rates
     times beta: N_d = beta k_axial du/dt, M_d = beta K dq/dt, mapped to
     forces and torques as the elastic loads are.  Each measure is
     unchanged by a rigid motion, so the damping forces form a balanced
     system (momentum and angular momentum conserved) and vanish under
     any rigid motion; their power is -beta (k_axial du^2 + dq.K.dq) <= 0.
     Adds the damping forces and torques; returns the power dissipated.
  -------------------------------------------------------------------- */

  // what the damping reads: the velocity of j relative to i, and the two
  // angular velocities (in the element's order)
  struct BeamRates {
    double w[3], oi[3], oj[3];
  };

  MCA_INLINE double planar_damping(const BeamCoeff &c, const double L0, const double dx,
                                   const double dy, const BeamRates &r, double &fx, double &fy,
                                   double &ti, double &tj)
  {
    const double L = sqrt(dx * dx + dy * dy);
    const double ex = dx / L, ey = dy / L;
    const double ud = ex * r.w[0] + ey * r.w[1];
    const double ad = (ex * r.w[1] - ey * r.w[0]) / L;    // the chord's turn
    const double qdi = r.oi[2] - ad, qdj = r.oj[2] - ad;
    double own, cross;
    bending_stiffness(c, c.EI, c.shear, L0, own, cross);
    const double Nd = c.beta * axial_stiffness(c, L0) * ud;
    const double Mdi = c.beta * (own * qdi + cross * qdj);
    const double Mdj = c.beta * (cross * qdi + own * qdj);
    const double Vd = (Mdi + Mdj) / L;
    fx += -Nd * ex - Vd * ey;
    fy += -Nd * ey + Vd * ex;
    ti -= Mdi;
    tj -= Mdj;
    return Nd * ud + Mdi * qdi + Mdj * qdj;
  }

  MCA_INLINE double frame_damping(const BeamCoeff &c, const double L0, const FrameState &st,
                                  const BeamRates &r, double *f, double *ti, double *tj)
  {
    // dm/dt of an end's measure: g . (de/dt + e x w_end), de/dt = P w / L;
    // the twist's: gp . (w_i - w_j)
    const double ud = dot3(st.e, r.w);
    double ri[3], rj[3], ew[3], dw[3];
    cross3(st.e, r.oi, ew);
    for (int k = 0; k < 3; k++) ri[k] = (r.w[k] - ud * st.e[k]) / st.L + ew[k];
    cross3(st.e, r.oj, ew);
    for (int k = 0; k < 3; k++) {
      rj[k] = (r.w[k] - ud * st.e[k]) / st.L + ew[k];
      dw[k] = r.oi[k] - r.oj[k];
    }
    const double aid = dot3(st.gai, ri), ajd = dot3(st.gaj, rj);
    const double cid = dot3(st.gci, ri), cjd = dot3(st.gcj, rj);
    const double pd = dot3(st.gp, dw);
    double own_z, cross_z, own_y, cross_y;
    bending_stiffness(c, c.EIz, c.shear_z, L0, own_z, cross_z);
    bending_stiffness(c, c.EIy, c.shear_y, L0, own_y, cross_y);
    const double Nd = c.beta * axial_stiffness(c, L0) * ud;
    const double Td = c.beta * torsion_stiffness(c, L0) * pd;
    const double Mizd = c.beta * (own_z * aid + cross_z * ajd);
    const double Mjzd = c.beta * (cross_z * aid + own_z * ajd);
    const double Miyd = c.beta * (own_y * cid + cross_y * cjd);
    const double Mjyd = c.beta * (cross_y * cid + own_y * cjd);
    double fd[3], tid[3], tjd[3];
    frame_loads(st, Nd, Td, Mizd, Mjzd, Miyd, Mjyd, fd, tid, tjd);
    for (int k = 0; k < 3; k++) {
      f[k] += fd[k];
      ti[k] += tid[k];
      tj[k] += tjd[k];
    }
    return Nd * ud + Td * pd + Mizd * aid + Mjzd * ajd + Miyd * cid + Mjyd * cjd;
  }

  /* --------------------------------------------------------------------
     breaking (digest A.5): the elliptic criterion
       (sigma / sigma0)^2 + (tau / tau0)^2 >= 1,
     2-D: sigma = N / A + fibre max(|M_i|, |M_j|) / I (the most stretched
     fibre), tau = |V| / A; 3-D: sigma = N / A + fibre max over the ends of
     sqrt((M_y / I_y)^2 + (M_z / I_z)^2) (exact for a round section),
     tau = |V| / A + fibre |T| / J (the torsional stress at the rim).  In
     tension only (sigma < 0 counts as 0), or with the Mohr-Coulomb branch:
     in compression tau0 grows to tau0 - sigma tan(phi) and sigma drops
     out.  strength: the bond's factor on sigma0 and tau0
  -------------------------------------------------------------------- */

  MCA_INLINE double elliptic_measure(const BeamCoeff &c, const double sigma, const double tau,
                                     const double strength)
  {
    const double s0 = strength * c.sigma0, t0 = strength * c.tau0;
    if (sigma < 0.0 && c.mohr) {
      const double t = tau / (t0 - sigma * c.tan_phi);
      return t * t;
    }
    const double s = (sigma > 0.0 ? sigma : 0.0) / s0, t = tau / t0;
    return s * s + t * t;
  }

  MCA_INLINE double break_measure(const BeamCoeff &c, const BeamForce &f, const double strength)
  {
    const double mi = fabs(f.Mi), mj = fabs(f.Mj);
    const double sigma = f.N / c.A + c.fibre * (mi > mj ? mi : mj) / c.I;
    const double tau = fabs(f.V) / c.A;
    return elliptic_measure(c, sigma, tau, strength);
  }

  MCA_INLINE double break_measure(const BeamCoeff &c, const BeamForce3D &f, const double strength)
  {
    const double sigma = f.N / c.A + c.fibre * f.bend;
    const double tau = f.V / c.A + c.fibre * fabs(f.T) / c.J;
    return elliptic_measure(c, sigma, tau, strength);
  }

  /* --------------------------------------------------------------------
     one bond of either dimension, particles i, j in the order of the
     reference: force on j, torques, energy, and whether it breaks
     (measure >= 1; 0 for a bond that cannot break: the elastic loads
     decide), with the damping forces of rates (nullptr: none) and the
     power they dissipate
  -------------------------------------------------------------------- */

  struct BeamBond {
    double f[3], ti[3], tj[3];
    double fe[3];    // the elastic part of f (the particle criterion's stress)
    double energy, measure, dissipation;
  };

  template <int DIM>
  MCA_INLINE BeamBond beam_bond(const BeamCoeff &c, const double *ref, const double *d,
                                const double *qi, const double *qj, const double strength,
                                const BeamRates *rates = nullptr)
  {
    BeamBond b;
    if (DIM == 2) {
      const BeamForce out =
          beam_force_2d(c, ref, d[0], d[1], planar_angle(qi[0], qi[3]), planar_angle(qj[0], qj[3]));
      b.f[0] = out.fx;
      b.f[1] = out.fy;
      b.f[2] = 0.0;
      b.ti[0] = b.ti[1] = b.tj[0] = b.tj[1] = 0.0;
      b.ti[2] = out.ti;
      b.tj[2] = out.tj;
      b.energy = out.energy;
      b.measure = c.breakable ? break_measure(c, out, strength) : 0.0;
      b.fe[0] = b.f[0];
      b.fe[1] = b.f[1];
      b.fe[2] = 0.0;
      b.dissipation = rates
          ? planar_damping(c, ref[REF_L0], d[0], d[1], *rates, b.f[0], b.f[1], b.ti[2], b.tj[2])
          : 0.0;
    } else {
      const FrameState st = frame_state(ref, d, qi, qj);
      const BeamForce3D out = beam_force_3d(c, ref, st);
      for (int k = 0; k < 3; k++) {
        b.f[k] = out.f[k];
        b.ti[k] = out.ti[k];
        b.tj[k] = out.tj[k];
      }
      b.energy = out.energy;
      b.measure = c.breakable ? break_measure(c, out, strength) : 0.0;
      for (int k = 0; k < 3; k++) b.fe[k] = b.f[k];
      b.dissipation = rates ? frame_damping(c, ref[REF_L0], st, *rates, b.f, b.ti, b.tj) : 0.0;
    }
    return b;
  }

  /* --------------------------------------------------------------------
     the stable time step (doc/src/bond_beam.rst, "Stable time step";
     digest R12).  The stiffness of a bond now is K = G^T H G: its
     measures m (2-D: u, q_i, q_j; 3-D: u, p, a_i, a_j, c_i, c_j), their
     gradients G by the degrees of freedom of the two ends (per end its
     DIM displacements, then its turn(s); i's end first) and H, the loads'
     derivatives by the measures (the axial, torsion and bending
     stiffness).  This is the material stiffness of the element at its
     present geometry; the geometric part (the loads times the measures'
     second derivatives) vanishes in the reference state and is left out.
     The squared angular frequencies of the lattice are the eigenvalues of
     S = M^-1/2 K M^-1/2 (M: the masses, and the moments of inertia for
     the turns), and Gershgorin's theorem bounds the largest of them by
     the largest absolute row sum of S:  omega^2 <= max_r sum_c |S_rc|.
     The block that couples a particle with itself is summed over all its
     bonds before the absolute values are taken (self: nd x nd per
     particle); a block that couples it with a partner is one bond's
     (couple: the row sums of its absolute values, nd per particle).
  -------------------------------------------------------------------- */

  enum { BEAM_MAX_MEASURES = 6, BEAM_MAX_DOF = 12 };

  struct BeamTangent {
    int nm, nd;    // measures; degrees of freedom of one end (3 in 2-D, 6 in 3-D)
    double g[BEAM_MAX_MEASURES][BEAM_MAX_DOF];
    double h[BEAM_MAX_MEASURES][BEAM_MAX_MEASURES];
  };

  MCA_INLINE int tangent_dof(const int dimension)
  {
    return dimension == 3 ? 6 : 3;
  }

  // the Gershgorin sums of one particle: self (nd x nd), then couple (nd)
  MCA_INLINE int gershgorin_size(const int dimension)
  {
    const int nd = tangent_dof(dimension);
    return nd * nd + nd;
  }

  template <int DIM>
  MCA_INLINE BeamTangent beam_tangent(const BeamCoeff &c, const double *ref, const double *d,
                                      const double *qi, const double *qj)
  {
    BeamTangent t;
    const int nd = (DIM == 3) ? 6 : 3;
    t.nd = nd;
    t.nm = (DIM == 3) ? 6 : 3;
    for (int m = 0; m < BEAM_MAX_MEASURES; m++) {
      for (int k = 0; k < BEAM_MAX_DOF; k++) t.g[m][k] = 0.0;
      for (int k = 0; k < BEAM_MAX_MEASURES; k++) t.h[m][k] = 0.0;
    }
    const double L0 = ref[REF_L0];
    const double L = sqrt(dot3(d, d));
    // u = L - L0: du/dx_j = e = -du/dx_i
    for (int k = 0; k < DIM; k++) {
      t.g[0][k] = -d[k] / L;
      t.g[0][nd + k] = d[k] / L;
    }
    t.h[0][0] = axial_stiffness(c, L0);
    if (DIM == 2) {
      // q_i = t_i + b_i - a (q_j likewise), da/dx_j = e_perp / L = -da/dx_i
      const double px = -d[1] / (L * L), py = d[0] / (L * L);
      for (int m = 1; m <= 2; m++) {
        t.g[m][0] = px;
        t.g[m][1] = py;
        t.g[m][3] = -px;
        t.g[m][4] = -py;
      }
      t.g[1][2] = 1.0;
      t.g[2][5] = 1.0;
      double own, cross;
      bending_stiffness(c, c.EI, c.shear, L0, own, cross);
      t.h[1][1] = t.h[2][2] = own;
      t.h[1][2] = t.h[2][1] = cross;
    } else {
      const FrameState st = frame_state(ref, d, qi, qj);
      // the twist p: dp/dw_i = gp = -dp/dw_j
      for (int k = 0; k < 3; k++) {
        t.g[1][3 + k] = st.gp[k];
        t.g[1][nd + 3 + k] = -st.gp[k];
      }
      t.h[1][1] = torsion_stiffness(c, L0);
      // a measure of one end (gradient gm by e): dm/dx_j = (gm - (gm.e) e) / L
      // = -dm/dx_i, and dm/dw = gm x e for that end's turn
      const double *grad[4] = {st.gai, st.gaj, st.gci, st.gcj};
      for (int m = 0; m < 4; m++) {
        const double *gm = grad[m];
        const int end = (m % 2) ? nd : 0;
        const double along = dot3(gm, st.e);
        double w[3];
        cross3(gm, st.e, w);
        for (int k = 0; k < 3; k++) {
          const double dx = (gm[k] - along * st.e[k]) / st.L;
          t.g[2 + m][k] = -dx;
          t.g[2 + m][nd + k] = dx;
          t.g[2 + m][end + 3 + k] = w[k];
        }
      }
      double own_z, cross_z, own_y, cross_y;
      bending_stiffness(c, c.EIz, c.shear_z, L0, own_z, cross_z);
      bending_stiffness(c, c.EIy, c.shear_y, L0, own_y, cross_y);
      t.h[2][2] = t.h[3][3] = own_z;
      t.h[2][3] = t.h[3][2] = cross_z;
      t.h[4][4] = t.h[5][5] = own_y;
      t.h[4][5] = t.h[5][4] = cross_y;
    }
    return t;
  }

  // the reciprocal square roots of a particle's mass (its DIM
  // displacements) and moment of inertia (its turns); 0 for a particle
  // without either, which an integrator does not move
  MCA_INLINE void mass_scale(const int dimension, const double mass, const double inertia,
                             double *s)
  {
    const double st = mass > 0.0 ? 1.0 / sqrt(mass) : 0.0;
    const double sr = inertia > 0.0 ? 1.0 / sqrt(inertia) : 0.0;
    const int nd = tangent_dof(dimension);
    for (int k = 0; k < nd; k++) s[k] = (k < dimension) ? st : sr;
  }

  // adds one bond's S to its ends' sums (si, sj: mass_scale of each end;
  // sum_i or sum_j nullptr: rows this rank does not sum)
  MCA_INLINE void gershgorin_add(const BeamTangent &t, const double *si, const double *sj,
                                 double *sum_i, double *sum_j)
  {
    const int nd = t.nd, n = 2 * nd;
    double s[BEAM_MAX_DOF], hg[BEAM_MAX_MEASURES][BEAM_MAX_DOF];
    for (int k = 0; k < nd; k++) {
      s[k] = si[k];
      s[nd + k] = sj[k];
    }
    for (int m = 0; m < t.nm; m++)
      for (int c = 0; c < n; c++) {
        double v = 0.0;
        for (int l = 0; l < t.nm; l++) v += t.h[m][l] * t.g[l][c];
        hg[m][c] = v;
      }
    for (int r = 0; r < n; r++) {
      double *sum = (r < nd) ? sum_i : sum_j;
      if (!sum) continue;
      const int row = r % nd, own = (r < nd) ? 0 : nd;
      for (int c = 0; c < n; c++) {
        double k = 0.0;
        for (int m = 0; m < t.nm; m++) k += t.g[m][r] * hg[m][c];
        k *= s[r] * s[c];
        if (c >= own && c < own + nd)
          sum[row * nd + c - own] += k;
        else
          sum[nd * nd + row] += fabs(k);
      }
    }
  }

  // a particle's bound of omega^2: its largest absolute row sum
  MCA_INLINE double gershgorin_bound(const int nd, const double *sum)
  {
    double most = 0.0;
    for (int r = 0; r < nd; r++) {
      double row = sum[nd * nd + r];
      for (int c = 0; c < nd; c++) row += fabs(sum[r * nd + c]);
      most = row > most ? row : most;
    }
    return most;
  }

  // the stable time step of a mode of angular frequency omega under the
  // bonds' stiffness-proportional damping beta (damping ratio
  // zeta = beta omega / 2): velocity Verlet, whose forces read the
  // half-step velocities, is stable for omega dt < 2 (sqrt(1 + zeta^2) - zeta)
  // (2 undamped).  It falls as omega grows: a bound of omega bounds it.
  MCA_INLINE double critical_step(const double omega, const double beta)
  {
    const double zeta = 0.5 * beta * omega;
    return 2.0 * (sqrt(1.0 + zeta * zeta) - zeta) / omega;
  }

  /* --------------------------------------------------------------------
     the particle criterion (criterion particle; digest A.7): the stress of
     a particle averaged over its bonds (all of them, of any type),
       sigma = -(1/V) sym sum_b d_b (x) f_b / 2,
     d_b = x_j - x_i and f_b the bond's elastic force on j (either end
     gives the same term: the particle's share of the bond's virial, as
     compute stress/atom sums it; without damping forces, as the bonds'
     own measures), sym its symmetric part (the end moments make
     d (x) f unsymmetric), V = 4 pi r^3 / 3 (2-D: pi r^2 per unit
     thickness); tension positive.  Its mean normal stress tr(sigma) / d
     and sqrt(J2) of its deviator enter the ellipse as sigma and tau.  A
     particle that fails loses one bond: of its bonds of such types, the
     one nearest its own limit (the largest elliptic measure of the bond's
     own loads; a tie: the partner of lower ID)
  -------------------------------------------------------------------- */

  // what a particle collects during the bond loop: its virial sum (xx yy
  // zz xy xz yz, symmetric), the measure and the partner's ID of its
  // candidate bond; and what it keeps: its mean stress, sqrt(J2), the
  // candidate's partner (0: none)
  enum { PSUM_VIRIAL = 0, PSUM_MEASURE = 6, PSUM_PARTNER = 7, NPSUM = 8 };
  enum { PSTATE_SIGMA = 0, PSTATE_TAU = 1, PSTATE_PARTNER = 2, NPSTATE = 3 };

  MCA_INLINE double particle_volume(const int dimension, const double r)
  {
    return dimension == 3 ? 4.0 / 3.0 * M_PI * r * r * r : M_PI * r * r;
  }

  // the symmetric part of a bond's virial d (x) f, halved: each end's share
  MCA_INLINE void virial_share(const double *d, const double *f, double *w)
  {
    w[0] = 0.5 * d[0] * f[0];
    w[1] = 0.5 * d[1] * f[1];
    w[2] = 0.5 * d[2] * f[2];
    w[3] = 0.25 * (d[0] * f[1] + d[1] * f[0]);
    w[4] = 0.25 * (d[0] * f[2] + d[2] * f[0]);
    w[5] = 0.25 * (d[1] * f[2] + d[2] * f[1]);
  }

  // (measure, partner) is a better candidate than (best, best_partner)
  MCA_INLINE bool better_candidate(const double measure, const double partner, const double best,
                                   const double best_partner)
  {
    return measure > best || (measure == best && partner < best_partner);
  }

  // a particle's sums (PSUM_*) take the candidate (measure, partner) if it is better
  MCA_INLINE void take_candidate(double *sum, const double measure, const double partner)
  {
    if (better_candidate(measure, partner, sum[PSUM_MEASURE], sum[PSUM_PARTNER])) {
      sum[PSUM_MEASURE] = measure;
      sum[PSUM_PARTNER] = partner;
    }
  }

  // mean normal stress and sqrt(J2) of a particle of the given volume
  // from its virial sum w (xx yy zz xy xz yz)
  MCA_INLINE void particle_stress(const double *w, const int dimension, const double volume,
                                  double &sigma, double &tau)
  {
    const double sxx = -w[0] / volume, syy = -w[1] / volume;
    const double szz = dimension == 3 ? -w[2] / volume : 0.0;
    const double sxy = -w[3] / volume;
    const double sxz = dimension == 3 ? -w[4] / volume : 0.0;
    const double syz = dimension == 3 ? -w[5] / volume : 0.0;
    const double mean = (sxx + syy + szz) / dimension;
    const double dx = sxx - mean, dy = syy - mean, dz = dimension == 3 ? szz - mean : 0.0;
    sigma = mean;
    tau = sqrt(0.5 * (dx * dx + dy * dy + dz * dz) + sxy * sxy + sxz * sxz + syz * syz);
  }

  // what a bond reads of each end: the PSTATE values of the particle
  struct ParticleState {
    double sigma, tau, partner;
  };

  // whether a bond of a particle-criterion type breaks at this evaluation:
  // it is the candidate of an end whose stress (from the last evaluation)
  // is on or beyond the ellipse of the bond's type and strength
  MCA_INLINE bool particle_breaks(const BeamCoeff &c, const ParticleState &si,
                                  const ParticleState &sj, const double tag_i, const double tag_j,
                                  const double strength)
  {
    if (si.partner == tag_j && elliptic_measure(c, si.sigma, si.tau, strength) >= 1.0) return true;
    return sj.partner == tag_i && elliptic_measure(c, sj.sigma, sj.tau, strength) >= 1.0;
  }

  // the share of a bond's energy and virial summed on this rank (LAMMPS's
  // ev_tally): all with newton_bond, else half for each owned atom
  MCA_INLINE double bond_share(const int newton_bond, const int i, const int j, const int nlocal)
  {
    return newton_bond ? 1.0 : 0.5 * ((i < nlocal) + (j < nlocal));
  }

  // the random numbers of a bond: hashes of a seed and the two atom IDs
  // (and of the step), the same on every rank and in every restart, with
  // no state kept: splitmix64's finaliser over a combination of the words
  MCA_INLINE unsigned long long mix64(unsigned long long z)
  {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }

  MCA_INLINE unsigned long long bond_hash(const int seed, const long long tag_lo,
                                          const long long tag_hi)
  {
    unsigned long long z = (unsigned long long) seed * 0x9E3779B97F4A7C15ULL;
    z ^= (unsigned long long) tag_lo + 0x632BE59BD9B4E019ULL + (z << 6) + (z >> 2);
    z ^= (unsigned long long) tag_hi + 0x85157AF5ULL + (z << 6) + (z >> 2);
    return mix64(z);
  }

  // (0, 1): the middle of one of 2^53 bins (u = 0 would give a Weibull strength 0)
  MCA_INLINE double open_unit(const unsigned long long z)
  {
    return ((double) (z >> 11) + 0.5) * (1.0 / 9007199254740992.0);
  }

  // a uniform number in (0, 1) for the pair tag_lo < tag_hi at a step (a
  // bond's melting, a pair's freezing: fix beam/freeze)
  MCA_INLINE double step_draw(const int seed, const long long tag_lo, const long long tag_hi,
                              const long long step)
  {
    unsigned long long z = bond_hash(seed, tag_lo, tag_hi);
    z ^= (unsigned long long) step + 0x2545F4914F6CDD1DULL + (z << 6) + (z >> 2);
    return open_unit(mix64(z));
  }

  // the strength factor of the bond between atoms tag_lo < tag_hi, drawn
  // from the two IDs and the seed: uniform in [1 - w, 1 + w] or Weibull of
  // modulus m with mean 1
  MCA_INLINE double strength_factor(const BeamCoeff &c, const long long tag_lo,
                                    const long long tag_hi)
  {
    if (c.scatter == SCATTER_NONE) return 1.0;
    const double u = open_unit(bond_hash(c.seed, tag_lo, tag_hi));
    if (c.scatter == SCATTER_UNIFORM) return 1.0 + c.scatter_width * (2.0 * u - 1.0);
    const double m = c.scatter_width;
    return pow(-log(1.0 - u), 1.0 / m) / tgamma(1.0 + 1.0 / m);
  }

  /* --------------------------------------------------------------------
     stochastic melting and re-freezing (keywords melt, refreeze; digest
     A.8 and R4): a bond melts during a step dt with probability
       P = 1 - exp(-lambda dt),
     independently of its other steps and of the other bonds; lambda is a
     constant rate, or Glen's law of ice (n = 3),
       lambda = 2 A E^2 U / L0^d,
     U the bond's elastic energy (2-D: per unit thickness), L0 its
     reference length for the particle diameter a, d the dimension: a
     melted beam relaxes the strain sigma / E of its stress, which gives
     the flow rate D = lambda t^D / E = A sigma_e^2 t^D (U = sigma^2 a^d
     / 2E).  A melted bond freezes again at once, stress-free in its
     present geometry, if it is no longer than the capture distance;
     otherwise (or without refreeze) it is broken.  The draw is a hash of
     the seed, the two atom IDs and the step
  -------------------------------------------------------------------- */

  MCA_INLINE double melt_rate(const BeamCoeff &c, const int dimension, const double energy,
                              const double L0)
  {
    if (c.melt == MELT_RATE) return c.melt_value;
    const double a = (dimension == 3) ? L0 * L0 * L0 : L0 * L0;
    return 2.0 * c.melt_value * c.E * c.E * energy / a;
  }

  MCA_INLINE bool melts(const BeamCoeff &c, const int dimension, const double energy,
                        const double L0, const double dt, const long long step,
                        const long long tag_lo, const long long tag_hi)
  {
    const double p = -expm1(-melt_rate(c, dimension, energy, L0) * dt);
    return step_draw(c.melt_seed, tag_lo, tag_hi, step) < p;
  }

  // what melting does to a bond of a melting type at this evaluation
  enum BeamFate { FATE_KEEP = 0, FATE_BREAK = 1, FATE_REFREEZE = 2 };

  MCA_INLINE int melt_fate(const BeamCoeff &c, const int dimension, const double energy,
                           const double L0, const double *d, const double dt, const long long step,
                           const long long tag_lo, const long long tag_hi)
  {
    if (!melts(c, dimension, energy, L0, dt, step, tag_lo, tag_hi)) return FATE_KEEP;
    return (c.capture > 0.0 && dot3(d, d) <= c.capture * c.capture) ? FATE_REFREEZE : FATE_BREAK;
  }

}    // namespace BeamKernels
}    // namespace LAMMPS_NS

#endif
