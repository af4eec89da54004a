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

#include "compute_mca_atom.h"

#include "atom.h"
#include "atom_vec_mca.h"
#include "error.h"
#include "fix_mca_links.h"
#include "mca_compat.h"
#include "mca_contact.h"
#include "mca_link_law.h"
#include "memory.h"
#include "update.h"

#include <cstring>

using namespace LAMMPS_NS;

namespace {
enum {
  SXX,
  SYY,
  SZZ,
  SXY,
  SXZ,
  SYZ,
  SMEAN,
  SEQ,
  EEQ,
  LINKS,
  EPSP,
  PLASTIC_WORK,
  DAMAGE,
  CONTACTS,
  FRICTION,
  CONTACT_WORK,
  HEALED,
  NKEYWORD
};
const char *const keywords[NKEYWORD] = {
    "sxx",    "syy",      "szz",      "sxy",          "sxz",   "syz",
    "smean",  "seq",      "eeq",      "links",        "epsp",  "plastic_work",
    "damage", "contacts", "friction", "contact_work", "healed"};
}    // namespace

/* ----------------------------------------------------------------------
   compute ID group mca/atom keyword ...
------------------------------------------------------------------------- */

ComputeMCAAtom::ComputeMCAAtom(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), nmax(0), vector(nullptr), array(nullptr), avec(nullptr), links(nullptr)
{
  if (narg < 4) utils::missing_cmd_args(FLERR, "compute mca/atom (needs keywords)", error);
  for (int iarg = 3; iarg < narg; iarg++) {
    int k = 0;
    while (k < NKEYWORD && strcmp(arg[iarg], keywords[k]) != 0) k++;
    if (k == NKEYWORD)
      error->all(FLERR,
                 "Unknown compute mca/atom keyword {} (allowed: sxx syy szz sxy sxz syz "
                 "smean seq eeq links epsp plastic_work damage contacts friction "
                 "contact_work healed)",
                 arg[iarg]);
    which.push_back(k);
  }
  peratom_flag = 1;
  size_peratom_cols = (which.size() == 1) ? 0 : (int) which.size();

  avec = MCAAtomFields::find(atom);
  if (!avec)
    error->all(FLERR, "Compute mca/atom requires atom_style mca, not {}", atom->atom_style);
}

/* ---------------------------------------------------------------------- */

ComputeMCAAtom::~ComputeMCAAtom()
{
  memory->destroy(vector);
  memory->destroy(array);
}

/* ---------------------------------------------------------------------- */

void ComputeMCAAtom::init()
{
  avec = MCAAtomFields::find(atom);
  if (!avec) error->all(FLERR, "Compute mca/atom requires atom_style mca");
  // the values are what the pair style stored at its last force
  // evaluation: without it they would be zeros or stale
  links = dynamic_cast<FixMCALinks *>(MCACompat::fix_by_id(modify, "MCA_LINKS"));
  if (!links)
    error->all(FLERR,
               "Compute mca/atom requires pair_style mca (its values are those of the pair "
               "style's last force evaluation)");
}

/* ---------------------------------------------------------------------- */

double ComputeMCAAtom::value(int i, int w)
{
  if (w <= SYZ) return avec->stress[i][w];
  if (w == SMEAN) return avec->smean[i];
  if (w == SEQ) return avec->seq[i];
  if (w == EEQ) return avec->eeq[i];
  if (w == EPSP) return avec->epsp[i];
  if (w == DAMAGE) return avec->damage[i];
  if (w == PLASTIC_WORK) {
    const int offset = links->model.layout().atom_offset[MCAKernels::PART_PLASTICITY];
    return offset >= 0 ? links->atom_state[i][offset + MCAKernels::PA_WORK] : 0.0;
  }
  const MCAKernels::MCALinkLayout &layout = links->model.layout();
  if (w == HEALED) {
    // half of its links that healed: the sum over the automata is the count
    const int ha = layout.atom_offset[MCAKernels::PART_HEALING];
    return ha >= 0 ? 0.5 * links->atom_state[i][ha + MCAKernels::HA_HEALED] : 0.0;
  }
  if (w == FRICTION || w == CONTACT_WORK) {
    // half of what its rows and its dropped contacts hold (each automaton
    // of a pair holds the whole): the sum over the automata is the total
    const int ca = layout.atom_offset[MCAKernels::PART_CONTACT];
    if (ca < 0) return 0.0;
    if (w == CONTACT_WORK) return 0.5 * links->atom_state[i][ca + MCAKernels::CA_WORK];
    double sum = links->atom_state[i][ca + MCAKernels::CA_FRICTION];
    double work[MCAKernels::MAX_ROW_SIZE];
    for (int m = 0; m < links->nlinks[i]; m++)
      sum += MCAKernels::link_friction_work(links->read_row(i, m, work), layout);
    return 0.5 * sum;
  }
  // links: linked partners of the automaton; contacts: the partners it
  // touches (contact rows that push)
  const int state = (w == CONTACTS) ? MCAKernels::LINK_CONTACT : MCAKernels::LINK_LINKED;
  int n = 0;
  double work[MCAKernels::MAX_ROW_SIZE];
  for (int m = 0; m < links->nlinks[i]; m++) {
    if (links->link_state(i, m) != state) continue;
    if (w == CONTACTS) {
      const double *row = links->read_row(i, m, work);
      if (!(row[MCAKernels::H_LO + MCAKernels::HALF_SIG] +
                row[MCAKernels::H_HI + MCAKernels::HALF_SIG] <
            0.0))
        continue;
    }
    n++;
  }
  return n;
}

/* ---------------------------------------------------------------------- */

void ComputeMCAAtom::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(vector);
    memory->destroy(array);
    if (size_peratom_cols == 0) {
      memory->create(vector, nmax, "mca/atom:vector");
      vector_atom = vector;
    } else {
      memory->create(array, nmax, size_peratom_cols, "mca/atom:array");
      array_atom = array;
    }
  }

  // the values of the last force evaluation (on a device for kk styles)
  avec->sync_host();
  links->to_host();
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; i++) {
    const bool in = mask[i] & groupbit;
    if (size_peratom_cols == 0)
      vector[i] = in ? value(i, which[0]) : 0.0;
    else
      for (int k = 0; k < size_peratom_cols; k++) array[i][k] = in ? value(i, which[k]) : 0.0;
  }
}

/* ---------------------------------------------------------------------- */

double ComputeMCAAtom::memory_usage()
{
  return (double) nmax * MAX(size_peratom_cols, 1) * sizeof(double);
}
