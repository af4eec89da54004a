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
   Fracture of links: the contact stress tensor of a link, the breaking
   criteria (chosen per pair of atom types), the per-link strength
   scatter, and the compression-only law of a broken link.  See
   doc/src/pair_mca.rst, "Fracture of links".
------------------------------------------------------------------------- */

#ifndef LMP_MCA_FRACTURE_H
#define LMP_MCA_FRACTURE_H

#include "mca_geometry.h"
#include "mca_inline.h"

#include <cmath>
#include <cstdint>

namespace LAMMPS_NS {
namespace MCAKernels {

  // the criterion of a pair of atom types (pair_coeff I J break ...); the
  // id is the cause a broken link records (0: not broken)
  enum BreakCriterion {
    BREAK_NONE = 0,
    BREAK_STRAIN,            // ultimate equivalent strain
    BREAK_STRESS,            // ultimate equivalent stress
    BREAK_DRUCKER_PRAGER,    // tensile and compressive strengths
    BREAK_ELLIPTIC,          // (sigma/sigma0)^2 + (tau/tau0)^2 >= 1
    NBREAK
  };

  struct MCABreakRule {
    int criterion;    // BreakCriterion
    double p1, p2;    // eps_u | sigma_u | sigma_t, sigma_c | sigma0, tau0
  };

  // what a criterion reads of a link and its two automata
  struct MCABreakInput {
    const double *n;              // unit normal lo -> hi
    double sig;                   // normal traction (tension positive)
    const double *t;              // shear traction vector
    double q_lo, q_hi;            // current half lengths
    const double *s_lo, *s_hi;    // stress tensors of the automata (xx yy zz xy xz yz)
    double epsp_lo, epsp_hi;      // their equivalent plastic strains
    double shear_lo, shear_hi;    // their shear moduli
  };

  /* ----------------------------------------------------------------------
     contact stress tensor of a link (thesis 3.126 in 3-D): along the link
     the link's own tractions, sigma_nn = sig and sigma_nt = t; across it
     the stress of the two automata interpolated to the contact point,
     (q_hi sigma_lo + q_lo sigma_hi) / r, projected on the contact plane:
       S = sig n n^T + t n^T + n t^T + P A P,  P = I - n n^T
     In a uniform stress field (tractions sigma n) S is that stress exactly.
  ------------------------------------------------------------------------- */

  MCA_INLINE void contact_stress(const MCABreakInput &in, double *s)
  {
    const double r = in.q_lo + in.q_hi;
    const double w_lo = in.q_hi / r, w_hi = in.q_lo / r;
    double a[6];
    for (int k = 0; k < 6; k++) a[k] = w_lo * in.s_lo[k] + w_hi * in.s_hi[k];
    const double *n = in.n;
    // A n and n A n
    const double an[3] = {a[0] * n[0] + a[3] * n[1] + a[4] * n[2],
                          a[3] * n[0] + a[1] * n[1] + a[5] * n[2],
                          a[4] * n[0] + a[5] * n[1] + a[2] * n[2]};
    const double nan_ = dot3(n, an);
    // Voigt index pairs xx yy zz xy xz yz
    const int ia[6] = {0, 1, 2, 0, 0, 1}, ib[6] = {0, 1, 2, 1, 2, 2};
    for (int k = 0; k < 6; k++) {
      const int p = ia[k], q = ib[k];
      const double lateral = a[k] - n[p] * an[q] - an[p] * n[q] + nan_ * n[p] * n[q];
      s[k] = lateral + in.sig * n[p] * n[q] + in.t[p] * n[q] + n[p] * in.t[q];
    }
  }

  // von Mises equivalent stress and mean stress (tension positive) of S
  MCA_INLINE void stress_invariants(const double *s, double &seq, double &smean)
  {
    smean = (s[0] + s[1] + s[2]) / 3.0;
    seq = sqrt(0.5 *
                   ((s[0] - s[1]) * (s[0] - s[1]) + (s[1] - s[2]) * (s[1] - s[2]) +
                    (s[2] - s[0]) * (s[2] - s[0])) +
               3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
  }

  /* ----------------------------------------------------------------------
     failure index of a link: load over strength, homogeneous of degree 1
     in the load, so that a link breaks when it reaches its strength factor
     (1 without scatter).
       strain           (S_eq / (3 G_c) + eps_p) / eps_u; G_c the shear
                        modulus of the two halves in series, eps_p
                        interpolated as the stress (von Mises equivalent
                        strain, elastic plus plastic)
       stress           S_eq / sigma_u
       drucker_prager   (0.5 (a + 1) S_eq + 1.5 (a - 1) S_mean) / sigma_c,
                        a = sigma_c / sigma_t (thesis 3.127): sigma_t in
                        uniaxial tension, sigma_c in uniaxial compression
       elliptic         sqrt((max(sig, 0)/sigma0)^2 + (|t|/tau0)^2) on the
                        link's own tractions; compression does not count
  ------------------------------------------------------------------------- */

  MCA_INLINE double failure_index(const MCABreakRule &rule, const MCABreakInput &in)
  {
    if (rule.criterion == BREAK_ELLIPTIC) {
      const double sn = in.sig > 0.0 ? in.sig / rule.p1 : 0.0;
      const double tau = sqrt(dot3(in.t, in.t)) / rule.p2;
      return sqrt(sn * sn + tau * tau);
    }
    double s[6], seq, smean;
    contact_stress(in, s);
    stress_invariants(s, seq, smean);
    if (rule.criterion == BREAK_STRESS) return seq / rule.p1;
    if (rule.criterion == BREAK_DRUCKER_PRAGER) {
      const double a = rule.p2 / rule.p1;
      return (0.5 * (a + 1.0) * seq + 1.5 * (a - 1.0) * smean) / rule.p2;
    }
    if (rule.criterion == BREAK_STRAIN) {
      const double r = in.q_lo + in.q_hi;
      const double shear_c = r / (in.q_lo / in.shear_lo + in.q_hi / in.shear_hi);
      const double epsp = (in.q_hi * in.epsp_lo + in.q_lo * in.epsp_hi) / r;
      return (seq / (3.0 * shear_c) + epsp) / rule.p1;
    }
    return 0.0;
  }

  /* ----------------------------------------------------------------------
     strength factor of a link with scatter w: uniform in [1 - w, 1 + w],
     drawn from the seed and the IDs of the two automata, so the same for
     any number of ranks and threads and across restarts
  ------------------------------------------------------------------------- */

  MCA_INLINE std::uint64_t mix64(std::uint64_t z)
  {
    // splitmix64 finaliser
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }

  MCA_INLINE double strength_factor(double scatter, int seed, std::int64_t id_lo,
                                    std::int64_t id_hi)
  {
    if (scatter == 0.0) return 1.0;
    std::uint64_t h = mix64(static_cast<std::uint64_t>(seed));
    h = mix64(h ^ static_cast<std::uint64_t>(id_lo));
    h = mix64(h ^ static_cast<std::uint64_t>(id_hi));
    const double u = static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0);    // [0, 1)
    return 1.0 + scatter * (2.0 * u - 1.0);
  }

}    // namespace MCAKernels
}    // namespace LAMMPS_NS

#endif
