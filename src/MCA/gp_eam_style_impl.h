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
   Definitions of PairGPEAMStyle<Base, Format, Tables>, included by the
   translation units that instantiate it (pair_gp_eam_*.cpp and their
   Kokkos variants)
------------------------------------------------------------------------- */

#ifndef LMP_GP_EAM_STYLE_IMPL_H
#define LMP_GP_EAM_STYLE_IMPL_H

#include "gp_eam_style.h"

#include "atom.h"
#include "error.h"
#include "memory.h"

#include <algorithm>
#include <cstring>

namespace LAMMPS_NS {

// (LAMMPS 2021's CPU EAM styles derive virtually from PairEAM: their
// instantiations specialise this constructor to initialise it)
template <class Base, class Format, class Tables>
PairGPEAMStyle<Base, Format, Tables>::PairGPEAMStyle(LAMMPS *lmp) :
    Base(lmp), levels(lmp, Format::style()), tables(lmp)
{
}

template <class Base, class Format, class Tables>
void PairGPEAMStyle<Base, Format, Tables>::allocate()
{
  Base::allocate();
  levels.allocate(this->atom->ntypes);
}

/* ----------------------------------------------------------------------
   pair_style gp/eam/... [ratio k] [scaling energy|pmap|pmap_invmap]
------------------------------------------------------------------------- */

template <class Base, class Format, class Tables>
void PairGPEAMStyle<Base, Format, Tables>::settings(int narg, char **arg)
{
  const int nbase = levels.settings(narg, arg);
  if (nbase != 0)
    this->error->all(FLERR,
                     "Pair style {} takes only the keywords ratio and scaling; got {} arguments "
                     "before them",
                     Format::style(), nbase);
  Base::settings(0, arg);
}

/* ----------------------------------------------------------------------
   pair_coeff * * file element_1 ... element_N level n_1 ... n_N: the
   base style reads the file and maps the elements; the level of each
   type follows, and each type's mass becomes l_n times the element's
------------------------------------------------------------------------- */

template <class Base, class Format, class Tables>
void PairGPEAMStyle<Base, Format, Tables>::coeff(int narg, char **arg)
{
  if (!this->allocated) allocate();
  const int nbase = levels.coeff_types(narg, arg, 3 + this->atom->ntypes);
  tables.check_elements(Format::style(), arg[2], this->atom->ntypes, arg + 3);
  Base::coeff(nbase, arg);
  for (int i = 1; i <= this->atom->ntypes; i++)
    if (this->map[i] >= 0)
      this->atom->set_mass(
          FLERR, i, GPKernels::level_atoms(levels.ratio, levels.level[i]) * this->atom->mass[i]);
}

template <class Base, class Format, class Tables>
void PairGPEAMStyle<Base, Format, Tables>::init_style()
{
  levels.check_all_set();
  levels.exclude_other_levels();
  Base::init_style();
}

/* ----------------------------------------------------------------------
   the base style's arrays and type maps (its file2array), then the level
   tables in their place; the atomic splines are the ones PairEAM makes
------------------------------------------------------------------------- */

template <class Base, class Format, class Tables>
void PairGPEAMStyle<Base, Format, Tables>::file2array()
{
  Base::file2array();
  double ***rhor_atomic = nullptr, ***z2r_atomic = nullptr;
  this->memory->create(rhor_atomic, this->nrhor, this->nr + 1, 7, "pair:rhor_atomic");
  this->memory->create(z2r_atomic, this->nz2r, this->nr + 1, 7, "pair:z2r_atomic");
  for (int t = 0; t < this->nrhor; t++)
    this->PairEAM::interpolate(this->nr, this->dr, this->rhor[t], rhor_atomic[t]);
  for (int t = 0; t < this->nz2r; t++)
    this->PairEAM::interpolate(this->nr, this->dr, this->z2r[t], z2r_atomic[t]);
  const double cut = this->setfl ? this->setfl->cut : this->fs->cut;
  tables.expand(*this, levels, cut, rhor_atomic, z2r_atomic);
  this->memory->destroy(rhor_atomic);
  this->memory->destroy(z2r_atomic);
  Tables::copy_maps(*this);
}

template <class Base, class Format, class Tables>
void PairGPEAMStyle<Base, Format, Tables>::array2spline()
{
  Base::array2spline();
  Tables::write_splines(*this, tables);
  tables.release();
}

/* ----------------------------------------------------------------------
   cutoff s_n rc of a pair of level n, none between levels; the base
   style's kernels test one cutoff for all pairs: the largest
------------------------------------------------------------------------- */

template <class Base, class Format, class Tables>
double PairGPEAMStyle<Base, Format, Tables>::init_one(int i, int j)
{
  const double cut = Base::init_one(i, j);
  int top = 1;
  for (int t = 1; t <= this->atom->ntypes; t++) top = std::max(top, levels.level[t]);
  const double reach = GPKernels::level_length(levels.ratio, top) * cut;
  this->cutforcesq = reach * reach;
  if (!levels.same_level(i, j)) return 0.0;
  return levels.length(i) * cut;
}

template <class Base, class Format, class Tables>
void *PairGPEAMStyle<Base, Format, Tables>::extract(const char *str, int &dim)
{
  if (strcmp(str, "gp_level") == 0) {
    dim = 1;
    return levels.level.data();
  }
  return Base::extract(str, dim);
}

}    // namespace LAMMPS_NS

#endif
