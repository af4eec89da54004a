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

#ifdef PAIR_CLASS
// clang-format off
PairStyle(gp/eam/fs/kk,PairGPEAMFSKokkos<LMPDeviceType>);
PairStyle(gp/eam/fs/kk/device,PairGPEAMFSKokkos<LMPDeviceType>);
PairStyle(gp/eam/fs/kk/host,PairGPEAMFSKokkos<LMPHostType>);
// clang-format on
#else

#ifndef LMP_PAIR_GP_EAM_FS_KOKKOS_H
#define LMP_PAIR_GP_EAM_FS_KOKKOS_H

#include "gp_eam_kokkos.h"
#include "pair_eam_fs_kokkos.h"
#include "pair_gp_eam_fs.h"

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   pair_style gp/eam/fs/kk: the kernels of eam/fs/kk with the tables of
   the GP scale levels (gp_eam_style.h), so that it matches gp/eam/fs as
   eam/fs/kk matches eam/fs
------------------------------------------------------------------------- */

template <class DeviceType>
class PairGPEAMFSKokkos :
    public PairGPEAMStyle<PairEAMFSKokkos<DeviceType>, GPEAMFS, GPEAMKokkosTables> {
 public:
  PairGPEAMFSKokkos(class LAMMPS *lmp) :
      PairGPEAMStyle<PairEAMFSKokkos<DeviceType>, GPEAMFS, GPEAMKokkosTables>(lmp)
  {
  }
};

}    // namespace LAMMPS_NS

#endif
#endif
