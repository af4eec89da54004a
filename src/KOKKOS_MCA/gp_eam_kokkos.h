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

#ifndef LMP_GP_EAM_KOKKOS_H
#define LMP_GP_EAM_KOKKOS_H

#include "gp_eam_style.h"
#include "kokkos_type.h"

#include <type_traits>

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   where the Kokkos EAM styles keep their tables: in views on their device
   (d_type2frho, d_type2rhor, d_type2z2r, d_rhor_spline, d_z2r_spline,
   the names of both KOKKOS versions), made from the host arrays in their
   file2array and array2spline.  The GP styles replace the views with the
   level tables (gp_eam_style.h)
------------------------------------------------------------------------- */

struct GPEAMKokkosTables {
  // a new view of the same type, extents and label, filled on the host by
  // fill(mirror) (views a kernel reads as const are made anew)
  template <class View, class Fill> static void replace_view(View &view, Fill fill)
  {
    using Fresh = Kokkos::View<typename View::non_const_data_type, typename View::array_layout,
                               typename View::device_type>;
    Fresh fresh(Kokkos::view_alloc(Kokkos::WithoutInitializing, view.label()), view.layout());
    auto host = Kokkos::create_mirror_view(fresh);
    fill(host);
    Kokkos::deep_copy(fresh, host);
    view = fresh;
  }

  template <class Pair> static void copy_maps(Pair &pair)
  {
    const int n = pair.atom->ntypes;
    replace_view(pair.d_type2frho, [&](auto &h) {
      for (int i = 0; i <= n; i++) h(i) = (i > 0) ? pair.type2frho[i] : 0;
    });
    replace_view(pair.d_type2rhor, [&](auto &h) {
      for (int i = 0; i <= n; i++)
        for (int j = 0; j <= n; j++) h(i, j) = (i > 0 && j > 0) ? pair.type2rhor[i][j] : 0;
    });
    replace_view(pair.d_type2z2r, [&](auto &h) {
      for (int i = 0; i <= n; i++)
        for (int j = 0; j <= n; j++) h(i, j) = (i > 0 && j > 0) ? pair.type2z2r[i][j] : 0;
    });
  }

  template <class Pair> static void write_splines(Pair &pair, const GPEAMTables &tables)
  {
    replace_view(pair.d_rhor_spline, [&](auto &h) {
      using Value = typename std::decay<decltype(h)>::type::non_const_value_type;
      for (int t = 0; t < tables.nrhor(); t++)
        for (int m = 0; m < tables.nrows(); m++)
          for (int k = 0; k < 7; k++) h(t, m, k) = static_cast<Value>(tables.rhor_row(t, m, k));
    });
    replace_view(pair.d_z2r_spline, [&](auto &h) {
      using Value = typename std::decay<decltype(h)>::type::non_const_value_type;
      for (int t = 0; t < tables.nz2r(); t++)
        for (int m = 0; m < tables.nrows(); m++)
          for (int k = 0; k < 7; k++) h(t, m, k) = static_cast<Value>(tables.z2r_row(t, m, k));
    });
  }
};

}    // namespace LAMMPS_NS

#endif
