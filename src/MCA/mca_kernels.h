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

// internal linkage: the kernels are inlined and never called through the
// procedure linkage table of the shared library
#ifndef MCA_INLINE
#if defined(KOKKOS_INLINE_FUNCTION)
#define MCA_INLINE static KOKKOS_INLINE_FUNCTION
#else
#define MCA_INLINE static inline
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

  /* a velocity component of a grip (fix mca/setvelocity): the force that
     acted on it is the reaction (returned); a prescribed component then
     moves at the target velocity and its force is removed, so that the
     time integrator keeps it there                                       */

  MCA_INLINE double prescribe_velocity(bool prescribed, double target, double &v, double &f)
  {
    const double reaction = f;
    if (prescribed) {
      v = target;
      f = 0.0;
    }
    return reaction;
  }

  /* ======================================================================
     Elastic MCA interaction of a linked pair
     ======================================================================

     Conventions (see doc/src/pair_mca.rst):
     - a pair is stored and computed in canonical order: "lo" is the
       automaton with the lower atom ID, "hi" the other; n points lo -> hi
     - tractions are tension positive; sigma is the normal traction and t
       the shear traction vector acting on lo (on hi they act with opposite
       sign), both per unit contact area
     - each automaton keeps its half of the pair state (strain, tractions,
       couple); the Newton-3 splits below make the two halves equal
     - q0 = reference distance from an automaton's centre to the contact
       plane (q0_lo + q0_hi = reference length r0), q = q0 (1 + eps)        */

  // layout of the per-link history (doubles); both owners store all of it.
  // What the mean-stress predictor reads comes first (up to the normal
  // tractions of both halves), so that its pass touches few cache lines.
  // H_LAYOUT numbers the layout in restart files: change it with the order
  enum { H_LAYOUT = 1 };
  enum LinkHistory {
    H_STATE = 0,    // link state (LINKED)
    H_RPREV,        // length at the last step
    H_Q0LO,         // reference half lengths
    H_Q0HI,
    H_LO,                     // half of lo: sigma, eps, t(3), couple(3)
    H_HI = H_LO + 8,          // half of hi
    H_R0 = H_HI + 8,          // reference length r0
    H_A0,                     // reference contact area
    H_NPREV,                  // unit normal lo -> hi at the last step (3)
    H_APREV = H_NPREV + 3,    // contact area at the last step
    H_WORK,                   // elastic energy of the link
    H_SIZE
  };
  // offsets inside a half (ints: C++20 deprecates adding them to the
  // LinkHistory enumerators if they were another enumeration)
  constexpr int HALF_SIG = 0, HALF_EPS = 1, HALF_T = 2, HALF_COUPLE = HALF_T + 3, HALF_SIZE = 8;
  enum LinkState { LINK_NONE = 0, LINK_LINKED = 1 };

  MCA_INLINE double dot3(const double *a, const double *b)
  {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }

  MCA_INLINE void cross3(const double *a, const double *b, double *c)
  {
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
  }

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

  // contact face area of a cell: R A N_c = 3 Omega
  MCA_INLINE double face_area(int packing, double radius, double volume)
  {
    return 3.0 * volume / (packing * radius);
  }

  /* second moment of area of a contact face about an in-plane axis
     through its centre, isotropic average (half the polar moment), in
     units of A^2: square face of the sc cube (2R)^4/12 / (4R^2)^2 = 1/12;
     rhombic face of the fcc cell (diagonals 2R, sqrt(2) R): sqrt(2)/16 */

  MCA_INLINE double face_moment_factor(int packing)
  {
    if (packing == PACKING_SC) return 1.0 / 12.0;
    return 0.08838834764831845;    // sqrt(2)/16
  }

  /* ----------------------------------------------------------------------
     mean-stress predictor (thesis eqs. 3.74-3.95, corrected):
     stiffness of a half for the predicted strain, interpolated between an
     isolated pair (H1) and a complete environment that does not move (Hc)
     by the number of interacting neighbours N
  ------------------------------------------------------------------------- */

  MCA_INLINE double predictor_stiffness(double G, double K, int nc, int n)
  {
    const double D = mean_stress_coupling(G, K);
    const double h1 = 2.0 * G * nc / (nc - D);
    const double hc = 2.0 * G + (3.0 * K - 2.0 * G) / nc;
    if (nc <= 1 || n <= 1) return h1;
    const int m = (n < nc) ? n : nc;
    return h1 + (hc - h1) * (m - 1) / (nc - 1.0);
  }

  // predicted normal strain increment of half i for a length change dr
  MCA_INLINE double predicted_strain(double sig_i, double sig_j, double h_i, double h_j,
                                     double q0_i, double q0_j, double dr)
  {
    return (q0_j * (sig_j - sig_i) + h_j * dr) / (h_i * q0_j + h_j * q0_i);
  }

  /* ----------------------------------------------------------------------
     homogenised stress of an automaton from the tractions T_j acting on it
     through its links j (unit normals n_j pointing to the partners):
       sigma = sym( B F^-1 ),  B = sum_j T_j n_j^T,  F = sum_j n_j n_j^T
     For a complete sc or fcc shell F = (N_c/3) I and this is the source's
     (3/N_c) sum_j (sigma_j n_j n_j + n_j t_j).  The fabric tensor F makes
     it exact for any uniform stress (T_j = sigma n_j) also where links are
     missing (free surfaces), where the source's formula counts missing
     links as tractions of zero.  A tiny multiple of the identity keeps F
     invertible for links that span less than 3d (isolated pairs, chains);
     B F^-1 only acts on the span of the links, so this does not bias it.
     Symmetric 3x3 tensors are stored as xx yy zz xy xz yz.
  ------------------------------------------------------------------------- */

  MCA_INLINE void fabric_add(double *fab, const double *n)
  {
    fab[0] += n[0] * n[0];
    fab[1] += n[1] * n[1];
    fab[2] += n[2] * n[2];
    fab[3] += n[0] * n[1];
    fab[4] += n[0] * n[2];
    fab[5] += n[1] * n[2];
  }

  // inverse of a symmetric 3x3 tensor regularised by 1e-12 of its trace
  MCA_INLINE void fabric_inverse(const double *fab, double *inv)
  {
    const double reg = 1.0e-12 * (fab[0] + fab[1] + fab[2]);
    const double a = fab[0] + reg, b = fab[1] + reg, c = fab[2] + reg;
    const double d = fab[3], e = fab[4], f = fab[5];
    const double c00 = b * c - f * f, c01 = e * f - d * c, c02 = d * f - b * e;
    const double det = a * c00 + d * c01 + e * c02;
    const double idet = (det != 0.0) ? 1.0 / det : 0.0;
    inv[0] = c00 * idet;
    inv[1] = (a * c - e * e) * idet;
    inv[2] = (a * b - d * d) * idet;
    inv[3] = c01 * idet;
    inv[4] = c02 * idet;
    inv[5] = (d * e - a * f) * idet;
  }

  // B += T n^T (B row-major 3x3)
  MCA_INLINE void traction_add(double *bmat, const double *trac, const double *n)
  {
    for (int a = 0; a < 3; a++)
      for (int b = 0; b < 3; b++) bmat[3 * a + b] += trac[a] * n[b];
  }

  // sigma = sym(B F^-1), Voigt order xx yy zz xy xz yz
  MCA_INLINE void homogenised_stress(const double *bmat, const double *fab, double *sig)
  {
    double inv[6];
    fabric_inverse(fab, inv);
    const double fi[9] = {inv[0], inv[3], inv[4], inv[3], inv[1], inv[5], inv[4], inv[5], inv[2]};
    double s[9];
    for (int a = 0; a < 3; a++)
      for (int b = 0; b < 3; b++)
        s[3 * a + b] =
            bmat[3 * a] * fi[b] + bmat[3 * a + 1] * fi[3 + b] + bmat[3 * a + 2] * fi[6 + b];
    sig[0] = s[0];
    sig[1] = s[4];
    sig[2] = s[8];
    sig[3] = 0.5 * (s[1] + s[3]);
    sig[4] = 0.5 * (s[2] + s[6]);
    sig[5] = 0.5 * (s[5] + s[7]);
  }

  /* predicted mean-stress increment of an automaton: the mean of the
     homogenised normal-traction increments 2G de_j + D dsm satisfies
       dsm = (1/3) sum_j (n_j F^-1 n_j)(2G de_j + D dsm),  sum_j n_j F^-1 n_j = 3
     so dsm = K tr(F^-1 M), M = sum_j de_j n_j n_j^T (thesis 3.91 for a
     complete shell; replaces its free-surface correction 3.92-3.95, which
     belongs to the zero-traction count of missing links)                  */

  MCA_INLINE double predicted_mean_stress_increment(const double *fab, const double *mstrain,
                                                    double K)
  {
    double inv[6];
    fabric_inverse(fab, inv);
    const double tr = inv[0] * mstrain[0] + inv[1] * mstrain[1] + inv[2] * mstrain[2] +
        2.0 * (inv[3] * mstrain[3] + inv[4] * mstrain[4] + inv[5] * mstrain[5]);
    return K * tr;
  }

  /* ----------------------------------------------------------------------
     the predictor pass, per link and per automaton
  ------------------------------------------------------------------------- */

  // length of a link and the dyad n n^T of its direction; del = x_j - x_i
  // (the dyad does not depend on the sign of del)
  MCA_INLINE double link_direction(const double *del, double *nn)
  {
    const double r = sqrt(dot3(del, del));
    const double n[3] = {del[0] / r, del[1] / r, del[2] / r};
    for (int k = 0; k < 6; k++) nn[k] = 0.0;
    fabric_add(nn, n);
    return r;
  }

  // predicted strain increment of the half of automaton i (the lower ID
  // if i_is_lo) of a link whose length changed by dr since the last step;
  // h_i, h_j: predictor stiffnesses of the two automata
  MCA_INLINE double link_half_strain(const double *hist, bool i_is_lo, double h_i, double h_j,
                                     double dr)
  {
    const double sig_i = hist[(i_is_lo ? H_LO : H_HI) + HALF_SIG];
    const double sig_j = hist[(i_is_lo ? H_HI : H_LO) + HALF_SIG];
    const double q0_i = hist[i_is_lo ? H_Q0LO : H_Q0HI];
    const double q0_j = hist[i_is_lo ? H_Q0HI : H_Q0LO];
    return predicted_strain(sig_i, sig_j, h_i, h_j, q0_i, q0_j, dr);
  }

  // the predictor's view of one link between automata i and j (del =
  // x_j - x_i): the dyad n n^T and the predicted strain increments of the
  // half of i and of the half of j
  MCA_INLINE void link_prediction(const double *hist, const double *del, bool i_is_lo, double h_i,
                                  double h_j, double *nn, double &de_i, double &de_j)
  {
    const double dr = link_direction(del, nn) - hist[H_RPREV];
    de_i = link_half_strain(hist, i_is_lo, h_i, h_j, dr);
    de_j = link_half_strain(hist, !i_is_lo, h_j, h_i, dr);
  }

  // F += n n^T, M += de n n^T
  MCA_INLINE void predictor_add(double *fab, double *mstrain, const double *nn, double de)
  {
    for (int k = 0; k < 6; k++) {
      fab[k] += nn[k];
      mstrain[k] += de * nn[k];
    }
  }

  /* mean stress the normal law of an automaton applies at this step
     (smean_pred) and its increment over the last step's (dsmean): the
     prediction builds on the mean stress of the last step's tractions
     (smean_step), so the error of one step's prediction is corrected at
     the next.  A setup (or run 0) repeats the last step with only what
     changed since; an automaton without interacting links keeps its mean
     stress.                                                               */

  MCA_INLINE void mean_stress_prediction(bool interacting, bool setup_pass, double smean_step,
                                         double smean_law, const double *fab, const double *mstrain,
                                         double K, double &smean_pred, double &dsmean)
  {
    if (!interacting) {
      smean_pred = setup_pass ? smean_law : smean_step;
      dsmean = smean_pred - smean_law;
      return;
    }
    const double dsm = predicted_mean_stress_increment(fab, mstrain, K);
    if (setup_pass) {
      smean_pred = smean_law + dsm;
      dsmean = dsm;
    } else {
      smean_pred = smean_step + dsm;
      dsmean = smean_pred - smean_law;
    }
  }

  // outputs of an automaton: stress tensor, mean stress (tension positive),
  // von Mises equivalent stress and the equivalent strain seq / 3G
  MCA_INLINE void automaton_stress(const double *bmat, const double *fab, double G, double *stress,
                                   double &smean, double &seq, double &eeq)
  {
    homogenised_stress(bmat, fab, stress);
    smean = (stress[0] + stress[1] + stress[2]) / 3.0;
    const double sxx = stress[0], syy = stress[1], szz = stress[2];
    seq = sqrt(
        0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx)) +
        3.0 * (stress[3] * stress[3] + stress[4] * stress[4] + stress[5] * stress[5]));
    eeq = seq / (3.0 * G);
  }

  /* ----------------------------------------------------------------------
     normal strain increments of the two halves such that their tractions
     stay equal (Newton 3), for unequal materials and sizes:
       sig_i + 2G_i de_i + D_i dsm_i = sig_j + 2G_j de_j + D_j dsm_j
       q0_i de_i + q0_j de_j = dr
     (the source's eq. 3.68 has 2G_i where 2G_j belongs)
  ------------------------------------------------------------------------- */

  MCA_INLINE void split_normal_strain(double sig_i, double sig_j, double g_i, double g_j,
                                      double d_i, double d_j, double dsm_i, double dsm_j,
                                      double q0_i, double q0_j, double dr, double &de_i,
                                      double &de_j)
  {
    de_i = (q0_j * (sig_j - sig_i + d_j * dsm_j - d_i * dsm_i) + 2.0 * g_j * dr) /
        (2.0 * g_i * q0_j + 2.0 * g_j * q0_i);
    de_j = (dr - q0_i * de_i) / q0_j;
  }

  /* ----------------------------------------------------------------------
     tangential displacement of the contact point of j relative to that of
     i during a step: the change of the centre-to-centre vector (from the
     positions, so that displacements made between runs count too) minus
     the part carried by the spins, normal to the current normal n.
     The spins turn the contact points about the mid-step normal
     (n_old + n)/|n_old + n|: for a rigid rotation by an angle alpha per
     step the change of the centre-to-centre vector is exactly
     2 sin(alpha/2) w x r_mid, so the slip left is O(alpha^3) per step and
     does not accumulate (with the end-of-step normal it would be
     O(alpha^2) and grow steadily along an arc).  Thesis 3.107-3.109
     without the 1/r, there written with velocities.
       del, del_old   centre-to-centre vector now and at the last step
       n_old          unit normal at the last step
       w_i, w_j       angular velocities over the step (spin increments w dt)
  ------------------------------------------------------------------------- */

  MCA_INLINE void contact_slip(const double *n, const double *n_old, const double *del,
                               const double *del_old, double q_i, double q_j, const double *w_i,
                               const double *w_j, double dt, double *dl)
  {
    double nm[3] = {n[0] + n_old[0], n[1] + n_old[1], n[2] + n_old[2]};
    const double len = sqrt(dot3(nm, nm));
    for (int m = 0; m < 3; m++) nm[m] = (len > 0.0) ? nm[m] / len : n[m];
    const double s[3] = {dt * (q_i * w_i[0] + q_j * w_j[0]), dt * (q_i * w_i[1] + q_j * w_j[1]),
                         dt * (q_i * w_i[2] + q_j * w_j[2])};
    double sxn[3];
    cross3(s, nm, sxn);
    const double u[3] = {del[0] - del_old[0] - sxn[0], del[1] - del_old[1] - sxn[1],
                         del[2] - del_old[2] - sxn[2]};
    const double un = dot3(u, n);
    for (int m = 0; m < 3; m++) dl[m] = u[m] - un * n[m];
  }

  /* ----------------------------------------------------------------------
     shear strain increments of the two halves with equal resulting shear
     tractions (thesis 3.104-3.106, solved exactly for unequal G and q):
       t_i + 2G_i dg_i = t_j + 2G_j dg_j,   q_i dg_i + q_j dg_j = dl
  ------------------------------------------------------------------------- */

  MCA_INLINE void split_shear_strain(const double *t_i, const double *t_j, double g_i, double g_j,
                                     double q_i, double q_j, const double *dl, double *dg_i,
                                     double *dg_j)
  {
    const double inv = 1.0 / (g_i * q_j + g_j * q_i);
    for (int k = 0; k < 3; k++) {
      dg_i[k] = (g_j * dl[k] + 0.5 * q_j * (t_j[k] - t_i[k])) * inv;
      dg_j[k] = (dl[k] - q_i * dg_i[k]) / q_j;
    }
  }

  /* ----------------------------------------------------------------------
     carry a vector of the pair frame along with the pair: the minimal
     rotation that takes the old normal a to the new normal b, then a twist
     by angle phi about b.  A tangential vector (shear traction) also loses
     the component along b that round-off leaves; a couple keeps its twist
     component along b.
  ------------------------------------------------------------------------- */

  // cosine and sine; the twist per step is tiny, where a series is exact
  // to round-off (the first term left out is phi^6/720 < 2e-21)
  MCA_INLINE void cos_sin(double phi, double &c, double &s)
  {
    if (fabs(phi) < 1.0e-3) {
      const double p2 = phi * phi;
      c = 1.0 - 0.5 * p2 * (1.0 - p2 / 12.0);
      s = phi * (1.0 - p2 / 6.0 * (1.0 - p2 / 20.0));
    } else {
      c = cos(phi);
      s = sin(phi);
    }
  }

  MCA_INLINE void pair_rotation(const double *a, const double *b, double cos_phi, double sin_phi,
                                double *rot)
  {
    // minimal rotation a -> b: R v = c v + k x v + k (k.v)/(1 + c), k = a x b
    double k[3];
    cross3(a, b, k);
    const double c = dot3(a, b);
    const double f = (c > -1.0 + 1.0e-12) ? 1.0 / (1.0 + c) : 0.0;
    double rmin[9];
    rmin[0] = c + f * k[0] * k[0];
    rmin[1] = -k[2] + f * k[0] * k[1];
    rmin[2] = k[1] + f * k[0] * k[2];
    rmin[3] = k[2] + f * k[1] * k[0];
    rmin[4] = c + f * k[1] * k[1];
    rmin[5] = -k[0] + f * k[1] * k[2];
    rmin[6] = -k[1] + f * k[2] * k[0];
    rmin[7] = k[0] + f * k[2] * k[1];
    rmin[8] = c + f * k[2] * k[2];
    // twist about b (Rodrigues): cos I + sin [b]x + (1 - cos) b b^T
    const double d = 1.0 - cos_phi;
    const double tw[9] = {cos_phi + d * b[0] * b[0],         -sin_phi * b[2] + d * b[0] * b[1],
                          sin_phi * b[1] + d * b[0] * b[2],  sin_phi * b[2] + d * b[1] * b[0],
                          cos_phi + d * b[1] * b[1],         -sin_phi * b[0] + d * b[1] * b[2],
                          -sin_phi * b[1] + d * b[2] * b[0], sin_phi * b[0] + d * b[2] * b[1],
                          cos_phi + d * b[2] * b[2]};
    for (int r = 0; r < 3; r++)
      for (int q = 0; q < 3; q++)
        rot[3 * r + q] =
            tw[3 * r] * rmin[q] + tw[3 * r + 1] * rmin[3 + q] + tw[3 * r + 2] * rmin[6 + q];
  }

  MCA_INLINE void rotate_with_pair(double *v, const double *rot, const double *b, bool tangential)
  {
    double r[3];
    for (int m = 0; m < 3; m++)
      r[m] = rot[3 * m] * v[0] + rot[3 * m + 1] * v[1] + rot[3 * m + 2] * v[2];
    const double rb = tangential ? dot3(r, b) : 0.0;
    for (int m = 0; m < 3; m++) v[m] = r[m] - rb * b[m];
  }

  // contact area from the mean stresses (thesis 3.65): A r = A0 r0 (1 + mean volumetric strain)
  MCA_INLINE double contact_area(double a0, double r0, double r, double sm_i, double k_i,
                                 double sm_j, double k_j)
  {
    return a0 * (r0 / r) * (1.0 + 0.5 * (sm_i / k_i + sm_j / k_j));
  }

  /* ----------------------------------------------------------------------
     one step of a linked pair: all inputs in canonical order (lo, hi)

     in:  hist      link history (H_SIZE doubles) at the last step
          x, w      position and angular velocity of lo and hi
                    (x_hi is the image of hi closest to lo)
          g, d, k   shear modulus, mean-stress coupling, bulk modulus
          dsm       mean-stress increments to apply this step
          sm        predicted mean stresses (for the contact area)
          chi       face second moment / area^2
          dt        time step
     out: hist      updated history (the caller keeps or discards it)
          f         force on lo (on hi: -f)
          tq_lo, tq_hi  torques on lo and hi
          sig       normal traction of the pair (for the mean stress)
          trac      traction on lo (sig n + t); T n^T is the same for both
                    automata of the pair
          r, nvec   current length and normal
  ------------------------------------------------------------------------- */

  MCA_INLINE void linked_pair(double *hist, const double *x_lo, const double *x_hi,
                              const double *w_lo, const double *w_hi, double g_lo, double g_hi,
                              double d_lo, double d_hi, double k_lo, double k_hi, double dsm_lo,
                              double dsm_hi, double sm_lo, double sm_hi, double chi, double dt,
                              double *f, double *tq_lo, double *tq_hi, double &sig, double *trac,
                              double &r, double *nvec)
  {
    double *lo = hist + H_LO;
    double *hi = hist + H_HI;
    const double del[3] = {x_hi[0] - x_lo[0], x_hi[1] - x_lo[1], x_hi[2] - x_lo[2]};
    r = sqrt(dot3(del, del));
    const double rinv = 1.0 / r;
    for (int m = 0; m < 3; m++) nvec[m] = del[m] * rinv;
    const double *n = nvec;
    const double q0_lo = hist[H_Q0LO], q0_hi = hist[H_Q0HI];
    const double dr = r - hist[H_RPREV];

    // normal tractions
    double de_lo, de_hi;
    const double sig_lo0 = lo[HALF_SIG], sig_hi0 = hi[HALF_SIG];
    split_normal_strain(sig_lo0, sig_hi0, g_lo, g_hi, d_lo, d_hi, dsm_lo, dsm_hi, q0_lo, q0_hi, dr,
                        de_lo, de_hi);
    lo[HALF_EPS] += de_lo;
    hi[HALF_EPS] += de_hi;
    lo[HALF_SIG] = sig_lo0 + 2.0 * g_lo * de_lo + d_lo * dsm_lo;
    hi[HALF_SIG] = sig_hi0 + 2.0 * g_hi * de_hi + d_hi * dsm_hi;
    const double q_lo = q0_lo * (1.0 + lo[HALF_EPS]);
    const double q_hi = q0_hi * (1.0 + hi[HALF_EPS]);

    // carry shear tractions and couples along with the pair
    const double phi = 0.5 * dt * (dot3(w_lo, n) + dot3(w_hi, n));
    // (t_old, c_old: the shear traction and couple that acted at the last
    // step, for the work of this step)
    const double *n_old = hist + H_NPREV;
    double t_old[3], c_old[3];
    for (int m = 0; m < 3; m++) {
      t_old[m] = 0.5 * (lo[HALF_T + m] + hi[HALF_T + m]);
      c_old[m] = 0.5 * (lo[HALF_COUPLE + m] + hi[HALF_COUPLE + m]);
    }
    double rot[9];
    double cos_phi, sin_phi;
    cos_sin(phi, cos_phi, sin_phi);
    pair_rotation(n_old, n, cos_phi, sin_phi, rot);
    rotate_with_pair(lo + HALF_T, rot, n, true);
    rotate_with_pair(hi + HALF_T, rot, n, true);
    rotate_with_pair(lo + HALF_COUPLE, rot, n, false);
    rotate_with_pair(hi + HALF_COUPLE, rot, n, false);

    // shear tractions
    double dl[3], dg_lo[3], dg_hi[3];
    const double rprev = hist[H_RPREV];
    const double del_old[3] = {rprev * n_old[0], rprev * n_old[1], rprev * n_old[2]};
    contact_slip(n, n_old, del, del_old, q_lo, q_hi, w_lo, w_hi, dt, dl);
    split_shear_strain(lo + HALF_T, hi + HALF_T, g_lo, g_hi, q_lo, q_hi, dl, dg_lo, dg_hi);
    for (int m = 0; m < 3; m++) {
      lo[HALF_T + m] += 2.0 * g_lo * dg_lo[m];
      hi[HALF_T + m] += 2.0 * g_hi * dg_hi[m];
    }

    // contact area and pair force on lo
    const double area = contact_area(hist[H_A0], hist[H_R0], r, sm_lo, k_lo, sm_hi, k_hi);
    sig = 0.5 * (lo[HALF_SIG] + hi[HALF_SIG]);
    double t[3];
    for (int m = 0; m < 3; m++) {
      t[m] = 0.5 * (lo[HALF_T + m] + hi[HALF_T + m]);
      f[m] = area * (sig * n[m] + t[m]);
    }

    // bending and torsion: the faces act as two elastic layers of
    // thickness q_lo, q_hi in series; the relative rotation splits into
    // twist (along n) and bending (normal to n)
    const double compliance = q_lo / (2.0 * g_lo) + q_hi / (2.0 * g_hi);
    const double kbend = chi * area * area / compliance;
    double dth[3] = {dt * (w_hi[0] - w_lo[0]), dt * (w_hi[1] - w_lo[1]), dt * (w_hi[2] - w_lo[2])};
    const double twist = dot3(dth, n);
    double dcouple[3];
    for (int m = 0; m < 3; m++)
      dcouple[m] = kbend * (dth[m] - twist * n[m]) + 2.0 * kbend * twist * n[m];
    for (int m = 0; m < 3; m++) {
      lo[HALF_COUPLE + m] += dcouple[m];
      hi[HALF_COUPLE + m] += dcouple[m];
    }
    double couple[3];
    for (int m = 0; m < 3; m++) couple[m] = 0.5 * (lo[HALF_COUPLE + m] + hi[HALF_COUPLE + m]);

    // torques: moment of the shear force about each centre, plus the couple
    double nxf[3];
    cross3(n, f, nxf);
    for (int m = 0; m < 3; m++) {
      tq_lo[m] = q_lo * nxf[m] + couple[m];
      tq_hi[m] = q_hi * nxf[m] - couple[m];
    }

    for (int m = 0; m < 3; m++) trac[m] = sig * n[m] + t[m];

    // elastic energy: work of the pair forces over the step, trapezoidal
    // rule with the forces that acted at the last step and now
    const double sig_old = 0.5 * (sig_lo0 + sig_hi0);
    const double a_old = hist[H_APREV];
    double work = 0.5 * (a_old * sig_old + area * sig) * dr;
    for (int m = 0; m < 3; m++)
      work +=
          0.5 * (a_old * t_old[m] + area * t[m]) * dl[m] + 0.5 * (c_old[m] + couple[m]) * dth[m];
    hist[H_WORK] += work;

    hist[H_RPREV] = r;
    for (int m = 0; m < 3; m++) hist[H_NPREV + m] = n[m];
    hist[H_APREV] = area;
  }

}    // namespace MCAKernels
}    // namespace LAMMPS_NS

#endif
