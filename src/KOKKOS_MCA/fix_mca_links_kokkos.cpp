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

#include "fix_mca_links_kokkos.h"

#include "atom.h"
#include "memory.h"
#include "memory_kokkos.h"

using namespace LAMMPS_NS;
using namespace MCAKernels;

/* ---------------------------------------------------------------------- */

FixMCALinksKokkos::FixMCALinksKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixMCALinks(lmp, narg, arg)
{
  MCAKokkos::require_kokkos(lmp, "Fix MCA_LINKS/kk (internal fix of pair mca/kk)");
  kokkosable = 1;

  // a restart file restores the per-atom rows of a fix only into a fix of
  // the same ID and style: this one and the CPU fix read each other's files
  delete[] style;
  style = utils::strdup("MCA_LINKS");

  // the base constructor allocated the table with plain arrays (virtual
  // calls do not reach this class there): redo it in DualViews
  memory->destroy(nlinks);
  memory->destroy(partner);
  memory->destroy(slot);
  memory->destroy(atom_state);
  nmax_atoms = 0;
  const int capacity = maxlinks;
  maxlinks = 0;
  set_capacity(capacity);
}

/* ---------------------------------------------------------------------- */

FixMCALinksKokkos::~FixMCALinksKokkos()
{
  // the base destructor then finds null pointers
  memoryKK->destroy_kokkos(k_nlinks, nlinks);
  memoryKK->destroy_kokkos(k_partner, partner);
  memoryKK->destroy_kokkos(k_slot, slot);
  k_rows = MCAKokkos::dual_double_2d();
  rows = nullptr;
  memoryKK->destroy_kokkos(k_atom_state, atom_state);
}

/* ---------------------------------------------------------------------- */

void FixMCALinksKokkos::allocate_links(int nmax)
{
  memoryKK->destroy_kokkos(k_partner, partner);
  memoryKK->destroy_kokkos(k_slot, slot);
  memoryKK->create_kokkos(k_partner, partner, nmax, maxlinks, "mca/links:partner");
  memoryKK->create_kokkos(k_slot, slot, nmax, maxlinks, "mca/links:slot");
}

// (on the host: the rows are added there)
void FixMCALinksKokkos::grow_pool(int n)
{
  to_host();
  // (a flat host pool, as the base class's: no array of row pointers)
  if (k_rows.extent(0) == 0)
    k_rows = MCAKokkos::dual_double_2d("mca/links:rows", n, stored_size);
  else
    k_rows.resize(n, stored_size);
  rows = k_rows.view_host().data();
  maxrows = n;
  host_changed();
}

/* ---------------------------------------------------------------------- */

// (on the host, within the base class's reserve_atoms)
void FixMCALinksKokkos::resize_atom_tables(int nmax)
{
  memoryKK->grow_kokkos(k_nlinks, nlinks, nmax, "mca/links:nlinks");
  memoryKK->grow_kokkos(k_partner, partner, nmax, maxlinks, "mca/links:partner");
  memoryKK->grow_kokkos(k_slot, slot, nmax, maxlinks, "mca/links:slot");
  memoryKK->grow_kokkos(k_atom_state, atom_state, nmax, atom_size, "mca/links:atom_state");
}

/* ---------------------------------------------------------------------- */

void FixMCALinksKokkos::to_host()
{
  k_nlinks.sync_host();
  k_partner.sync_host();
  k_slot.sync_host();
  k_rows.sync_host();
  k_atom_state.sync_host();
}

void FixMCALinksKokkos::host_changed()
{
  k_nlinks.modify_host();
  k_partner.modify_host();
  k_slot.modify_host();
  k_rows.modify_host();
  k_atom_state.modify_host();
}

void FixMCALinksKokkos::to_device()
{
  k_nlinks.sync_device();
  k_partner.sync_device();
  k_slot.sync_device();
  k_rows.sync_device();
  k_atom_state.sync_device();
}

// the pair style changes only the rows and the law state
void FixMCALinksKokkos::device_changed()
{
  k_rows.modify_device();
  k_atom_state.modify_device();
}
