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
   Elastic MCA law of a linked pair.
------------------------------------------------------------------------- */

#ifndef LMP_MCA_LINK_LAW_H
#define LMP_MCA_LINK_LAW_H

#include "mca_fracture.h"
#include "mca_geometry.h"
#include "mca_link_layout.h"
#include "mca_material.h"
#include "mca_plasticity.h"

#include <cmath>
#include <string>

namespace LAMMPS_NS {
namespace MCAKernels {

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

  MCA_FORCE_INLINE void contact_slip(const double *n, const double *n_old, const double *del,
                                     const double *del_old, double q_i, double q_j,
                                     const double *w_i, const double *w_j, double dt, double *dl)
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

  // contact area from the mean stresses (thesis 3.65): A r = A0 r0 (1 + mean volumetric strain)
  MCA_INLINE double contact_area(double a0, double r0, double r, double sm_i, double k_i,
                                 double sm_j, double k_j)
  {
    return a0 * (r0 / r) * (1.0 + 0.5 * (sm_i / k_i + sm_j / k_j));
  }

  /* ----------------------------------------------------------------------
     the parts a link model is made of, one per slot of the law: the
     elastic part always; the part of an optional slot is selected by
     "pair_style mca <slot> <part>".  Each declares the blocks it keeps
     (doubles per link row and per automaton).  A new part is a line here,
     its kernel in the link step below and its doc (Developer_mca.rst)
  ------------------------------------------------------------------------- */

  enum LinkPart {
    PART_ELASTIC = 0,
    PART_DAMPING,
    PART_PLASTICITY,
    PART_FRACTURE,
    PART_CONTACT,
    PART_HEALING,
    NPARTS
  };

  // the block of the damping part in a link row: the damping force on lo
  // of the last step (normal, tangential) and the energy the link's
  // dampers dissipated
  enum DampingSlot { D_FN = 0, D_FT, D_WORK = D_FT + 3, D_SIZE };

  // the block of the plasticity part in a link row: the part of this
  // step's elastic work that the tractions of the last step did (the
  // trial pass computes it before the correction changes them), and the
  // plastic work of the link; per automaton: its plastic work (its
  // plastic strain is the atom style's epsp), and the couple of hi's
  // half (the correction scales each half's couple by its automaton's M,
  // so the halves' couples differ; H_COUPLE is lo's)
  enum PlasticitySlot { P_WORK_OLD = 0, P_WORK, P_COUPLE_HI, P_SIZE = P_COUPLE_HI + 3 };
  enum PlasticityAtomSlot { PA_WORK = 0, PA_SIZE };
  // the block of the fracture part in a link row: the criterion that broke
  // the link (BreakCriterion, 0 while intact), the step it broke at and
  // the elastic energy it held then (released by the break); per
  // automaton: the links it has forgotten (broken pairs that moved apart
  // farther than the cutoff, dropped from its table), by criterion, and
  // the energy their breaks released
  enum FractureSlot { F_CAUSE = 0, F_STEP, F_RELEASED, F_SIZE };
  enum FractureAtomSlot { FA_FORGOTTEN = 0, FA_RELEASED = FA_FORGOTTEN + NBREAK - 1, FA_SIZE };
  // the block of the contact part in a link row: the energy friction
  // dissipated at the pair; per automaton: what its dropped contacts and
  // forgotten broken pairs left (the energy their friction dissipated and
  // the rest of the work of their forces, each automaton keeping the whole
  // of each of its rows), and their number (mca_contact.h)
  enum ContactSlot { C_FRICTION = 0, C_SIZE };
  enum ContactAtomSlot { CA_FRICTION = 0, CA_WORK, CA_DROPPED, CA_SIZE };
  // the block of the healing part in a link row: the step the contact
  // becomes (or became) a link at (0: never; steps of a run are >= 1) and
  // what it left then, the energy its friction had dissipated and the
  // rest of the work of its forces (its elastic energy: the new link
  // starts stress-free); per automaton: the number of its links that
  // healed (mca_contact.h)
  enum HealingSlot { HL_STEP = 0, HL_FRICTION, HL_WORK, HL_SIZE };
  enum HealingAtomSlot { HA_HEALED = 0, HA_SIZE };
  static_assert(NPARTS <= MAX_PARTS, "more link parts than MCALinkLayout holds");

  // the couples of the two halves of a row: one, H_COUPLE, unless the
  // model has plasticity, whose block keeps hi's
  MCA_INLINE int couple_hi_offset(const MCALinkLayout &layout)
  {
    const int plasticity = layout.link_offset[PART_PLASTICITY];
    return plasticity >= 0 ? plasticity + P_COUPLE_HI : static_cast<int>(H_COUPLE);
  }
  // the two halves keep couples of their own (else they share H_COUPLE)
  MCA_INLINE bool separate_couples(const MCALinkLayout &layout)
  {
    return couple_hi_offset(layout) != H_COUPLE;
  }

  struct MCALinkPartInfo {
    const char *slot;    // elastic, (plasticity, fracture, damping, ...)
    const char *name;    // the part's keyword, and its name in restart files
    int part;            // LinkPart id
    int link_size, atom_size;
    bool required;    // in every model
    // the slots of its block (a bit each) that a row in "precision mixed"
    // keeps in double (mca_row_codec.h): the lengths and the normal, from
    // which every step's strain and rotation are differences (in floats
    // the wave's energy strays by 96 %, bench/README.md), and step numbers
    // (exact integers in a double, not in a float beyond 2^24)
    unsigned exact_slots;
  };

  constexpr MCALinkPartInfo MCA_LINK_PARTS[] = {
      {"elastic", "elastic", PART_ELASTIC, H_SIZE, A_SIZE, true, ELASTIC_EXACT_SLOTS},
      {"damping", "viscous", PART_DAMPING, D_SIZE, 0, false, 0u},
      {"plasticity", "mises", PART_PLASTICITY, P_SIZE, PA_SIZE, false, 0u},
      {"fracture", "links", PART_FRACTURE, F_SIZE, FA_SIZE, false, 1u << F_STEP},
      {"contacts", "coulomb", PART_CONTACT, C_SIZE, CA_SIZE, false, 0u},
      {"healing", "weld", PART_HEALING, HL_SIZE, HA_SIZE, false, 1u << HL_STEP},
  };
  constexpr int MCA_NUM_LINK_PARTS = sizeof(MCA_LINK_PARTS) / sizeof(MCA_LINK_PARTS[0]);
  static_assert(MCA_LINK_PARTS[PART_ELASTIC].part == PART_ELASTIC,
                "MCA_LINK_PARTS lists the elastic part at its id");

  // the id of the part a block is named after (restart files and the links
  // fix name blocks by their part's keyword), -1 if none
  inline int link_part_id(const std::string &name)
  {
    for (const auto &p : MCA_LINK_PARTS)
      if (name == p.name) return p.part;
    return -1;
  }
  // the slots of a part's block that a mixed row keeps in double
  inline unsigned link_part_exact_slots(int part)
  {
    for (const auto &p : MCA_LINK_PARTS)
      if (part == p.part) return p.exact_slots;
    return 0u;
  }

  /* ----------------------------------------------------------------------
     one step of a linked pair, all in canonical order (lo, hi):
       link_motion        length, normal, relative rotation
       normal_traction    elastic trial of the normal tractions (Newton-3 split)
       shear_traction     carry shear tractions and couples with the pair,
                          elastic trial of the shear tractions
       link_area          contact area
       link_couple        bending and torsion increments of the halves
       link_force         pair force from the mean tractions of the halves
       link_torques       couple of the pair, torques
       link_damping       (damping viscous) dashpot force and torques, the
                          energy it dissipated
       link_work          elastic work of the step; the row is committed
     (the order of the elastic law before the plasticity part: the same
     instructions).  Plasticity takes the step in two passes, below; see
     doc/src/Developer_mca.rst.
  ------------------------------------------------------------------------- */

  // what the law reads of the two automata of a link
  struct MCALinkEnds {
    const double *x_lo, *x_hi;    // positions (x_hi: the image of hi closest to lo)
    const double *w_lo, *w_hi;    // angular velocities
    double dsm_lo, dsm_hi;        // mean-stress increments to apply this step
    double sm_lo, sm_hi;          // predicted mean stresses (for the contact area)
    double chi;                   // face second moment / area^2
    double dt;                    // time step (0 in a setup: no spin)
    // where the blocks of the parts lie in the row: the elastic block is
    // at 0 (H_*); a part that follows finds its own at link_offset[part]
    const MCALinkLayout *layout;
  };

  // what a step gives the automata
  struct MCALinkForces {
    double f[3];                  // force on lo (on hi: -f)
    double tq_lo[3], tq_hi[3];    // torques on lo and hi
    double sig;                   // normal traction (for the mean stress)
    double t[3];                  // shear traction
    double trac[3];               // traction on lo, sig n + t; T n^T is the same for both
    double couple[3];             // bending and torsion couple
    double area;                  // contact area
    double r, n[3];               // current length and normal
  };

  // kinematics of the step and what the tractions acted with at the last step
  struct MCALinkMotion {
    double del[3];                         // x_hi - x_lo
    double dr;                             // length change since the last step
    double q_lo, q_hi;                     // current half lengths (after the normal update)
    double dl[3];                          // tangential slip of the contact points
    double dth[3];                         // relative rotation of hi against lo
    double sig_old, t_old[3], c_old[3];    // tractions and couple of the last step
  };

  // the kinematics of the step (not the tractions of the last step)
  MCA_INLINE void link_kinematics(const double *hist, const MCALinkEnds &e, MCALinkForces &out,
                                  MCALinkMotion &mo)
  {
    for (int m = 0; m < 3; m++) mo.del[m] = e.x_hi[m] - e.x_lo[m];
    out.r = sqrt(dot3(mo.del, mo.del));
    const double rinv = 1.0 / out.r;
    for (int m = 0; m < 3; m++) out.n[m] = mo.del[m] * rinv;
    mo.dr = out.r - hist[H_RPREV];
    for (int m = 0; m < 3; m++) mo.dth[m] = e.dt * (e.w_hi[m] - e.w_lo[m]);
  }

  // (forced inline: with the couple's offset read from the layout, GCC
  // stopped inlining it, and the call passed out and mo through memory)
  MCA_FORCE_INLINE void link_motion(const double *hist, const MCALinkEnds &e, MCALinkForces &out,
                                    MCALinkMotion &mo)
  {
    link_kinematics(hist, e, out, mo);
    const double *lo = hist + H_LO, *hi = hist + H_HI;
    const double *c_lo = hist + H_COUPLE, *c_hi = hist + couple_hi_offset(*e.layout);
    mo.sig_old = 0.5 * (lo[HALF_SIG] + hi[HALF_SIG]);
    for (int m = 0; m < 3; m++) {
      mo.t_old[m] = 0.5 * (lo[HALF_T + m] + hi[HALF_T + m]);
      mo.c_old[m] = 0.5 * (c_lo[m] + c_hi[m]);
    }
  }

  // the current half lengths q = q0 (1 + eps) of the two halves
  MCA_INLINE void half_lengths(const double *hist, MCALinkMotion &mo)
  {
    mo.q_lo = hist[H_Q0LO] * (1.0 + hist[H_LO + HALF_EPS]);
    mo.q_hi = hist[H_Q0HI] * (1.0 + hist[H_HI + HALF_EPS]);
  }

  MCA_INLINE void normal_traction(double *hist, const MCALinkEnds &e, const MCAMaterial &m_lo,
                                  const MCAMaterial &m_hi, MCALinkMotion &mo)
  {
    double *lo = hist + H_LO;
    double *hi = hist + H_HI;
    const double q0_lo = hist[H_Q0LO], q0_hi = hist[H_Q0HI];
    double de_lo, de_hi;
    const double sig_lo0 = lo[HALF_SIG], sig_hi0 = hi[HALF_SIG];
    split_normal_strain(sig_lo0, sig_hi0, m_lo.shear, m_hi.shear, m_lo.coupling, m_hi.coupling,
                        e.dsm_lo, e.dsm_hi, q0_lo, q0_hi, mo.dr, de_lo, de_hi);
    lo[HALF_EPS] += de_lo;
    hi[HALF_EPS] += de_hi;
    lo[HALF_SIG] = sig_lo0 + 2.0 * m_lo.shear * de_lo + m_lo.coupling * e.dsm_lo;
    hi[HALF_SIG] = sig_hi0 + 2.0 * m_hi.shear * de_hi + m_hi.coupling * e.dsm_hi;
    half_lengths(hist, mo);
  }

  // the slip of the contact points over the step (mo.q_lo, mo.q_hi set)
  MCA_FORCE_INLINE void link_slip(const double *hist, const MCALinkEnds &e, const double *n,
                                  MCALinkMotion &mo)
  {
    const double *n_old = hist + H_NPREV;
    const double rprev = hist[H_RPREV];
    const double del_old[3] = {rprev * n_old[0], rprev * n_old[1], rprev * n_old[2]};
    contact_slip(n, n_old, mo.del, del_old, mo.q_lo, mo.q_hi, e.w_lo, e.w_hi, e.dt, mo.dl);
  }

  /* the cosine and sine of the pair's twist in a step, as the law takes
     them: MCAExactTwist (every pass but one), or MCASeriesTwist, the series
     only, for a loop over several links at once that a call of cos() and
     sin() would keep from being vectorized (PairMCA's batched link pass):
     it marks a twist beyond the series' range (the same test as cos_sin),
     whose link the caller evaluates again with MCAExactTwist */
  struct MCAExactTwist {
    MCA_FUNCTION void cos_sin_of(double phi, double &c, double &s) { cos_sin(phi, c, s); }
  };
  struct MCASeriesTwist {
    bool beyond = false;
    MCA_FUNCTION void cos_sin_of(double phi, double &c, double &s)
    {
      beyond = !cos_sin_by_series(phi);
      cos_sin_series(phi, c, s);
    }
  };

  template <class Twist>
  MCA_FORCE_INLINE void shear_traction(double *hist, const MCALinkEnds &e, const MCAMaterial &m_lo,
                                       const MCAMaterial &m_hi, const double *n, MCALinkMotion &mo,
                                       Twist &twist)
  {
    double *lo = hist + H_LO;
    double *hi = hist + H_HI;

    // carry shear tractions and couples along with the pair
    const double phi = 0.5 * e.dt * (dot3(e.w_lo, n) + dot3(e.w_hi, n));
    const double *n_old = hist + H_NPREV;
    double rot[9];
    double cos_phi, sin_phi;
    twist.cos_sin_of(phi, cos_phi, sin_phi);
    pair_rotation(n_old, n, cos_phi, sin_phi, rot);
    rotate_with_pair(lo + HALF_T, rot, n, true);
    rotate_with_pair(hi + HALF_T, rot, n, true);
    rotate_with_pair(hist + H_COUPLE, rot, n, false);
    if (separate_couples(*e.layout))
      rotate_with_pair(hist + couple_hi_offset(*e.layout), rot, n, false);

    // shear tractions
    double dg_lo[3], dg_hi[3];
    link_slip(hist, e, n, mo);
    split_shear_strain(lo + HALF_T, hi + HALF_T, m_lo.shear, m_hi.shear, mo.q_lo, mo.q_hi, mo.dl,
                       dg_lo, dg_hi);
    for (int m = 0; m < 3; m++) {
      lo[HALF_T + m] += 2.0 * m_lo.shear * dg_lo[m];
      hi[HALF_T + m] += 2.0 * m_hi.shear * dg_hi[m];
    }
  }
  MCA_FORCE_INLINE void shear_traction(double *hist, const MCALinkEnds &e, const MCAMaterial &m_lo,
                                       const MCAMaterial &m_hi, const double *n, MCALinkMotion &mo)
  {
    MCAExactTwist twist;
    shear_traction(hist, e, m_lo, m_hi, n, mo, twist);
  }

  // contact area of the step (thesis 3.65)
  MCA_INLINE void link_area(const double *hist, const MCALinkEnds &e, const MCAMaterial &m_lo,
                            const MCAMaterial &m_hi, MCALinkForces &out)
  {
    out.area = contact_area(hist[H_A0], hist[H_R0], out.r, e.sm_lo, m_lo.bulk, e.sm_hi, m_hi.bulk);
  }

  // the tractions of the pair: the mean of the two halves
  MCA_INLINE void link_mean_tractions(const double *hist, MCALinkForces &out)
  {
    const double *lo = hist + H_LO;
    const double *hi = hist + H_HI;
    out.sig = 0.5 * (lo[HALF_SIG] + hi[HALF_SIG]);
    for (int m = 0; m < 3; m++) out.t[m] = 0.5 * (lo[HALF_T + m] + hi[HALF_T + m]);
  }

  // the pair force on lo from the mean tractions of the two halves
  MCA_INLINE void link_force(const double *hist, MCALinkForces &out)
  {
    link_mean_tractions(hist, out);
    const double *n = out.n;
    for (int m = 0; m < 3; m++) out.f[m] = out.area * (out.sig * n[m] + out.t[m]);
  }

  // the couple increments of the step in both halves: the faces act as
  // two elastic layers of thickness q_lo, q_hi in series; the relative
  // rotation splits into twist (along n) and bending (normal to n)
  MCA_INLINE void link_couple(double *hist, const MCALinkEnds &e, const MCAMaterial &m_lo,
                              const MCAMaterial &m_hi, const MCALinkMotion &mo,
                              const MCALinkForces &out)
  {
    const double *n = out.n;
    const double compliance = mo.q_lo / (2.0 * m_lo.shear) + mo.q_hi / (2.0 * m_hi.shear);
    const double kbend = e.chi * out.area * out.area / compliance;
    const double twist = dot3(mo.dth, n);
    double dcouple[3];
    for (int m = 0; m < 3; m++)
      dcouple[m] = kbend * (mo.dth[m] - twist * n[m]) + 2.0 * kbend * twist * n[m];
    for (int m = 0; m < 3; m++) hist[H_COUPLE + m] += dcouple[m];
    if (separate_couples(*e.layout)) {
      double *c_hi = hist + couple_hi_offset(*e.layout);
      for (int m = 0; m < 3; m++) c_hi[m] += dcouple[m];
    }
  }

  // the couple of the pair (mean of the halves) and the torques: moment
  // of the shear force about each centre, plus the couple
  MCA_INLINE void link_torques(const double *hist, const MCALinkLayout &layout,
                               const MCALinkMotion &mo, MCALinkForces &out)
  {
    const double *c_lo = hist + H_COUPLE, *c_hi = hist + couple_hi_offset(layout);
    const double *n = out.n;
    for (int m = 0; m < 3; m++) out.couple[m] = 0.5 * (c_lo[m] + c_hi[m]);
    double nxf[3];
    cross3(n, out.f, nxf);
    for (int m = 0; m < 3; m++) {
      out.tq_lo[m] = mo.q_lo * nxf[m] + out.couple[m];
      out.tq_hi[m] = mo.q_hi * nxf[m] - out.couple[m];
    }
    for (int m = 0; m < 3; m++) out.trac[m] = out.sig * n[m] + out.t[m];
  }

  /* ----------------------------------------------------------------------
     damping viscous: a dashpot of viscosity eta in each half, the two in
     series, on the relative velocity of the contact points over the step
     (dr/dt along n, the slip dl/dt across it), acting through the contact
     area.  The force is not part of the tractions (the stress and the
     mean-stress law stay elastic); it adds to the force and torques.  A
     setup (dt = 0) applies the force of the last step again, as the
     elastic part does; the dissipated energy is the trapezoidal work of
     the force over the step, as the elastic energy is
  ------------------------------------------------------------------------- */

  // force per unit area and relative velocity of two dashpots in series:
  // eta_lo eta_hi / (q_lo eta_hi + q_hi eta_lo), eta/r for equal halves
  MCA_INLINE double series_viscosity(double eta_lo, double eta_hi, double q_lo, double q_hi)
  {
    const double den = q_lo * eta_hi + q_hi * eta_lo;
    return den > 0.0 ? eta_lo * eta_hi / den : 0.0;
  }

  MCA_INLINE void link_damping(double *block, const MCALinkEnds &e, const MCAMaterial &m_lo,
                               const MCAMaterial &m_hi, const MCALinkMotion &mo, MCALinkForces &out)
  {
    const double *n = out.n;
    double fn, ft[3];
    if (e.dt > 0.0) {
      const double c =
          out.area * series_viscosity(m_lo.viscosity, m_hi.viscosity, mo.q_lo, mo.q_hi) / e.dt;
      fn = c * mo.dr;
      for (int m = 0; m < 3; m++) ft[m] = c * mo.dl[m];
      double work = 0.5 * (block[D_FN] + fn) * mo.dr;
      for (int m = 0; m < 3; m++) work += 0.5 * (block[D_FT + m] + ft[m]) * mo.dl[m];
      block[D_WORK] += work;
      block[D_FN] = fn;
      for (int m = 0; m < 3; m++) block[D_FT + m] = ft[m];
    } else {
      // the last step's force, its shear part kept in the contact plane
      fn = block[D_FN];
      const double ftn = dot3(block + D_FT, n);
      for (int m = 0; m < 3; m++) ft[m] = block[D_FT + m] - ftn * n[m];
    }
    double fd[3], nxf[3];
    for (int m = 0; m < 3; m++) fd[m] = fn * n[m] + ft[m];
    cross3(n, fd, nxf);
    for (int m = 0; m < 3; m++) {
      out.f[m] += fd[m];
      out.tq_lo[m] += mo.q_lo * nxf[m];
      out.tq_hi[m] += mo.q_hi * nxf[m];
    }
  }

  // elastic energy: work of the pair forces over the step, trapezoidal
  // rule with the forces that acted at the last step and now; the row
  // then holds this step's length, normal and area
  MCA_INLINE void link_work(double *hist, const MCALinkMotion &mo, const MCALinkForces &out)
  {
    const double a_old = hist[H_APREV];
    double work = 0.5 * (a_old * mo.sig_old + out.area * out.sig) * mo.dr;
    for (int m = 0; m < 3; m++)
      work += 0.5 * (a_old * mo.t_old[m] + out.area * out.t[m]) * mo.dl[m] +
          0.5 * (mo.c_old[m] + out.couple[m]) * mo.dth[m];
    hist[H_WORK] += work;

    hist[H_RPREV] = out.r;
    for (int m = 0; m < 3; m++) hist[H_NPREV + m] = out.n[m];
    hist[H_APREV] = out.area;
  }

  // the same in two parts: what the tractions of the last step did (in
  // the trial pass, before the correction changes them) and what this
  // step's do
  MCA_INLINE double link_work_old(const double *hist, const MCALinkMotion &mo)
  {
    const double a_old = hist[H_APREV];
    double work = 0.5 * a_old * mo.sig_old * mo.dr;
    for (int m = 0; m < 3; m++)
      work += 0.5 * a_old * mo.t_old[m] * mo.dl[m] + 0.5 * mo.c_old[m] * mo.dth[m];
    return work;
  }

  MCA_INLINE void link_work_new(double *hist, double work_old, const MCALinkMotion &mo,
                                const MCALinkForces &out)
  {
    double work = 0.5 * out.area * out.sig * mo.dr;
    for (int m = 0; m < 3; m++)
      work += 0.5 * out.area * out.t[m] * mo.dl[m] + 0.5 * out.couple[m] * mo.dth[m];
    hist[H_WORK] += work_old + work;

    hist[H_RPREV] = out.r;
    for (int m = 0; m < 3; m++) hist[H_NPREV + m] = out.n[m];
    hist[H_APREV] = out.area;
  }

  // the elastic trial of a step: the tractions of both halves, the
  // contact area and the couples, in the row (m_lo, m_hi: the caller's
  // local copies of the materials)
  template <class Twist>
  MCA_FORCE_INLINE void elastic_trial(double *hist, const MCALinkEnds &e, const MCAMaterial &m_lo,
                                      const MCAMaterial &m_hi, MCALinkForces &out,
                                      MCALinkMotion &mo, Twist &twist)
  {
    link_motion(hist, e, out, mo);
    normal_traction(hist, e, m_lo, m_hi, mo);
    shear_traction(hist, e, m_lo, m_hi, out.n, mo, twist);
    link_area(hist, e, m_lo, m_hi, out);
    link_couple(hist, e, m_lo, m_hi, mo, out);
  }

  // one step of a linked pair: hist is updated (the caller keeps or
  // discards it), out holds what acts on the automata
  template <class Twist>
  MCA_FORCE_INLINE void linked_pair(double *hist, const MCALinkEnds &e, const MCAMaterial &mat_lo,
                                    const MCAMaterial &mat_hi, MCALinkForces &out, Twist &twist)
  {
    // local copies of the materials: the stores into the row cannot change
    // them, so they stay in registers where the call is not inlined.  (Not
    // of e: the caller has just written it, and a wide copy of fresh
    // stores stalls)
    const MCAMaterial m_lo = mat_lo, m_hi = mat_hi;
    MCALinkMotion mo;
    elastic_trial(hist, e, m_lo, m_hi, out, mo, twist);
    link_force(hist, out);
    link_torques(hist, *e.layout, mo, out);
    // optional parts: one test each when they are off
    const int damping = e.layout->link_offset[PART_DAMPING];
    if (damping >= 0) link_damping(hist + damping, e, m_lo, m_hi, mo, out);
    link_work(hist, mo, out);
  }

  MCA_FORCE_INLINE void linked_pair(double *hist, const MCALinkEnds &e, const MCAMaterial &mat_lo,
                                    const MCAMaterial &mat_hi, MCALinkForces &out)
  {
    MCAExactTwist twist;
    linked_pair(hist, e, mat_lo, mat_hi, out, twist);
  }

  /* ----------------------------------------------------------------------
     a model with plasticity takes a step of a linked pair in two passes,
     between which each automaton finds its return factor M from the
     trial stress of all its links (doc/src/Developer_mca.rst):
       linked_pair_trial      the elastic trial of the tractions and
                              couples (left in the row), the old part of
                              the work; out.n and out.trac for the trial
                              stress of the automata
       linked_pair_corrected  the kinematics again, the plastic correction
                              of each half with its automaton's M and mean
                              stress, the forces (mean of the halves),
                              damping and the work
  ------------------------------------------------------------------------- */

  MCA_FORCE_INLINE void linked_pair_trial(double *hist, const MCALinkEnds &e,
                                          const MCAMaterial &mat_lo, const MCAMaterial &mat_hi,
                                          MCALinkForces &out)
  {
    const MCAMaterial m_lo = mat_lo, m_hi = mat_hi;
    MCALinkMotion mo;
    MCAExactTwist twist;
    elastic_trial(hist, e, m_lo, m_hi, out, mo, twist);
    hist[e.layout->link_offset[PART_PLASTICITY] + P_WORK_OLD] = link_work_old(hist, mo);
    link_mean_tractions(hist, out);
    for (int m = 0; m < 3; m++) out.trac[m] = out.sig * out.n[m] + out.t[m];
  }

  // what the correction reads of an automaton: its return factor M and
  // the mean stress of its trial
  struct MCAReturnEnds {
    double scale_lo, scale_hi;
    double smean_lo, smean_hi;
  };

  MCA_FORCE_INLINE void linked_pair_corrected(double *hist, const MCALinkEnds &e,
                                              const MCAMaterial &mat_lo, const MCAMaterial &mat_hi,
                                              const MCAReturnEnds &ret, MCALinkForces &out)
  {
    const MCAMaterial m_lo = mat_lo, m_hi = mat_hi;
    MCALinkMotion mo;
    // the kinematics of the trial, from the same row values
    link_kinematics(hist, e, out, mo);
    half_lengths(hist, mo);
    link_slip(hist, e, out.n, mo);
    link_area(hist, e, m_lo, m_hi, out);

    double *block = hist + e.layout->link_offset[PART_PLASTICITY];
    double work = 0.0;
    if (ret.scale_lo != 1.0)
      work += plastic_correct_half(hist + H_LO, hist + H_COUPLE, ret.scale_lo, ret.smean_lo,
                                   m_lo.shear, hist[H_Q0LO], mo.q_lo, out.area, e.chi, out.n);
    if (ret.scale_hi != 1.0)
      work += plastic_correct_half(hist + H_HI, block + P_COUPLE_HI, ret.scale_hi, ret.smean_hi,
                                   m_hi.shear, hist[H_Q0HI], mo.q_hi, out.area, e.chi, out.n);
    block[P_WORK] += work;

    link_force(hist, out);
    link_torques(hist, *e.layout, mo, out);
    const int damping = e.layout->link_offset[PART_DAMPING];
    if (damping >= 0) link_damping(hist + damping, e, m_lo, m_hi, mo, out);
    link_work_new(hist, block[P_WORK_OLD], mo, out);
  }

  /* ----------------------------------------------------------------------
     fracture links: a link that meets its criterion breaks (the fracture
     pass, after the step); from the next step on it is a broken pair that
     carries compression only.  Its two halves keep their normal strain
     and traction, which go on following the elastic normal law
     (normal_traction: the Newton-3 split with the mean-stress term) as
     "virtual" halves; the pair pushes with that traction while it is
     compressive and with none while it is tensile, so contact is lost and
     found again where the halves pass their stress-free length.  Shear
     tractions and couples are dropped at the break (no friction before
     the contact model).  A broken pair is not part of its automata's
     stress, mean stress or plastic return (those are over links).
  ------------------------------------------------------------------------- */

  MCA_INLINE bool broken(const double *row)
  {
    return static_cast<int>(row[H_STATE]) == LINK_BROKEN;
  }

  // the plastic work of a link (0 in a model without plasticity): its
  // elastic energy is the work of its forces, H_WORK, less this
  MCA_INLINE double link_plastic_work(const double *hist, const MCALinkLayout &layout)
  {
    const int plasticity = layout.link_offset[PART_PLASTICITY];
    return plasticity >= 0 ? hist[plasticity + P_WORK] : 0.0;
  }

  // a link breaks: its elastic energy (less its plastic work) is released.
  // Its tractions stay in the row for the first step of the broken pair
  // (finish_break)
  MCA_INLINE void break_link(double *hist, const MCALinkLayout &layout, int cause, double step)
  {
    const double plastic_work = link_plastic_work(hist, layout);
    double *block = hist + layout.link_offset[PART_FRACTURE];
    block[F_CAUSE] = cause;
    block[F_STEP] = step;
    block[F_RELEASED] = hist[H_WORK] - plastic_work;
    hist[H_WORK] = plastic_work;
    hist[H_STATE] = LINK_BROKEN;
  }

  // the first step of a broken pair: the forces of the link at its last
  // step (tractions, couples, dampers) gave the automata the first half
  // kick of this step (velocity Verlet), so their work over this step
  // (trapezoidal: half of it) belongs to the break, the elastic part to
  // the released energy, the dampers' to their dissipated energy; the
  // shear tractions, couples and damper forces are then dropped
  MCA_INLINE void finish_break(double *hist, const MCALinkLayout &layout, const MCALinkMotion &mo)
  {
    hist[layout.link_offset[PART_FRACTURE] + F_RELEASED] += link_work_old(hist, mo);
    const int damping = layout.link_offset[PART_DAMPING];
    if (damping >= 0) {
      double *block = hist + damping;
      double work = 0.5 * block[D_FN] * mo.dr;
      for (int m = 0; m < 3; m++) work += 0.5 * block[D_FT + m] * mo.dl[m];
      block[D_WORK] += work;
      block[D_FN] = 0.0;
      for (int m = 0; m < 3; m++) block[D_FT + m] = 0.0;
    }
    const int c_hi = couple_hi_offset(layout);
    for (int m = 0; m < 3; m++) {
      hist[H_LO + HALF_T + m] = hist[H_HI + HALF_T + m] = 0.0;
      hist[H_COUPLE + m] = hist[c_hi + m] = 0.0;
    }
  }

  // the pushing traction of a broken pair: the virtual normal traction
  // where it is compressive
  MCA_INLINE double broken_traction(double sig_virtual)
  {
    return sig_virtual < 0.0 ? sig_virtual : 0.0;
  }

  // one step of a broken pair (hist updated, as linked_pair); first: the
  // first step after the break.  In two parts, between which the contact
  // part puts its friction (mca_contact.h): the normal law of the virtual
  // halves and the pushing traction, then the forces and the work
  MCA_FORCE_INLINE void broken_pair_normal(double *hist, const MCALinkEnds &e,
                                           const MCAMaterial &m_lo, const MCAMaterial &m_hi,
                                           bool first, MCALinkForces &out, MCALinkMotion &mo)
  {
    link_motion(hist, e, out, mo);
    for (int m = 0; m < 3; m++) mo.dl[m] = 0.0;
    normal_traction(hist, e, m_lo, m_hi, mo);
    if (first) {
      // (the link's forces of the last step are accounted for whole)
      link_slip(hist, e, out.n, mo);
      finish_break(hist, *e.layout, mo);
      for (int m = 0; m < 3; m++) mo.t_old[m] = mo.c_old[m] = mo.dl[m] = 0.0;
      mo.sig_old = 0.0;
    } else {
      mo.sig_old = broken_traction(mo.sig_old);
    }
    link_area(hist, e, m_lo, m_hi, out);
    out.sig = broken_traction(0.5 * (hist[H_LO + HALF_SIG] + hist[H_HI + HALF_SIG]));
    for (int m = 0; m < 3; m++) out.t[m] = out.couple[m] = 0.0;
  }

  // the force of a pair that pushes with out.sig and rubs with out.t (a
  // broken pair, a contact) on lo, its torques (no couple: a pair that is
  // not linked resists no rolling), and the work of the step
  MCA_INLINE void pushing_pair_forces(double *hist, const MCALinkMotion &mo, MCALinkForces &out)
  {
    for (int m = 0; m < 3; m++) {
      out.couple[m] = 0.0;
      out.trac[m] = out.sig * out.n[m] + out.t[m];
      out.f[m] = out.area * out.trac[m];
    }
    double nxf[3];
    cross3(out.n, out.f, nxf);
    for (int m = 0; m < 3; m++) {
      out.tq_lo[m] = mo.q_lo * nxf[m];
      out.tq_hi[m] = mo.q_hi * nxf[m];
    }
    link_work(hist, mo, out);
  }

  MCA_FORCE_INLINE void broken_pair(double *hist, const MCALinkEnds &e, const MCAMaterial &mat_lo,
                                    const MCAMaterial &mat_hi, bool first, MCALinkForces &out)
  {
    const MCAMaterial m_lo = mat_lo, m_hi = mat_hi;
    MCALinkMotion mo;
    broken_pair_normal(hist, e, m_lo, m_hi, first, out, mo);
    for (int m = 0; m < 3; m++) {
      out.f[m] = out.area * out.sig * out.n[m];
      out.tq_lo[m] = out.tq_hi[m] = 0.0;    // a central force
      out.trac[m] = out.sig * out.n[m];
    }
    link_work(hist, mo, out);
  }

}    // namespace MCAKernels
}    // namespace LAMMPS_NS

#endif
