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
   Plasticity of the automata (pair_style mca plasticity mises): von Mises
   yield with isotropic hardening, Wilkins' radial return applied to the
   pair tractions of each automaton (thesis 3.115-3.119), a monotone
   equivalent plastic strain and the plastic work.  See
   doc/src/pair_mca.rst, "Plasticity".
------------------------------------------------------------------------- */

#ifndef LMP_MCA_PLASTICITY_H
#define LMP_MCA_PLASTICITY_H

#include "mca_geometry.h"
#include "mca_inline.h"
#include "mca_link_layout.h"

#include <cmath>

namespace LAMMPS_NS {
namespace MCAKernels {

  /* ----------------------------------------------------------------------
     the hardening curve of a material: the flow stress sigma_y(eps_p) as
     a function of the equivalent plastic strain, piecewise linear through
     npoints points (eps_p[0] = 0, eps_p increasing, sigma_y not
     decreasing) and with the slope slope_end beyond the last point.
     Linear hardening "yield s hardening H" is the point (0, s) with slope
     H; a table (hardening table) ends with slope 0.  npoints = 0: the
     material does not yield.
  ------------------------------------------------------------------------- */

  constexpr int MAX_HARDENING_POINTS = 64;

  struct MCAHardening {
    int npoints;
    double slope_end;
    double eps[MAX_HARDENING_POINTS];
    double sig[MAX_HARDENING_POINTS];
  };

  // slope of segment k (from point k to k + 1, or beyond the last point)
  MCA_INLINE double hardening_slope(const MCAHardening &h, int k)
  {
    if (k + 1 >= h.npoints) return h.slope_end;
    return (h.sig[k + 1] - h.sig[k]) / (h.eps[k + 1] - h.eps[k]);
  }

  // the segment that holds eps_p
  MCA_INLINE int hardening_segment(const MCAHardening &h, double ep)
  {
    int k = 0;
    while (k + 1 < h.npoints && ep >= h.eps[k + 1]) k++;
    return k;
  }

  MCA_INLINE double flow_stress(const MCAHardening &h, double ep)
  {
    const int k = hardening_segment(h, ep);
    return h.sig[k] + hardening_slope(h, k) * (ep - h.eps[k]);
  }

  // the plastic work per unit volume of a material strained plastically
  // to eps_p along its curve: the integral of sigma_y from 0 to eps_p
  // (exact for the piecewise-linear curve; 0 for a material that does not
  // yield)
  MCA_INLINE double plastic_work_density(const MCAHardening &h, double ep)
  {
    if (h.npoints == 0 || ep <= 0.0) return 0.0;
    double work = 0.0;
    int k = 0;
    for (; k + 1 < h.npoints && ep >= h.eps[k + 1]; k++)
      work += 0.5 * (h.sig[k] + h.sig[k + 1]) * (h.eps[k + 1] - h.eps[k]);
    return work + 0.5 * (h.sig[k] + flow_stress(h, ep)) * (ep - h.eps[k]);
  }

  /* ----------------------------------------------------------------------
     radial return of a trial equivalent stress seq > sigma_y(ep): the
     plastic strain increment dep >= 0 with
       seq - 3G dep = sigma_y(ep + dep)
     (the equivalent stress falls by 3G per unit of equivalent plastic
     strain), solved exactly segment by segment of the curve.  The slopes
     are >= 0, so the left side falls and the right side rises with dep:
     the root is unique.
  ------------------------------------------------------------------------- */

  MCA_INLINE double plastic_increment(const MCAHardening &h, double ep, double seq, double g3)
  {
    int k = hardening_segment(h, ep);
    double e = ep;    // start of the part of segment k still to search
    for (;;) {
      const double slope = hardening_slope(h, k);
      const double sy = h.sig[k] + slope * (e - h.eps[k]);
      // the root in this segment, measured from e
      const double de = (seq - g3 * (e - ep) - sy) / (g3 + slope);
      if (k + 1 >= h.npoints || e + de <= h.eps[k + 1]) return e + de - ep;
      e = h.eps[++k];
    }
  }

  /* ----------------------------------------------------------------------
     the return of one automaton from its trial stress (tension positive
     Voigt tensor from the elastic trial of its links): the factor M that
     scales the deviator back to the flow stress (1: elastic), the plastic
     strain increment and the flow stress after it
  ------------------------------------------------------------------------- */

  struct MCAPlasticReturn {
    double scale;    // M = sigma_y(ep + dep) / seq_trial, 1 if elastic
    double dep;      // increment of the equivalent plastic strain
    double flow;     // flow stress after the step
  };

  MCA_INLINE void plastic_return(const MCAHardening &h, double g, double ep, double seq_trial,
                                 MCAPlasticReturn &ret)
  {
    ret.scale = 1.0;
    ret.dep = 0.0;
    ret.flow = 0.0;
    if (h.npoints == 0) return;
    ret.flow = flow_stress(h, ep);
    if (!(seq_trial > ret.flow)) return;
    ret.dep = plastic_increment(h, ep, seq_trial, 3.0 * g);
    ret.flow = flow_stress(h, ep + ret.dep);
    ret.scale = ret.flow / seq_trial;
  }

  /* ----------------------------------------------------------------------
     the plastic correction of one half of a link (thesis 3.119): its
     normal traction is scaled about the mean stress of its automaton,
     its shear traction and couple are scaled, all by the automaton's M.
     A full, isotropic shell of links then carries exactly the corrected
     stress sm I + M dev(sigma_trial) (3.117-3.118).  Returns the plastic
     work of the half: the corrected tractions times the plastic parts of
     the half's displacements, which are the traction changes over the
     half's stiffness (normal 2G/q0, shear 2G/q, bending chi A^2 2G/q and
     twice that in twist), times the contact area for the tractions.
  ------------------------------------------------------------------------- */

  MCA_INLINE double plastic_correct_half(double *half, double *couple, double scale, double smean,
                                         double g, double q0, double q, double area, double chi,
                                         const double *n)
  {
    const int sig = HALF_SIG, t = HALF_T;
    const double sig_c = (half[sig] - smean) * scale + smean;
    double work = sig_c * (half[sig] - sig_c) * q0;
    half[sig] = sig_c;
    for (int m = 0; m < 3; m++) {
      const double t_c = half[t + m] * scale;
      work += t_c * (half[t + m] - t_c) * q;
      half[t + m] = t_c;
    }
    work *= area / (2.0 * g);
    // couples: the bending part over the bending stiffness, the twist
    // part over the twice stiffer torsion
    double dc[3], cc[3];
    for (int m = 0; m < 3; m++) {
      cc[m] = couple[m] * scale;
      dc[m] = couple[m] - cc[m];
      couple[m] = cc[m];
    }
    const double kface = chi * area * area * 2.0 * g / q;
    if (kface > 0.0) {
      const double dcn = dot3(dc, n);
      double rot[3];
      for (int m = 0; m < 3; m++) rot[m] = (dc[m] - 0.5 * dcn * n[m]) / kface;
      work += dot3(cc, rot);
    }
    return work;
  }

}    // namespace MCAKernels
}    // namespace LAMMPS_NS

#endif
