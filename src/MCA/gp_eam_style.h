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

#ifndef LMP_GP_EAM_STYLE_H
#define LMP_GP_EAM_STYLE_H

#include "gp_eam_tables.h"

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   a GP pair style over a LAMMPS EAM style of setfl or Finnis-Sinclair
   files (Base: eam/alloy, eam/fs or their Kokkos variants): the energy of
   a level-n particle is c_n [F(sum rho(R/s_n)) + 1/2 sum phi(R/s_n)], so
   the base style's tables are replaced by the level tables
   (gp_eam_tables.h) and its kernels evaluate them; cutoff s_n rc per
   level, types of different levels do not interact, masses l_n m0.
   Tables: where the base keeps its splines (Tables::write_splines,
   Tables::copy_maps: the host arrays, or the Kokkos views), a friend
------------------------------------------------------------------------- */

struct GPEAMAlloy {
  static const char *style() { return "gp/eam/alloy"; }
};

struct GPEAMFS {
  static const char *style() { return "gp/eam/fs"; }
};

// the base style keeps its tables on the host only (CPU styles)
struct GPEAMHostTables {
  template <class Pair> static void copy_maps(Pair &) {}
  template <class Pair> static void write_splines(Pair &pair, const GPEAMTables &tables)
  {
    tables.write_rows(pair.rhor_spline, pair.z2r_spline);
  }
};

template <class Base, class Format, class Tables> class PairGPEAMStyle : public Base {
  friend Tables;

 public:
  PairGPEAMStyle(class LAMMPS *);

  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  // "gp_level": the level of each atom type (for fix gp/link)
  void *extract(const char *, int &) override;

 protected:
  GPLevels levels;
  GPEAMTables tables;

  void allocate() override;
  void file2array() override;
  void array2spline() override;
};

}    // namespace LAMMPS_NS

#endif
