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

#include "pair_gp_eam_fs.h"

#include "gp_eam_style_impl.h"

namespace LAMMPS_NS {

#ifdef MCA_HAVE_EAM_VIRTUAL_BASE
template <>
PairGPEAMStyle<PairEAMFS, GPEAMFS, GPEAMHostTables>::PairGPEAMStyle(LAMMPS *lmp) :
    PairEAM(lmp), PairEAMFS(lmp), levels(lmp, GPEAMFS::style()), tables(lmp)
{
}
#endif

template class PairGPEAMStyle<PairEAMFS, GPEAMFS, GPEAMHostTables>;

}    // namespace LAMMPS_NS
