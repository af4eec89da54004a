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
   The passes of pair_style mca over the links of one automaton, written
   once for the CPU style (a loop over the local automata) and the Kokkos
   style (one kernel call per automaton or per chunk of automata).

   A pass is a template over
     D      the data: per-automaton fields and the link table, read as
            d.x(i, k), d.x_row(i, scratch) (the 3 coordinates in a row:
            the array's own, or copied into scratch), d.tag(i),
            d.nlinks(i), d.partner(i, m) (local or
            ghost index), d.history_row(i, m) (the link's stored row: one
            row for both ends of a link between local automata; read and
            written through mca_row_codec.h), d.atom_state(i, k),
            d.material(type), ... (PairMCA::HostData, MCAPairViews)
     Sums   where a link adds to its two automata: begin(i) gives the
            adder of automaton i; own(add, i, k, v) adds v to column k of
            i, partner_of(add, j) the target of a local partner,
            partner(add, to, k, v) adds there (pair_mca_host.h,
            pair_mca_kokkos_kernels.h); one value at a time, the product
            computed in the call, which keeps the link pass free of
            temporary arrays
     Tally  energy and virial of a link (Pair::ev_tally_xyz on the CPU, a
            reduction in Kokkos), where wanted()

   Each link is evaluated once per processor that owns one of its
   automata: by the lower ID when both are local, by each owner (in its
   own row) when the partner is a ghost atom.
------------------------------------------------------------------------- */

#ifndef LMP_MCA_LINK_PASSES_H
#define LMP_MCA_LINK_PASSES_H

#include "lmptype.h"
#include "mca_contact.h"
#include "mca_link_law.h"
#include "mca_mean_stress.h"
#include "mca_row_codec.h"

namespace LAMMPS_NS {
namespace MCAKernels {

  // per-automaton sums of the two link passes (columns): the predictor's
  // fabric tensor F and strain moment M, and the link pass's force,
  // torque and traction moment B
  constexpr int PS_FABRIC = 0, PS_STRAIN = 6, PS_SIZE = 12;
  constexpr int LS_FORCE = 0, LS_TORQUE = 3, LS_BMAT = 6, LS_SIZE = 15;

  // the ownership rule: a link between two local automata is evaluated
  // by the lower ID.  Is that the partner j of automaton i?
  template <class D> MCA_FUNCTION bool partner_evaluates(const D &d, int i, int j)
  {
    return j < d.nlocal && d.tag(j) < d.tag(i);
  }

  // what partner_evaluates reads, where no data policy is at hand (the
  // links fix sharing rows, the pair style making the links)
  struct MCALinkOwners {
    int nlocal;
    const tagint *tags;
    MCA_FUNCTION tagint tag(int i) const { return tags[i]; }
  };

  MCA_INLINE bool linked(const double *row)
  {
    return static_cast<int>(row[H_STATE]) == LINK_LINKED;
  }

  // does automaton i evaluate its link m, in the state State (LinkState)?
  // row: the link's stored row, j: the partner.  The row is read only for the
  // links i evaluates: the row of a link the partner evaluates is the
  // partner's (loading it would be wasted traffic, and on threads the
  // partner's thread may be changing it)
  template <int State, class D>
  MCA_FORCE_INLINE bool evaluates(const D &d, int i, int m, double *&row, int &j)
  {
    j = d.partner(i, m);
    if (partner_evaluates(d, i, j)) return false;
    row = d.history_row(i, m);
    return stored_state(d.layout, row) == State;
  }

  /* ----------------------------------------------------------------------
     count: interacting links of automaton i and its stiffness in the
     mean-stress predictor (sent to the ghost atoms)
  ------------------------------------------------------------------------- */

  template <class D> MCA_FUNCTION void count_links_of(const D &d, int i)
  {
    int n = 0;
    for (int m = 0; m < d.nlinks(i); m++)
      if (stored_state(d.layout, d.history_row(i, m)) == LINK_LINKED) n++;
    d.link_count(i) = n;
    const MCAMaterial &mat = d.material(d.type(i));
    const int nc = d.packing(i);
    d.pred_stiffness(i) = (nc > 0) ? predictor_stiffness(mat.shear, mat.bulk, nc, n) : 0.0;
  }

  /* ----------------------------------------------------------------------
     predictor: fabric tensor and predicted strain moment of the links
     that automaton i evaluates, added to i and a local partner
  ------------------------------------------------------------------------- */

  template <class D, class Sums>
  MCA_FUNCTION void predictor_links_of(const D &d, const Sums &sums, int i)
  {
    auto add = sums.begin(i);
    double work[MAX_ROW_SIZE];
    for (int m = 0; m < d.nlinks(i); m++) {
      const int j = d.partner(i, m);
      if (partner_evaluates(d, i, j)) continue;
      const double *stored = d.history_row(i, m);
      const int state = stored_state(d.layout, stored);
      const double del[3] = {d.x(j, 0) - d.x(i, 0), d.x(j, 1) - d.x(i, 1), d.x(j, 2) - d.x(i, 2)};
      double nn[6], de_i, de_j;
      if (state != LINK_LINKED) {
        // the face of a broken link stays in the fabric tensor with a
        // traction of zero (a crack face): the stress of an automaton that
        // lost links keeps a well-conditioned fit (the links left may all
        // lie in a plane)
        if (state != LINK_BROKEN) continue;
        link_direction(del, nn);
        de_i = de_j = 0.0;
      } else {
        link_prediction(read_row(d.layout, stored, work, H_PREDICTOR_END), del, d.tag(i) < d.tag(j),
                        d.pred_stiffness(i), d.pred_stiffness(j), nn, de_i, de_j);
      }
      for (int k = 0; k < 6; k++) {
        sums.own(add, i, PS_FABRIC + k, nn[k]);
        sums.own(add, i, PS_STRAIN + k, de_i * nn[k]);
      }
      if (j < d.nlocal) {
        const auto to = sums.partner_of(add, j);
        for (int k = 0; k < 6; k++) {
          sums.partner(add, to, PS_FABRIC + k, nn[k]);
          sums.partner(add, to, PS_STRAIN + k, de_j * nn[k]);
        }
      }
    }
  }

  // the mean stress automaton i's normal law applies this step, from its
  // predictor sums; its fabric tensor is kept for the stress
  template <class D>
  MCA_FUNCTION void predictor_finish_of(const D &d, int i, const double *sums, bool setup_pass)
  {
    const double *fab = sums + PS_FABRIC, *mstrain = sums + PS_STRAIN;
    for (int k = 0; k < 6; k++) d.fabric(i, k) = fab[k];
    const bool interacting = d.link_count(i) > 0 && d.packing(i) != PACKING_NONE;
    double smean_pred, dsmean;
    mean_stress_prediction(interacting, setup_pass, d.atom_state(i, A_SMEAN_STEP),
                           d.atom_state(i, A_SMEAN_LAW), fab, mstrain, d.material(d.type(i)).bulk,
                           smean_pred, dsmean);
    d.smean_pred(i) = smean_pred;
    d.dsmean(i) = dsmean;
  }

  /* ----------------------------------------------------------------------
     link pass: the links automaton i evaluates; force, torque and
     traction moment added to i and a local partner
  ------------------------------------------------------------------------- */

  struct MCALinkPassFlags {
    bool commit;     // a step of a run: the rows advance (a setup works on copies)
    double dt;       // time step, 0 in a setup (spins turn automata only in steps)
    double cutsq;    // square of the pair cutoff (links longer are counted)
    double step;     // the time step number (a broken pair's first step)
    // healing with criteria of the contact pressure only: the contact pass
    // marks the contacts that heal (the heal pass would read the same
    // tractions: nothing changes a contact's row in between)
    bool heal_in_pass;
  };

  // what the law reads of the automata lo and hi of a link (scratch: 12
  // doubles for rows that are not contiguous in memory)
  template <class D>
  MCA_FORCE_INLINE void link_ends_of(const D &d, int lo, int hi, double dt, double *scratch,
                                     MCALinkEnds &e)
  {
    e.x_lo = d.x_row(lo, scratch);
    e.x_hi = d.x_row(hi, scratch + 3);
    e.w_lo = d.omega_row(lo, scratch + 6);
    e.w_hi = d.omega_row(hi, scratch + 9);
    e.dsm_lo = d.dsmean(lo);
    e.dsm_hi = d.dsmean(hi);
    e.sm_lo = d.smean_pred(lo);
    e.sm_hi = d.smean_pred(hi);
    e.chi = face_moment_factor(d.packing(lo));
    e.dt = dt;
    e.layout = &d.layout;
  }

  // T n^T of a link (the same for both automata) to the LS_BMAT columns of
  // automaton i, or of a local partner (to: Sums::partner_of)
  template <class Sums, class Thread>
  MCA_FORCE_INLINE void add_traction_moment(const Sums &sums, Thread &add, int i,
                                            const MCALinkForces &out)
  {
    for (int a = 0; a < 3; a++)
      for (int b = 0; b < 3; b++) sums.own(add, i, LS_BMAT + 3 * a + b, out.trac[a] * out.n[b]);
  }

  template <class Sums, class Thread, class To>
  MCA_FORCE_INLINE void add_traction_moment_to_partner(const Sums &sums, Thread &add, const To &to,
                                                       const MCALinkForces &out)
  {
    for (int a = 0; a < 3; a++)
      for (int b = 0; b < 3; b++)
        sums.partner(add, to, LS_BMAT + 3 * a + b, out.trac[a] * out.n[b]);
  }

  // what a linked pair's step gives automaton i, which evaluates it, and a
  // local partner j: force, torque and T n^T, the count of long links,
  // energy and virial (elastic_work: the pair's elastic energy).  Each pass
  // over linked pairs adds them in the order of the automata and their links
  template <class D, class Sums, class Thread, class Tally, class Totals>
  MCA_FORCE_INLINE void add_link_outputs(const D &d, const Sums &sums, Thread &add,
                                         const Tally &tally, const MCALinkPassFlags &p, int i,
                                         int j, double elastic_work, const MCALinkForces &out,
                                         Totals &totals)
  {
    const bool jlocal = j < d.nlocal;
    const bool ilo = d.tag(i) < d.tag(j);
    // counted once per owner: the warning halves the sum
    if (out.r * out.r > p.cutsq) totals.nlong += jlocal ? 2 : 1;

    // force on lo is f, on hi -f; T n^T is the same for both
    const double sign = ilo ? 1.0 : -1.0;
    // (a value chosen per component, not a pointer to one of the two
    // arrays: a pointer chosen at run time puts all of out in the local
    // memory of a GPU thread, which costs the link pass 10 %)
    for (int k = 0; k < 3; k++) {
      sums.own(add, i, LS_FORCE + k, sign * out.f[k]);
      sums.own(add, i, LS_TORQUE + k, ilo ? out.tq_lo[k] : out.tq_hi[k]);
    }
    add_traction_moment(sums, add, i, out);
    if (jlocal) {
      const auto to = sums.partner_of(add, j);
      for (int k = 0; k < 3; k++) {
        sums.partner(add, to, LS_FORCE + k, -out.f[k]);
        sums.partner(add, to, LS_TORQUE + k, out.tq_hi[k]);
      }
      add_traction_moment_to_partner(sums, add, to, out);
    }

    // energy and virial: the whole pair, or this owner's half of it
    if (tally.wanted()) tally.link(totals, d, i, j, jlocal, sign, elastic_work, out.f);
  }

  // the law of a link pass: elastic (also with damping), or with
  // plasticity: a step (the second pass, after the trial pass and the
  // return of the automata) or a setup (no return: the elastic sequence on
  // a copy, the energy less the plastic work).  One instantiation each, so
  // that no kernel carries the code of a sequence it does not run
  enum LinkPassLaw { LAW_ELASTIC = 0, LAW_PLASTIC_SETUP, LAW_PLASTIC };

  template <int Law, class D, class Sums, class Tally, class Totals>
  MCA_FUNCTION void link_pass_of(const D &d, const Sums &sums, const Tally &tally,
                                 const MCALinkPassFlags &p, int i, Totals &totals)
  {
    auto add = sums.begin(i);
    for (int m = 0; m < d.nlinks(i); m++) {
      double *row;
      int j;
      if (!evaluates<LINK_LINKED>(d, i, m, row, j)) continue;
      const bool ilo = d.tag(i) < d.tag(j);
      const int lo = ilo ? i : j, hi = ilo ? j : i;

      // a step updates the row (in place, or decoded and encoded again);
      // a setup works on a copy
      double work[MAX_ROW_SIZE];
      double *h = open_row(d.layout, row, work, p.commit);
      MCALinkEnds e;
      double scratch[12];
      link_ends_of(d, lo, hi, p.dt, scratch, e);
      MCALinkForces out;
      const MCAMaterial &m_lo = d.material(d.type(lo)), &m_hi = d.material(d.type(hi));
      if (Law == LAW_PLASTIC_SETUP) {
        // a setup returns no automaton: its forces are those of the last
        // step (the split of the halves gives back their mean) plus the
        // elastic response to what moved since
        linked_pair(h, e, m_lo, m_hi, out);
      } else if (Law == LAW_PLASTIC) {
        MCAReturnEnds ret;
        ret.scale_lo = d.return_scale(lo);
        ret.scale_hi = d.return_scale(hi);
        ret.smean_lo = d.return_smean(lo);
        ret.smean_hi = d.return_smean(hi);
        linked_pair_corrected(h, e, m_lo, m_hi, ret, out);
      } else {
        linked_pair(h, e, m_lo, m_hi, out);
      }
      // the energy of the pair is elastic: with plasticity, less the
      // plastic work
      double elastic_work = h[H_WORK];
      if (Law != LAW_ELASTIC) elastic_work -= h[d.layout.link_offset[PART_PLASTICITY] + P_WORK];
      if (p.commit) close_row(d.layout, h, row);
      add_link_outputs(d, sums, add, tally, p, i, j, elastic_work, out, totals);
    }
  }

  /* ----------------------------------------------------------------------
     a model with plasticity: the trial pass (the elastic trial of the
     links automaton i evaluates, left in their rows; its traction moment
     B in the LS_BMAT columns of i and a local partner), then the return
     of each automaton from its trial stress (M and the trial mean stress,
     sent to the ghosts), then link_pass_of<LAW_PLASTIC>.  In steps of a run
     only
  ------------------------------------------------------------------------- */

  // (steps of a run only: a setup returns no automaton, see link_pass_of)
  template <class D, class Sums>
  MCA_FUNCTION void trial_pass_of(const D &d, const Sums &sums, const MCALinkPassFlags &p, int i)
  {
    auto add = sums.begin(i);
    for (int m = 0; m < d.nlinks(i); m++) {
      double *row;
      int j;
      if (!evaluates<LINK_LINKED>(d, i, m, row, j)) continue;
      const bool ilo = d.tag(i) < d.tag(j);
      const int lo = ilo ? i : j, hi = ilo ? j : i;
      MCALinkEnds e;
      double scratch[12];
      link_ends_of(d, lo, hi, p.dt, scratch, e);
      MCALinkForces out;
      double work[MAX_ROW_SIZE];
      double *h = open_row(d.layout, row, work, true);
      linked_pair_trial(h, e, d.material(d.type(lo)), d.material(d.type(hi)), out);
      close_row(d.layout, h, row);
      add_traction_moment(sums, add, i, out);
      if (j < d.nlocal) {
        const auto to = sums.partner_of(add, j);
        add_traction_moment_to_partner(sums, add, to, out);
      }
    }
  }

  // the return of automaton i from its trial traction moment: M and the
  // trial mean stress for the links; in a step, the plastic strain and
  // work advance
  template <class D>
  MCA_FUNCTION void plastic_return_of(const D &d, int i, const double *bmat, bool commit)
  {
    const int type = d.type(i);
    double fab[6], stress[6], smean, seq, eeq;
    for (int k = 0; k < 6; k++) fab[k] = d.fabric(i, k);
    const double g = d.material(type).shear;
    automaton_stress(bmat, fab, g, stress, smean, seq, eeq);
    MCAPlasticReturn ret = {1.0, 0.0, 0.0};    // an automaton without links stays elastic
    if (d.link_count(i) > 0 && d.packing(i) != PACKING_NONE)
      plastic_return(d.hardening(type), g, d.epsp(i), seq, ret);
    d.return_scale(i) = ret.scale;
    d.return_smean(i) = smean;
    if (commit && ret.dep > 0.0) {
      d.epsp(i) += ret.dep;
      d.atom_state(i, d.layout.atom_offset[PART_PLASTICITY] + PA_WORK) +=
          d.volume(i) * ret.flow * ret.dep;
    }
  }

  /* ----------------------------------------------------------------------
     fracture links (mca_fracture.h, mca_link_law.h): the broken pass
     gives the force of the broken pairs automaton i evaluates (the same
     ownership rule and sums as the link pass; no torque, no traction
     moment: a broken pair is not part of the automata's stress); the
     fracture pass, after the stress of the step is known (and sent to
     the ghosts with the plastic strain), breaks the links i evaluates that
     meet their criterion; the damage of i then counts its broken links.
     The decision for a link is made once per owner from the same values
     (its row and the automata's stress of this step), so every rank and
     thread count breaks the same links
  ------------------------------------------------------------------------- */

  // mark a contact that meets its criterion (a link from the
  // next step on: healing weld, below)
  MCA_INLINE bool mark_heal(double *row, const MCALinkLayout &layout, const MCAContactRule &rule,
                            double w_lo, double w_hi, double step)
  {
    if (!heals(row, rule, w_lo, w_hi)) return false;
    row[layout.link_offset[PART_HEALING] + HL_STEP] = step + 1.0;
    return true;
  }

  // pairs that push (State: the broken pairs, or the contacts of the
  // contact part, mca_contact.h): the same ownership rule and sums as the
  // link pass; a force (and, with friction, torques), no traction moment:
  // such a pair is not part of the automata's stress
  template <int State, class D, class Sums, class Tally, class Totals>
  MCA_FUNCTION void pushing_pass_of(const D &d, const Sums &sums, const Tally &tally,
                                    const MCALinkPassFlags &p, int i, Totals &totals)
  {
    const int ff = d.layout.link_offset[PART_FRACTURE];
    const bool friction = d.layout.link_offset[PART_CONTACT] >= 0;
    auto add = sums.begin(i);
    for (int m = 0; m < d.nlinks(i); m++) {
      double *row;
      int j;
      if (!evaluates<State>(d, i, m, row, j)) continue;
      const bool jlocal = j < d.nlocal;
      const bool ilo = d.tag(i) < d.tag(j);
      const int lo = ilo ? i : j, hi = ilo ? j : i;
      double work[MAX_ROW_SIZE];
      double *h = open_row(d.layout, row, work, p.commit);
      MCALinkEnds e;
      double scratch[12];
      link_ends_of(d, lo, hi, p.dt, scratch, e);
      MCALinkForces out;
      const MCAMaterial &m_lo = d.material(d.type(lo)), &m_hi = d.material(d.type(hi));
      if (State == LINK_CONTACT) {
        const MCAContactRule &rule = d.contact_rule(d.type(lo), d.type(hi));
        if (p.commit && heal_pending(h, d.layout, p.step)) {
          heal_contact(h, e, out);
          totals.nhealed++;
        } else {
          contact_pair(h, e, m_lo, m_hi, rule.mu, out);
          if (p.heal_in_pass) mark_heal(h, d.layout, rule, 0.0, 0.0, p.step);
        }
      } else {
        const bool first = p.commit && h[ff + F_STEP] == p.step - 1.0;
        if (friction)
          broken_pair_friction(h, e, m_lo, m_hi, first, d.contact_rule(d.type(lo), d.type(hi)).mu,
                               out);
        else
          broken_pair(h, e, m_lo, m_hi, first, out);
      }
      if (p.commit) close_row(d.layout, h, row);
      const double elastic_work =
          h[H_WORK] - link_plastic_work(h, d.layout) - link_friction_work(h, d.layout);
      const double sign = ilo ? 1.0 : -1.0;
      for (int k = 0; k < 3; k++) sums.own(add, i, LS_FORCE + k, sign * out.f[k]);
      if (friction)
        for (int k = 0; k < 3; k++)
          sums.own(add, i, LS_TORQUE + k, ilo ? out.tq_lo[k] : out.tq_hi[k]);
      if (jlocal) {
        const auto to = sums.partner_of(add, j);
        for (int k = 0; k < 3; k++) sums.partner(add, to, LS_FORCE + k, -out.f[k]);
        if (friction)
          for (int k = 0; k < 3; k++) sums.partner(add, to, LS_TORQUE + k, out.tq_hi[k]);
      }
      if (tally.wanted()) tally.link(totals, d, i, j, jlocal, sign, elastic_work, out.f);
    }
  }

  struct MCABreakFlags {
    double step;       // the time step number, recorded by a break
    double scatter;    // strength scatter w (0: none) and its seed
    int seed;
  };

  // (returns the number of links it broke)
  template <class D> MCA_FUNCTION int fracture_pass_of(const D &d, const MCABreakFlags &p, int i)
  {
    int nbroke = 0;
    for (int m = 0; m < d.nlinks(i); m++) {
      double *row;
      int j;
      if (!evaluates<LINK_LINKED>(d, i, m, row, j)) continue;
      const bool ilo = d.tag(i) < d.tag(j);
      const int lo = ilo ? i : j, hi = ilo ? j : i;
      const MCABreakRule rule = d.break_rule(d.type(lo), d.type(hi));
      if (rule.criterion == BREAK_NONE) continue;
      double work[MAX_ROW_SIZE];
      double *h = open_row(d.layout, row, work, true);

      // the link's tractions of this step (mean of the halves), its normal
      // and half lengths, and the stress of its automata
      MCALinkForces tractions;
      link_mean_tractions(h, tractions);
      MCALinkMotion halves;
      half_lengths(h, halves);
      double s_lo[6], s_hi[6];
      MCABreakInput in;
      in.n = h + H_NPREV;
      in.sig = tractions.sig;
      in.t = tractions.t;
      in.q_lo = halves.q_lo;
      in.q_hi = halves.q_hi;
      for (int k = 0; k < 6; k++) {
        s_lo[k] = d.stress(lo, k);
        s_hi[k] = d.stress(hi, k);
      }
      in.s_lo = s_lo;
      in.s_hi = s_hi;
      in.epsp_lo = d.epsp(lo);
      in.epsp_hi = d.epsp(hi);
      in.shear_lo = d.material(d.type(lo)).shear;
      in.shear_hi = d.material(d.type(hi)).shear;
      const double index = failure_index(rule, in);
      if (!(index >= strength_factor(p.scatter, p.seed, d.tag(lo), d.tag(hi)))) continue;

      break_link(h, d.layout, rule.criterion, p.step);
      close_row(d.layout, h, row);
      nbroke++;
    }
    return nbroke;
  }

  // damage of automaton i: the fraction of its links that are broken,
  // counting those it has forgotten.  Returns the energy released by its
  // links that broke at step break_step (its half of each; none for a
  // negative step): the energy tally of that step, made before the
  // fracture pass, still counts it as elastic energy
  template <class D> MCA_FUNCTION double damage_of(const D &d, int i, double break_step)
  {
    const int ff = d.layout.link_offset[PART_FRACTURE];
    int nbroken = 0, ncontacts = 0;
    double released = 0.0;
    double work[MAX_ROW_SIZE];
    for (int m = 0; m < d.nlinks(i); m++) {
      const double *stored = d.history_row(i, m);
      const int state = stored_state(d.layout, stored);
      if (state == LINK_CONTACT) ncontacts++;
      if (state != LINK_BROKEN) continue;
      const double *row = read_row(d.layout, stored, work);
      nbroken++;
      if (row[ff + F_STEP] == break_step) released += 0.5 * row[ff + F_RELEASED];
    }
    const int fa = d.layout.atom_offset[PART_FRACTURE];
    double forgotten = 0.0;
    for (int c = 0; c < NBREAK - 1; c++) forgotten += d.atom_state(i, fa + FA_FORGOTTEN + c);
    // (the links made at the start: contacts are not links)
    const double total = d.nlinks(i) - ncontacts + forgotten;
    d.damage(i) = total > 0.0 ? (nbroken + forgotten) / total : 0.0;
    return released;
  }

  /* ----------------------------------------------------------------------
     healing weld (mca_contact.h): the heal pass, after the contact pass
     and the fracture pass of a step, marks the contacts automaton i
     evaluates that meet their criterion (with the same ownership rule, so
     every rank and thread count marks the same contacts); the contact
     pass of the next step makes them links (heal_contact); then each
     automaton takes what its healed contacts left into its law state
     (healed_of).  The plastic work density reads the plastic strain of
     the automata of this step (sent to the ghosts).  Without a work
     criterion the contact pass itself marks them (heal_in_pass), which
     saves a sweep over the rows
  ------------------------------------------------------------------------- */

  // (with a plastic work criterion; without, the contact pass marks them:
  // MCALinkPassFlags::heal_in_pass)
  template <class D> MCA_FUNCTION void heal_pass_of(const D &d, const MCABreakFlags &p, int i)
  {
    const bool plastic = d.layout.link_offset[PART_PLASTICITY] >= 0;
    for (int m = 0; m < d.nlinks(i); m++) {
      double *row;
      int j;
      if (!evaluates<LINK_CONTACT>(d, i, m, row, j)) continue;
      const bool ilo = d.tag(i) < d.tag(j);
      const int lo = ilo ? i : j, hi = ilo ? j : i;
      const int type_lo = d.type(lo), type_hi = d.type(hi);
      const MCAContactRule &rule = d.contact_rule(type_lo, type_hi);
      double w_lo = 0.0, w_hi = 0.0;
      if (plastic && rule.heal_work > 0.0) {
        w_lo = plastic_work_density(d.hardening(type_lo), d.epsp(lo));
        w_hi = plastic_work_density(d.hardening(type_hi), d.epsp(hi));
      }
      double work[MAX_ROW_SIZE];
      double *h = open_row(d.layout, row, work, true);
      if (mark_heal(h, d.layout, rule, w_lo, w_hi, p.step)) close_row(d.layout, h, row);
    }
  }

  // what the contacts of automaton i that became links at step heal_step
  // (this one) left, to its law state (each automaton keeps the whole
  // of each of its rows, as for a dropped contact,
  // PairMCA::keep_dropped_energy)
  template <class D> MCA_FUNCTION void healed_of(const D &d, int i, double heal_step)
  {
    const int hl = d.layout.link_offset[PART_HEALING];
    const int ca = d.layout.atom_offset[PART_CONTACT], ha = d.layout.atom_offset[PART_HEALING];
    double work[MAX_ROW_SIZE];
    for (int m = 0; m < d.nlinks(i); m++) {
      const double *stored = d.history_row(i, m);
      if (stored_state(d.layout, stored) != LINK_LINKED) continue;
      const double *row = read_row(d.layout, stored, work);
      if (row[hl + HL_STEP] != heal_step) continue;
      d.atom_state(i, ca + CA_FRICTION) += row[hl + HL_FRICTION];
      d.atom_state(i, ca + CA_WORK) += row[hl + HL_WORK];
      d.atom_state(i, ha + HA_HEALED) += 1.0;
    }
  }

  // forces and torques of automaton i from its link sums
  template <class D> MCA_FUNCTION void add_link_forces(const D &d, int i, const double *sums)
  {
    for (int k = 0; k < 3; k++) {
      d.f(i, k) += sums[LS_FORCE + k];
      d.torque(i, k) += sums[LS_TORQUE + k];
    }
  }

  // stress and law state of automaton i from its traction moment B
  template <class D>
  MCA_FUNCTION void automaton_outputs_of(const D &d, int i, const double *bmat, bool commit)
  {
    // per-automaton outputs; the mean stress is tension positive
    double fab[6], stress[6], smean, seq, eeq;
    for (int k = 0; k < 6; k++) fab[k] = d.fabric(i, k);
    automaton_stress(bmat, fab, d.material(d.type(i)).shear, stress, smean, seq, eeq);
    for (int k = 0; k < 6; k++) d.stress(i, k) = stress[k];
    d.smean(i) = smean;
    d.seq(i) = seq;
    d.eeq(i) = eeq;
    if (commit) {
      d.atom_state(i, A_SMEAN_STEP) = smean;
      d.atom_state(i, A_SMEAN_LAW) = d.smean_pred(i);
    }
  }

}    // namespace MCAKernels
}    // namespace LAMMPS_NS

#endif
