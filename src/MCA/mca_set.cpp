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

#include "mca_set.h"

#include "atom.h"
#include "atom_vec_mca.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "input.h"
#include "math_const.h"
#include "mca_compat.h"
#include "mca_kernels.h"
#include "memory.h"
#include "variable.h"

#include <cmath>
#include <cstring>
#include <limits>

using namespace LAMMPS_NS;
using namespace MCAKernels;

namespace {

// one numeric mca_set value: a constant or an atom-style variable
struct Value {
  bool given = false;
  int ivar = -1;
  double constant = 0.0;
  double *per_atom = nullptr;
  double at(int i) const { return ivar >= 0 ? per_atom[i] : constant; }
};

// keywords with one numeric value; lower bound and whether it is inclusive
struct ScalarKeyword {
  const char *name;
  double lo, hi;
  bool lo_inclusive;
};

enum {
  RADIUS,
  DIAMETER,
  DENSITY,
  MASS,
  VOLUME,
  INERTIA,
  SMEAN,
  SEQ,
  EEQ,
  EPSP,
  DAMAGE,
  ANGLE,
  TURNX,
  TURNY,
  TURNZ,
  NSCALAR
};

constexpr double BIG = 1.0e300;
const ScalarKeyword scalar_keywords[NSCALAR] = {
    {"radius", 0.0, BIG, false}, {"diameter", 0.0, BIG, false}, {"density", 0.0, BIG, false},
    {"mass", 0.0, BIG, false},   {"volume", 0.0, BIG, false},   {"inertia", 0.0, BIG, false},
    {"smean", -BIG, BIG, true},  {"seq", 0.0, BIG, true},       {"eeq", 0.0, BIG, true},
    {"epsp", 0.0, BIG, true},    {"damage", 0.0, 1.0, true},    {"angle", -BIG, BIG, true},
    {"turnx", -BIG, BIG, true},  {"turny", -BIG, BIG, true},    {"turnz", -BIG, BIG, true}};

std::string range_text(const ScalarKeyword &k)
{
  if (k.hi < BIG) return fmt::format("in [{}, {}]", k.lo, k.hi);
  if (k.lo <= -BIG) return fmt::format("in [{}, {}]", -BIG, BIG);
  return fmt::format("{} {} and <= {}", k.lo_inclusive ? ">=" : ">", k.lo, BIG);
}

// the geometry and mass of an automaton, as mca_set leaves them
struct Geometry {
  int packing;
  double radius, volume, mass, inertia;
  bool valid() const
  {
    for (double v : {radius, volume, mass, inertia})
      if (!(v > 0.0 && v <= std::numeric_limits<double>::max())) return false;
    return true;
  }
};

bool in_range(const ScalarKeyword &k, double value)
{
  if (value != value) return false;    // NaN
  if (k.lo_inclusive ? value < k.lo : value <= k.lo) return false;
  return value <= k.hi;
}

}    // namespace

/* ----------------------------------------------------------------------
   mca_set group-ID keyword value ...
   sets the packing, size, mass and state of automata and keeps the derived
   cell volume and moment of inertia consistent with them
------------------------------------------------------------------------- */

void MCASet::command(int narg, char **arg)
{
  if (narg < 2) utils::missing_cmd_args(FLERR, "mca_set", error);
  if (domain->box_exist == 0) error->all(FLERR, "mca_set command before simulation box is defined");
  auto avec = MCAAtomFields::find(atom);
  if (!avec) error->all(FLERR, "mca_set requires atom_style mca, not {}", atom->atom_style);
  avec->sync_host();    // atom-style variables below read the host copy

  const int igroup = group->find(arg[0]);
  if (igroup < 0) error->all(FLERR, "mca_set: could not find group ID {}", arg[0]);
  const int groupbit = group->bitmask[igroup];

  int new_packing = -1;
  Value values[NSCALAR];
  bool stress_given = false;
  double new_stress[MCAAtomFields::NSTRESS] = {0.0};

  int iarg = 1;
  while (iarg < narg) {
    const std::string keyword = arg[iarg];
    int k = 0;
    while (k < NSCALAR && keyword != scalar_keywords[k].name) k++;

    if (k < NSCALAR) {
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, "mca_set " + keyword, error);
      Value &value = values[k];
      value.given = true;
      if (utils::strmatch(arg[iarg + 1], "^v_")) {
        value.ivar = input->variable->find(arg[iarg + 1] + 2);
        if (value.ivar < 0)
          error->all(FLERR, "mca_set {}: variable {} does not exist", keyword, arg[iarg + 1] + 2);
        if (!input->variable->atomstyle(value.ivar))
          error->all(FLERR, "mca_set {}: variable {} is not atom-style", keyword,
                     arg[iarg + 1] + 2);
      } else {
        value.constant = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
        if (!in_range(scalar_keywords[k], value.constant))
          error->all(FLERR, "mca_set {} must be {}, got {}", keyword,
                     range_text(scalar_keywords[k]), arg[iarg + 1]);
      }
      iarg += 2;
    } else if (keyword == "packing") {
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, "mca_set packing", error);
      const std::string word = arg[iarg + 1];
      if (word == "none")
        new_packing = PACKING_NONE;
      else if (word == "sc")
        new_packing = PACKING_SC;
      else if (word == "fcc" || word == "hcp")
        new_packing = PACKING_FCC;
      else
        error->all(FLERR, "mca_set packing must be one of none, sc, fcc, hcp; got {}", word);
      iarg += 2;
    } else if (keyword == "stress") {
      if (iarg + 1 + MCAAtomFields::NSTRESS > narg)
        utils::missing_cmd_args(FLERR, "mca_set stress (needs sxx syy szz sxy sxz syz)", error);
      for (int m = 0; m < MCAAtomFields::NSTRESS; m++)
        new_stress[m] = utils::numeric(FLERR, arg[iarg + 1 + m], false, lmp);
      stress_given = true;
      iarg += 1 + MCAAtomFields::NSTRESS;
    } else {
      error->all(FLERR,
                 "Unknown mca_set keyword {} (allowed: packing radius diameter density "
                 "mass volume inertia smean stress seq eeq epsp damage angle turnx turny turnz)",
                 keyword);
    }
  }
  if (values[RADIUS].given && values[DIAMETER].given)
    error->all(FLERR, "mca_set: use either radius or diameter, not both");
  if (values[MASS].given && values[DENSITY].given)
    error->all(FLERR, "mca_set: use either mass or density, not both");
  const bool turn = values[TURNX].given || values[TURNY].given || values[TURNZ].given;
  if (turn && values[ANGLE].given)
    error->all(FLERR, "mca_set: use either angle (set) or turnx/turny/turnz (turn by), not both");
  if (domain->dimension == 2 && (values[TURNX].given || values[TURNY].given))
    error->all(FLERR,
               "mca_set: turnx and turny need dimension 3 (a 2-D particle turns about z: "
               "angle or turnz)");

  // evaluate atom-style variables over all local atoms

  const int nlocal = atom->nlocal;
  for (int k = 0; k < NSCALAR; k++) {
    if (values[k].ivar < 0) continue;
    memory->create(values[k].per_atom, nlocal > 0 ? nlocal : 1, "mca_set:per_atom");
    input->variable->compute_atom(values[k].ivar, igroup, values[k].per_atom, 1, 0);
  }

  const bool geometry_changed = new_packing >= 0 || values[RADIUS].given || values[DIAMETER].given;
  const bool volume_changed = geometry_changed || values[VOLUME].given;
  const bool mass_changed = volume_changed || values[MASS].given || values[DENSITY].given;

  // values from variables are checked per atom before anything changes

  int bad = -1, badall;
  for (int i = 0; i < nlocal; i++)
    if (atom->mask[i] & groupbit)
      for (int k = 0; k < NSCALAR; k++)
        if (values[k].ivar >= 0 && !in_range(scalar_keywords[k], values[k].at(i))) bad = k;
  MPI_Allreduce(&bad, &badall, 1, MPI_INT, MPI_MAX, world);
  if (badall >= 0) {
    for (auto &value : values) memory->destroy(value.per_atom);
    error->all(FLERR,
               "mca_set {}: atom-style variable gives a value outside the allowed range "
               "({})",
               scalar_keywords[badall].name, range_text(scalar_keywords[badall]));
  }

  // what an automaton becomes (nothing is changed here)
  auto planned = [&](int i) {
    Geometry g{avec->packing[i], atom->radius[i], avec->volume[i], atom->rmass[i],
               avec->inertia[i]};
    const double old_density = g.mass / g.volume;
    if (new_packing >= 0) g.packing = new_packing;
    if (values[RADIUS].given) g.radius = values[RADIUS].at(i);
    if (values[DIAMETER].given) g.radius = 0.5 * values[DIAMETER].at(i);

    if (values[VOLUME].given)
      g.volume = values[VOLUME].at(i);
    else if (geometry_changed)
      g.volume = MCAKernels::cell_volume(g.packing, g.radius);

    // a new volume without mass or density keeps the material density
    if (values[MASS].given)
      g.mass = values[MASS].at(i);
    else if (values[DENSITY].given)
      g.mass = values[DENSITY].at(i) * g.volume;
    else if (volume_changed)
      g.mass = old_density * g.volume;

    if (values[INERTIA].given)
      g.inertia = values[INERTIA].at(i);
    else if (mass_changed)
      g.inertia = MCAKernels::cell_inertia(g.packing, g.mass, g.radius);
    return g;
  };

  // values that are each in range can still make a derived quantity
  // overflow (the volume grows as radius^3): checked before any change
  tagint bad_tag = 0;
  double bad_values[4] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL, -HUGE_VAL}, bad_all[4];
  for (int i = 0; i < nlocal && !bad_tag; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const Geometry g = planned(i);
    if (g.valid()) continue;
    bad_tag = atom->tag[i];
    bad_values[0] = g.radius, bad_values[1] = g.volume, bad_values[2] = g.mass;
    bad_values[3] = g.inertia;
  }
  tagint bad_tag_all;
  MPI_Allreduce(&bad_tag, &bad_tag_all, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  if (bad_tag_all) {
    if (bad_tag != bad_tag_all)
      for (double &v : bad_values) v = -HUGE_VAL;
    MPI_Allreduce(bad_values, bad_all, 4, MPI_DOUBLE, MPI_MAX, world);
    for (auto &value : values) memory->destroy(value.per_atom);
    error->all(FLERR,
               "mca_set: automaton {} would get radius {}, cell volume {}, mass {} and moment of "
               "inertia {}; each must be finite and > 0 (a value given is too large or too "
               "small for the quantities derived from it)",
               bad_tag_all, bad_all[0], bad_all[1], bad_all[2], bad_all[3]);
  }

  int count = 0;
  for (int i = 0; i < nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;

    const Geometry g = planned(i);
    avec->packing[i] = g.packing;
    atom->radius[i] = g.radius;
    avec->volume[i] = g.volume;
    atom->rmass[i] = g.mass;
    avec->inertia[i] = g.inertia;
    // pair mca keeps a mass or inertia given here (and the mass it has
    // already, for an inertia given alone)
    if (values[MASS].given || values[DENSITY].given) avec->given[i] |= MCAAtomFields::GIVEN_MASS;
    if (values[INERTIA].given) avec->given[i] |= MCAAtomFields::GIVEN_INERTIA;
    avec->given[i] &= ~MCAAtomFields::FROM_DATA;

    if (values[SMEAN].given) avec->smean[i] = values[SMEAN].at(i);
    if (values[SEQ].given) avec->seq[i] = values[SEQ].at(i);
    if (values[EEQ].given) avec->eeq[i] = values[EEQ].at(i);
    if (values[EPSP].given) avec->epsp[i] = values[EPSP].at(i);
    if (values[DAMAGE].given) avec->damage[i] = values[DAMAGE].at(i);
    // orientation: a turn about z by the angle (degrees; 2-D particles)
    if (values[ANGLE].given) {
      const double half = 0.5 * values[ANGLE].at(i) * MathConst::MY_PI / 180.0;
      avec->quat[i][0] = cos(half);
      avec->quat[i][1] = avec->quat[i][2] = 0.0;
      avec->quat[i][3] = sin(half);
    }
    // a turn from the present orientation by the rotation vector (degrees)
    if (turn) {
      const double to_rad = MathConst::MY_PI / 180.0;
      const double r[3] = {values[TURNX].given ? values[TURNX].at(i) * to_rad : 0.0,
                           values[TURNY].given ? values[TURNY].at(i) * to_rad : 0.0,
                           values[TURNZ].given ? values[TURNZ].at(i) * to_rad : 0.0};
      const double angle = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
      const double s = (angle > 0.0) ? sin(0.5 * angle) / angle : 0.0;
      const double dq[4] = {cos(0.5 * angle), s * r[0], s * r[1], s * r[2]};
      double *q = avec->quat[i];
      const double turned[4] = {dq[0] * q[0] - dq[1] * q[1] - dq[2] * q[2] - dq[3] * q[3],
                                dq[0] * q[1] + dq[1] * q[0] + dq[2] * q[3] - dq[3] * q[2],
                                dq[0] * q[2] - dq[1] * q[3] + dq[2] * q[0] + dq[3] * q[1],
                                dq[0] * q[3] + dq[1] * q[2] - dq[2] * q[1] + dq[3] * q[0]};
      for (int k = 0; k < 4; k++) q[k] = turned[k];
    }
    if (stress_given)
      for (int m = 0; m < MCAAtomFields::NSTRESS; m++) avec->stress[i][m] = new_stress[m];
    count++;
  }
  avec->modified_host();
  for (auto &value : values) memory->destroy(value.per_atom);

  bigint nlocal_set = count, nall_set;
  MPI_Allreduce(&nlocal_set, &nall_set, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (comm->me == 0) utils::logmesg(lmp, "mca_set: {} automata updated\n", nall_set);
}
