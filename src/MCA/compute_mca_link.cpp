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

#include "compute_mca_link.h"

#include "atom.h"
#include "atom_vec_mca.h"
#include "domain.h"
#include "error.h"
#include "fix_mca_links.h"
#include "mca_compat.h"
#include "mca_contact.h"
#include "mca_geometry.h"
#include "mca_link_law.h"
#include "memory.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace MCAKernels;

namespace {
enum {
  ID1,
  ID2,
  STATE,
  LENGTH,
  STRAIN,
  NORMAL,
  SHEAR,
  AREA,
  FORCE,
  ENERGY,
  DISSIPATED,
  PLASTIC_WORK,
  CAUSE,
  BREAK_STEP,
  RELEASED,
  FRICTION,
  NKEYWORD
};
const char *const keywords[NKEYWORD] = {"id1",    "id2",        "state",      "length",
                                        "strain", "normal",     "shear",      "area",
                                        "force",  "energy",     "dissipated", "plastic_work",
                                        "cause",  "break_step", "released",   "friction"};
}    // namespace

/* ----------------------------------------------------------------------
   compute ID group mca/link keyword ...
   one row per link whose lower-ID automaton is in the group
------------------------------------------------------------------------- */

ComputeMCALink::ComputeMCALink(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), nmax(0), vlocal(nullptr), alocal(nullptr), links(nullptr)
{
  if (narg < 4) utils::missing_cmd_args(FLERR, "compute mca/link (needs keywords)", error);
  for (int iarg = 3; iarg < narg; iarg++) {
    int k = 0;
    while (k < NKEYWORD && strcmp(arg[iarg], keywords[k]) != 0) k++;
    if (k == NKEYWORD)
      error->all(FLERR,
                 "Unknown compute mca/link keyword {} (allowed: id1 id2 state length "
                 "strain normal shear area force energy dissipated plastic_work cause break_step "
                 "released friction)",
                 arg[iarg]);
    which.push_back(k);
  }
  local_flag = 1;
  size_local_rows = 0;
  size_local_cols = (which.size() == 1) ? 0 : (int) which.size();
  if (!MCAAtomFields::find(atom))
    error->all(FLERR, "Compute mca/link requires atom_style mca, not {}", atom->atom_style);
}

/* ---------------------------------------------------------------------- */

ComputeMCALink::~ComputeMCALink()
{
  memory->destroy(vlocal);
  memory->destroy(alocal);
}

/* ---------------------------------------------------------------------- */

void ComputeMCALink::init()
{
  links = dynamic_cast<FixMCALinks *>(MCACompat::fix_by_id(modify, "MCA_LINKS"));
  if (!links) error->all(FLERR, "Compute mca/link requires pair_style mca (it has no links)");
}

/* ---------------------------------------------------------------------- */

int ComputeMCALink::count_rows()
{
  links->to_host();
  const tagint *tag = atom->tag;
  int n = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    for (int m = 0; m < links->nlinks[i]; m++)
      if (tag[i] < links->partner[i][m]) n++;
  }
  return n;
}

/* ---------------------------------------------------------------------- */

void ComputeMCALink::reallocate(int n)
{
  if (n <= nmax) return;
  nmax = n;
  memory->destroy(vlocal);
  memory->destroy(alocal);
  if (size_local_cols == 0) {
    memory->create(vlocal, nmax, "mca/link:vlocal");
    vector_local = vlocal;
  } else {
    memory->create(alocal, nmax, size_local_cols, "mca/link:alocal");
    array_local = alocal;
  }
}

/* ---------------------------------------------------------------------- */

void ComputeMCALink::compute_local()
{
  invoked_local = update->ntimestep;
  size_local_rows = count_rows();
  reallocate(MAX(size_local_rows, 1));

  double **x = atom->x;
  const tagint *tag = atom->tag;
  const int ncols = MAX(size_local_cols, 1);
  // the damping block, if the link model has one
  const int damping = links->model.layout().link_offset[PART_DAMPING];
  // and the fracture block
  const int fracture = links->model.layout().link_offset[PART_FRACTURE];
  // friction: broken pairs and contacts rub (a broken pair from its first
  // step on: until then its row holds the link's shear tractions)
  const bool friction = links->model.layout().link_offset[PART_CONTACT] >= 0;
  // each link once: from its lower ID
  int row = 0;
  double work[MAX_ROW_SIZE];
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    for (int m = 0; m < links->nlinks[i]; m++) {
      const tagint other = links->partner[i][m];
      if (tag[i] >= other) continue;
      const double *h = links->read_row(i, m, work);
      int j = atom->map(other);
      if (j < 0)
        error->one(FLERR,
                   "Compute mca/link: partner {} of automaton {} is not a local or ghost "
                   "atom",
                   other, tag[i]);
      j = domain->closest_image(i, j);
      const double del[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
      const double r = sqrt(dot3(del, del));
      // a broken pair or a contact pushes only (mca_link_law.h, mca_contact.h)
      const bool contact = static_cast<int>(h[H_STATE]) == LINK_CONTACT;
      double sig = 0.5 * (h[H_LO + HALF_SIG] + h[H_HI + HALF_SIG]);
      if (broken(h) || contact) sig = broken_traction(sig);
      // (a broken pair rubs only with friction, and not before its first
      // step: the row keeps the link's shear tractions until then)
      const bool no_shear = broken(h) &&
          (!friction || h[fracture + F_STEP] >= static_cast<double>(update->ntimestep));
      double t[3];
      for (int k = 0; k < 3; k++)
        t[k] = no_shear ? 0.0 : 0.5 * (h[H_LO + HALF_T + k] + h[H_HI + HALF_T + k]);
      const double tau = sqrt(dot3(t, t));
      const double area = h[H_APREV];
      const double dissipated = damping >= 0 ? h[damping + D_WORK] : 0.0;
      // the elastic energy is the work of the link forces less the plastic
      // work and what friction dissipated
      const double plastic_work = link_plastic_work(h, links->model.layout());
      const double friction_work = link_friction_work(h, links->model.layout());
      for (int c = 0; c < ncols; c++) {
        double value = 0.0;
        switch (which[c]) {
          case ID1:
            value = tag[i];
            break;
          case ID2:
            value = other;
            break;
          case STATE:
            value = h[H_STATE];
            break;
          case LENGTH:
            value = r;
            break;
          case STRAIN:
            value = r / h[H_R0] - 1.0;
            break;
          case NORMAL:
            value = sig;
            break;
          case SHEAR:
            value = tau;
            break;
          case AREA:
            value = area;
            break;
          case FORCE:
            value = area * sqrt(sig * sig + tau * tau);
            break;
          case ENERGY:
            value = h[H_WORK] - plastic_work - friction_work;
            break;
          case DISSIPATED:
            value = dissipated;
            break;
          case PLASTIC_WORK:
            value = plastic_work;
            break;
          case CAUSE:
            value = fracture >= 0 ? h[fracture + F_CAUSE] : 0.0;
            break;
          case BREAK_STEP:
            value = (fracture >= 0 && broken(h)) ? h[fracture + F_STEP] : -1.0;
            break;
          case RELEASED:
            value = fracture >= 0 ? h[fracture + F_RELEASED] : 0.0;
            break;
          case FRICTION:
            value = friction_work;
            break;
        }
        if (size_local_cols == 0)
          vlocal[row] = value;
        else
          alocal[row][c] = value;
      }
      row++;
    }
  }
}

/* ---------------------------------------------------------------------- */

double ComputeMCALink::memory_usage()
{
  return (double) nmax * MAX(size_local_cols, 1) * sizeof(double);
}
