// clang-format off
/* ----------------------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   LAMMPS development team: developers@lammps.org

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */
// clang-format on

#include "pair_gp_eam_fs_kokkos.h"

#include "gp_eam_style_impl.h"

namespace LAMMPS_NS {
template class PairGPEAMStyle<PairEAMFSKokkos<LMPDeviceType>, GPEAMFS, GPEAMKokkosTables>;
template class PairGPEAMFSKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class PairGPEAMStyle<PairEAMFSKokkos<LMPHostType>, GPEAMFS, GPEAMKokkosTables>;
template class PairGPEAMFSKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
