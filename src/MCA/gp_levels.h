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
   Generalized Particle (GP) method: the scale levels of the atom types and
   how a level scales a pair potential (doc/src/pair_gp.rst).

   A level-n particle stands for l_n = k^(3(n-1)) atoms of a lattice scaled
   by s_n = k^(n-1) (k the integer scale ratio).  Its potential is the
   atomic one of the mapped distance, E_n(R) = c_n phi(R / s_n), with
     energy (default)  c_n = l_n          force (l_n / s_n) f: -dE/dR
     pmap              c_n = l_n s_n      force l_n f (the thesis's text)
     pmap_invmap       c_n = l_n s_n^2    force l_n s_n f (inverse mapping)
   (the thesis's two modes, for comparison: the energy reported is the one
   whose gradient the force is).  Types of different levels do not
   interact; the cutoff of level n is s_n times the atomic one.
------------------------------------------------------------------------- */

#ifndef LMP_GP_LEVELS_H
#define LMP_GP_LEVELS_H

#include "mca_inline.h"
#include "pointers.h"

#include <cmath>
#include <string>
#include <vector>

namespace LAMMPS_NS {
namespace GPKernels {

  enum GPScaling { GP_ENERGY = 0, GP_PMAP, GP_PMAP_INVMAP, GP_NSCALING };

  // length scale s_n = k^(n-1) and atoms per particle l_n = s_n^3
  MCA_INLINE double level_length(int ratio, int level)
  {
    double s = 1.0;
    for (int n = 1; n < level; n++) s *= ratio;
    return s;
  }

  MCA_INLINE double level_atoms(int ratio, int level)
  {
    const double s = level_length(ratio, level);
    return s * s * s;
  }

  // the factor c_n of the energy E_n(R) = c_n phi(R / s_n)
  MCA_INLINE double level_energy_factor(int ratio, int level, int scaling)
  {
    const double s = level_length(ratio, level), l = s * s * s;
    if (scaling == GP_PMAP) return l * s;
    if (scaling == GP_PMAP_INVMAP) return l * s * s;
    return l;
  }

}    // namespace GPKernels

/* ----------------------------------------------------------------------
   what a GP pair style adds to its base style: the scale ratio, the
   scaling mode, the level of each atom type, parsed from the pair_style
   and pair_coeff keywords and written to restart and data files
------------------------------------------------------------------------- */

class GPLevels : protected Pointers {
 public:
  GPLevels(class LAMMPS *, const char *style);

  // "ratio k [scaling energy|pmap|pmap_invmap]" at the end of the
  // pair_style arguments, from iarg on; returns the arguments left before
  // them (the base style's)
  int settings(int narg, char **arg);
  // "level n" at the end of pair_coeff I J ...; the levels of types
  // ilo..ihi and jlo..jhi; returns the number of arguments before it
  int coeff(int narg, char **arg, int ilo, int ihi, int jlo, int jhi);
  // "level n_1 ... n_N" from arg[first] on, N the number of types (the
  // pair_coeff * * file elements ... of a many-body style); returns first
  int coeff_types(int narg, char **arg, int first);
  void allocate(int ntypes);
  // an error naming the first type without a level
  void check_all_set() const;
  // neighbor lists leave out the pairs of types of different levels
  // (neigh_modify exclude type, added once): their particles may
  // coincide (every level-n site is a level-(n-1) site), and a pair at
  // distance 0 within a zero cutoff would still be listed
  void exclude_other_levels() const;
  bool same_level(int i, int j) const { return level[i] == level[j]; }
  double length(int type) const { return GPKernels::level_length(ratio, level[type]); }
  double energy_factor(int type) const
  {
    return GPKernels::level_energy_factor(ratio, level[type], scaling);
  }
  const char *scaling_name() const;

  void write_restart(FILE *) const;
  void read_restart(FILE *);

  int ratio;                 // scale ratio k
  int scaling;               // GPScaling
  std::vector<int> level;    // [ntypes + 1], 0: not set

 private:
  std::string style;
};

/* ----------------------------------------------------------------------
   the atomic coefficients of a GP pair style, per type pair ("p1 ... pN
   [cutoff] level n" of pair_coeff), with the levels; parsed, kept and
   written to restart and data files here, so that a style only says how
   its base style's parameters follow from them (scaled by level)
------------------------------------------------------------------------- */

class GPPairCoeffs : protected Pointers {
 public:
  GPPairCoeffs(class LAMMPS *, const char *style, const std::vector<std::string> &names);
  ~GPPairCoeffs() override;

  // the pair_style arguments: the atomic cutoff, then the keywords of
  // the levels
  void settings(int narg, char **arg);
  void allocate(int ntypes);
  // pair_coeff I J p1 ... pN [cutoff] level n; the pairs it sets get
  // setflag 1
  void coeff(int narg, char **arg, int **setflag);
  bool given(int i, int j) const { return set[i][j] != 0; }
  double value(int i, int j, int k) const { return values[i][j * nparams + k]; }
  double cutoff(int i, int j) const { return cut[i][j]; }

  void write_restart(FILE *);
  // (setflag gets the pairs the file gives)
  void read_restart(FILE *, int **setflag);
  void write_data(FILE *);
  void write_data_all(FILE *);

  GPLevels levels;
  double cut_global;

 private:
  std::string style;
  std::vector<std::string> names;
  int nparams, ntypes;
  double **values;    // [i][j * nparams + k]
  double **cut;
  int **set;
  std::string data_line(int i, int j) const;
};

}    // namespace LAMMPS_NS

#endif
