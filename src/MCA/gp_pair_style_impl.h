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
   Definitions of PairGPStyle<Base, Potential>, included by the
   translation units that instantiate it (pair_gp_*.cpp and their Kokkos
   variants)
------------------------------------------------------------------------- */

#ifndef LMP_GP_PAIR_STYLE_IMPL_H
#define LMP_GP_PAIR_STYLE_IMPL_H

#include "gp_pair_style.h"

#include "atom.h"
#include "error.h"

#include <cstring>

namespace LAMMPS_NS {

template <class Base, class Potential>
PairGPStyle<Base, Potential>::PairGPStyle(LAMMPS *lmp) :
    Base(lmp), coeffs(lmp, Potential::style(), Potential::names())
{
  // no rRESPA: the cutoffs of the levels differ by k^(n-1), and types of
  // different levels have none
  this->respa_enable = 0;
}

template <class Base, class Potential> void PairGPStyle<Base, Potential>::allocate()
{
  Base::allocate();
  coeffs.allocate(this->atom->ntypes);
}

/* ----------------------------------------------------------------------
   pair_style gp/... cutoff [ratio k] [scaling energy|pmap|pmap_invmap]
------------------------------------------------------------------------- */

template <class Base, class Potential>
void PairGPStyle<Base, Potential>::settings(int narg, char **arg)
{
  coeffs.settings(narg, arg);
  Base::settings(1, arg);    // the atomic cutoff (the base style's cut_global)
}

// pair_coeff I J <atomic parameters> [cutoff] level n
template <class Base, class Potential>
void PairGPStyle<Base, Potential>::coeff(int narg, char **arg)
{
  if (!this->allocated) allocate();
  coeffs.coeff(narg, arg, this->setflag);
}

// the scaled parameters of every pair the user set, before the base
// style's init_one mixes or reads them
template <class Base, class Potential> void PairGPStyle<Base, Potential>::init_style()
{
  coeffs.levels.check_all_set();
  coeffs.levels.exclude_other_levels();
  for (int i = 1; i <= this->atom->ntypes; i++)
    for (int j = i; j <= this->atom->ntypes; j++) {
      if (!coeffs.given(i, j)) continue;
      const double s = coeffs.levels.length(i), c = coeffs.levels.energy_factor(i);
      Potential::set_scaled(*this, coeffs, i, j, s, c);
      this->cut[i][j] = s * coeffs.cutoff(i, j);
    }
  Base::init_style();
}

// types of different levels do not interact: a zero potential and cutoff
template <class Base, class Potential> double PairGPStyle<Base, Potential>::init_one(int i, int j)
{
  if (!coeffs.levels.same_level(i, j)) {
    Potential::set_zero(*this, i, j);
    this->cut[i][j] = 0.0;
    this->setflag[i][j] = 1;
  }
  return Base::init_one(i, j);
}

/* ----------------------------------------------------------------------
   restart and data files: the base style's global settings, then the
   atomic coefficients and the levels
------------------------------------------------------------------------- */

template <class Base, class Potential> void PairGPStyle<Base, Potential>::write_restart(FILE *fp)
{
  this->write_restart_settings(fp);
  coeffs.write_restart(fp);
}

template <class Base, class Potential> void PairGPStyle<Base, Potential>::read_restart(FILE *fp)
{
  this->read_restart_settings(fp);
  allocate();
  coeffs.read_restart(fp, this->setflag);
}

template <class Base, class Potential> void PairGPStyle<Base, Potential>::write_data(FILE *fp)
{
  coeffs.write_data(fp);
}

template <class Base, class Potential> void PairGPStyle<Base, Potential>::write_data_all(FILE *fp)
{
  coeffs.write_data_all(fp);
}

template <class Base, class Potential>
void *PairGPStyle<Base, Potential>::extract(const char *str, int &dim)
{
  if (strcmp(str, "gp_level") == 0) {
    dim = 1;
    return coeffs.levels.level.data();
  }
  return Base::extract(str, dim);
}

}    // namespace LAMMPS_NS

#endif
