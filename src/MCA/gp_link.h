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
   The link of an imaginary GP particle to its members (doc/src/fix_gp_link.rst).

   An imaginary particle I follows the N real particles it is linked to:
   its position is the mean of theirs plus its reference offset e from
   that mean, transformed by the least-squares deformation gradient of
   the members,
     x_I = xbar + F e,  F = sum_j (x_j - xbar) (D_j - Dbar)^T A^-1,
     A = sum_j (D_j - Dbar)(D_j - Dbar)^T,  e = -Dbar,
   D_j the members' offsets from I when linked.  That is a fixed linear
   combination of the members' positions, x_I = sum_j w_j x_j with
     w_j = 1/N + (D_j - Dbar) . A^-1 e,   sum_j w_j = 1,
   exact for any affine motion x = F X + c (the patch test), and x_I
   unchanged at the time of linking.  The thesis's link (the mean plus a
   constant offset) is the special case F = I, exact for translations only.
------------------------------------------------------------------------- */

#ifndef LMP_GP_LINK_H
#define LMP_GP_LINK_H

#include "mca_inline.h"

#include <cmath>

namespace LAMMPS_NS {
namespace GPKernels {

  // the weights w[0..n-1] of n members at offsets d[j][3] from the
  // imaginary particle; returns the determinant of A over (tr A / 3)^3
  // (0 for members on a plane or line: then F is undefined, no weights)
  MCA_INLINE double link_weights(int n, const double (*d)[3], double *w)
  {
    double mean[3] = {0.0, 0.0, 0.0};
    for (int j = 0; j < n; j++)
      for (int k = 0; k < 3; k++) mean[k] += d[j][k] / n;
    double a[3][3] = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
    for (int j = 0; j < n; j++)
      for (int k = 0; k < 3; k++)
        for (int l = 0; l < 3; l++) a[k][l] += (d[j][k] - mean[k]) * (d[j][l] - mean[l]);
    const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
        a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
        a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    const double scale = (a[0][0] + a[1][1] + a[2][2]) / 3.0;
    const double quality = (scale > 0.0) ? det / (scale * scale * scale) : 0.0;
    if (!(quality > 1.0e-8)) return 0.0;
    // g = A^-1 e with e = -mean (the cofactors over the determinant)
    const double e[3] = {-mean[0], -mean[1], -mean[2]};
    const double inv[3][3] = {{(a[1][1] * a[2][2] - a[1][2] * a[2][1]) / det,
                               (a[0][2] * a[2][1] - a[0][1] * a[2][2]) / det,
                               (a[0][1] * a[1][2] - a[0][2] * a[1][1]) / det},
                              {(a[1][2] * a[2][0] - a[1][0] * a[2][2]) / det,
                               (a[0][0] * a[2][2] - a[0][2] * a[2][0]) / det,
                               (a[0][2] * a[1][0] - a[0][0] * a[1][2]) / det},
                              {(a[1][0] * a[2][1] - a[1][1] * a[2][0]) / det,
                               (a[0][1] * a[2][0] - a[0][0] * a[2][1]) / det,
                               (a[0][0] * a[1][1] - a[0][1] * a[1][0]) / det}};
    double g[3];
    for (int k = 0; k < 3; k++) g[k] = inv[k][0] * e[0] + inv[k][1] * e[1] + inv[k][2] * e[2];
    for (int j = 0; j < n; j++)
      w[j] = 1.0 / n + (d[j][0] - mean[0]) * g[0] + (d[j][1] - mean[1]) * g[1] +
          (d[j][2] - mean[2]) * g[2];
    return quality;
  }

  // the most members a link may have (fix gp/link's members keyword)
  constexpr int MAX_LINK_MEMBERS = 12;

  // solves the m x m system a y = b in place (y in b) by Gaussian
  // elimination with partial pivoting; false for a singular matrix
  template <int M> MCA_INLINE bool solve_dense(int m, double (*a)[M], double *b)
  {
    for (int c = 0; c < m; c++) {
      int p = c;
      for (int r = c + 1; r < m; r++)
        if (fabs(a[r][c]) > fabs(a[p][c])) p = r;
      if (!(fabs(a[p][c]) > 0.0)) return false;
      if (p != c) {
        for (int k = 0; k < m; k++) {
          const double t = a[c][k];
          a[c][k] = a[p][k];
          a[p][k] = t;
        }
        const double t = b[c];
        b[c] = b[p];
        b[p] = t;
      }
      for (int r = c + 1; r < m; r++) {
        const double f = a[r][c] / a[c][c];
        if (f == 0.0) continue;
        for (int k = c; k < m; k++) a[r][k] -= f * a[c][k];
        b[r] -= f * b[c];
      }
    }
    for (int c = m - 1; c >= 0; c--) {
      double sum = b[c];
      for (int k = c + 1; k < m; k++) sum -= a[c][k] * b[k];
      b[c] = sum / a[c][c];
    }
    return true;
  }

  // fit quadratic: the weights nearest the linear ones (link_weights) that
  // keep their exactness for affine motions and also reproduce quadratic
  // motions x = c + F X + 1/2 G:XX as far as the members allow,
  //   min |Q w|^2 + lambda |w - w_lin|^2  subject to  C w = C w_lin,
  // C the rows 1, D_x, D_y, D_z and Q the second moments D_a D_b of the
  // members (scaled by the farthest), lambda 1e-6 of Q's mean diagonal: a
  // quadratic the members do not determine (all of them on one quadric,
  // e.g. on the two planes z = +-c for z^2) keeps the linear weights in
  // that direction instead of large, noisy ones.  The position error in a
  // smooth field drops from O(h^2 |grad grad u|) to O(h^3 |grad^3 u|), h
  // the members' reach: the interface of a fine and a coarse level where
  // the field curves (a crack tip's).  Returns the linear quality (0: no
  // weights).
  MCA_INLINE double link_weights_quadratic(int n, const double (*d)[3], double *w)
  {
    const double quality = link_weights(n, d, w);
    if (quality == 0.0 || n > MAX_LINK_MEMBERS) return quality;
    constexpr int M = MAX_LINK_MEMBERS + 4;
    double h2 = 0.0;
    for (int j = 0; j < n; j++)
      h2 = fmax(h2, d[j][0] * d[j][0] + d[j][1] * d[j][1] + d[j][2] * d[j][2]);
    const double h = sqrt(h2);
    double q[MAX_LINK_MEMBERS][6];
    for (int j = 0; j < n; j++) {
      const double x = d[j][0] / h, y = d[j][1] / h, z = d[j][2] / h;
      q[j][0] = x * x;
      q[j][1] = y * y;
      q[j][2] = z * z;
      q[j][3] = x * y;
      q[j][4] = x * z;
      q[j][5] = y * z;
    }
    // the KKT system of the correction v = w - w_lin:
    //   [Q^T Q + lambda I, C^T; C, 0] [v; mu] = [-Q^T Q w_lin; 0]
    double a[M][M], b[M];
    double diag = 0.0;
    for (int j = 0; j < n; j++)
      for (int k = 0; k < n; k++) {
        double s = 0.0;
        for (int l = 0; l < 6; l++) s += q[j][l] * q[k][l];
        a[j][k] = s;
        if (j == k) diag += s / n;
      }
    const double lambda = 1.0e-6 * diag;
    double qw[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    for (int j = 0; j < n; j++)
      for (int l = 0; l < 6; l++) qw[l] += q[j][l] * w[j];
    for (int j = 0; j < n; j++) {
      a[j][j] += lambda;
      const double c[4] = {1.0, d[j][0] / h, d[j][1] / h, d[j][2] / h};
      for (int r = 0; r < 4; r++) a[j][n + r] = a[n + r][j] = c[r];
      double s = 0.0;
      for (int l = 0; l < 6; l++) s += q[j][l] * qw[l];
      b[j] = -s;
    }
    for (int r = 0; r < 4; r++) {
      for (int c = 0; c < 4; c++) a[n + r][n + c] = 0.0;
      b[n + r] = 0.0;
    }
    if (!solve_dense<M>(n + 4, a, b)) return quality;    // (the linear weights stay)
    for (int j = 0; j < n; j++) w[j] += b[j];
    return quality;
  }

  // x_I = x_ref + sum_j w_j (x_j - x_ref): the members' positions as
  // offsets from a nearby point (the particle's last position), so that
  // the sum does not lose digits to the coordinates' size
  MCA_INLINE void linked_position(int n, const double *w, const double (*offset)[3],
                                  const double *ref, double *x)
  {
    double sum[3] = {0.0, 0.0, 0.0};
    for (int j = 0; j < n; j++)
      for (int k = 0; k < 3; k++) sum[k] += w[j] * offset[j][k];
    for (int k = 0; k < 3; k++) x[k] = ref[k] + sum[k];
  }

}    // namespace GPKernels
}    // namespace LAMMPS_NS

#endif
