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

#ifdef FIX_CLASS
// clang-format off
FixStyle(MCA_LINKS/kk,FixMCALinksKokkos);
FixStyle(MCA_LINKS/kk/device,FixMCALinksKokkos);
FixStyle(MCA_LINKS/kk/host,FixMCALinksKokkos);
// clang-format on
#else

#ifndef LMP_FIX_MCA_LINKS_KOKKOS_H
#define LMP_FIX_MCA_LINKS_KOKKOS_H

#include "fix_mca_links.h"
#include "mca_kokkos_compat.h"

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   the link table of FixMCALinks in DualViews: the host pointers of the
   base class alias the host views, so migration, sorting and restart
   files work unchanged on the host; pair mca/kk works on the device
   views.  Which side is current is tracked by the DualView flags: the
   base class calls to_host() before and host_changed() after it touches
   the table, the pair style to_device() and device_changed().
------------------------------------------------------------------------- */

class FixMCALinksKokkos : public FixMCALinks {
 public:
  FixMCALinksKokkos(class LAMMPS *, int, char **);
  ~FixMCALinksKokkos() override;

  void to_host() override;
  void host_changed() override;
  void to_device();
  void device_changed();

  MCAKokkos::dual_int_1d k_nlinks;
  MCAKokkos::dual_tagint_2d k_partner;
  MCAKokkos::dual_int_2d k_slot;
  MCAKokkos::dual_double_2d k_rows;
  MCAKokkos::dual_double_2d k_atom_state;

 protected:
  void allocate_links(int nmax) override;
  void resize_atom_tables(int nmax) override;
  void grow_pool(int n) override;
};

}    // namespace LAMMPS_NS

#endif
#endif
