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
   contacts coulomb: automata that are not linked push and rub where they
   touch (doc/src/pair_mca.rst, "Contacts").  A contact is a row of the
   link table in the state CONTACT, made when LAMMPS reneighbors for every
   unlinked pair closer than R_lo + R_hi + skin and dropped when the pair
   is farther apart (PairMCA::update_contacts); its reference length r0 is
   the touch distance R_lo + R_hi.

   While r < r0 the two halves follow the elastic normal law of a link
   (normal_traction, the Newton-3 split) without the mean-stress term from
   the touch distance on and push with the compressive part of their
   traction (broken_traction); the shear tractions of the halves follow
   the elastic shear law of a link, capped by Coulomb's law
   |t| <= mu |sigma|.  While
   r >= r0 the halves are at rest: the next contact starts stress-free.
   The contact part gives broken pairs the same friction.
------------------------------------------------------------------------- */

#ifndef LMP_MCA_CONTACT_H
#define LMP_MCA_CONTACT_H

#include "mca_link_law.h"

namespace LAMMPS_NS {
namespace MCAKernels {

  // what the contact and healing parts know of a pair of atom types
  struct MCAContactRule {
    double mu;               // Coulomb friction coefficient
    int heal;                // may its contacts heal into links (healing weld)?
    double heal_pressure;    // at a compressive normal traction of at least this
    double heal_work;        // once an automaton has done this plastic work per volume
  };

  // the work of a row's forces that friction dissipated (0 in a model
  // without the contact part)
  MCA_INLINE double link_friction_work(const double *hist, const MCALinkLayout &layout)
  {
    const int contact = layout.link_offset[PART_CONTACT];
    return contact >= 0 ? hist[contact + C_FRICTION] : 0.0;
  }

  // shear traction per unit tangential slip of the two halves in series
  // (split_shear_strain): 1 / (q_lo/(2 G_lo) + q_hi/(2 G_hi)); its inverse
  MCA_INLINE double shear_compliance(const MCAMaterial &m_lo, const MCAMaterial &m_hi,
                                     const MCALinkMotion &mo)
  {
    return mo.q_lo / (2.0 * m_lo.shear) + mo.q_hi / (2.0 * m_hi.shear);
  }

  // Coulomb's law on the (equal) shear tractions of the halves: their mean
  // is capped at mu |sig| (sig <= 0, the pushing traction), both halves
  // scaled alike.  Returns what friction dissipated over the step: the
  // work of the shear force (trapezoidal, as the elastic energy is
  // counted, mca_link_law.h link_work) less the change of the energy of
  // the tangential spring, area compliance |t|^2 / 2, which is
  //   area compliance (t_old + t) . (t_trial - t) / 2
  // (the slip at the cap, compliance (t_trial - t), times the mean
  // traction): mu |sig| area per unit slip while sliding, the spring's
  // energy when it lets go, and exactly zero while the contact sticks.
  // out.t set
  MCA_INLINE double coulomb_cap(double *hist, double mu, double sig, double compliance, double area,
                                const double *t_old, MCALinkForces &out)
  {
    double *lo = hist + H_LO, *hi = hist + H_HI;
    double t[3];
    for (int m = 0; m < 3; m++) t[m] = 0.5 * (lo[HALF_T + m] + hi[HALF_T + m]);
    const double tt = dot3(t, t);
    const double limit = -mu * sig;
    double dissipated = 0.0;
    if (tt > limit * limit) {
      const double scale = limit / sqrt(tt);
      for (int m = 0; m < 3; m++) {
        const double capped = scale * t[m];
        dissipated += (t_old[m] + capped) * (t[m] - capped);
        lo[HALF_T + m] *= scale;
        hi[HALF_T + m] *= scale;
        t[m] = capped;
      }
      dissipated *= 0.5 * area * compliance;
    }
    for (int m = 0; m < 3; m++) out.t[m] = t[m];
    return dissipated;
  }

  // the shear of a pair that pushes with out.sig: the elastic trial of the
  // shear tractions (carried with the pair, the slip of the contact points)
  // and Coulomb's cap; friction's work to the contact block
  MCA_FORCE_INLINE void contact_shear(double *hist, const MCALinkEnds &e, const MCAMaterial &m_lo,
                                      const MCAMaterial &m_hi, double mu, MCALinkMotion &mo,
                                      MCALinkForces &out)
  {
    shear_traction(hist, e, m_lo, m_hi, out.n, mo);
    hist[e.layout->link_offset[PART_CONTACT] + C_FRICTION] +=
        coulomb_cap(hist, mu, out.sig, shear_compliance(m_lo, m_hi, mo), out.area, mo.t_old, out);
  }

  // one step of a broken pair with friction (broken_pair, plus the shear
  // from its second step on: the break dropped the link's shear tractions)
  MCA_FORCE_INLINE void broken_pair_friction(double *hist, const MCALinkEnds &e,
                                             const MCAMaterial &mat_lo, const MCAMaterial &mat_hi,
                                             bool first, double mu, MCALinkForces &out)
  {
    const MCAMaterial m_lo = mat_lo, m_hi = mat_hi;
    MCALinkMotion mo;
    broken_pair_normal(hist, e, m_lo, m_hi, first, out, mo);
    if (!first) contact_shear(hist, e, m_lo, m_hi, mu, mo, out);
    pushing_pair_forces(hist, mo, out);
  }

  // the halves of a contact at rest (apart: the next contact starts
  // stress-free at the touch distance)
  MCA_INLINE void contact_rest(double *hist, const MCALinkLayout &layout)
  {
    for (int k = 0; k < HALF_SIZE; k++) hist[H_LO + k] = hist[H_HI + k] = 0.0;
    const int c_hi = couple_hi_offset(layout);
    for (int m = 0; m < 3; m++) hist[H_COUPLE + m] = hist[c_hi + m] = 0.0;
  }

  // one step of a contact (hist updated, as linked_pair).  Its halves
  // follow the normal law of a link without the mean-stress term, and its
  // area does not follow the mean stress: the force of a contact depends
  // on its own motion alone, so that it does no net work over an approach
  // and a separation (with the term, an oblique impact gained 6.8 % of its
  // energy from its contacts; doc/src/pair_mca.rst, "Contacts")
  MCA_FORCE_INLINE void contact_pair(double *hist, const MCALinkEnds &ends,
                                     const MCAMaterial &mat_lo, const MCAMaterial &mat_hi,
                                     double mu, MCALinkForces &out)
  {
    const MCAMaterial m_lo = mat_lo, m_hi = mat_hi;
    MCALinkEnds e = ends;
    e.dsm_lo = e.dsm_hi = e.sm_lo = e.sm_hi = 0.0;
    MCALinkMotion mo;
    link_motion(hist, e, out, mo);
    mo.sig_old = broken_traction(mo.sig_old);
    const double r0 = hist[H_R0];
    if (out.r < r0) {
      const bool touched = hist[H_RPREV] < r0;
      // the first step in touch: strained from the touch distance, no slip yet
      if (!touched) mo.dr = out.r - r0;
      normal_traction(hist, e, m_lo, m_hi, mo);
      link_area(hist, e, m_lo, m_hi, out);
      out.sig = broken_traction(0.5 * (hist[H_LO + HALF_SIG] + hist[H_HI + HALF_SIG]));
      if (touched) {
        contact_shear(hist, e, m_lo, m_hi, mu, mo, out);
      } else {
        for (int m = 0; m < 3; m++) mo.dl[m] = out.t[m] = 0.0;
      }
    } else {
      // apart: the last step's forces act over this step (their work);
      // the tangential spring lets go: friction dissipates its energy and
      // the work of its force over the step; the halves come to rest
      half_lengths(hist, mo);
      link_slip(hist, e, out.n, mo);
      const double compliance = shear_compliance(m_lo, m_hi, mo);
      double released = 0.0;
      for (int m = 0; m < 3; m++) released += mo.t_old[m] * (compliance * mo.t_old[m] + mo.dl[m]);
      hist[e.layout->link_offset[PART_CONTACT] + C_FRICTION] += 0.5 * hist[H_APREV] * released;
      contact_rest(hist, *e.layout);
      link_area(hist, e, m_lo, m_hi, out);
      out.sig = 0.0;
      for (int m = 0; m < 3; m++) out.t[m] = 0.0;
    }
    pushing_pair_forces(hist, mo, out);
  }

  /* ----------------------------------------------------------------------
     healing weld (doc/src/pair_mca.rst, "Healing"): a contact whose type
     pair may heal is marked at the end of a step where it pushes with a
     normal traction of at least heal_pressure and where the larger of the
     plastic work densities of its automata (the softer one's, where one
     deforms) has reached heal_work.  At the next step it becomes a link,
     stress-free at its length of that step: its last forces gave the
     automata the first half kick of that step, so their work over the
     step (trapezoidal: half of it) still belongs to the contact, as the
     work of a broken link's last forces belongs to its break
     (finish_break).  What the contact held, its friction energy and the
     rest of the work of its forces (its elastic energy), leaves the row
     for its automata's law state (healed_of, mca_link_passes.h)
  ------------------------------------------------------------------------- */

  // does contact row hist meet its type pair's healing criterion?  w_lo,
  // w_hi: the plastic work densities of its automata
  MCA_INLINE bool heals(const double *hist, const MCAContactRule &rule, double w_lo, double w_hi)
  {
    if (!rule.heal) return false;
    const double sig = 0.5 * (hist[H_LO + HALF_SIG] + hist[H_HI + HALF_SIG]);
    return -sig >= rule.heal_pressure && (w_lo > w_hi ? w_lo : w_hi) >= rule.heal_work;
  }

  // a contact marked to become a link at this step?
  MCA_INLINE bool heal_pending(const double *hist, const MCALinkLayout &layout, double step)
  {
    const int healing = layout.link_offset[PART_HEALING];
    return healing >= 0 && hist[healing + HL_STEP] == step;
  }

  // the step of a marked contact: it becomes a link, stress-free at the
  // present length, with the same contact plane (half lengths in the
  // ratio of the radii, R_lo : R_hi) and reference area; no force this
  // step (hist updated, out set)
  MCA_FORCE_INLINE void heal_contact(double *hist, const MCALinkEnds &e, MCALinkForces &out)
  {
    const MCALinkLayout &layout = *e.layout;
    MCALinkMotion mo;
    link_motion(hist, e, out, mo);
    mo.sig_old = broken_traction(mo.sig_old);
    half_lengths(hist, mo);
    link_slip(hist, e, out.n, mo);
    double *block = hist + layout.link_offset[PART_HEALING];
    const double friction = link_friction_work(hist, layout);
    block[HL_FRICTION] = friction;
    block[HL_WORK] = hist[H_WORK] + link_work_old(hist, mo) - friction;
    hist[layout.link_offset[PART_CONTACT] + C_FRICTION] = 0.0;
    hist[H_WORK] = 0.0;
    // (a contact row has no plastic work, no damper force, no break)
    contact_rest(hist, layout);
    const double scale = out.r / (hist[H_Q0LO] + hist[H_Q0HI]);
    hist[H_Q0LO] *= scale;
    hist[H_Q0HI] *= scale;
    hist[H_R0] = hist[H_RPREV] = out.r;
    for (int m = 0; m < 3; m++) hist[H_NPREV + m] = out.n[m];
    hist[H_APREV] = out.area = hist[H_A0];
    hist[H_STATE] = LINK_LINKED;
    out.sig = 0.0;
    for (int m = 0; m < 3; m++)
      out.t[m] = out.trac[m] = out.couple[m] = out.f[m] = out.tq_lo[m] = out.tq_hi[m] = 0.0;
  }

}    // namespace MCAKernels
}    // namespace LAMMPS_NS

#endif
