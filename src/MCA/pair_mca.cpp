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
   Elastic Movable Cellular Automata: linked automata interact through
   normal tractions with a many-body mean-stress term, shear tractions from
   the relative motion of the contact points, and bending/torsion couples.
   See doc/src/pair_mca.rst for the model and every modelling choice.
------------------------------------------------------------------------- */

#include "pair_mca.h"
#include "pair_mca_host.h"

#include "atom.h"
#include "atom_vec_mca.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "force.h"
#include "group.h"
#include "mca_compat.h"
#include "mca_link_passes.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <cmath>
#include <cstring>
#include <utility>
#include <vector>

using namespace LAMMPS_NS;
using namespace MCAKernels;

// restart files mark their layout with a negative first value (those of
// earlier versions begin with the link tolerance, >= 0)
static constexpr double RESTART_NAMED_MATERIALS = -2.0;
// then the parts of the link model by name too
static constexpr double RESTART_NAMED_PARTS = -3.0;
// then the hardening tables after the materials
static constexpr double RESTART_HARDENING = -4.0;
// then the fracture rules after the linking rules
static constexpr double RESTART_FRACTURE = -5.0;
// then the friction of the type pairs
static constexpr double RESTART_CONTACTS = -6.0;
// then the healing criteria of the type pairs
static constexpr double RESTART_HEALING = -7.0;
// then the precision of the rows after the parts of the link model
static constexpr double RESTART_PRECISION = -8.0;
// the id of the contact neighbor list among the pair style's requests
static constexpr int CONTACT_LIST_ID = 1;

PairMCA::HostData PairMCA::host_data()
{
  HostData d;
  static_cast<MCAHostLinks &>(d) = host_links();
  d.x_ = atom->x;
  d.omega_ = atom->omega;
  d.f_ = atom->f;
  d.torque_ = atom->torque;
  d.type_ = atom->type;
  d.packing_ = avec->packing;
  d.material_ = materials.type;
  d.pred_stiffness_ = pred_stiffness;
  d.dsmean_ = dsmean;
  d.smean_pred_ = smean_pred;
  d.link_count_ = link_count;
  d.fabric_ = predictor_sums;    // its PS_FABRIC columns
  d.stress_ = avec->stress;
  d.smean_ = avec->smean;
  d.seq_ = avec->seq;
  d.eeq_ = avec->eeq;
  d.hardening_ = materials.hardening;
  d.epsp_ = avec->epsp;
  d.volume_ = avec->volume;
  d.return_scale_ = return_scale;
  d.return_smean_ = return_smean;
  d.break_rules_ = break_rules.data();
  d.break_stride = atom->ntypes + 1;
  d.contact_rules_ = contact_rules.data();
  d.damage_ = avec->damage;
  return d;
}

/* ---------------------------------------------------------------------- */

PairMCA::PairMCA(LAMMPS *lmp) :
    PairMCALinked(lmp, "Pair mca"), materials(lmp), link_allowed(nullptr), link_tolerance(nullptr),
    link_count(nullptr), pred_stiffness(nullptr), dsmean(nullptr), smean_pred(nullptr),
    return_scale(nullptr), return_smean(nullptr), nsums(0), predictor_sums(nullptr), bmat(nullptr),
    avec(nullptr), contact_list(nullptr), restart_contacts(0), restart_healing(0),
    stability(nullptr), dt_monitor(), dt_estimated(0), dt_warned_ratio(0.0), links_changed(0)
{
  single_enable = 0;
  restartinfo = 1;
  one_coeff = 0;
  manybody_flag = 1;
  no_virial_fdotr_compute = 1;
  centroidstressflag = CENTROID_NOTAVAIL;
  comm_forward = 7;    // the largest stage: stress and plastic strain
  writedata = 0;

  tolerance_default = 0.02;
  batch_links = true;
  cutoff_user = -1.0;
  nmax = 0;
  comm_stage = STAGE_COUNT;
  restart_named = 0;
  restart_tables = 0;
  restart_fracture = 0;
  links_broke = 0;
  links_healed = 0;
  break_scatter = 0.0;
  break_seed = 0;
  select_parts({});
  stability = new MCAStableTimestep(lmp);
}

/* ---------------------------------------------------------------------- */

PairMCA::~PairMCA()
{
  if (copymode) return;
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(link_allowed);
    memory->destroy(link_tolerance);
  }
  destroy_peratom();
  memory->destroy(predictor_sums);
  memory->destroy(bmat);
  delete stability;
}

/* ---------------------------------------------------------------------- */

void PairMCA::allocate()
{
  allocated = 1;
  const int n = atom->ntypes + 1;
  memory->create(setflag, n, n, "pair:setflag");
  memory->create(cutsq, n, n, "pair:cutsq");
  memory->create(link_allowed, n, n, "pair:link_allowed");
  memory->create(link_tolerance, n, n, "pair:link_tolerance");
  materials.allocate(atom->ntypes);
  break_rules.assign(n * n, MCABreakRule{BREAK_NONE, 0.0, 0.0});
  contact_rules.assign(n * n, MCAContactRule{0.0, 0, 0.0, 0.0});
  friction_given.assign(n * n, 0);
  for (int i = 0; i < n; i++) {
    for (int j = 0; j < n; j++) {
      setflag[i][j] = 0;
      link_allowed[i][j] = 1;
      link_tolerance[i][j] = -1.0;    // pair style default
    }
  }
}

/* ----------------------------------------------------------------------
   pair_style mca [tolerance t] [capacity N] [cutoff rc] [precision p]
     [batch yes|no] [scatter w seed] [<slot> <part> ...]
------------------------------------------------------------------------- */

void PairMCA::settings(int narg, char **arg)
{
  std::vector<std::string> chosen;
  bool mixed = false;
  int iarg = 0;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "tolerance") == 0) {
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, "pair_style mca tolerance", error);
      tolerance_default = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (tolerance_default < 0.0 || tolerance_default >= 0.5)
        error->all(FLERR, "Pair style mca tolerance must be in [0, 0.5), got {}", arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "capacity") == 0) {
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, "pair_style mca capacity", error);
      capacity_user = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (capacity_user < 1 || capacity_user > 64)
        error->all(FLERR, "Pair style mca capacity must be in [1, 64], got {}", arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "cutoff") == 0) {
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, "pair_style mca cutoff", error);
      cutoff_user = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (cutoff_user <= 0.0)
        error->all(FLERR, "Pair style mca cutoff must be > 0, got {}", arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "precision") == 0) {
      // how the link rows are stored (mca_row_codec.h); the arithmetic is double
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, "pair_style mca precision", error);
      if (strcmp(arg[iarg + 1], "mixed") != 0 && strcmp(arg[iarg + 1], "double") != 0)
        error->all(FLERR, "Pair style mca precision must be double or mixed, got {}",
                   arg[iarg + 1]);
      mixed = strcmp(arg[iarg + 1], "mixed") == 0;
    } else if (strcmp(arg[iarg], "batch") == 0) {
      // the elastic link pass over batches of links (pair_mca_batch.cpp) or
      // link by link: the same numbers, a choice of speed
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, "pair_style mca batch", error);
      batch_links = utils::logical(FLERR, arg[iarg + 1], false, lmp) != 0;
    } else if (strcmp(arg[iarg], "scatter") == 0) {
      // scatter w seed: strength factors of the links uniform in [1 - w, 1 + w]
      if (iarg + 3 > narg)
        utils::missing_cmd_args(FLERR, "pair_style mca scatter (width seed)", error);
      break_scatter = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (break_scatter < 0.0 || break_scatter >= 1.0)
        error->all(FLERR, "Pair style mca scatter width must be in [0, 1), got {}", arg[iarg + 1]);
      break_seed = utils::inumeric(FLERR, arg[iarg + 2], false, lmp);
      if (break_seed <= 0)
        error->all(FLERR, "Pair style mca scatter seed must be a positive integer, got {}",
                   arg[iarg + 2]);
      iarg += 3;
      continue;
    } else if (const char *slot = link_slot(arg[iarg])) {
      // <slot> <part>: the part of the link law for that slot
      if (iarg + 2 > narg)
        utils::missing_cmd_args(FLERR, std::string("pair_style mca ") + slot, error);
      std::string allowed;
      for (const auto &p : MCA_LINK_PARTS) {
        if (strcmp(p.slot, slot) != 0) continue;
        if (strcmp(p.name, arg[iarg + 1]) == 0) chosen.push_back(p.name);
        allowed += std::string(allowed.empty() ? "" : ", ") + p.name;
      }
      if (chosen.empty() || chosen.back() != arg[iarg + 1])
        error->all(FLERR, "Unknown {} part {} for pair_style mca (allowed: {})", slot,
                   arg[iarg + 1], allowed);
    } else {
      std::string slots;
      for (const auto &p : MCA_LINK_PARTS)
        if (slots.find(p.slot) == std::string::npos) slots += std::string(", ") + p.slot;
      error->all(FLERR,
                 "Unknown pair_style mca keyword {} (allowed: tolerance, capacity, cutoff, "
                 "precision, batch, scatter{})",
                 arg[iarg], slots);
    }
    iarg += 2;
  }
  select_parts(chosen);
  model.set_mixed(mixed);
}

bool PairMCA::plastic() const
{
  return model.layout().link_offset[PART_PLASTICITY] >= 0;
}

bool PairMCA::fractured() const
{
  return model.layout().link_offset[PART_FRACTURE] >= 0;
}

bool PairMCA::contacts() const
{
  return model.layout().link_offset[PART_CONTACT] >= 0;
}

bool PairMCA::healing() const
{
  return model.layout().link_offset[PART_HEALING] >= 0;
}

// a work criterion needs the plastic strain of the ghost automata of the
// step, which the fracture part sends anyway
bool PairMCA::heal_reads_epsp() const
{
  if (!plastic()) return false;
  for (const auto &rule : contact_rules)
    if (rule.heal && rule.heal_work > 0.0) return true;
  return false;
}

// a parameter without its part of the link law, or a part without its
// parameter, is most likely a mistake of the input: say so
void PairMCA::check_parts()
{
  bool any_eta = false;
  for (int t = 1; t <= atom->ntypes; t++) any_eta = any_eta || materials.type[t].viscosity > 0.0;
  const bool damped = model.layout().link_offset[PART_DAMPING] >= 0;
  const bool any_yield = materials.any_plastic();
  bool any_break = false;
  for (const auto &rule : break_rules) any_break = any_break || rule.criterion != BREAK_NONE;
  bool any_friction = false;
  for (int given : friction_given) any_friction = any_friction || given;
  bool any_heal = false, any_heal_work = false;
  for (const auto &rule : contact_rules) {
    any_heal = any_heal || rule.heal;
    any_heal_work = any_heal_work || (rule.heal && rule.heal_work > 0.0);
  }
  // healing turns contacts into links: without them it would do nothing
  if (healing() && !contacts())
    error->all(FLERR,
               "Pair mca: healing weld needs contacts to heal: add 'contacts coulomb' to "
               "pair_style mca");
  if (any_heal && !healing())
    error->all(FLERR,
               "Pair mca: pair_coeff heal is given but the link model has no healing part: add "
               "'healing weld' (and 'contacts coulomb') to pair_style mca");
  if (any_heal_work && !plastic())
    error->all(FLERR,
               "Pair mca: pair_coeff heal ... work needs the plastic work of the automata: add "
               "'plasticity mises' to pair_style mca (or leave out the work criterion)");
  if (comm->me != 0) return;
  if (healing() && !any_heal)
    error->warning(FLERR,
                   "Pair mca: healing weld without a healing criterion for any pair of atom "
                   "types heals nothing (give 'heal' in pair_coeff)");
  if (!contacts() && any_friction)
    error->warning(FLERR,
                   "Pair mca: friction is given but the link model has no contact part: add "
                   "'contacts coulomb' to pair_style mca to use it");
  if (fractured() && !any_break)
    error->warning(FLERR,
                   "Pair mca: fracture links without a break criterion for any pair of atom "
                   "types breaks nothing (give 'break' in pair_coeff)");
  if (!fractured() && any_break)
    error->warning(FLERR,
                   "Pair mca: a break criterion is given but the link model has no fracture "
                   "part: add 'fracture links' to pair_style mca to use it");
  if (!fractured() && break_scatter > 0.0)
    error->warning(FLERR,
                   "Pair mca: scatter has no effect without 'fracture links' in pair_style mca");
  if (damped && !any_eta)
    error->warning(FLERR,
                   "Pair mca: damping viscous with eta = 0 for every atom type damps nothing "
                   "(give eta in pair_coeff)");
  if (!damped && any_eta)
    error->warning(FLERR,
                   "Pair mca: eta is given but the link model has no damping part: add "
                   "'damping viscous' to pair_style mca to use it");
  if (plastic() && !any_yield)
    error->warning(FLERR,
                   "Pair mca: plasticity mises without a yield stress for any atom type "
                   "changes nothing (give yield or hardening table in pair_coeff)");
  if (!plastic() && any_yield)
    error->warning(FLERR,
                   "Pair mca: a yield stress is given but the link model has no plasticity "
                   "part: add 'plasticity mises' to pair_style mca to use it");
}

// the slot of the link law a keyword names, or nullptr
const char *PairMCA::link_slot(const char *keyword)
{
  for (const auto &p : MCA_LINK_PARTS)
    if (strcmp(p.slot, keyword) == 0) return p.slot;
  return nullptr;
}

// the link model: the required parts and those chosen, in table order
void PairMCA::select_parts(const std::vector<std::string> &chosen)
{
  model = MCALinkModel();
  for (const auto &p : MCA_LINK_PARTS) {
    bool on = p.required;
    for (const auto &name : chosen) on = on || name == p.name;
    if (on) model.add_part(p.part, p.name, p.link_size, p.atom_size, p.exact_slots);
  }
}

/* ----------------------------------------------------------------------
   pair_coeff I J [material keywords (MCAMaterials)] [link yes/no] [tolerance t]
   the material keywords need I and J to name the same types
------------------------------------------------------------------------- */

void PairMCA::coeff(int narg, char **arg)
{
  if (narg < 3)
    error->all(FLERR,
               "Incorrect args for pair coefficients: pair_coeff I J keyword "
               "value ... (keywords: E nu rho link tolerance)");
  if (!allocated) allocate();

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  MCAMaterials::Input material;
  double tol = -1.0;
  double friction = -1.0;
  int link = -1;
  int iarg = 2;
  while (iarg < narg) {
    if (iarg + 2 > narg)
      utils::missing_cmd_args(FLERR, std::string("pair_coeff ") + arg[iarg], error);
    const std::string key = arg[iarg];
    if (key == "break") {
      parse_break(ilo, ihi, jlo, jhi, narg, arg, iarg);
      continue;
    } else if (key == "heal") {
      parse_heal(ilo, ihi, jlo, jhi, narg, arg, iarg);
      continue;
    } else if (key == "hardening" && strcmp(arg[iarg + 1], "table") == 0) {
      if (iarg + 4 > narg)
        utils::missing_cmd_args(FLERR, "pair_coeff hardening table (file keyword)", error);
      materials.read_hardening_table(arg[iarg + 2], arg[iarg + 3], material);
      iarg += 4;
      continue;
    } else if (key == "hardening" && !utils::is_double(arg[iarg + 1])) {
      error->all(FLERR,
                 "Pair mca: hardening takes a modulus (a number >= 0) or 'table file keyword', "
                 "got {}",
                 arg[iarg + 1]);
    } else if (materials.parse(key, arg[iarg + 1], material)) {
    } else if (key == "link") {
      link = utils::logical(FLERR, arg[iarg + 1], false, lmp);
    } else if (key == "tolerance") {
      tol = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (tol < 0.0 || tol >= 0.5)
        error->all(FLERR, "Pair mca: link tolerance must be in [0, 0.5), got {}", tol);
    } else if (key == "friction") {
      friction = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (!(friction >= 0.0 && friction < 1.0e300))
        error->all(FLERR, "Pair mca: friction (Coulomb coefficient mu) must be >= 0, got {}",
                   arg[iarg + 1]);
    } else {
      error->all(FLERR,
                 "Unknown pair_coeff keyword {} for pair mca (allowed: {} link tolerance break "
                 "friction heal)",
                 key, materials.keyword_list());
    }
    iarg += 2;
  }

  if (material.given || !material.table_eps.empty()) {
    if (ilo != jlo || ihi != jhi)
      error->all(FLERR,
                 "Pair mca: the material keywords ({}, hardening table) belong to atom "
                 "types; use them with two equal type ranges (e.g. pair_coeff 1 1 or "
                 "pair_coeff * *), not {} {}",
                 materials.keyword_list(), arg[0], arg[1]);
    materials.assign(ilo, ihi, material);
  }

  int count = 0;
  const int n = atom->ntypes + 1;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      if (friction >= 0.0) {
        contact_rules[i * n + j].mu = contact_rules[j * n + i].mu = friction;
        friction_given[i * n + j] = friction_given[j * n + i] = 1;
      }
      if (link >= 0) link_allowed[i][j] = link_allowed[j][i] = link;
      if (tol >= 0.0) link_tolerance[i][j] = link_tolerance[j][i] = tol;
      setflag[i][j] = 1;
      count++;
    }
  }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
}

/* ----------------------------------------------------------------------
   pair_coeff I J ... break none | strain eps_u | stress sigma_u |
                            drucker_prager sigma_t sigma_c | elliptic sigma0 tau0
   the criterion of every type pair in the ranges (symmetric)
------------------------------------------------------------------------- */

void PairMCA::parse_break(int ilo, int ihi, int jlo, int jhi, int narg, char **arg, int &iarg)
{
  static const char *const names[NBREAK] = {"none", "strain", "stress", "drucker_prager",
                                            "elliptic"};
  static const int nparams[NBREAK] = {0, 1, 1, 2, 2};
  const std::string allowed =
      "none, strain eps_u, stress sigma_u, drucker_prager sigma_t sigma_c, elliptic sigma0 tau0";
  MCABreakRule rule{BREAK_NONE, 0.0, 0.0};
  int c = 0;
  while (c < NBREAK && strcmp(arg[iarg + 1], names[c]) != 0) c++;
  if (c == NBREAK)
    error->all(FLERR, "Pair mca: unknown break criterion {} (allowed: {})", arg[iarg + 1], allowed);
  if (iarg + 2 + nparams[c] > narg)
    utils::missing_cmd_args(FLERR, std::string("pair_coeff break ") + names[c], error);
  rule.criterion = c;
  if (nparams[c] > 0) rule.p1 = utils::numeric(FLERR, arg[iarg + 2], false, lmp);
  if (nparams[c] > 1) rule.p2 = utils::numeric(FLERR, arg[iarg + 3], false, lmp);
  const double big = 1.0e300;
  if (c == BREAK_STRAIN && !(rule.p1 > 0.0 && rule.p1 < big))
    error->all(FLERR, "Pair mca: break strain eps_u must be > 0, got {}", arg[iarg + 2]);
  if (c == BREAK_STRESS && !(rule.p1 > 0.0 && rule.p1 < big))
    error->all(FLERR, "Pair mca: break stress sigma_u must be > 0, got {}", arg[iarg + 2]);
  if (c == BREAK_DRUCKER_PRAGER) {
    if (!(rule.p1 > 0.0 && rule.p1 < big))
      error->all(FLERR, "Pair mca: break drucker_prager sigma_t must be > 0, got {}",
                 arg[iarg + 2]);
    if (!(rule.p2 >= rule.p1 && rule.p2 < big))
      error->all(FLERR, "Pair mca: break drucker_prager sigma_c must be >= sigma_t ({}), got {}",
                 rule.p1, arg[iarg + 3]);
  }
  if (c == BREAK_ELLIPTIC) {
    if (!(rule.p1 > 0.0 && rule.p1 < big))
      error->all(FLERR, "Pair mca: break elliptic sigma0 must be > 0, got {}", arg[iarg + 2]);
    if (!(rule.p2 > 0.0 && rule.p2 < big))
      error->all(FLERR, "Pair mca: break elliptic tau0 must be > 0, got {}", arg[iarg + 3]);
  }
  const int n = atom->ntypes + 1;
  for (int i = ilo; i <= ihi; i++)
    for (int j = jlo; j <= jhi; j++) break_rules[i * n + j] = break_rules[j * n + i] = rule;
  iarg += 2 + nparams[c];
}

/* ----------------------------------------------------------------------
   pair_coeff I J ... heal no | heal p [work w]
   healing weld: contacts of the type pairs in the ranges heal into links
   at a compressive normal traction of at least p (> 0), and once one of
   their automata has done the plastic work w per volume (>= 0, default 0)
------------------------------------------------------------------------- */

void PairMCA::parse_heal(int ilo, int ihi, int jlo, int jhi, int narg, char **arg, int &iarg)
{
  MCAContactRule rule{0.0, 0, 0.0, 0.0};
  if (strcmp(arg[iarg + 1], "no") == 0) {
    iarg += 2;
  } else {
    rule.heal = 1;
    rule.heal_pressure = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
    if (!(rule.heal_pressure > 0.0 && rule.heal_pressure < 1.0e300))
      error->all(FLERR,
                 "Pair mca: heal pressure (compressive normal traction) must be > 0, got {} "
                 "('heal no' forbids healing)",
                 arg[iarg + 1]);
    iarg += 2;
    if (iarg < narg && strcmp(arg[iarg], "work") == 0) {
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, "pair_coeff heal ... work", error);
      rule.heal_work = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (!(rule.heal_work >= 0.0 && rule.heal_work < 1.0e300))
        error->all(FLERR,
                   "Pair mca: heal work (plastic work per volume of an automaton) must be >= 0, "
                   "got {}",
                   arg[iarg + 1]);
      iarg += 2;
    }
  }
  const int n = atom->ntypes + 1;
  for (int i = ilo; i <= ihi; i++)
    for (int j = jlo; j <= jhi; j++)
      for (int k : {i * n + j, j * n + i}) {
        contact_rules[k].heal = rule.heal;
        contact_rules[k].heal_pressure = rule.heal_pressure;
        contact_rules[k].heal_work = rule.heal_work;
      }
}

/* ---------------------------------------------------------------------- */

void PairMCA::init_style()
{
  avec = MCAAtomFields::find(atom);
  if (!avec) error->all(FLERR, "Pair style mca requires atom_style mca, not {}", atom->atom_style);
  if (domain->dimension != 3) error->all(FLERR, "Pair style mca requires a 3d simulation");
  if (!comm->ghost_velocity)
    error->all(FLERR,
               "Pair style mca requires ghost atoms to carry velocities: use "
               "'comm_modify vel yes'");
  if (atom->map_style == Atom::MAP_NONE)
    error->all(FLERR, "Pair style mca requires an atom map (atom_modify map array or hash)");

  materials.check_all_set();
  check_parts();

  // the internal fix that keeps the links, with the blocks of the model
  init_links();

  avec->sync_host();
  set_masses();
  avec->modified_host();

  // cutoff: the longest possible link plus room to stretch by R_max/2
  double rmax = 0.0, rmaxall = 0.0;
  for (int k = 0; k < atom->nlocal; k++) rmax = MAX(rmax, atom->radius[k]);
  MPI_Allreduce(&rmax, &rmaxall, 1, MPI_DOUBLE, MPI_MAX, world);
  if (cutoff_user > 0.0) {
    cut_global = cutoff_user;
  } else {
    double tolmax = tolerance_default;
    for (int a = 1; a <= atom->ntypes; a++)
      for (int b = 1; b <= atom->ntypes; b++) tolmax = MAX(tolmax, link_tolerance[a][b]);
    cut_global = 2.0 * rmaxall * (1.0 + tolmax) + 0.5 * rmaxall;
    if (cut_global <= 0.0) cut_global = 1.0;    // no atoms yet
  }

  if (contacts()) init_contacts(rmaxall);
}

/* ----------------------------------------------------------------------
   contacts: friction of the mixed type pairs, the settings that let every
   contact be seen, their neighbor list and the fix that keeps it current
   when the box moves (FixMCARebuild)
------------------------------------------------------------------------- */

void PairMCA::init_contacts(double rmax)
{
  mix_friction();
  // a contact row exists for every pair that can touch before the next
  // reneighboring only if the lists are rebuilt as soon as an automaton
  // moved half the skin
  if (neighbor->delay > 0 || neighbor->every > 1 || !neighbor->dist_check)
    error->all(FLERR,
               "Pair mca contacts need the neighbor lists rebuilt as soon as an automaton has "
               "moved half the skin: use 'neigh_modify delay 0 every 1 check yes' (now delay {} "
               "every {} check {})",
               neighbor->delay, neighbor->every, neighbor->dist_check ? "yes" : "no");
  if (cut_global < 2.0 * rmax)
    error->all(FLERR,
               "Pair mca: contacts need a cutoff of at least the largest touch distance 2 R_max = "
               "{}; pair_style mca cutoff is {}",
               2.0 * rmax, cut_global);
  MCACompat::request_full_list(neighbor, this, instance_me, CONTACT_LIST_ID);
  if (!MCACompat::fix_by_id(modify, "MCA_REBUILD")) modify->add_fix("MCA_REBUILD all MCA_REBUILD");
}

// a type pair without its own friction takes the geometric mean of the
// two types' own (0 if either is frictionless)
void PairMCA::mix_friction()
{
  const int n = atom->ntypes + 1;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i + 1; j <= atom->ntypes; j++) {
      if (friction_given[i * n + j]) continue;
      const double mu = sqrt(contact_rules[i * n + i].mu * contact_rules[j * n + j].mu);
      contact_rules[i * n + j].mu = contact_rules[j * n + i].mu = mu;
    }
}

void PairMCA::init_list(int id, NeighList *ptr)
{
  if (id == CONTACT_LIST_ID)
    contact_list = ptr;
  else
    Pair::init_list(id, ptr);
}

/* ----------------------------------------------------------------------
   the mass and moment of inertia of an automaton follow from the density
   of its material and its virtual cell, unless mca_set gave them (the
   type's density is the default, not an override).  The masses of a data
   file are replaced, and the replacement is reported
------------------------------------------------------------------------- */

void PairMCA::set_masses()
{
  const int nlocal = atom->nlocal;
  const int *type = atom->type;
  double *rmass = atom->rmass;
  const double *radius = atom->radius;
  int *given = avec->given;
  bigint replaced = 0;
  for (int i = 0; i < nlocal; i++) {
    if (!(given[i] & MCAAtomFields::GIVEN_MASS)) {
      const double mass = materials.type[type[i]].density * avec->volume[i];
      if ((given[i] & MCAAtomFields::FROM_DATA) && fabs(rmass[i] - mass) > 1.0e-12 * mass)
        replaced++;
      rmass[i] = mass;
    }
    given[i] &= ~MCAAtomFields::FROM_DATA;
    if (!(given[i] & MCAAtomFields::GIVEN_INERTIA))
      avec->inertia[i] = cell_inertia(avec->packing[i], rmass[i], radius[i]);
  }
  bigint replaced_all = 0;
  MPI_Allreduce(&replaced, &replaced_all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (replaced_all > 0 && comm->me == 0)
    error->warning(FLERR,
                   "Pair mca: the masses of {} automata read from a data file differ from rho "
                   "Omega of their type and are set to it; to keep an automaton's own mass, give "
                   "it with mca_set mass (or density) after read_data",
                   replaced_all);
}

/* ----------------------------------------------------------------------
   the stable time step (doc/src/pair_mca.rst, "Stable time step"): made
   at the first setup and again when what it depends on changed: the
   links (at a setup or a query: a link that breaks only softens the
   scene), the masses or the materials, or the stiffness of the
   deformed automata (the monitor: the largest trace of an automaton's
   mass-scaled stiffness; when LAMMPS reneighbors only if it grew)
------------------------------------------------------------------------- */

// relative change of the monitor that makes the estimate again
static constexpr double MONITOR_TOL = 0.02;

#if __cplusplus < 201703L
constexpr double PairMCA::RECOMMENDED_FRACTION;    // (C++14: a definition where it is bound)
#endif

MCAStableTimestep::Input PairMCA::stability_input()
{
  MCAStableTimestep::Input in;
  in.links = host_links();
  in.type = atom->type;
  in.packing = avec->packing;
  in.rmass = atom->rmass;
  in.inertia = avec->inertia;
  in.material = materials.type;
  in.damping = model.layout().link_offset[PART_DAMPING] >= 0;
  in.friction = contacts();
  return in;
}

// the sums of the masses and moments of inertia of the automata and the
// elastic and damping input of each type
std::vector<double> PairMCA::stability_inputs()
{
  double local[2] = {0.0, 0.0}, all[2];
  for (int i = 0; i < atom->nlocal; i++) {
    local[0] += atom->rmass[i];
    local[1] += avec->inertia[i];
  }
  MPI_Allreduce(local, all, 2, MPI_DOUBLE, MPI_SUM, world);
  std::vector<double> v = {all[0], all[1]};
  for (int t = 1; t <= atom->ntypes; t++) {
    const MCAMaterial &m = materials.type[t];
    v.insert(v.end(), {m.youngs, m.poisson, m.density, m.viscosity});
  }
  return v;
}

void PairMCA::check_stable_timestep(EstimateWhen when)
{
  estimate_host_state();
  const MCAStableTimestep::Input in = stability_input();
  const MCAStableTimestep::Monitor monitor = stability->monitor(in);
  const std::vector<double> inputs = stability_inputs();
  int changed = 0;
  if (when != ESTIMATE_RENEIGHBOR)
    MPI_Allreduce(&links_changed, &changed, 1, MPI_INT, MPI_MAX, world);
  bool stale = !dt_estimated || changed || inputs.size() != dt_inputs.size();
  for (std::size_t k = 0; !stale && k < inputs.size(); k++)
    stale = fabs(inputs[k] - dt_inputs[k]) > 1.0e-12 * fabs(dt_inputs[k]);
  // the largest relative change of a monitor value since the estimate
  double growth = 0.0, change = 0.0;
  for (int c = 0; c < MCAStableTimestep::NMONITOR; c++) {
    const double before = dt_monitor.value[c];
    if (!(before > 0.0)) {
      if (monitor.value[c] > 0.0) growth = change = 1.0;
      continue;
    }
    const double g = monitor.value[c] / before - 1.0;
    growth = std::max(growth, g);
    change = std::max(change, fabs(g));
  }
  if (!stale) stale = ((when == ESTIMATE_RENEIGHBOR) ? growth : change) > MONITOR_TOL;
  // the time step against the estimate at every setup, and when it changed
  if (!stale) {
    if (when == ESTIMATE_SETUP) timestep_warning({});
    return;
  }

  dt_estimate = stability->estimate(in, this);
  dt_estimated = 1;
  dt_monitor = monitor;
  dt_inputs = inputs;
  links_changed = 0;
  if (comm->me != 0) return;

  // the estimate is printed at a setup; made during a run (here, or for
  // compute mca/timestep) it is printed only in the warning of a time step
  // above it (a line between the thermo lines would break their readers)
  const MCAStableTimestep::Result &r = dt_estimate;
  if (when == ESTIMATE_SETUP && r.nlinks == 0)
    utils::logmesg(lmp, "pair mca: no links act, so pair mca sets no limit to the time step\n");
  if (when == ESTIMATE_SETUP && r.nlinks > 0) {
    const std::string damping_text = (r.zeta > 0.0) ? fmt::format(", damping ratio {:.3g}", r.zeta)
                                                    : std::string();
    utils::logmesg(lmp,
                   "pair mca: stable time step {:.6g} (fastest mode: omega {:.6g}{}; {} Lanczos "
                   "steps over {} links; stiffest automaton {} of type {}, its stiffest link "
                   "{}-{}); recommended time step <= {} x {:.6g} = {:.6g}\n",
                   r.dt, r.omega, damping_text, r.iterations, r.nlinks, monitor.atom,
                   monitor.atom_type, monitor.link_i, monitor.link_j, RECOMMENDED_FRACTION, r.dt,
                   RECOMMENDED_FRACTION * r.dt);
  }
  timestep_warning(when == ESTIMATE_SETUP ? std::string()
                                          : fmt::format(" at step {} (the stiffness changed by "
                                                        "up to {:.3g} %)",
                                                        update->ntimestep, 100.0 * change));
}

void PairMCA::timestep_warning(const std::string &when)
{
  const MCAStableTimestep::Result &r = dt_estimate;
  if (!dt_estimated || !(update->dt > r.dt)) return;
  // during a run, again only if the time step is 5 % further above it (a
  // run that blows up stiffens its links at every step)
  const double ratio = update->dt / r.dt;
  if (!when.empty() && ratio < 1.05 * dt_warned_ratio) return;
  dt_warned_ratio = when.empty() ? 0.0 : ratio;
  if (comm->me == 0)
    error->warning(FLERR,
                   "Time step {} is above the stable time step {:.6g} of pair mca{} ({:.4g} times "
                   "it); use a time step <= {:.6g} ({} of the stable time step)",
                   update->dt, r.dt, when, update->dt / r.dt, RECOMMENDED_FRACTION * r.dt,
                   RECOMMENDED_FRACTION);
}

const MCAStableTimestep::Result *PairMCA::stable_timestep()
{
  if (!links || !links->created) return nullptr;
  // the partners of the links are known for these automata
  if (cache_nlocal == atom->nlocal) check_stable_timestep(ESTIMATE_QUERY);
  return dt_estimated ? &dt_estimate : nullptr;
}

void PairMCA::estimate_forward_comm()
{
  comm_stage = STAGE_ESTIMATE;
  MCACompat::forward_comm(comm, this);
}

std::string PairMCA::timestep_hint()
{
  if (!dt_estimated || !(dt_estimate.dt > 0.0) || !std::isfinite(dt_estimate.dt)) return {};
  const double ratio = update->dt / dt_estimate.dt;
  if (ratio <= 0.8) return {};
  return fmt::format("; the time step {} is {:.3g} times the stable time step {:.6g} of pair mca: "
                     "a run that blows up stretches and loses links, use a time step <= {:.6g}",
                     update->dt, ratio, dt_estimate.dt, RECOMMENDED_FRACTION * dt_estimate.dt);
}

/* ----------------------------------------------------------------------
   cutoff: links are found through the atom map, not a neighbor list, but
   partners must be ghost atoms, so the cutoff covers the longest link
   with room to stretch
------------------------------------------------------------------------- */

double PairMCA::init_one(int i, int j)
{
  if (setflag[i][j] == 0) setflag[i][j] = 1;    // links between types are on by default
  link_allowed[j][i] = link_allowed[i][j];
  link_tolerance[j][i] = link_tolerance[i][j];

  return cut_global;
}

/* ----------------------------------------------------------------------
   at the first run: link every pair of packed automata closer than
   (1 + tolerance) (R_i + R_j), unless their types are not to be linked
------------------------------------------------------------------------- */

void PairMCA::setup()
{
  if (!links->created) {
    avec->sync_host();
    links->to_host();
    create_links();
    links->host_changed();
  }
  check_rigid_bodies();
}

/* ----------------------------------------------------------------------
   an automaton of a rigid body (fix rigid and its variants) that is linked
   to an automaton outside the body is ill-defined: the rigid body would
   carry the link's forces and couples without the link's deformation
   being able to follow.  Links inside a body and contacts with the
   outside (an indenter pressed into a sample) are fine
------------------------------------------------------------------------- */

void PairMCA::check_rigid_bodies()
{
  std::vector<Fix *> rigid;
  for (int k = 0; k < modify->nfix; k++)
    if (utils::strmatch(modify->fix[k]->style, "^rigid")) rigid.push_back(modify->fix[k]);
  if (rigid.empty()) return;
  links->to_host();
  const int *mask = atom->mask;
  for (Fix *fix : rigid) {
    const int bit = fix->groupbit;
    bigint crossing = 0;
    tagint example = MAXTAGINT;
    for (int i = 0; i < atom->nlocal; i++) {
      if (!(mask[i] & bit)) continue;
      for (int m = 0; m < links->nlinks[i]; m++) {
        if (links->link_state(i, m) != LINK_LINKED) continue;
        const int j = atom->map(links->partner[i][m]);
        if (j >= 0 && (mask[j] & bit)) continue;
        crossing++;
        example = MIN(example, atom->tag[i]);
      }
    }
    bigint crossing_all = 0;
    MPI_Allreduce(&crossing, &crossing_all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
    if (crossing_all == 0) continue;
    tagint mine = crossing ? example : MAXTAGINT;
    tagint first = 0;
    MPI_Allreduce(&mine, &first, 1, MPI_LMP_TAGINT, MPI_MIN, world);
    error->all(FLERR,
               "Pair mca: {} links join automata of the rigid bodies of fix {} (group {}) to "
               "automata outside them (e.g. automaton {}); a rigid body cannot follow a link's "
               "deformation: unlink the body's atom types from the others (pair_coeff I J link "
               "no; with contacts coulomb they still push and rub) or put the partners in the body",
               crossing_all, fix->id, group->names[fix->igroup], first);
  }
}

bool PairMCA::linkable(int i, int j)
{
  const int *packing = avec->packing;
  if (packing[i] == PACKING_NONE || packing[j] == PACKING_NONE) return false;
  const int it = atom->type[i], jt = atom->type[j];
  if (!link_allowed[it][jt]) return false;
  const double tol = (link_tolerance[it][jt] >= 0.0) ? link_tolerance[it][jt] : tolerance_default;
  const double *radius = atom->radius;
  double **x = atom->x;
  const double cut = (1.0 + tol) * (radius[i] + radius[j]);
  const double dx = x[j][0] - x[i][0], dy = x[j][1] - x[i][1], dz = x[j][2] - x[i][2];
  return dx * dx + dy * dy + dz * dz <= cut * cut;
}

// a new link: stress-free at the present positions
void PairMCA::init_link_row(int i, int j, double *h)
{
  init_pair_row(i, j, LINK_LINKED, h);
}

// a new contact: its reference length is the touch distance R_lo + R_hi;
// its halves at rest (one found already closer starts stress-free where
// it is, as a link does)
void PairMCA::init_contact_row(int i, int j, double *h)
{
  init_pair_row(i, j, LINK_CONTACT, h);
}

void PairMCA::init_pair_row(int i, int j, int state, double *h)
{
  const tagint *tag = atom->tag;
  const double *radius = atom->radius;
  const int *packing = avec->packing;
  double **x = atom->x;
  const bool ilo = tag[i] < tag[j];
  const int lo = ilo ? i : j, hi = ilo ? j : i;
  const double del[3] = {x[hi][0] - x[lo][0], x[hi][1] - x[lo][1], x[hi][2] - x[lo][2]};
  const double r = sqrt(dot3(del, del));
  h[H_STATE] = state;
  if (state == LINK_CONTACT) {
    h[H_R0] = radius[lo] + radius[hi];
    h[H_Q0LO] = radius[lo];
    h[H_Q0HI] = radius[hi];
  } else {
    h[H_R0] = r;
    h[H_Q0LO] = r * radius[lo] / (radius[lo] + radius[hi]);
    h[H_Q0HI] = r * radius[hi] / (radius[lo] + radius[hi]);
  }
  h[H_A0] = 0.5 *
      (face_area(packing[lo], radius[lo], avec->volume[lo]) +
       face_area(packing[hi], radius[hi], avec->volume[hi]));
  h[H_RPREV] = r;
  for (int k = 0; k < 3; k++) h[H_NPREV + k] = del[k] / r;
  h[H_APREV] = h[H_A0];
}

/* ----------------------------------------------------------------------
   per-atom work arrays for local and ghost atoms
------------------------------------------------------------------------- */

void PairMCA::grow_peratom()
{
  if (atom->nmax <= nmax) return;
  nmax = atom->nmax;
  destroy_peratom();
  memory->create(pred_stiffness, nmax, "pair:pred_stiffness");
  memory->create(link_count, nmax, "pair:link_count");
  memory->create(dsmean, nmax, "pair:dsmean");
  memory->create(smean_pred, nmax, "pair:smean_pred");
  // (the return's arrays only in a model with plasticity)
  if (plastic()) {
    memory->create(return_scale, nmax, "pair:return_scale");
    memory->create(return_smean, nmax, "pair:return_smean");
  }
}

void PairMCA::destroy_peratom()
{
  memory->destroy(link_count);
  memory->destroy(pred_stiffness);
  memory->destroy(dsmean);
  memory->destroy(smean_pred);
  memory->destroy(return_scale);
  memory->destroy(return_smean);
}

/* ----------------------------------------------------------------------
   the sums for the local automata, grown with some room (the number of
   local automata changes at each reneighboring); their values do not
   last from one step to the next
------------------------------------------------------------------------- */

void PairMCA::grow_sums()
{
  if (atom->nlocal <= nsums) return;
  nsums = local_rows(atom->nlocal);
  memory->destroy(predictor_sums);
  memory->destroy(bmat);
  memory->create(predictor_sums, nsums, PS_SIZE, "pair:predictor_sums");
  memory->create(bmat, nsums, 9, "pair:bmat");
}

/* ----------------------------------------------------------------------
   number of interacting links of each automaton, sent to the ghosts
------------------------------------------------------------------------- */

void PairMCA::count_links()
{
  const HostData d = host_data();
  for (int i = 0; i < d.nlocal; i++) count_links_of(d, i);
  comm_stage = STAGE_COUNT;
  MCACompat::forward_comm(comm, this);
}

/* ----------------------------------------------------------------------
   mean-stress predictor (thesis 3.74-3.95, corrected): estimate the mean
   stress of each automaton at the new positions before its tractions are
   known.  The normal law applies the difference between this prediction,
   built on the mean stress of the last step's tractions, and the mean
   stress it applied at the last step; the prediction error of one step is
   thus corrected at the next instead of accumulating.
------------------------------------------------------------------------- */

void PairMCA::predict_mean_stress()
{
  const HostData d = host_data();
  const HostSums sums{predictor_sums};
  const bool setup_pass = (update->setupflag != 0);
  for (int i = 0; i < d.nlocal; i++)
    for (int k = 0; k < PS_SIZE; k++) predictor_sums[i][k] = 0.0;
  for (int i = 0; i < d.nlocal; i++) predictor_links_of(d, sums, i);
  // (the fabric tensor stays in the first columns of the sums)
  for (int i = 0; i < d.nlocal; i++) predictor_finish_of(d, i, predictor_sums[i], setup_pass);
  comm_stage = STAGE_MEAN;
  MCACompat::forward_comm(comm, this);
}

/* ---------------------------------------------------------------------- */

void PairMCA::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  if (!links->created) error->all(FLERR, "Pair mca: compute() before the links were made");
  grow_peratom();
  grow_sums();

  // link states (and so the predictor stiffness, sent to the ghost atoms)
  // change only when the partners are found again, or when links broke at
  // the last step (on any processor)
  if (fractured() && partners_outdated()) forget_broken_links();
  if (contacts() && neighbor->ago == 0) update_contacts();
  if (refresh_partners() || links_broke || links_healed) count_links();
  links_broke = links_healed = 0;
  if (neighbor->ago == 0)
    check_stable_timestep(update->setupflag ? ESTIMATE_SETUP : ESTIMATE_RENEIGHBOR);

  predict_mean_stress();

  // the history advances only in steps of a run, not in its setup, so that
  // a run 0 or a restarted run sees the same state.  Spins turn the
  // automata only in steps of a run: a setup (or run 0) sees the positions
  // of the last step plus any displacement since, but no rotation
  const MCALinkPassFlags p = link_pass_flags(update->setupflag == 0);

  const HostData d = host_data();
  const HostLinkSums sums{atom->f, atom->torque, bmat};
  const HostTally tally{this, evflag != 0};
  MCAHostTotals totals;
  for (int i = 0; i < d.nlocal; i++)
    for (int k = 0; k < 9; k++) bmat[i][k] = 0.0;
  if (plastic() && p.commit) {
    // the elastic trial of the links, the return of each automaton from
    // its trial stress (sent to the ghosts), then the corrected links.  A
    // setup returns no automaton: its forces are those of the last step
    // plus the elastic response to what moved since
    for (int i = 0; i < d.nlocal; i++) trial_pass_of(d, sums, p, i);
    for (int i = 0; i < d.nlocal; i++) {
      plastic_return_of(d, i, bmat[i], p.commit);
      for (int k = 0; k < 9; k++) bmat[i][k] = 0.0;
    }
    comm_stage = STAGE_RETURN;
    MCACompat::forward_comm(comm, this);
  }
  if (!plastic()) {
    if (batched_link_pass_applies())
      batched_link_pass(d, sums, tally, p, totals);
    else
      for (int i = 0; i < d.nlocal; i++) link_pass_of<LAW_ELASTIC>(d, sums, tally, p, i, totals);
  } else if (p.commit) {
    for (int i = 0; i < d.nlocal; i++) link_pass_of<LAW_PLASTIC>(d, sums, tally, p, i, totals);
  } else {
    for (int i = 0; i < d.nlocal; i++)
      link_pass_of<LAW_PLASTIC_SETUP>(d, sums, tally, p, i, totals);
  }
  // broken pairs: their compressive force (and friction) only
  if (fractured())
    for (int i = 0; i < d.nlocal; i++) pushing_pass_of<LINK_BROKEN>(d, sums, tally, p, i, totals);
  if (contacts())
    for (int i = 0; i < d.nlocal; i++) pushing_pass_of<LINK_CONTACT>(d, sums, tally, p, i, totals);

  for (int i = 0; i < d.nlocal; i++) automaton_outputs_of(d, i, bmat[i], p.commit);

  // fracture: the links that meet their criterion with the stress of this
  // step break (from the next step on they are broken pairs); the damage
  // changes only then (and is found again at a setup).  The energy the
  // breaks released leaves the elastic energy of this step's tally
  const MCABreakFlags b = break_flags();
  if (p.commit && (fractured() || heal_reads_epsp())) {
    comm_stage = STAGE_BREAK;
    MCACompat::forward_comm(comm, this);
  }
  if (fractured() && p.commit) {
    int nbroke = 0;
    for (int i = 0; i < d.nlocal; i++) nbroke += fracture_pass_of(d, b, i);
    note_breaks(nbroke);
  }
  // healing: the contacts marked at the last step became links in the
  // contact pass; what they held goes to their automata's law state.  The
  // contacts that meet their criterion now are marked (by the contact pass
  // itself when the criterion reads no plastic work)
  if (healing() && p.commit) {
    note_heals(totals.nhealed);
    if (links_healed)
      for (int i = 0; i < d.nlocal; i++) healed_of(d, i, b.step);
    // (without a work criterion the contact pass marked them)
    if (heal_reads_epsp())
      for (int i = 0; i < d.nlocal; i++) heal_pass_of(d, b, i);
  }
  if (fractured()) {
    if (links_broke || links_healed || !p.commit) {
      const double break_step = p.commit ? b.step : -1.0;
      double released = 0.0;
      for (int i = 0; i < d.nlocal; i++) {
        const double released_i = damage_of(d, i, break_step);
        if (eflag_atom) eatom[i] -= released_i;
        released += released_i;
      }
      if (eflag_global) eng_vdwl -= released;
    }
  }

  nstretched = totals.nlong;
  if (neighbor->ago == 0) stretched_warning();
}

/* ----------------------------------------------------------------------
   contacts (mca_contact.h): at each reneighboring, with the contact
   neighbor list just built, before the partners are found again.  A pair
   within reach, closer than R_i + R_j + skin, can touch before the next
   reneighboring (no automaton moves more than half the skin before it);
   every unlinked pair within reach has a contact row in both automata's
   tables, and a contact row of a pair beyond reach goes.  Both owners
   decide from the same distance (a pair that could be decided differently
   on two ranks, at the edge of reach, is a skin apart and at rest).  A
   dropped row leaves what it held to the law state of each automaton:
   the energy its friction dissipated and the rest of the work of its
   forces.  The table grows when an automaton needs more rows (to the
   largest need over the ranks; pair_style mca capacity caps it)
------------------------------------------------------------------------- */

void PairMCA::update_contacts()
{
  if (!contact_list) error->all(FLERR, "Pair mca: contacts without their neighbor list");
  links->to_host();
  const double skin = neighbor->skin;
  const double *radius = atom->radius;
  const tagint *tag = atom->tag;
  double **x = atom->x;
  const int nlocal = atom->nlocal;
  auto distsq = [x](int i, int j) {
    const double dx = x[j][0] - x[i][0], dy = x[j][1] - x[i][1], dz = x[j][2] - x[i][2];
    return dx * dx + dy * dy + dz * dz;
  };
  bool changed = false;

  // contacts beyond reach go (the last row takes the place of one)
  double work[MAX_ROW_SIZE];
  for (int i = 0; i < nlocal; i++) {
    int &n = links->nlinks[i];
    double *state = links->atom_state[i];
    for (int m = n - 1; m >= 0; m--) {
      if (links->link_state(i, m) != LINK_CONTACT) continue;
      const double *row = links->read_row(i, m, work);
      const int j = atom->map(links->partner[i][m]);
      if (j >= 0) {
        const double reach = row[H_R0] + skin;
        if (distsq(i, domain->closest_image(i, j)) < reach * reach) continue;
      }
      keep_dropped_energy(row, state);
      links->remove_row(i, m);
      changed = true;
    }
  }

  // the unlinked pairs within reach that have no row yet
  std::vector<std::pair<int, int>> found;
  int most = 0;
  tagint worst = 0;
  const int inum = contact_list->inum;
  for (int ii = 0; ii < inum; ii++) {
    const int i = contact_list->ilist[ii];
    const int *jlist = contact_list->firstneigh[i];
    int rows = links->nlinks[i];
    for (int jj = 0; jj < contact_list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double reach = radius[i] + radius[j] + skin;
      if (distsq(i, j) >= reach * reach) continue;
      bool known = false;
      for (int m = 0; m < links->nlinks[i] && !known; m++) known = links->partner[i][m] == tag[j];
      if (known) continue;
      found.emplace_back(i, j);
      rows++;
    }
    if (rows > most) {
      most = rows;
      worst = tag[i];
    }
  }
  int most_all = 0;
  MPI_Allreduce(&most, &most_all, 1, MPI_INT, MPI_MAX, world);
  if (most_all > links->maxlinks) {
    if (capacity_user > 0) {
      tagint worst_local = (most == most_all) ? worst : MAXTAGINT, worst_all;
      MPI_Allreduce(&worst_local, &worst_all, 1, MPI_LMP_TAGINT, MPI_MIN, world);
      error->all(FLERR,
                 "Pair mca: automaton {} has {} links and contacts at step {}, more than the "
                 "capacity {} (pair_style mca capacity); raise the capacity or leave it out "
                 "(the tables then grow as needed)",
                 worst_all, most_all, update->ntimestep, capacity_user);
    }
    // room for a few more, so that the tables seldom grow
    links->set_capacity(most_all + 4);
  }
  for (const auto &p : found) {
    const int i = p.first, j = p.second;
    int &n = links->nlinks[i];
    // (two images of one partner within reach: one row, the first image's)
    bool known = false;
    for (int m = 0; m < n && !known; m++) known = links->partner[i][m] == tag[j];
    if (known) continue;
    // (both ends of a local pair make the row: the partner cache keeps one)
    double row[MAX_ROW_SIZE] = {};
    init_contact_row(i, j, row);
    links->add_row(i, n, row);
    links->partner[i][n] = tag[j];
    n++;
  }
  int changed_any = (changed || !found.empty()) ? 1 : 0;
  if (changed_any) {
    links->host_changed();
    cache_nlocal = -1;
    links_changed = 1;
  }
}

// the energy of a contact or broken pair whose row goes, kept in the law
// state of the automaton (each automaton of the pair keeps the whole):
// what its friction dissipated, the rest of the work of its forces (less
// the plastic work of a link that broke), and the count
void PairMCA::keep_dropped_energy(const double *row, double *state) const
{
  const MCALinkLayout &layout = model.layout();
  const int ca = layout.atom_offset[PART_CONTACT];
  const double friction = link_friction_work(row, layout);
  state[ca + CA_FRICTION] += friction;
  state[ca + CA_WORK] += row[H_WORK] - link_plastic_work(row, layout) - friction;
  state[ca + CA_DROPPED] += 1.0;
}

/* ----------------------------------------------------------------------
   fracture: what the fracture pass needs besides the data
------------------------------------------------------------------------- */

// whether links broke on any processor: they are counted again at the
// next step
void PairMCA::note_breaks(int nbroke_local)
{
  MPI_Allreduce(&nbroke_local, &links_broke, 1, MPI_INT, MPI_MAX, world);
  if (links_broke) links_changed = 1;
}

// the same for contacts that became links
void PairMCA::note_heals(int nhealed_local)
{
  MPI_Allreduce(&nhealed_local, &links_healed, 1, MPI_INT, MPI_MAX, world);
  if (links_healed) links_changed = 1;
}

// what a link pass needs besides the data (spins turn the automata only
// in steps of a run: dt = 0 in a setup)
MCALinkPassFlags PairMCA::link_pass_flags(bool commit) const
{
  MCALinkPassFlags p;
  p.commit = commit;
  p.dt = commit ? update->dt : 0.0;
  p.cutsq = cut_global * cut_global;
  p.step = static_cast<double>(update->ntimestep);
  p.heal_in_pass = commit && healing() && !heal_reads_epsp();
  return p;
}

MCABreakFlags PairMCA::break_flags() const
{
  MCABreakFlags b;
  b.step = static_cast<double>(update->ntimestep);
  b.scatter = break_scatter;
  b.seed = break_seed;
  return b;
}

/* ----------------------------------------------------------------------
   a broken pair whose automata are farther apart than the cutoff (at the
   last step) is dropped from both automata's tables at reneighboring,
   before the partners are looked up: its partner may soon leave the ghost
   atoms.  Both owners decide from the same row (two local automata share
   it; ranks that own one each have identical copies), each keeps what the link
   counted for (criterion, released energy) in its law state.  (A pair
   that comes close again interacts only through a contact model.)
------------------------------------------------------------------------- */

void PairMCA::forget_broken_links()
{
  links->to_host();
  const int fa = model.layout().atom_offset[PART_FRACTURE];
  const int ff = model.layout().link_offset[PART_FRACTURE];
  const double last_step = static_cast<double>(update->ntimestep) - 1.0;
  bool changed = false;
  double work[MAX_ROW_SIZE];
  for (int i = 0; i < atom->nlocal; i++) {
    int &n = links->nlinks[i];
    double *state = links->atom_state[i];
    for (int m = n - 1; m >= 0; m--) {
      if (links->link_state(i, m) != LINK_BROKEN) continue;
      const double *row = links->read_row(i, m, work);
      // (not before the first step of the broken pair: finish_break)
      if (row[H_RPREV] <= cut_global || row[ff + F_STEP] >= last_step) continue;
      const int cause = static_cast<int>(row[ff + F_CAUSE]);
      if (cause > BREAK_NONE && cause < NBREAK) state[fa + FA_FORGOTTEN + cause - 1] += 1.0;
      state[fa + FA_RELEASED] += row[ff + F_RELEASED];
      // (with contacts, what the broken pair did since its break too)
      if (contacts()) keep_dropped_energy(row, state);
      links->remove_row(i, m);
      changed = true;
    }
  }
  if (changed) {
    links_changed = 1;
    links->host_changed();
    cache_nlocal = -1;    // the row indices of the partners changed
  }
}

/* ---------------------------------------------------------------------- */

int PairMCA::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  if (comm_stage == STAGE_ESTIMATE) return stability->pack_forward_comm(n, list, buf);
  int m = 0;
  if (comm_stage == STAGE_BREAK) {
    for (int i = 0; i < n; i++) {
      buf[m++] = avec->epsp[list[i]];
      for (int k = 0; k < 6; k++) buf[m++] = avec->stress[list[i]][k];
    }
  } else if (comm_stage == STAGE_COUNT) {
    for (int i = 0; i < n; i++) buf[m++] = pred_stiffness[list[i]];
  } else if (comm_stage == STAGE_RETURN) {
    for (int i = 0; i < n; i++) {
      buf[m++] = return_scale[list[i]];
      buf[m++] = return_smean[list[i]];
    }
  } else {
    for (int i = 0; i < n; i++) {
      buf[m++] = dsmean[list[i]];
      buf[m++] = smean_pred[list[i]];
    }
  }
  return m;
}

/* ---------------------------------------------------------------------- */

void PairMCA::unpack_forward_comm(int n, int first, double *buf)
{
  if (comm_stage == STAGE_ESTIMATE) {
    stability->unpack_forward_comm(n, first, buf);
    return;
  }
  int m = 0;
  const int last = first + n;
  if (comm_stage == STAGE_BREAK) {
    for (int i = first; i < last; i++) {
      avec->epsp[i] = buf[m++];
      for (int k = 0; k < 6; k++) avec->stress[i][k] = buf[m++];
    }
  } else if (comm_stage == STAGE_COUNT) {
    for (int i = first; i < last; i++) pred_stiffness[i] = buf[m++];
  } else if (comm_stage == STAGE_RETURN) {
    for (int i = first; i < last; i++) {
      return_scale[i] = buf[m++];
      return_smean[i] = buf[m++];
    }
  } else {
    for (int i = first; i < last; i++) {
      dsmean[i] = buf[m++];
      smean_pred[i] = buf[m++];
    }
  }
}

/* ----------------------------------------------------------------------
   proc 0 writes to restart file: settings, materials by keyword name,
   linking rules per type pair
------------------------------------------------------------------------- */

void PairMCA::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  materials.write_restart(fp);
  for (int i = 1; i <= atom->ntypes; i++) {
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      fwrite(&link_allowed[i][j], sizeof(int), 1, fp);
      fwrite(&link_tolerance[i][j], sizeof(double), 1, fp);
    }
  }
  // fracture rules
  fwrite(&break_scatter, sizeof(double), 1, fp);
  fwrite(&break_seed, sizeof(int), 1, fp);
  const int n = atom->ntypes + 1;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      const MCABreakRule &rule = break_rules[i * n + j];
      fwrite(&rule.criterion, sizeof(int), 1, fp);
      fwrite(&rule.p1, sizeof(double), 1, fp);
      fwrite(&rule.p2, sizeof(double), 1, fp);
    }
  // friction of the type pairs
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&contact_rules[i * n + j].mu, sizeof(double), 1, fp);
      fwrite(&friction_given[i * n + j], sizeof(int), 1, fp);
    }
  // healing criteria of the type pairs
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      const MCAContactRule &rule = contact_rules[i * n + j];
      fwrite(&rule.heal, sizeof(int), 1, fp);
      fwrite(&rule.heal_pressure, sizeof(double), 1, fp);
      fwrite(&rule.heal_work, sizeof(double), 1, fp);
    }
}

/* ----------------------------------------------------------------------
   proc 0 reads from restart file, bcasts; files of earlier versions hold
   E, nu and rho of each type before its linking rules
------------------------------------------------------------------------- */

void PairMCA::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  if (restart_named) materials.read_restart(fp, restart_tables);
  const int me = comm->me;
  for (int i = 1; i <= atom->ntypes; i++) {
    if (!restart_named) {
      int set = 0;
      double values[3];
      if (me == 0) {
        utils::sfread(FLERR, &set, sizeof(int), 1, fp, nullptr, error);
        utils::sfread(FLERR, values, sizeof(double), 3, fp, nullptr, error);
      }
      MPI_Bcast(&set, 1, MPI_INT, 0, world);
      MPI_Bcast(values, 3, MPI_DOUBLE, 0, world);
      materials.read_restart_values(i, values, set);
    }
    for (int j = i; j <= atom->ntypes; j++) {
      if (me == 0) {
        utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
        utils::sfread(FLERR, &link_allowed[i][j], sizeof(int), 1, fp, nullptr, error);
        utils::sfread(FLERR, &link_tolerance[i][j], sizeof(double), 1, fp, nullptr, error);
      }
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      MPI_Bcast(&link_allowed[i][j], 1, MPI_INT, 0, world);
      MPI_Bcast(&link_tolerance[i][j], 1, MPI_DOUBLE, 0, world);
    }
  }
  if (!restart_fracture) return;
  if (me == 0) {
    utils::sfread(FLERR, &break_scatter, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &break_seed, sizeof(int), 1, fp, nullptr, error);
  }
  MPI_Bcast(&break_scatter, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&break_seed, 1, MPI_INT, 0, world);
  const int n = atom->ntypes + 1;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      MCABreakRule rule;
      if (me == 0) {
        utils::sfread(FLERR, &rule.criterion, sizeof(int), 1, fp, nullptr, error);
        utils::sfread(FLERR, &rule.p1, sizeof(double), 1, fp, nullptr, error);
        utils::sfread(FLERR, &rule.p2, sizeof(double), 1, fp, nullptr, error);
      }
      MPI_Bcast(&rule.criterion, 1, MPI_INT, 0, world);
      MPI_Bcast(&rule.p1, 1, MPI_DOUBLE, 0, world);
      MPI_Bcast(&rule.p2, 1, MPI_DOUBLE, 0, world);
      break_rules[i * n + j] = break_rules[j * n + i] = rule;
    }
  if (!restart_contacts) return;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      double mu = 0.0;
      int given = 0;
      if (me == 0) {
        utils::sfread(FLERR, &mu, sizeof(double), 1, fp, nullptr, error);
        utils::sfread(FLERR, &given, sizeof(int), 1, fp, nullptr, error);
      }
      MPI_Bcast(&mu, 1, MPI_DOUBLE, 0, world);
      MPI_Bcast(&given, 1, MPI_INT, 0, world);
      contact_rules[i * n + j].mu = contact_rules[j * n + i].mu = mu;
      friction_given[i * n + j] = friction_given[j * n + i] = given;
    }
  if (!restart_healing) return;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      MCAContactRule rule{0.0, 0, 0.0, 0.0};
      if (me == 0) {
        utils::sfread(FLERR, &rule.heal, sizeof(int), 1, fp, nullptr, error);
        utils::sfread(FLERR, &rule.heal_pressure, sizeof(double), 1, fp, nullptr, error);
        utils::sfread(FLERR, &rule.heal_work, sizeof(double), 1, fp, nullptr, error);
      }
      MPI_Bcast(&rule.heal, 1, MPI_INT, 0, world);
      MPI_Bcast(&rule.heal_pressure, 1, MPI_DOUBLE, 0, world);
      MPI_Bcast(&rule.heal_work, 1, MPI_DOUBLE, 0, world);
      for (int k : {i * n + j, j * n + i}) {
        contact_rules[k].heal = rule.heal;
        contact_rules[k].heal_pressure = rule.heal_pressure;
        contact_rules[k].heal_work = rule.heal_work;
      }
    }
}

/* ---------------------------------------------------------------------- */

void PairMCA::write_restart_settings(FILE *fp)
{
  fwrite(&RESTART_PRECISION, sizeof(double), 1, fp);
  fwrite(&tolerance_default, sizeof(double), 1, fp);
  fwrite(&cutoff_user, sizeof(double), 1, fp);
  fwrite(&capacity_user, sizeof(int), 1, fp);
  // the parts of the link model, by keyword
  const std::string names = model.names();
  const int len = names.size() + 1;
  fwrite(&len, sizeof(int), 1, fp);
  fwrite(names.c_str(), sizeof(char), len, fp);
  const int mixed = model.mixed() ? 1 : 0;
  fwrite(&mixed, sizeof(int), 1, fp);
}

/* ---------------------------------------------------------------------- */

void PairMCA::read_restart_settings(FILE *fp)
{
  double first = 0.0;
  if (comm->me == 0) utils::sfread(FLERR, &first, sizeof(double), 1, fp, nullptr, error);
  MPI_Bcast(&first, 1, MPI_DOUBLE, 0, world);
  const bool restart_precision = (first == RESTART_PRECISION);
  restart_healing = restart_precision || (first == RESTART_HEALING);
  restart_contacts = restart_healing || (first == RESTART_CONTACTS);
  restart_fracture = restart_contacts || (first == RESTART_FRACTURE);
  restart_tables = restart_fracture || (first == RESTART_HARDENING);
  const bool named_parts = restart_tables || (first == RESTART_NAMED_PARTS);
  restart_named = named_parts || (first == RESTART_NAMED_MATERIALS);
  if (!restart_named && first < 0.0)
    error->all(FLERR, "Restart file holds pair mca settings of an unknown layout ({})", first);
  tolerance_default = first;
  if (comm->me == 0) {
    if (restart_named)
      utils::sfread(FLERR, &tolerance_default, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &cutoff_user, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &capacity_user, sizeof(int), 1, fp, nullptr, error);
  }
  MPI_Bcast(&tolerance_default, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&cutoff_user, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&capacity_user, 1, MPI_INT, 0, world);

  // the link model: named in the file, else (earlier versions) elastic
  std::vector<std::string> chosen;
  if (named_parts) {
    int len = 0;
    if (comm->me == 0) utils::sfread(FLERR, &len, sizeof(int), 1, fp, nullptr, error);
    MPI_Bcast(&len, 1, MPI_INT, 0, world);
    std::vector<char> names(len);
    if (comm->me == 0) utils::sfread(FLERR, names.data(), sizeof(char), len, fp, nullptr, error);
    MPI_Bcast(names.data(), len, MPI_CHAR, 0, world);
    chosen = utils::split_words(std::string(names.data()));
    for (const auto &name : chosen)
      if (link_part_id(name) < 0)
        error->all(FLERR,
                   "Restart file holds a pair mca link model with the part {}, which this "
                   "version does not know",
                   name);
  }
  // (files of earlier versions: double)
  int mixed = 0;
  if (restart_precision && comm->me == 0)
    utils::sfread(FLERR, &mixed, sizeof(int), 1, fp, nullptr, error);
  MPI_Bcast(&mixed, 1, MPI_INT, 0, world);
  select_parts(chosen);
  model.set_mixed(mixed != 0);
}

/* ---------------------------------------------------------------------- */

void *PairMCA::extract(const char *str, int &dim)
{
  dim = 1;
  return (void *) materials.column(str);
}

/* ---------------------------------------------------------------------- */

double PairMCA::memory_usage()
{
  // pred_stiffness, dsmean, smean_pred and link_count; with plasticity
  // the return's M and mean stress; the sums; the partner cache
  return ((3.0 + (plastic() ? 2.0 : 0.0)) * sizeof(double) + sizeof(int)) * nmax +
      (PS_SIZE + 9.0) * nsums * sizeof(double) + (double) cache_rows * cache_cols * sizeof(int);
}
