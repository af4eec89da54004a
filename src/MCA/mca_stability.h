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
   The linearised link law, for the stable time step: the stiffness that a
   small displacement and rotation of the automata meets, link by link
   (see doc/src/pair_mca.rst, "Stable time step").
------------------------------------------------------------------------- */

#ifndef LMP_MCA_STABILITY_H
#define LMP_MCA_STABILITY_H

#include "mca_fracture.h"
#include "mca_geometry.h"
#include "mca_link_law.h"
#include "mca_link_layout.h"
#include "mca_material.h"
#include "mca_mean_stress.h"

#include <cmath>

namespace LAMMPS_NS {
namespace MCAKernels {

  /* ----------------------------------------------------------------------
     a link seen from one of its automata, i (partner j), linearised about
     its present state.  For a displacement u and a rotation th of each
     automaton, the contact point of j moves against that of i by
       d  = (u_j - u_i) - (q_i th_i + q_j th_j) x n       (n: i -> j)
     and the link's tension, shear force and couple change by
       T  = kn n.d + (mean-stress term, below)
       ft = kt (d - (n.d) n)
       C  = kb (dth - (n.dth) n) + 2 kb (n.dth) n,        dth = th_j - th_i
     (the normal and the shear law with their halves in series, bending
     and torsion: link_couple).  The mean-stress term: the normal law adds
     D dsm of each half, with dsm = K s and s = sum over the automaton's
     links of beta dr (the predictor, exact for the length changes of a
     step); weighted by the halves' compliances it adds a_i s_i + a_j s_j
     to the tension, a = A w lambda (lambda = D K).  Its symmetric part,
     which the estimate uses, is
       T_ms = (a_i s_i + beta_i r_i + a_j s_j + beta_j r_j) / 2,
       r = sum over the automaton's links of a dr.
     The geometric terms of the present tractions (the rotation of the
     normal and of the shear tractions with the pair, the change of the
     contact area) are left out: they are of the order of the elastic
     strain against 1.
  ------------------------------------------------------------------------- */

  struct MCALinkTangent {
    double n[3];              // unit normal i -> j
    double q_i, q_j;          // present half lengths
    double kn, kt, kb;        // normal, shear and bending stiffness
    double a_i, a_j;          // tension per unit predictor strain s of i and j
    double beta_i, beta_j;    // weight of the link's length change in s_i and s_j
    double damp;              // dashpot coefficient of the pair (damping viscous), or 0
    double area;              // contact area
    double w_i, w_j;          // shares of the halves in the normal compliance c_n
    double inv_cn, inv_ct;    // 1 / c_n and 1 / c_t: traction per unit stretch and slip
    bool linked;              // a link (not a broken pair)
  };

  // the weight of a link's length change in the predicted mean strain of
  // automaton i: (n F_i^-1 n) times the predictor's split h_j / (h_i q0_j + h_j q0_i)
  MCA_INLINE double predictor_weight(const double *finv, const double *n, double h_i, double h_j,
                                     double q0_i, double q0_j)
  {
    const double nfn = finv[0] * n[0] * n[0] + finv[1] * n[1] * n[1] + finv[2] * n[2] * n[2] +
        2.0 * (finv[3] * n[0] * n[1] + finv[4] * n[0] * n[2] + finv[5] * n[1] * n[2]);
    const double den = h_i * q0_j + h_j * q0_i;
    return den > 0.0 ? nfn * h_j / den : 0.0;
  }

  /* the tangent of link row 'row' seen from i (i_is_lo: i is its lower
     ID).  ms_i, ms_j: whether the automaton's mean stress is predicted
     (interacting and packed); finv, h: its inverse fabric tensor and its
     predictor stiffness; chi: the face moment factor of lo's packing.
     A broken pair or a contact acts only while it is compressed, through
     its normal stiffness and, with friction (the contact part), the
     stiffness of its tangential spring while it sticks; an unlinked pair
     without a contact row does not act (kn = kt = kb = 0)                */

  MCA_INLINE void link_tangent(const double *row, bool i_is_lo, const MCAMaterial &m_i,
                               const MCAMaterial &m_j, double chi, bool ms_i, bool ms_j,
                               const double *finv_i, const double *finv_j, double h_i, double h_j,
                               bool damping, bool friction, MCALinkTangent &t)
  {
    const double sign = i_is_lo ? 1.0 : -1.0;
    for (int k = 0; k < 3; k++) t.n[k] = sign * row[H_NPREV + k];
    const double q0_i = row[i_is_lo ? H_Q0LO : H_Q0HI], q0_j = row[i_is_lo ? H_Q0HI : H_Q0LO];
    const double eps_i = row[(i_is_lo ? H_LO : H_HI) + HALF_EPS];
    const double eps_j = row[(i_is_lo ? H_HI : H_LO) + HALF_EPS];
    t.q_i = q0_i * (1.0 + eps_i);
    t.q_j = q0_j * (1.0 + eps_j);
    const double area = row[H_APREV];
    const double g2_i = 2.0 * m_i.shear, g2_j = 2.0 * m_j.shear;
    const double cn = q0_i / g2_i + q0_j / g2_j;
    const double ct = t.q_i / g2_i + t.q_j / g2_j;
    t.kn = t.kt = t.kb = t.a_i = t.a_j = t.beta_i = t.beta_j = t.damp = 0.0;
    t.area = area;
    t.w_i = q0_i / (g2_i * cn);
    t.w_j = q0_j / (g2_j * cn);
    t.inv_cn = 1.0 / cn;
    t.inv_ct = 1.0 / ct;
    const int state = static_cast<int>(row[H_STATE]);
    t.linked = (state == LINK_LINKED);
    if (state == LINK_BROKEN || state == LINK_CONTACT) {
      // pushing: the virtual halves' normal traction is compressive
      if (row[H_LO + HALF_SIG] + row[H_HI + HALF_SIG] < 0.0) {
        t.kn = area / cn;
        if (friction) t.kt = area / ct;
      }
      return;
    }
    if (state != LINK_LINKED) return;
    t.kn = area / cn;
    t.kt = area / ct;
    t.kb = chi * area * area / ct;
    // mean stress: lambda = D K; the weight of each half is its share of
    // the compliance, w_i = q0_i / (2 G_i c_n)
    if (ms_i) {
      t.a_i = area * t.w_i * m_i.coupling * m_i.bulk;
      t.beta_i = predictor_weight(finv_i, t.n, h_i, h_j, q0_i, q0_j);
    }
    if (ms_j) {
      t.a_j = area * t.w_j * m_j.coupling * m_j.bulk;
      t.beta_j = predictor_weight(finv_j, t.n, h_j, h_i, q0_j, q0_i);
    }
    if (damping) t.damp = area * series_viscosity(m_i.viscosity, m_j.viscosity, t.q_i, t.q_j);
  }

  // the link seen from its other end: the normal reversed, the sides
  // exchanged.  That is link_tangent of the other end bit for bit: c_n,
  // c_t, kn, kt and kb are sums and products of two terms, one per side,
  // which IEEE arithmetic gives alike in either order, and the predictor
  // weights are even in n
  MCA_INLINE void swap_sides(MCALinkTangent &t)
  {
    auto swap = [](double &a, double &b) {
      const double c = a;
      a = b;
      b = c;
    };
    for (int k = 0; k < 3; k++) t.n[k] = -t.n[k];
    swap(t.q_i, t.q_j);
    swap(t.a_i, t.a_j);
    swap(t.beta_i, t.beta_j);
    swap(t.w_i, t.w_j);
  }

  // the length change of the link for displacements u_i, u_j
  MCA_INLINE double tangent_stretch(const MCALinkTangent &t, const double *u_i, const double *u_j)
  {
    return t.n[0] * (u_j[0] - u_i[0]) + t.n[1] * (u_j[1] - u_i[1]) + t.n[2] * (u_j[2] - u_i[2]);
  }

  // the relative displacement of the contact points: its stretch along n
  // and its slip across n
  MCA_INLINE void tangent_motion(const MCALinkTangent &t, const double *u_i, const double *th_i,
                                 const double *u_j, const double *th_j, double &dr, double *slip)
  {
    const double s[3] = {t.q_i * th_i[0] + t.q_j * th_j[0], t.q_i * th_i[1] + t.q_j * th_j[1],
                         t.q_i * th_i[2] + t.q_j * th_j[2]};
    double sxn[3];
    cross3(s, t.n, sxn);
    const double d[3] = {u_j[0] - u_i[0] - sxn[0], u_j[1] - u_i[1] - sxn[1],
                         u_j[2] - u_i[2] - sxn[2]};
    dr = dot3(d, t.n);
    for (int k = 0; k < 3; k++) slip[k] = d[k] - dr * t.n[k];
  }

  /* force f and torque tq on automaton i from the link, for the
     displacements and rotations of i and j and the link's mean-stress
     tension tension_ms (T_ms above): the linearised law, f = -K u        */

  MCA_INLINE void tangent_force(const MCALinkTangent &t, const double *u_i, const double *th_i,
                                const double *u_j, const double *th_j, double tension_ms, double *f,
                                double *tq)
  {
    double dr, slip[3];
    tangent_motion(t, u_i, th_i, u_j, th_j, dr, slip);
    const double tension = t.kn * dr + tension_ms;
    double ft[3];
    for (int k = 0; k < 3; k++) {
      ft[k] = t.kt * slip[k];
      f[k] = tension * t.n[k] + ft[k];
    }
    const double dth[3] = {th_j[0] - th_i[0], th_j[1] - th_i[1], th_j[2] - th_i[2]};
    const double twist = dot3(dth, t.n);
    double nxf[3];
    cross3(t.n, ft, nxf);
    for (int k = 0; k < 3; k++)
      tq[k] = t.q_i * nxf[k] + t.kb * (dth[k] - twist * t.n[k]) + 2.0 * t.kb * twist * t.n[k];
  }

  // F^-1 n of an automaton's inverse fabric tensor and a link normal
  MCA_INLINE void fabric_times(const double *finv, const double *n, double *fn)
  {
    fn[0] = finv[0] * n[0] + finv[3] * n[1] + finv[4] * n[2];
    fn[1] = finv[3] * n[0] + finv[1] * n[1] + finv[5] * n[2];
    fn[2] = finv[4] * n[0] + finv[5] * n[1] + finv[2] * n[2];
  }

  // force and torque on i of a tension T along the link and a force tau
  // across it at the contact point (what the transposed mean-stress terms
  // give, below)
  MCA_INLINE void tangent_load(const MCALinkTangent &t, double tension, const double *tau,
                               double *f, double *tq)
  {
    const double taun = dot3(tau, t.n);
    double tp[3];
    for (int k = 0; k < 3; k++) {
      tp[k] = tau[k] - taun * t.n[k];
      f[k] = tension * t.n[k] + tp[k];
    }
    double nxt[3];
    cross3(t.n, tp, nxt);
    for (int k = 0; k < 3; k++) tq[k] = t.q_i * nxt[k];
  }

  // the elastic energy of the link (without its mean-stress part) and the
  // power its dashpots dissipate per unit velocity squared, for the
  // displacements and rotations of a mode
  MCA_INLINE void tangent_energy(const MCALinkTangent &t, const double *u_i, const double *th_i,
                                 const double *u_j, const double *th_j, double &energy,
                                 double &damping)
  {
    double dr, slip[3];
    tangent_motion(t, u_i, th_i, u_j, th_j, dr, slip);
    const double dth[3] = {th_j[0] - th_i[0], th_j[1] - th_i[1], th_j[2] - th_i[2]};
    const double twist = dot3(dth, t.n);
    const double bend = dot3(dth, dth) - twist * twist;
    const double slip2 = dot3(slip, slip);
    energy = 0.5 * (t.kn * dr * dr + t.kt * slip2 + t.kb * (bend + 2.0 * twist * twist));
    damping = t.damp * (dr * dr + slip2);
  }

  // the trace of the link's block of the mass-scaled stiffness on i's own
  // motion: (kn + 2 kt) / m + (2 kt q_i^2 + 4 kb) / J (for the monitor of
  // the estimate: how the stiffness of an automaton changes with the
  // deformation)
  MCA_INLINE double tangent_trace(const MCALinkTangent &t, double mass, double inertia)
  {
    return (t.kn + 2.0 * t.kt) / mass + (2.0 * t.kt * t.q_i * t.q_i + 4.0 * t.kb) / inertia;
  }

  /* ----------------------------------------------------------------------
     velocity Verlet on a mode of angular frequency omega with damping
     ratio zeta (the damping force from the velocity of the half step, as
     the link dashpots take it) is stable for
       omega dt <= 2 (sqrt(1 + zeta^2) - zeta)
     (the roots of z^2 - (2 - W^2 - 2 zeta W) z + 1 - 2 zeta W, W = omega dt,
     lie in the unit circle)
  ------------------------------------------------------------------------- */

  MCA_INLINE double critical_timestep(double omega, double zeta)
  {
    return 2.0 * (sqrt(1.0 + zeta * zeta) - zeta) / omega;
  }

  // pseudo-random number in [-1, 1) from an automaton's ID and a component
  // (the start of the Lanczos iteration, the same on any number of ranks)
  MCA_INLINE double start_component(std::int64_t id, int k)
  {
    const std::uint64_t h = mix64(mix64(static_cast<std::uint64_t>(id)) ^ (0x9e37ULL + k));
    return 2.0 * (static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0)) - 1.0;
  }

}    // namespace MCAKernels
}    // namespace LAMMPS_NS

#endif
