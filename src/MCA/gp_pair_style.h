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

#ifndef LMP_GP_PAIR_STYLE_H
#define LMP_GP_PAIR_STYLE_H

#include "gp_levels.h"

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   a GP pair style over a LAMMPS pair potential (Base: its CPU style or
   its Kokkos variant): E_n(R) = c_n phi(R / s_n) of a potential whose
   parameters scale with the level (Potential: which, and how):
     Morse   D0' = c D0, alpha' = alpha / s, r0' = s r0
     LJ      epsilon' = c epsilon, sigma' = s sigma
   and cutoff s rc.  The style keeps the atomic coefficients and the
   levels (GPPairCoeffs), gives the base style the scaled parameters at
   each run and a zero potential and cutoff to types of different levels;
   the base style's kernels do the rest (doc/src/pair_gp.rst)
------------------------------------------------------------------------- */

// (a potential sets its base style's parameters of pair i, j from the
// atomic coefficients, scaled by s and c, or to zero: a friend of the
// style, it reaches the base style's protected arrays)
struct GPMorse {
  static const char *style() { return "gp/morse"; }
  static std::vector<std::string> names() { return {"d0", "alpha", "r0"}; }
  template <class Pair>
  static void set_scaled(Pair &p, const GPPairCoeffs &k, int i, int j, double s, double c)
  {
    p.d0[i][j] = c * k.value(i, j, 0);
    p.alpha[i][j] = k.value(i, j, 1) / s;
    p.r0[i][j] = s * k.value(i, j, 2);
  }
  template <class Pair> static void set_zero(Pair &p, int i, int j)
  {
    p.d0[i][j] = 0.0;
    p.alpha[i][j] = 1.0;
    p.r0[i][j] = 0.0;
  }
};

struct GPLJCut {
  static const char *style() { return "gp/lj/cut"; }
  static std::vector<std::string> names() { return {"epsilon", "sigma"}; }
  template <class Pair>
  static void set_scaled(Pair &p, const GPPairCoeffs &k, int i, int j, double s, double c)
  {
    p.epsilon[i][j] = c * k.value(i, j, 0);
    p.sigma[i][j] = s * k.value(i, j, 1);
  }
  template <class Pair> static void set_zero(Pair &p, int i, int j)
  {
    p.epsilon[i][j] = 0.0;
    p.sigma[i][j] = 0.0;
  }
};

template <class Base, class Potential> class PairGPStyle : public Base {
  friend Potential;

 public:
  PairGPStyle(class LAMMPS *);

  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_data(FILE *) override;
  void write_data_all(FILE *) override;
  // "gp_level": the level of each atom type (for fix gp/link)
  void *extract(const char *, int &) override;

 protected:
  GPPairCoeffs coeffs;
  void allocate() override;
};

}    // namespace LAMMPS_NS

#endif
