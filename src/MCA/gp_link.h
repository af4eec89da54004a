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
