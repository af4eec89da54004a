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
   Mean stress of the automata: the predictor that estimates it before the
   tractions of a step are known, and the homogenised stress after.
------------------------------------------------------------------------- */

#ifndef LMP_MCA_MEAN_STRESS_H
#define LMP_MCA_MEAN_STRESS_H

#include "mca_geometry.h"
#include "mca_link_layout.h"

#include <cmath>

namespace LAMMPS_NS {
namespace MCAKernels {

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

}    // namespace MCAKernels
}    // namespace LAMMPS_NS

#endif
