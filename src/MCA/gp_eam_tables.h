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
   The tables of an EAM potential at the GP scale levels
   (doc/src/pair_gp.rst).

   Level n maps a distance R to the atomic r = R / s_n and scales the
   energy by c_n: its density is rho(R / s_n), its pair term c_n phi(R /
   s_n), its embedding energy c_n F(rho).  LAMMPS's EAM styles evaluate
   every function from one grid of spacing dr, row m a cubic in the
   fraction p of [(m-1) dr, m dr].  On that grid the level-n function is
   a cubic in each row too (a row lies inside one atomic row, s_n rows of
   the grid for each), so the level tables hold the atomic spline itself,
   re-expanded row by row, and the styles' own kernels evaluate the
   levels: no kernel of our own, the atomic values to round-off.
------------------------------------------------------------------------- */

#ifndef LMP_GP_EAM_TABLES_H
#define LMP_GP_EAM_TABLES_H

#include "gp_levels.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {
namespace GPKernels {

  // LAMMPS's row of an EAM spline: [3..6] the cubic in p (Horner order),
  // [0..2] its derivative per unit length, delta the grid spacing (as
  // PairEAM::interpolate writes it)
  MCA_INLINE void spline_row_derivative(double *row, double delta)
  {
    row[2] = row[5] / delta;
    row[1] = 2.0 * row[4] / delta;
    row[0] = 3.0 * row[3] / delta;
  }

  // factor times the atomic cubic of an atomic row at the fraction
  // P = a + b p: the coefficients of the cubic in p
  MCA_INLINE void spline_row_mapped(const double *atomic, double a, double b, double factor,
                                    double *row)
  {
    const double c3 = atomic[3], c4 = atomic[4], c5 = atomic[5], c6 = atomic[6];
    row[3] = factor * (c3 * b * b * b);
    row[4] = factor * ((3.0 * c3 * a + c4) * b * b);
    row[5] = factor * ((3.0 * c3 * a * a + 2.0 * c4 * a + c5) * b);
    row[6] = factor * (((c3 * a + c4) * a + c5) * a + c6);
  }

}    // namespace GPKernels

/* ----------------------------------------------------------------------
   the level tables of an EAM style, made from the atomic tables its base
   style read (PairEAM's public arrays after file2array), which they
   replace: the tables of each atomic function for every level up to the
   highest, one zero table for pairs of different levels, the type maps
   pointing at the level of each type, and the grid of dr that reaches
   s_max times the cutoff
------------------------------------------------------------------------- */

class GPEAMTables : protected Pointers {
 public:
  GPEAMTables(class LAMMPS *lmp) : Pointers(lmp) {}

  // an error naming the first of the elements (arguments of pair_coeff,
  // NULL for a type the style does not handle) that the setfl or
  // Finnis-Sinclair file does not have (the base style's error does not
  // say which); nothing if the file cannot be read (the base says so)
  void check_elements(const char *style, const char *file, int nelements, char **elements);

  // pair: the style after its base's file2array; rhor_spline, z2r_spline:
  // the atomic splines of its rhor and z2r arrays (PairEAM::interpolate);
  // cut: the atomic cutoff
  void expand(class PairEAM &pair, const GPLevels &levels, double cut, double ***rhor_spline,
              double ***z2r_spline);
  // the spline rows of the level tables of rhor and z2r, after the base's
  // array2spline has splined the level arrays (replacing those rows)
  void write_rows(double ***rhor_spline, double ***z2r_spline) const;
  // the value of coefficient k of row m of level table t
  double rhor_row(int t, int m, int k) const { return rhor_rows[(t * rows + m) * 7 + k]; }
  double z2r_row(int t, int m, int k) const { return z2r_rows[(t * rows + m) * 7 + k]; }
  int nrhor() const { return ntab_rhor; }
  int nz2r() const { return ntab_z2r; }
  int nrows() const { return rows; }
  // let the rows go once written
  void release();
  // the memory of the level spline tables (bytes per table)
  double table_bytes() const { return 7.0 * sizeof(double) * rows; }

 private:
  int rows = 0, ntab_rhor = 0, ntab_z2r = 0;
  std::vector<double> rhor_rows, z2r_rows;    // [table][row 0..nr][7]

  void level_rows(double **atomic, int nr_atomic, double dr, double cut, double s, double factor,
                  double *out) const;
};

}    // namespace LAMMPS_NS

#endif
