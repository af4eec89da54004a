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

/* ----------------------------------------------------------------------
   Contributing authors: MCA package developers
------------------------------------------------------------------------- */

#include "atom_vec_mca.h"
#include "atom_vec_mca_impl.h"

#include "atom.h"
#include "error.h"
#include "group.h"

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

MCAAtomFields::MCAAtomFields() :
    radius(nullptr), rmass(nullptr), omega(nullptr), quat(nullptr), packing(nullptr),
    volume(nullptr), inertia(nullptr), smean(nullptr), stress(nullptr), seq(nullptr), eeq(nullptr),
    epsp(nullptr), damage(nullptr), given(nullptr)
{
}

/* ----------------------------------------------------------------------
   the MCA style of the system: mca or mca/kk, alone or in a hybrid style
------------------------------------------------------------------------- */

MCAAtomFields *MCAAtomFields::find(Atom *atom)
{
  auto fields = dynamic_cast<MCAAtomFields *>(atom->avec);
  if (!fields) fields = dynamic_cast<MCAAtomFields *>(atom->style_match("mca"));
  return fields;
}

void MCAAtomFields::require_mass_and_inertia(LAMMPS *lmp, int igroup, const char *style)
{
  const int groupbit = lmp->group->bitmask[igroup];
  const int *mask = lmp->atom->mask;
  int flag = 0, flagall;
  for (int i = 0; i < lmp->atom->nlocal; i++)
    if ((mask[i] & groupbit) && (lmp->atom->rmass[i] <= 0.0 || inertia[i] <= 0.0)) flag = 1;
  MPI_Allreduce(&flag, &flagall, 1, MPI_INT, MPI_MAX, lmp->world);
  if (flagall)
    lmp->error->all(FLERR,
                    "{} requires every automaton in group {} to have a positive mass and "
                    "moment of inertia",
                    style, lmp->group->names[igroup]);
}

namespace LAMMPS_NS {
template class AtomVecMCAStyle<AtomVec>;
}
