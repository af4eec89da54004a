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
   Geometry of the automata and their links: packing, cell volume and
   inertia, contact faces, vectors, fabric and homogenised stress, and the
   rotation that carries a vector of a pair frame along with the pair.
------------------------------------------------------------------------- */

#ifndef LMP_MCA_GEOMETRY_H
#define LMP_MCA_GEOMETRY_H

#include "mca_inline.h"

#include <cmath>

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

  // the six virial terms of a force f at separation d, in the order of
  // LAMMPS's ev_tally_xyz (xx, yy, zz, xy, xz, yz)
  MCA_INLINE void virial_terms(const double *d, const double *f, double *v)
  {
    v[0] = d[0] * f[0];
    v[1] = d[1] * f[1];
    v[2] = d[2] * f[2];
    v[3] = d[0] * f[1];
    v[4] = d[0] * f[2];
    v[5] = d[1] * f[2];
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

  /* ----------------------------------------------------------------------
     carry a vector of the pair frame along with the pair: the minimal
     rotation that takes the old normal a to the new normal b, then a twist
     by angle phi about b.  A tangential vector (shear traction) also loses
     the component along b that round-off leaves; a couple keeps its twist
     component along b.
  ------------------------------------------------------------------------- */

  // cosine and sine; the twist per step is tiny, where a series is exact
  // to round-off (the first term left out is phi^6/720 < 2e-21)
  MCA_INLINE bool cos_sin_by_series(double phi)
  {
    return fabs(phi) < 1.0e-3;
  }

  MCA_FORCE_INLINE void cos_sin_series(double phi, double &c, double &s)
  {
    const double p2 = phi * phi;
    c = 1.0 - 0.5 * p2 * (1.0 - p2 / 12.0);
    s = phi * (1.0 - p2 / 6.0 * (1.0 - p2 / 20.0));
  }

  MCA_FORCE_INLINE void cos_sin(double phi, double &c, double &s)
  {
    if (cos_sin_by_series(phi)) {
      cos_sin_series(phi, c, s);
    } else {
      c = cos(phi);
      s = sin(phi);
    }
  }

  MCA_FORCE_INLINE void pair_rotation(const double *a, const double *b, double cos_phi,
                                      double sin_phi, double *rot)
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

  MCA_FORCE_INLINE void rotate_with_pair(double *v, const double *rot, const double *b,
                                         bool tangential)
  {
    double r[3];
    for (int m = 0; m < 3; m++)
      r[m] = rot[3 * m] * v[0] + rot[3 * m + 1] * v[1] + rot[3 * m + 2] * v[2];
    const double rb = tangential ? dot3(r, b) : 0.0;
    for (int m = 0; m < 3; m++) v[m] = r[m] - rb * b[m];
  }

}    // namespace MCAKernels
}    // namespace LAMMPS_NS

#endif
