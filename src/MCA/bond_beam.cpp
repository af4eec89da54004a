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

#include "bond_beam.h"

#include "atom.h"
#include "atom_vec_mca.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_beam_state.h"
#include "force.h"
#include "math_const.h"
#include "mca_compat.h"
#include "mca_largest_row.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "pair.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

using namespace LAMMPS_NS;
using namespace BeamKernels;

static const char FIX_ID[] = "BEAM_STATE";

/* ---------------------------------------------------------------------- */

BondBeam::BondBeam(LAMMPS *_lmp) :
    Bond(_lmp), coeffs(nullptr), fix_state(nullptr), L0_max(0.0), nrec(REC_REF + NREF_2D),
    built_at(-1), built_n(0), breaking(0), damping(0), radii(0), particle(0), update_special(0),
    records(nullptr), maxrecords(0)
{
}

BondBeam::~BondBeam()
{
  if (copymode) return;
  if (allocated) {
    memory->destroy(setflag);
    memory->sfree(coeffs);
  }
  // the fix stays: a bond_style beam defined again keeps the reference states
  memory->destroy(records);
}

/* ---------------------------------------------------------------------- */

void BondBeam::allocate()
{
  allocated = 1;
  const int np1 = atom->nbondtypes + 1;
  memory->create(setflag, np1, "bond:setflag");
  for (int i = 1; i < np1; i++) setflag[i] = 0;
  coeffs = static_cast<BeamCoeff *>(memory->smalloc(np1 * sizeof(BeamCoeff), "bond:coeffs"));
  memset(coeffs, 0, np1 * sizeof(BeamCoeff));
}

/* ---------------------------------------------------------------------- */

void BondBeam::settings(int narg, char **arg)
{
  if (narg > 0)
    error->all(FLERR, "Illegal bond_style beam command: unexpected argument '{}' (no settings)",
               arg[0]);
}

/* ----------------------------------------------------------------------
   the internal fix with the reference states, made if there is none
------------------------------------------------------------------------- */

void BondBeam::find_state()
{
  fix_state = dynamic_cast<FixBeamState *>(MCACompat::fix_by_id(modify, FIX_ID));
  if (!fix_state) {
    modify->add_fix(fmt::format("{} all BEAM_STATE", FIX_ID), 0);
    fix_state = dynamic_cast<FixBeamState *>(MCACompat::fix_by_id(modify, FIX_ID));
  }
}

/* ----------------------------------------------------------------------
   bond_coeff N E A I     [shear G ks] [poisson nu] [section Iy Iz J] [damp beta]
                          [break sigma0 tau0] [bending c]
                          [mohr phi] [scatter uniform w seed | weibull m seed]
                          [criterion bond | particle]
                          [melt rate lambda seed | glen A seed] [refreeze capture]
   bond_coeff N E radii lambda [the same keywords but section; bending c | rim]
   bond_coeff N shearbeam kn kr [twist kt] [damp beta] [break N0 V0] [mohr phi] [scatter ...]
                                [criterion ...] [melt rate lambda seed] [refreeze capture]
   (3-D: a beam needs G, from shear or poisson; a shear beam needs twist)
------------------------------------------------------------------------- */

void BondBeam::coeff(int narg, char **arg)
{
  if (narg < 4)
    utils::missing_cmd_args(
        FLERR, "bond_coeff beam (N E A I, N E radii lambda or N shearbeam kn kr)", error);
  if (!allocated) allocate();

  int ilo, ihi;
  utils::bounds(FLERR, arg[0], 1, atom->nbondtypes, ilo, ihi, error);

  BeamCoeff c;
  memset(&c, 0, sizeof(c));
  auto positive = [&](const char *what, const char *word) {
    const double value = utils::numeric(FLERR, word, false, lmp);
    if (value <= 0.0) error->all(FLERR, "Bond_coeff beam: {} = {} must be > 0", what, value);
    return value;
  };
  if (strcmp(arg[1], "shearbeam") == 0) {
    // NUMFRAC's shear beam: the strengths are forces (A = 1) and moments (I = 1)
    c.model = MODEL_SPRINGS;
    c.kn = positive("shearbeam kn", arg[2]);
    c.kr = positive("shearbeam kr", arg[3]);
    c.A = c.I = c.Iy = c.Iz = c.J = 1.0;
  } else if (strcmp(arg[2], "radii") == 0) {
    // the section of each bond from its particles' radii (radii_section)
    c.model = MODEL_BEAM;
    c.E = positive("E", arg[1]);
    c.radii = 1;
    c.lambda = positive("radii lambda", arg[3]);
  } else {
    c.model = MODEL_BEAM;
    c.E = positive("E", arg[1]);
    c.A = positive("A", arg[2]);
    c.I = positive("I", arg[3]);
    // 3-D default: a round section
    c.Iy = c.Iz = c.I;
    c.J = 2.0 * c.I;
  }
  const bool three_d = domain->dimension == 3;
  auto only_3d = [&](const char *word) {
    if (!three_d)
      error->all(FLERR, "Bond_coeff beam: {} applies to 3-D beams only (dimension 3)", word);
  };
  auto only_beam = [&](const char *word) {
    if (c.model == MODEL_SPRINGS)
      error->all(FLERR, "Bond_coeff beam: {} applies to beams (N E A I), not to shearbeam", word);
  };
  bool bending = false, mohr = false, twist = false, criterion = false;
  int iarg = 4;
  while (iarg < narg) {
    const std::string word = arg[iarg];
    auto need = [&](int n, const char *what) {
      if (iarg + n + 1 > narg)
        utils::missing_cmd_args(FLERR, std::string("bond_coeff beam ") + what, error);
    };
    if (word == "shear") {
      need(2, "shear (G ks)");
      only_beam("shear (Timoshenko)");
      if (c.G > 0.0)
        error->all(FLERR,
                   "Bond_coeff beam: the shear modulus is given twice (by shear or poisson)");
      c.G = positive("shear G", arg[iarg + 1]);
      c.ks = utils::numeric(FLERR, arg[iarg + 2], false, lmp);
      if (c.ks <= 0.0 || c.ks > 1.0)
        error->all(FLERR, "Bond_coeff beam: shear ks = {} must be in (0, 1]", c.ks);
      iarg += 3;
    } else if (word == "poisson") {
      need(1, "poisson (nu)");
      only_3d("poisson (the torsion's G)");
      only_beam("poisson");
      if (c.G > 0.0)
        error->all(FLERR,
                   "Bond_coeff beam: the shear modulus is given twice (by shear or poisson)");
      c.nu = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (c.nu <= -1.0 || c.nu >= 0.5)
        error->all(FLERR, "Bond_coeff beam: poisson nu = {} must be in (-1, 0.5)", c.nu);
      c.G = c.E / (2.0 * (1.0 + c.nu));
      c.G_from_nu = 1;
      iarg += 2;
    } else if (word == "section") {
      need(3, "section (Iy Iz J)");
      only_3d("section");
      only_beam("section");
      if (c.radii)
        error->all(FLERR,
                   "Bond_coeff beam: section and radii exclude each other (radii makes a round "
                   "section of each bond)");
      c.Iy = positive("section Iy", arg[iarg + 1]);
      c.Iz = positive("section Iz", arg[iarg + 2]);
      c.J = positive("section J", arg[iarg + 3]);
      iarg += 4;
    } else if (word == "twist") {
      need(1, "twist (kt)");
      only_3d("twist");
      if (c.model != MODEL_SPRINGS)
        error->all(FLERR,
                   "Bond_coeff beam: twist (a torsion spring) applies to shearbeam; a beam's "
                   "torsion is G J / L0");
      c.kt = positive("twist kt", arg[iarg + 1]);
      twist = true;
      iarg += 2;
    } else if (word == "damp") {
      need(1, "damp (beta)");
      c.beta = positive("damp beta", arg[iarg + 1]);
      iarg += 2;
    } else if (word == "break") {
      need(2, "break (sigma0 tau0)");
      c.breakable = 1;
      c.sigma0 = positive("break sigma0", arg[iarg + 1]);
      c.tau0 = positive("break tau0", arg[iarg + 2]);
      iarg += 3;
    } else if (word == "bending") {
      need(1, "bending (fibre distance)");
      if (c.model == MODEL_SPRINGS)
        error->all(FLERR,
                   "Bond_coeff beam: bending (a fibre stress) needs a beam section (N E A "
                   "I), not shearbeam");
      if (strcmp(arg[iarg + 1], "rim") == 0) {
        if (!c.radii)
          error->all(FLERR,
                     "Bond_coeff beam: bending rim needs a section from the radii (N E radii "
                     "lambda); give the fibre distance c of a section N E A I");
        c.fibre_rim = 1;
      } else {
        c.fibre_rim = 0;
        c.fibre = positive("bending (fibre distance)", arg[iarg + 1]);
      }
      bending = true;
      iarg += 2;
    } else if (word == "mohr") {
      need(1, "mohr (friction angle)");
      const double phi = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (phi < 0.0 || phi >= 90.0)
        error->all(FLERR, "Bond_coeff beam: mohr friction angle = {} must be in [0, 90) degrees",
                   phi);
      c.mohr = 1;
      c.phi_deg = phi;
      c.tan_phi = tan(phi * MathConst::MY_PI / 180.0);
      mohr = true;
      iarg += 2;
    } else if (word == "scatter") {
      need(3, "scatter (uniform w seed | weibull m seed)");
      const std::string kind = arg[iarg + 1];
      const double value = utils::numeric(FLERR, arg[iarg + 2], false, lmp);
      if (kind == "uniform") {
        if (value < 0.0 || value >= 1.0)
          error->all(FLERR, "Bond_coeff beam: scatter uniform width = {} must be in [0, 1)", value);
        c.scatter = SCATTER_UNIFORM;
      } else if (kind == "weibull") {
        if (value <= 0.0)
          error->all(FLERR, "Bond_coeff beam: scatter weibull modulus = {} must be > 0", value);
        c.scatter = SCATTER_WEIBULL;
      } else
        error->all(FLERR, "Bond_coeff beam: scatter {} is unknown (allowed: uniform, weibull)",
                   kind);
      c.scatter_width = value;
      c.seed = utils::inumeric(FLERR, arg[iarg + 3], false, lmp);
      if (c.seed <= 0) error->all(FLERR, "Bond_coeff beam: scatter seed = {} must be > 0", c.seed);
      iarg += 4;
    } else if (word == "criterion") {
      need(1, "criterion (bond or particle)");
      const std::string kind = arg[iarg + 1];
      if (kind == "particle")
        c.particle = 1;
      else if (kind == "bond")
        c.particle = 0;
      else
        error->all(FLERR, "Bond_coeff beam: criterion {} is unknown (allowed: bond, particle)",
                   kind);
      criterion = true;
      iarg += 2;
    } else if (word == "melt") {
      need(3, "melt (rate lambda seed | glen A seed)");
      const std::string kind = arg[iarg + 1];
      const double value = utils::numeric(FLERR, arg[iarg + 2], false, lmp);
      if (kind == "rate") {
        if (value <= 0.0)
          error->all(FLERR, "Bond_coeff beam: melt rate lambda = {} must be > 0", value);
        c.melt = MELT_RATE;
      } else if (kind == "glen") {
        only_beam("melt glen (Glen's law needs the beam's E)");
        if (value <= 0.0) error->all(FLERR, "Bond_coeff beam: melt glen A = {} must be > 0", value);
        c.melt = MELT_GLEN;
      } else
        error->all(FLERR, "Bond_coeff beam: melt {} is unknown (allowed: rate, glen)", kind);
      c.melt_value = value;
      c.melt_seed = utils::inumeric(FLERR, arg[iarg + 3], false, lmp);
      if (c.melt_seed <= 0)
        error->all(FLERR, "Bond_coeff beam: melt seed = {} must be > 0", c.melt_seed);
      iarg += 4;
    } else if (word == "refreeze") {
      need(1, "refreeze (capture distance)");
      c.capture = positive("refreeze capture distance", arg[iarg + 1]);
      iarg += 2;
    } else
      error->all(FLERR,
                 "Bond_coeff beam: unknown keyword '{}' (allowed: shear, poisson, section, twist, "
                 "damp, break, bending, mohr, scatter, criterion, melt, refreeze)",
                 word);
  }
  if (c.capture > 0.0 && !c.melt)
    error->all(FLERR, "Bond_coeff beam: refreeze needs the melt keyword");
  if (!c.breakable && (bending || mohr || c.scatter || criterion))
    error->all(FLERR,
               "Bond_coeff beam: bending, mohr, scatter and criterion need the break keyword");
  if (three_d && c.model == MODEL_BEAM && c.G <= 0.0)
    error->all(FLERR,
               "Bond_coeff beam: a 3-D beam needs the shear modulus for its torsion (poisson nu, "
               "or shear G ks)");
  if (three_d && c.model == MODEL_SPRINGS && !twist)
    error->all(FLERR, "Bond_coeff beam: a 3-D shearbeam needs its torsion spring (twist kt)");
  // (radii: the type's own record holds the section of R = lambda, unused)
  if (c.radii)
    radii_section(c, domain->dimension, 1.0, 1.0);
  else
    set_coeff(c);

  for (int i = ilo; i <= ihi; i++) {
    coeffs[i] = c;
    setflag[i] = 1;
  }
}

/* ---------------------------------------------------------------------- */

void BondBeam::init_style()
{
  if (!MCAAtomFields::find(atom))
    error->all(FLERR,
               "Bond style beam requires atom_style mca (its quaternions are the "
               "particles' orientations), not atom_style {}",
               atom->atom_style);
  nrec = REC_REF + nref(domain->dimension);

  // (made here, during the run's init, before Modify's, which initialises it)
  find_state();
  built_at = -1;

  estimate_longest_bond();

  breaking = damping = radii = particle = melting = 0;
  for (int i = 1; i <= atom->nbondtypes; i++) {
    if (coeffs[i].breakable) breaking = 1;
    // (a melted bond that does not freeze again is broken)
    if (coeffs[i].melt) breaking = melting = 1;
    if (coeffs[i].beta > 0.0) damping = 1;
    if (coeffs[i].radii) radii = 1;
    if (coeffs[i].particle) particle = 1;
  }
  fix_state->use_particle_criterion(particle);
  if (damping && !comm->ghost_velocity)
    error->all(FLERR,
               "Bond style beam with damp requires comm_modify vel yes (the damping reads the "
               "velocities of the ghost atoms)");
  if (damping && utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR,
               "Bond style beam with damp does not support run_style respa (its energy tally "
               "counts one bond evaluation per step)");
  if (melting && utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR,
               "Bond style beam with melt does not support run_style respa (a bond melts with "
               "its probability once per step, at one bond evaluation)");
  // a broken bond leaves the bond arrays; with a pair style, either the
  // pair style acts between bonded particles as between any others
  // (special weights 1: BPM's overlay/pair yes) and nothing else changes,
  // or bonded pairs are left out of it (1-2 lj weight 0, 1-3 and 1-4
  // weights 1, so that the special lists hold the 1-2 partners only) and a
  // broken bond also leaves the special lists (BPM's fix
  // update/special/bonds, here on any newton_bond setting)
  const double *lj = force->special_lj, *coul = force->special_coul;
  const bool overlay = lj[1] == 1.0 && coul[1] == 1.0;
  const bool excluded = bonded_pairs_excluded(force);
  if (breaking && force->pair && !overlay && !excluded)
    error->all(FLERR,
               "Bond style beam with break and a pair style requires special_bonds lj/coul 1 1 1 "
               "(the pair style acts between bonded particles too) or lj 0 1 1 with coul 0 1 1 "
               "or 1 1 1 (bonded particles interact through the bond only, broken ones through "
               "the pair style); found lj {} {} {} coul {} {} {}",
               lj[1], lj[2], lj[3], coul[1], coul[2], coul[3]);
  update_special = breaking && force->pair && excluded;
  if (force->pair && excluded && comm->me == 0 &&
      MCACompat::pair_list_keeps_special_pairs(neighbor, force->pair))
    error->warning(FLERR,
                   "Bond style beam: pair style {} of this LAMMPS version (before 2023) keeps "
                   "bonded pairs in its neighbor list whatever the special_bonds weights (the "
                   "size lists of granular styles): bonded particles touch through it too",
                   force->pair_style);
}

bool BondBeam::bonded_pairs_excluded(const Force *force)
{
  const double *lj = force->special_lj, *coul = force->special_coul;
  return lj[1] == 0.0 && (coul[1] == 0.0 || coul[1] == 1.0) && lj[2] == 1.0 && lj[3] == 1.0 &&
      coul[2] == 1.0 && coul[3] == 1.0;
}

/* ----------------------------------------------------------------------
   the longest bond now (before the first forces), for LAMMPS's check of
   the communication cutoff against equilibrium_distance()
------------------------------------------------------------------------- */

void BondBeam::estimate_longest_bond()
{
  double lmax = 0.0;
  double **x = atom->x;
  for (int i = 0; i < atom->nlocal; i++)
    for (int m = 0; m < atom->num_bond[i]; m++) {
      const int j = atom->map(atom->bond_atom[i][m]);
      if (j < 0) continue;
      double d[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
      MCACompat::minimum_image(domain, d);
      lmax = MAX(lmax, sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
    }
  double all;
  MPI_Allreduce(&lmax, &all, 1, MPI_DOUBLE, MPI_MAX, world);
  L0_max = MAX(L0_max, all);
}

/* ---------------------------------------------------------------------- */

bool BondBeam::references_stale(int nlist) const
{
  if (!records_current()) return true;
  if (nlist != built_n)
    error->one(FLERR,
               "Bond style beam: the bond list changed without a neighbor list build "
               "(no fix that makes or deletes bonds during a run is supported)");
  return false;
}

void BondBeam::fill_records(int nlist, const int *list, long row_stride, long column_stride,
                            double *out)
{
  const int newton = force->newton_bond;
  const tagint *tag = atom->tag;
  const int nvalues = nref(domain->dimension);
  const double *radius = atom->radius;
  int missing = 0, zero = 0, no_radius = 0, no_volume = 0;
  double lmax = 0.0;
  for (int n = 0; n < nlist; n++) {
    const int i1 = list[n * row_stride], i2 = list[n * row_stride + column_stride];
    const int type = list[n * row_stride + 2 * column_stride];
    double *rec = out + n * nrec;
    const double *ref = fix_state->reference(i1, i2, newton);
    if (!ref) {
      missing = 1;
      continue;
    }
    for (int k = 0; k < nvalues; k++) rec[REC_REF + k] = ref[k];
    const bool swap = tag[i1] > tag[i2];
    rec[REC_SWAP] = swap ? 1.0 : 0.0;
    rec[REC_STRENGTH] = (type > 0)
        ? strength_factor(coeffs[type], swap ? tag[i2] : tag[i1], swap ? tag[i1] : tag[i2])
        : 1.0;
    if (ref[REF_L0] <= 0.0) zero = 1;
    if (type > 0 && !(radius[i1] > 0.0 && radius[i2] > 0.0)) {
      if (coeffs[type].radii) no_radius = type;
      if (coeffs[type].particle) no_volume = type;
    }
    if (ref[REF_L0] > lmax) lmax = ref[REF_L0];
  }
  int flags[4] = {missing, zero, no_radius, no_volume}, flagsall[4];
  MPI_Allreduce(flags, flagsall, 4, MPI_INT, MPI_MAX, world);
  if (flagsall[0]) error->all(FLERR, "Bond style beam: a listed bond is not stored by its atom");
  if (flagsall[1])
    error->all(FLERR, "Bond style beam: a bond of zero length (two particles at one place)");
  if (flagsall[2])
    error->all(FLERR,
               "Bond style beam: a bond of type {} (section from the radii) joins a particle of "
               "radius 0: set the radii > 0 (data file, set diameter)",
               flagsall[2]);
  if (flagsall[3])
    error->all(FLERR,
               "Bond style beam: a bond of type {} (criterion particle) joins a particle of radius "
               "0, which has no volume for its stress: set the radii > 0 (data file, set "
               "diameter)",
               flagsall[3]);
  double all;
  MPI_Allreduce(&lmax, &all, 1, MPI_DOUBLE, MPI_MAX, world);
  L0_max = MAX(L0_max, all);
  built_at = neighbor->ncalls;
  built_n = nlist;
}

/* ---------------------------------------------------------------------- */

void BondBeam::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);

  const int nlist = neighbor->nbondlist;
  int **bondlist = neighbor->bondlist;
  if (references_stale(nlist)) {
    if (nlist > maxrecords) {
      maxrecords = nlist + nlist / 4 + 16;
      memory->destroy(records);
      memory->create(records, maxrecords * nrec, "bond:records");
    }
    fill_records(nlist, nlist ? bondlist[0] : nullptr, 3, 1, records);
  }
  // (before the forces: a bond that breaks now still counts)
  if (update->setupflag && update->whichflag == 1) check_stable_timestep();

  std::vector<int> broken;
  if (particle) fix_state->clear_sums(atom->nlocal + atom->nghost);
  if (domain->dimension == 3)
    evaluate<3>(nlist, bondlist, broken);
  else
    evaluate<2>(nlist, bondlist, broken);
  if (breaking) remove_broken(static_cast<int>(broken.size() / 2), broken.data());
  if (particle) fix_state->decide_particles(force->newton_bond);
}

bool BondBeam::particle_now() const
{
  return particle && !update->setupflag;
}

bool BondBeam::melt_now() const
{
  return melting && update->whichflag == 1 && !update->setupflag;
}

/* ----------------------------------------------------------------------
   forces and torques of the listed bonds; those that break go to broken
------------------------------------------------------------------------- */

template <int DIM> void BondBeam::evaluate(int nlist, int **bondlist, std::vector<int> &broken)
{
  double **x = atom->x;
  double **f = atom->f;
  double **torque = atom->torque;
  double **quat = fix_state->avec->quat;
  double **v = atom->v;
  double **omega = atom->omega;
  const double *radius = atom->radius;
  const int nlocal = atom->nlocal;
  const int newton_bond = force->newton_bond;
  // damping in dynamics only (a minimizer's forces are the energy's gradient)
  const bool damp_now = damping && update->whichflag == 1;
  const bool decisions = particle_now();
  const bool melt_step = melt_now();
  const double dt = update->dt;
  const long long step = update->ntimestep;
  const tagint *tag = atom->tag;
  double dissipated = 0.0;

  // a bond that breaks: type 0 in the list, its ends to remove_broken
  auto drop = [&](int n) {
    bondlist[n][2] = 0;
    broken.push_back(bondlist[n][0]);
    broken.push_back(bondlist[n][1]);
  };
  for (int n = 0; n < nlist; n++) {
    const int type = bondlist[n][2];
    if (type <= 0) continue;
    double *rec = &records[n * nrec];
    // the element in the order lower atom ID first (BeamKernels::beam_bond)
    const bool swap = rec[REC_SWAP] != 0.0;
    const int i = swap ? bondlist[n][1] : bondlist[n][0];
    const int j = swap ? bondlist[n][0] : bondlist[n][1];
    const double d[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], DIM == 3 ? x[j][2] - x[i][2] : 0.0};
    BeamCoeff sized;
    const BeamCoeff &c = coeffs[type].radii
        ? bond_coeff(coeffs[type], DIM, radius[i], radius[j], sized)
        : coeffs[type];
    // (the particle criterion's decision of the last evaluation)
    const bool decided = decisions && c.particle &&
        particle_breaks(c, fix_state->particle_state(i), fix_state->particle_state(j), tag[i],
                        tag[j], rec[REC_STRENGTH]);
    if (decided) {
      drop(n);
      continue;
    }
    BeamBond out;
    if (damp_now && c.beta > 0.0) {
      BeamRates rates;
      for (int k = 0; k < 3; k++) {
        rates.w[k] = v[j][k] - v[i][k];
        rates.oi[k] = omega[i][k];
        rates.oj[k] = omega[j][k];
      }
      out = beam_bond<DIM>(c, rec + REC_REF, d, quat[i], quat[j], rec[REC_STRENGTH], &rates);
    } else
      out = beam_bond<DIM>(c, rec + REC_REF, d, quat[i], quat[j], rec[REC_STRENGTH]);
    if (out.measure >= 1.0 && !c.particle) {
      drop(n);
      continue;
    }
    if (melt_step && c.melt) {
      const int fate =
          melt_fate(c, DIM, out.energy, rec[REC_REF + REF_L0], d, dt, step, tag[i], tag[j]);
      if (fate == FATE_BREAK) {
        drop(n);
        continue;
      }
      if (fate == FATE_REFREEZE) {
        // stress-free from now on: no loads at this step
        fresh_reference(DIM, d, quat[i], quat[j], rec + REC_REF);
        fix_state->set_reference(bondlist[n][0], bondlist[n][1], newton_bond, rec + REC_REF);
        continue;
      }
    }
    if (particle) {
      // each end's share of the bond's virial; a candidate of each end
      double w[6];
      virial_share(d, out.fe, w);
      const double measure = c.particle ? out.measure : -1.0;
      if (newton_bond || i < nlocal) fix_state->add_share(i, w, measure, tag[j]);
      if (newton_bond || j < nlocal) fix_state->add_share(j, w, measure, tag[i]);
    }
    if (newton_bond || i < nlocal) {
      f[i][0] -= out.f[0];
      f[i][1] -= out.f[1];
      if (DIM == 3) {
        f[i][2] -= out.f[2];
        torque[i][0] += out.ti[0];
        torque[i][1] += out.ti[1];
      }
      torque[i][2] += out.ti[2];
    }
    if (newton_bond || j < nlocal) {
      f[j][0] += out.f[0];
      f[j][1] += out.f[1];
      if (DIM == 3) {
        f[j][2] += out.f[2];
        torque[j][0] += out.tj[0];
        torque[j][1] += out.tj[1];
      }
      torque[j][2] += out.tj[2];
    }
    if (evflag) tally(i, j, nlocal, newton_bond, out.energy, out.f, d);
    if (damp_now) dissipated += bond_share(newton_bond, i, j, nlocal) * out.dissipation;
  }
  // (a step taken: not the forces of a run's setup)
  if (damp_now && !update->setupflag) fix_state->dissipated.local += dissipated * update->dt;
}

/* ----------------------------------------------------------------------
   the stable time step (doc/src/bond_beam.rst, "Stable time step"):
   Gershgorin's bound of the fastest mode of the listed bonds, from the
   particles' masses and moments of inertia (atom_style mca: what fix
   nve/mca and fix nve/damped integrate with)
------------------------------------------------------------------------- */

bool BondBeam::records_current() const
{
  return built_at == neighbor->ncalls;
}

bool BondBeam::stable_timestep(StableStep &out)
{
  if (!records_current()) return false;
  const int nlist = neighbor->nbondlist;
  out = stable_timestep_of(nlist, nlist ? neighbor->bondlist[0] : nullptr, 3, 1, records);
  return true;
}

BondBeam::StableStep BondBeam::stable_timestep_of(int nlist, const int *list, long row_stride,
                                                  long column_stride, const double *recs)
{
  const int dimension = domain->dimension;
  const int nd = tangent_dof(dimension), size = gershgorin_size(dimension);
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int newton_bond = force->newton_bond;
  double **x = atom->x;
  double **quat = fix_state->avec->quat;
  const double *inertia = fix_state->avec->inertia;
  const double *rmass = atom->rmass;
  const double *radius = atom->radius;
  std::vector<double> &sums = fix_state->gershgorin;
  sums.assign((std::size_t) nall * size, 0.0);

  // with newton_bond off each bond of a local atom is listed here: the
  // rows of local atoms only; on, each bond once: both ends' rows, the
  // ghosts' then to their owners
  double beta = 0.0;
  bigint nbonds = 0;
  for (int n = 0; n < nlist; n++) {
    const int type = list[n * row_stride + 2 * column_stride];
    if (type <= 0) continue;
    const double *rec = recs + (std::size_t) n * nrec;
    const bool swap = rec[REC_SWAP] != 0.0;
    const int i = list[n * row_stride + (swap ? column_stride : 0)];
    const int j = list[n * row_stride + (swap ? 0 : column_stride)];
    const double d[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1],
                         dimension == 3 ? x[j][2] - x[i][2] : 0.0};
    BeamCoeff sized;
    const BeamCoeff &c = bond_coeff(coeffs[type], dimension, radius[i], radius[j], sized);
    const BeamTangent t = (dimension == 3) ? beam_tangent<3>(c, rec + REC_REF, d, quat[i], quat[j])
                                           : beam_tangent<2>(c, rec + REC_REF, d, quat[i], quat[j]);
    double si[6], sj[6];
    mass_scale(dimension, rmass[i], inertia[i], si);
    mass_scale(dimension, rmass[j], inertia[j], sj);
    double *sum_i = (newton_bond || i < nlocal) ? &sums[(std::size_t) i * size] : nullptr;
    double *sum_j = (newton_bond || j < nlocal) ? &sums[(std::size_t) j * size] : nullptr;
    gershgorin_add(t, si, sj, sum_i, sum_j);
    beta = MAX(beta, c.beta);
    if (newton_bond || i < nlocal) nbonds++;
  }
  if (newton_bond) fix_state->sum_gershgorin();

  std::vector<double> bound(nlocal);
  for (int i = 0; i < nlocal; i++) bound[i] = gershgorin_bound(nd, &sums[(std::size_t) i * size]);
  sums.clear();
  sums.shrink_to_fit();

  StableStep out;
  double all_beta;
  const MCALargestRow largest = mca_largest_row(world, nlocal, bound.data(), atom->tag);
  MPI_Allreduce(&beta, &all_beta, 1, MPI_DOUBLE, MPI_MAX, world);
  MPI_Allreduce(&nbonds, &out.nbonds, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  out.atom = largest.atom;
  if (!(largest.value > 0.0)) {
    out.dt = INFINITY;
    out.omega = out.zeta = 0.0;
    return out;
  }
  out.omega = sqrt(largest.value);
  out.zeta = 0.5 * all_beta * out.omega;
  out.dt = critical_step(out.omega, all_beta);
  return out;
}

void BondBeam::check_stable_timestep()
{
  StableStep s;
  if (!stable_timestep(s) || comm->me != 0) return;
  if (!std::isfinite(s.dt)) {
    utils::logmesg(lmp, "bond beam: no bond acts, so bond beam sets no limit to the time step\n");
    return;
  }
  const std::string damping_text = (s.zeta > 0.0) ? fmt::format(", damping ratio {:.3g}", s.zeta)
                                                  : std::string();
  utils::logmesg(lmp,
                 "bond beam: stable time step {:.6g} (Gershgorin bound of the fastest mode: omega "
                 "<= {:.6g}{}; {} bonds; stiffest row: particle {})\n",
                 s.dt, s.omega, damping_text, s.nbonds, s.atom);
  if (update->dt > s.dt)
    error->warning(FLERR,
                   "Time step {} is above the stable time step {:.6g} of bond_style beam ({:.4g} "
                   "times it; Gershgorin's bound, below which the bonds are stable): use a time "
                   "step <= {:.6g}",
                   update->dt, s.dt, update->dt / s.dt, s.dt);
}

/* ----------------------------------------------------------------------
   the bonds (i1, i2) of the list that broke this step leave the bond
   arrays of their local atoms (with their slots in the fix); the global
   bond count falls by the bonds broken, each counted by the rank that
   owns its lower-ID atom
------------------------------------------------------------------------- */

bool BondBeam::remove_broken(int nbroken, const int *pairs)
{
  const tagint *tag = atom->tag;
  const int nlocal = atom->nlocal;
  int *num_bond = atom->num_bond;
  int **bond_type = atom->bond_type;
  tagint **bond_atom = atom->bond_atom;
  bigint counted = 0;
  std::vector<int> reported;    // the bonds counted here (entries i1 i2)
  for (int b = 0; b < nbroken; b++) {
    const int ends[2] = {pairs[2 * b], pairs[2 * b + 1]};
    const int lo = tag[ends[0]] < tag[ends[1]] ? ends[0] : ends[1];
    // newton_bond on: each bond is listed once, on one rank; off: on the
    // ranks of both atoms, counted where the lower ID is owned
    if (force->newton_bond || lo < nlocal) {
      counted++;
      if (update_special) reported.insert(reported.end(), ends, ends + 2);
    }
    for (int e = 0; e < 2; e++) {
      const int i = ends[e], j = ends[1 - e];
      if (i >= nlocal) continue;
      for (int m = 0; m < num_bond[i]; m++)
        if (bond_atom[i][m] == tag[j]) {
          const int last = num_bond[i] - 1;
          fix_state->remove_slot(i, m);
          bond_atom[i][m] = bond_atom[i][last];
          bond_type[i][m] = bond_type[i][last];
          num_bond[i] = last;
          break;
        }
    }
  }
  bigint total;
  MPI_Allreduce(&counted, &total, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  atom->nbonds -= total;
  if (!update_special || total == 0) return false;
  specials_to_host();
  return forget_broken_pairs(static_cast<int>(reported.size() / 2), reported.data());
}

/* ----------------------------------------------------------------------
   bonds broken on any rank leave the special lists of the local atoms
   (with newton_bond on a bond is evaluated on one rank only, while both
   atoms' owners hold the pair in their special lists: every rank learns
   the broken pairs, each reported by the rank that counts it); the
   neighbor lists are built again at the next step
   (the forces of this step are done), so a pair style that left the
   bonded pair out sees it from then on.  A step that breaks no bond pays
   nothing for this
------------------------------------------------------------------------- */

bool BondBeam::forget_broken_pairs(int nbroken, const int *pairs)
{
  const tagint *tag = atom->tag;
  std::vector<tagint> mine(2 * nbroken);
  for (int b = 0; b < nbroken; b++) {
    const tagint t1 = tag[pairs[2 * b]], t2 = tag[pairs[2 * b + 1]];
    mine[2 * b] = MIN(t1, t2);
    mine[2 * b + 1] = MAX(t1, t2);
  }
  const int nprocs = comm->nprocs;
  int count = 2 * nbroken;    // not const: the MPI stubs of a serial build take void *
  std::vector<int> counts(nprocs), displs(nprocs);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  int all = 0;
  for (int p = 0; p < nprocs; p++) {
    displs[p] = all;
    all += counts[p];
  }
  std::vector<tagint> every(all);
  MPI_Allgatherv(mine.data(), count, MPI_LMP_TAGINT, every.data(), counts.data(), displs.data(),
                 MPI_LMP_TAGINT, world);

  // (each bond is reported once, by the rank that counts it; two bonds
  // between one pair would be reported twice: once is enough)
  const int nlocal = atom->nlocal;
  int **nspecial = atom->nspecial;
  tagint **special = atom->special;
  bool changed = false;
  std::vector<std::pair<tagint, tagint>> broken;
  for (int k = 0; k < all; k += 2) broken.emplace_back(every[k], every[k + 1]);
  std::sort(broken.begin(), broken.end());
  broken.erase(std::unique(broken.begin(), broken.end()), broken.end());
  for (const auto &pair : broken) {
    for (int e = 0; e < 2; e++) {
      const tagint self = e ? pair.second : pair.first, partner = e ? pair.first : pair.second;
      const int i = atom->map(self);
      if (i < 0 || i >= nlocal) continue;
      // the 1-2 partners come first; with weights 1 for 1-3 and 1-4 they are all there is
      const int n12 = nspecial[i][0], nall = nspecial[i][2];
      int m = 0;
      while (m < n12 && special[i][m] != partner) m++;
      // (gone already: a second bond between the pair broke earlier, or
      // the bond was made without its special entry, create_bonds special no)
      if (m == n12) continue;
      for (; m < nall - 1; m++) special[i][m] = special[i][m + 1];
      for (int k = 0; k < 3; k++) nspecial[i][k]--;
      changed = true;
    }
  }
  fix_state->next_reneighbor = update->ntimestep + 1;
  return changed;
}

/* ----------------------------------------------------------------------
   energy and virial of a bond whose force on j is f, d = x_j - x_i
   (Bond::ev_tally_xyz, which LAMMPS 2021 does not have)
------------------------------------------------------------------------- */

void BondBeam::tally(int i, int j, int nlocal, int newton_bond, double ebond, const double *f,
                     const double *d)
{
  const double share = bond_share(newton_bond, i, j, nlocal);
  if (eflag_either) {
    if (eflag_global) energy += share * ebond;
    if (eflag_atom) {
      if (newton_bond || i < nlocal) eatom[i] += 0.5 * ebond;
      if (newton_bond || j < nlocal) eatom[j] += 0.5 * ebond;
    }
  }
  if (vflag_either) {
    double v[6];
    virial_terms(d, f, v);
    if (vflag_global)
      for (int k = 0; k < 6; k++) virial[k] += share * v[k];
    if (vflag_atom) {
      if (newton_bond || i < nlocal)
        for (int k = 0; k < 6; k++) vatom[i][k] += 0.5 * v[k];
      if (newton_bond || j < nlocal)
        for (int k = 0; k < 6; k++) vatom[j][k] += 0.5 * v[k];
    }
  }
}

/* ---------------------------------------------------------------------- */

double BondBeam::equilibrium_distance(int /*type*/)
{
  // the longest bond seen so far (LAMMPS checks the ghost cutoff with it)
  return L0_max;
}

/* ---------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   the coefficient records behind a tag: the layout's version and size
   (a file of another layout is refused, not read askew)
------------------------------------------------------------------------- */

static constexpr int RESTART_TAG = 0x6265616d;    // "beam"
// 2: 3-D sections, damping; 3: radii; 4: criterion; 5: melt, refreeze
static constexpr int RESTART_VERSION = 5;

void BondBeam::write_restart(FILE *fp)
{
  const int header[3] = {RESTART_TAG, RESTART_VERSION, static_cast<int>(sizeof(BeamCoeff))};
  fwrite(header, sizeof(int), 3, fp);
  fwrite(&coeffs[1], sizeof(BeamCoeff), atom->nbondtypes, fp);
}

void BondBeam::read_restart(FILE *fp)
{
  allocate();
  int header[3] = {0, 0, 0};
  if (comm->me == 0) utils::sfread(FLERR, header, sizeof(int), 3, fp, nullptr, error);
  MPI_Bcast(header, 3, MPI_INT, 0, world);
  if (header[0] != RESTART_TAG || header[1] != RESTART_VERSION ||
      header[2] != static_cast<int>(sizeof(BeamCoeff)))
    error->all(FLERR,
               "Bond style beam: the restart file holds the coefficients in another layout "
               "(written by an earlier version of the style, which can convert it to a data "
               "file: write_data there, read_data here)");
  if (comm->me == 0)
    utils::sfread(FLERR, &coeffs[1], sizeof(BeamCoeff), atom->nbondtypes, fp, nullptr, error);
  MPI_Bcast(&coeffs[1], atom->nbondtypes * sizeof(BeamCoeff), MPI_CHAR, 0, world);
  for (int i = 1; i <= atom->nbondtypes; i++) setflag[i] = 1;
}

void BondBeam::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->nbondtypes; i++) {
    const BeamCoeff &c = coeffs[i];
    std::string line;
    if (c.model == MODEL_SPRINGS)
      line = fmt::format("{} shearbeam {:.17g} {:.17g}", i, c.kn, c.kr);
    else if (c.radii)
      line = fmt::format("{} {:.17g} radii {:.17g}", i, c.E, c.lambda);
    else
      line = fmt::format("{} {:.17g} {:.17g} {:.17g}", i, c.E, c.A, c.I);
    if (c.ks > 0.0) line += fmt::format(" shear {:.17g} {:.17g}", c.G, c.ks);
    if (c.G_from_nu) line += fmt::format(" poisson {:.17g}", c.nu);
    if (domain->dimension == 3) {
      if (c.model == MODEL_SPRINGS)
        line += fmt::format(" twist {:.17g}", c.kt);
      else if (!c.radii)
        line += fmt::format(" section {:.17g} {:.17g} {:.17g}", c.Iy, c.Iz, c.J);
    }
    if (c.beta > 0.0) line += fmt::format(" damp {:.17g}", c.beta);
    if (c.breakable) line += fmt::format(" break {:.17g} {:.17g}", c.sigma0, c.tau0);
    if (c.fibre_rim)
      line += " bending rim";
    else if (c.fibre > 0.0)
      line += fmt::format(" bending {:.17g}", c.fibre);
    if (c.mohr) line += fmt::format(" mohr {:.17g}", c.phi_deg);
    if (c.particle) line += " criterion particle";
    if (c.scatter)
      line += fmt::format(" scatter {} {:.17g} {}",
                          c.scatter == SCATTER_UNIFORM ? "uniform" : "weibull", c.scatter_width,
                          c.seed);
    if (c.melt)
      line += fmt::format(" melt {} {:.17g} {}", c.melt == MELT_RATE ? "rate" : "glen",
                          c.melt_value, c.melt_seed);
    if (c.capture > 0.0) line += fmt::format(" refreeze {:.17g}", c.capture);
    fprintf(fp, "%s\n", line.c_str());
  }
}

/* ----------------------------------------------------------------------
   energy of the bond of local atoms i and j; fforce: its axial force
   (force on i = fforce * (x_i - x_j))
------------------------------------------------------------------------- */

double BondBeam::single(int type, double /*rsq*/, int i, int j, double &fforce)
{
  fforce = 0.0;
  if (!fix_state) return 0.0;
  const double *ref = fix_state->stored_reference(i, j);
  if (!ref) ref = fix_state->stored_reference(j, i);
  if (!ref) return 0.0;
  // the reference is in the order lower atom ID first
  const int lo = atom->tag[i] < atom->tag[j] ? i : j, hi = (lo == i) ? j : i;
  double **x = atom->x;
  double **quat = fix_state->avec->quat;
  double d[3] = {x[hi][0] - x[lo][0], x[hi][1] - x[lo][1], x[hi][2] - x[lo][2]};
  MCACompat::minimum_image(domain, d);
  BeamCoeff sized;
  const BeamCoeff &c =
      bond_coeff(coeffs[type], domain->dimension, atom->radius[lo], atom->radius[hi], sized);
  if (domain->dimension == 3) {
    const BeamForce3D out = beam_force_3d(c, ref, frame_state(ref, d, quat[lo], quat[hi]));
    fforce = -out.N / sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    return out.energy;
  }
  const BeamForce out = beam_force_2d(c, ref, d[0], d[1], planar_angle(quat[lo][0], quat[lo][3]),
                                      planar_angle(quat[hi][0], quat[hi][3]));
  fforce = -out.N / sqrt(d[0] * d[0] + d[1] * d[1]);
  return out.energy;
}

/* ---------------------------------------------------------------------- */

double BondBeam::memory_usage()
{
  double bytes = Bond::memory_usage();
  bytes += static_cast<double>(maxrecords) * nrec * sizeof(double);
  return bytes;
}
