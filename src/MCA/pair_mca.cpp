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

#include "atom.h"
#include "atom_vec_mca.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_mca_links.h"
#include "force.h"
#include "mca_compat.h"
#include "mca_kernels.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace MCAKernels;

static const char FIX_LINKS_ID[] = "MCA_LINKS";

/* ---------------------------------------------------------------------- */

PairMCA::PairMCA(LAMMPS *lmp) :
    Pair(lmp), links(nullptr), youngs(nullptr), poisson(nullptr), density(nullptr), shear(nullptr),
    bulk(nullptr), coupling(nullptr), material_set(nullptr), link_allowed(nullptr),
    link_tolerance(nullptr), link_count(nullptr), pred_stiffness(nullptr), dsmean(nullptr),
    smean_pred(nullptr), bmat_atom(nullptr), fabric_atom(nullptr), pred_strain(nullptr),
    partner_cache(nullptr), row_cache(nullptr), avec(nullptr)
{
  single_enable = 0;
  restartinfo = 1;
  one_coeff = 0;
  manybody_flag = 1;
  no_virial_fdotr_compute = 1;
  centroidstressflag = CENTROID_NOTAVAIL;
  comm_forward = 2;
  writedata = 0;

  tolerance_default = 0.02;
  cutoff_user = -1.0;
  capacity_user = 0;
  cut_global = 0.0;
  nmax = 0;
  cache_rows = cache_cols = 0;
  cache_nlocal = -1;
  partner_rows_stale = 0;
  comm_stage = STAGE_COUNT;
  nstretched = 0;
}

/* ---------------------------------------------------------------------- */

PairMCA::~PairMCA()
{
  if (copymode) return;
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(youngs);
    memory->destroy(poisson);
    memory->destroy(density);
    memory->destroy(shear);
    memory->destroy(bulk);
    memory->destroy(coupling);
    memory->destroy(material_set);
    memory->destroy(link_allowed);
    memory->destroy(link_tolerance);
  }
  destroy_peratom();
  memory->destroy(partner_cache);
  memory->destroy(row_cache);
  // the MCA_LINKS fix is kept: a pair_style mca command issued again (e.g.
  // to change a setting) finds the links and their history; clear removes it
  auto fix = dynamic_cast<FixMCALinks *>(MCACompat::fix_by_id(modify, FIX_LINKS_ID));
  if (fix && fix->row_sync == this) fix->row_sync = nullptr;
}

/* ---------------------------------------------------------------------- */

void PairMCA::allocate()
{
  allocated = 1;
  const int n = atom->ntypes + 1;
  memory->create(setflag, n, n, "pair:setflag");
  memory->create(cutsq, n, n, "pair:cutsq");
  memory->create(youngs, n, "pair:youngs");
  memory->create(poisson, n, "pair:poisson");
  memory->create(density, n, "pair:density");
  memory->create(shear, n, "pair:shear");
  memory->create(bulk, n, "pair:bulk");
  memory->create(coupling, n, "pair:coupling");
  memory->create(material_set, n, "pair:material_set");
  memory->create(link_allowed, n, n, "pair:link_allowed");
  memory->create(link_tolerance, n, n, "pair:link_tolerance");
  for (int i = 0; i < n; i++) {
    material_set[i] = 0;
    youngs[i] = poisson[i] = density[i] = shear[i] = bulk[i] = coupling[i] = 0.0;
    for (int j = 0; j < n; j++) {
      setflag[i][j] = 0;
      link_allowed[i][j] = 1;
      link_tolerance[i][j] = -1.0;    // pair style default
    }
  }
}

/* ----------------------------------------------------------------------
   pair_style mca [tolerance t] [capacity N] [cutoff rc]
------------------------------------------------------------------------- */

void PairMCA::settings(int narg, char **arg)
{
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
    } else {
      error->all(FLERR, "Unknown pair_style mca keyword {} (allowed: tolerance, capacity, cutoff)",
                 arg[iarg]);
    }
    iarg += 2;
  }
}

/* ----------------------------------------------------------------------
   pair_coeff I J [E value nu value rho value] [link yes/no] [tolerance t]
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

  double e = -1.0, nu = -2.0, rho = -1.0, tol = -1.0;
  int link = -1;
  int iarg = 2;
  while (iarg < narg) {
    if (iarg + 2 > narg)
      utils::missing_cmd_args(FLERR, std::string("pair_coeff ") + arg[iarg], error);
    const std::string key = arg[iarg];
    if (key == "E") {
      e = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (e <= 0.0) error->all(FLERR, "Pair mca: Young's modulus E must be > 0, got {}", e);
    } else if (key == "nu") {
      nu = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (nu <= -1.0 || nu >= 0.5)
        error->all(FLERR, "Pair mca: Poisson's ratio nu must be in (-1, 0.5), got {}", nu);
      // the mean-stress term D = 3 nu/(1 + nu) feeds each step's prediction
      // error into the next with factor D; it must stay below 1 in size
      if (nu <= -0.25)
        error->all(FLERR,
                   "Pair mca: Poisson's ratio nu = {} is not supported: the mean-stress "
                   "predictor needs nu > -0.25 (|3 nu/(1 + nu)| < 1)",
                   nu);
    } else if (key == "rho") {
      rho = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (rho <= 0.0) error->all(FLERR, "Pair mca: density rho must be > 0, got {}", rho);
    } else if (key == "link") {
      link = utils::logical(FLERR, arg[iarg + 1], false, lmp);
    } else if (key == "tolerance") {
      tol = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (tol < 0.0 || tol >= 0.5)
        error->all(FLERR, "Pair mca: link tolerance must be in [0, 0.5), got {}", tol);
    } else {
      error->all(FLERR,
                 "Unknown pair_coeff keyword {} for pair mca (allowed: E nu rho link "
                 "tolerance)",
                 key);
    }
    iarg += 2;
  }

  const int nmaterial = (e > 0.0) + (nu > -2.0) + (rho > 0.0);
  if (nmaterial > 0) {
    if (nmaterial < 3)
      error->all(FLERR, "Pair mca: a material needs all of E, nu and rho in one pair_coeff");
    if (ilo != jlo || ihi != jhi)
      error->all(FLERR,
                 "Pair mca: E, nu and rho belong to atom types; use them with two equal "
                 "type ranges (e.g. pair_coeff 1 1 or pair_coeff * *), not {} {}",
                 arg[0], arg[1]);
    for (int i = ilo; i <= ihi; i++) {
      youngs[i] = e;
      poisson[i] = nu;
      density[i] = rho;
      shear[i] = shear_modulus(e, nu);
      bulk[i] = bulk_modulus(e, nu);
      coupling[i] = mean_stress_coupling(shear[i], bulk[i]);
      material_set[i] = 1;
    }
  }

  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      if (link >= 0) link_allowed[i][j] = link_allowed[j][i] = link;
      if (tol >= 0.0) link_tolerance[i][j] = link_tolerance[j][i] = tol;
      setflag[i][j] = 1;
      count++;
    }
  }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
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

  for (int i = 1; i <= atom->ntypes; i++)
    if (!material_set[i])
      error->all(FLERR,
                 "Pair mca: no material (E, nu, rho) for atom type {}: use pair_coeff {} {} "
                 "E value nu value rho value",
                 i, i, i);

  // the internal fix that keeps the links; its ID is fixed so that
  // restart files find it again
  links = dynamic_cast<FixMCALinks *>(MCACompat::fix_by_id(modify, FIX_LINKS_ID));
  if (!links)
    links = dynamic_cast<FixMCALinks *>(
        modify->add_fix(fmt::format("{} all {}", FIX_LINKS_ID, links_fix_style())));
  links->row_sync = this;

  avec->sync_host();
  set_masses();
  avec->modified_host();

  // cutoff: the longest possible link plus room to stretch by R_max/2
  if (cutoff_user > 0.0) {
    cut_global = cutoff_user;
  } else {
    double rmax = 0.0;
    for (int k = 0; k < atom->nlocal; k++) rmax = MAX(rmax, atom->radius[k]);
    double rmaxall;
    MPI_Allreduce(&rmax, &rmaxall, 1, MPI_DOUBLE, MPI_MAX, world);
    double tolmax = tolerance_default;
    for (int a = 1; a <= atom->ntypes; a++)
      for (int b = 1; b <= atom->ntypes; b++) tolmax = MAX(tolmax, link_tolerance[a][b]);
    cut_global = 2.0 * rmaxall * (1.0 + tolmax) + 0.5 * rmaxall;
    if (cut_global <= 0.0) cut_global = 1.0;    // no atoms yet
  }

  // time step: a P wave must not cross an automaton in one step; the
  // measured stability limit is 0.9 to 1.35 d/(2 c_p) (see doc/src/pair_mca.rst)
  const double dt_limit = recommended_timestep();
  if (comm->me == 0) {
    utils::logmesg(lmp,
                   "pair mca: time step limit d/(2 c_p) = {:.6g} (smallest, stiffest "
                   "automaton); recommended time step <= {:.6g}\n",
                   dt_limit, 0.5 * dt_limit);
    if (update->dt > 0.9 * dt_limit)
      error->warning(FLERR,
                     "Time step {} is at or above the stability limit of pair mca "
                     "(about d/(2 c_p) = {:.6g}); the recommended time step is <= {:.6g}",
                     update->dt, dt_limit, 0.5 * dt_limit);
  }
}

/* ----------------------------------------------------------------------
   the mass and moment of inertia of an automaton follow from the density
   of its material and its virtual cell
------------------------------------------------------------------------- */

void PairMCA::set_masses()
{
  const int nlocal = atom->nlocal;
  const int *type = atom->type;
  double *rmass = atom->rmass;
  const double *radius = atom->radius;
  for (int i = 0; i < nlocal; i++) {
    rmass[i] = density[type[i]] * avec->volume[i];
    avec->inertia[i] = cell_inertia(avec->packing[i], rmass[i], radius[i]);
  }
}

/* ----------------------------------------------------------------------
   time step limit d/(2 c_p) = R/c_p, minimum over automata
------------------------------------------------------------------------- */

double PairMCA::recommended_timestep()
{
  double dtmin = 1.0e300;
  const int nlocal = atom->nlocal;
  const int *type = atom->type;
  for (int i = 0; i < nlocal; i++) {
    const int t = type[i];
    const double cp = p_wave_speed(shear[t], bulk[t], density[t]);
    dtmin = MIN(dtmin, atom->radius[i] / cp);
  }
  double dtall;
  MPI_Allreduce(&dtmin, &dtall, 1, MPI_DOUBLE, MPI_MIN, world);
  return dtall;
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
  if (links->created) return;
  avec->sync_host();
  links->to_host();
  create_links();
  links->host_changed();
}

void PairMCA::create_links()
{
  NeighList *full = links->build_full_list();
  const int inum = full->inum;
  const int *ilist = full->ilist;
  const int *numneigh = full->numneigh;
  int **firstneigh = full->firstneigh;
  double **x = atom->x;
  const double *radius = atom->radius;
  const int *type = atom->type;
  const tagint *tag = atom->tag;
  const int *packing = avec->packing;

  auto linkable = [&](int i, int j) {
    if (packing[i] == PACKING_NONE || packing[j] == PACKING_NONE) return false;
    const int it = type[i], jt = type[j];
    if (!link_allowed[it][jt]) return false;
    const double tol = (link_tolerance[it][jt] >= 0.0) ? link_tolerance[it][jt] : tolerance_default;
    const double cut = (1.0 + tol) * (radius[i] + radius[j]);
    const double dx = x[j][0] - x[i][0], dy = x[j][1] - x[i][1], dz = x[j][2] - x[i][2];
    return dx * dx + dy * dy + dz * dz <= cut * cut;
  };

  // capacity: the user's, or the largest number of links of an automaton
  int nmost = 0;
  tagint worst = 0;
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    int n = 0;
    for (int jj = 0; jj < numneigh[i]; jj++)
      if (linkable(i, firstneigh[i][jj] & NEIGHMASK)) n++;
    if (n > nmost) {
      nmost = n;
      worst = tag[i];
    }
  }
  int nmostall;
  MPI_Allreduce(&nmost, &nmostall, 1, MPI_INT, MPI_MAX, world);
  if (capacity_user > 0 && nmostall > capacity_user) {
    tagint worst_local = (nmost == nmostall) ? worst : MAXTAGINT, worst_all;
    MPI_Allreduce(&worst_local, &worst_all, 1, MPI_LMP_TAGINT, MPI_MIN, world);
    error->all(FLERR,
               "Pair mca: automaton {} has {} neighbours to link, more than the capacity "
               "{} (pair_style mca capacity); reduce the link tolerance or raise the capacity",
               worst_all, nmostall, capacity_user);
  }
  links->set_capacity(capacity_user > 0 ? capacity_user : MAX(nmostall, 1));

  bigint nlocal_links = 0;
  int duplicate = 0;
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    int &n = links->nlinks[i];
    n = 0;
    for (int jj = 0; jj < numneigh[i]; jj++) {
      const int j = firstneigh[i][jj] & NEIGHMASK;
      if (!linkable(i, j)) continue;
      // two images of one partner: the periodic box is too small
      for (int k = 0; k < n; k++)
        if (links->partner[i][k] == tag[j]) duplicate = 1;
      const bool ilo = tag[i] < tag[j];
      const int lo = ilo ? i : j, hi = ilo ? j : i;
      double *h = &links->history[i][n * H_SIZE];
      for (int k = 0; k < H_SIZE; k++) h[k] = 0.0;
      const double del[3] = {x[hi][0] - x[lo][0], x[hi][1] - x[lo][1], x[hi][2] - x[lo][2]};
      const double r = sqrt(dot3(del, del));
      h[H_STATE] = LINK_LINKED;
      h[H_R0] = r;
      h[H_Q0LO] = r * radius[lo] / (radius[lo] + radius[hi]);
      h[H_Q0HI] = r * radius[hi] / (radius[lo] + radius[hi]);
      h[H_A0] = 0.5 *
          (face_area(packing[lo], radius[lo], avec->volume[lo]) +
           face_area(packing[hi], radius[hi], avec->volume[hi]));
      h[H_RPREV] = r;
      for (int k = 0; k < 3; k++) h[H_NPREV + k] = del[k] / r;
      h[H_APREV] = h[H_A0];
      links->partner[i][n] = tag[j];
      n++;
    }
    nlocal_links += n;
  }
  int duplicate_all;
  MPI_Allreduce(&duplicate, &duplicate_all, 1, MPI_INT, MPI_MAX, world);
  if (duplicate_all)
    error->all(FLERR,
               "Pair mca: an automaton would link to two periodic images of the same "
               "automaton; every periodic box length must exceed twice the link length "
               "(2 (1 + tolerance) (R_i + R_j))");
  links->created = 1;

  bigint nall_links;
  MPI_Allreduce(&nlocal_links, &nall_links, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (comm->me == 0)
    utils::logmesg(lmp, "pair mca: {} links made, at most {} per automaton\n", nall_links / 2,
                   nmostall);
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
  memory->create(fabric_atom, nmax, 6, "pair:fabric_atom");
  memory->create(pred_strain, nmax, 6, "pair:pred_strain");
  memory->create(bmat_atom, nmax, 9, "pair:bmat_atom");
  memory->create(link_count, nmax, "pair:link_count");
  memory->create(dsmean, nmax, "pair:dsmean");
  memory->create(smean_pred, nmax, "pair:smean_pred");
}

void PairMCA::destroy_peratom()
{
  memory->destroy(link_count);
  memory->destroy(pred_stiffness);
  memory->destroy(dsmean);
  memory->destroy(smean_pred);
  memory->destroy(bmat_atom);
  memory->destroy(fabric_atom);
  memory->destroy(pred_strain);
}

/* ----------------------------------------------------------------------
   index of automaton partner_tag as seen from i: the image closest to i;
   a link whose partner is not a local or ghost atom cannot be computed
------------------------------------------------------------------------- */

int PairMCA::partner_index(int i, tagint partner_tag)
{
  const int j = atom->map(partner_tag);
  if (j < 0)
    error->one(FLERR,
               "Pair mca: the link of automaton {} to automaton {} is lost: the partner is "
               "farther than the communication cutoff {} (stretched link, or a deleted automaton); "
               "increase it with comm_modify cutoff or pair_style mca cutoff",
               atom->tag[i], partner_tag, cut_global + neighbor->skin);
  return domain->closest_image(i, j);
}

/* ----------------------------------------------------------------------
   number of interacting links of each automaton, sent to the ghosts
------------------------------------------------------------------------- */

void PairMCA::count_links()
{
  const int nlocal = atom->nlocal;
  const tagint *tag = atom->tag;
  for (int i = 0; i < nlocal; i++) link_count[i] = 0.0;
  // a link between local automata is counted from (and current in the row
  // of) its lower ID
  for (int i = 0; i < nlocal; i++)
    for (int m = 0; m < links->nlinks[i]; m++) {
      const int j = partner_cache[i][m];
      const bool jlocal = j < nlocal;
      if (jlocal && tag[j] < tag[i]) continue;
      if (static_cast<int>(links->history[i][m * H_SIZE + H_STATE]) != LINK_LINKED) continue;
      link_count[i] += 1.0;
      if (jlocal) link_count[j] += 1.0;
    }
  for (int i = 0; i < nlocal; i++) {
    // stiffness of the automaton's halves in the mean-stress predictor
    const int it = atom->type[i];
    const int nc = avec->packing[i];
    const int n = static_cast<int>(link_count[i]);
    pred_stiffness[i] = (nc > 0) ? predictor_stiffness(shear[it], bulk[it], nc, n) : 0.0;
  }
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
  double **x = atom->x;
  const int *type = atom->type;
  const tagint *tag = atom->tag;
  const int nlocal = atom->nlocal;
  const int *packing = avec->packing;
  const bool setup_pass = (update->setupflag != 0);

  for (int i = 0; i < nlocal; i++)
    for (int k = 0; k < 6; k++) fabric_atom[i][k] = pred_strain[i][k] = 0.0;

  // each link once per owner, as in compute(): by the lower ID when both
  // automata are local, whose row is current
  for (int i = 0; i < nlocal; i++) {
    for (int m = 0; m < links->nlinks[i]; m++) {
      const int j = partner_cache[i][m];
      const bool jlocal = j < nlocal;
      if (jlocal && tag[j] < tag[i]) continue;
      const double *h = &links->history[i][m * H_SIZE];
      if (static_cast<int>(h[H_STATE]) != LINK_LINKED) continue;
      const double del[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
      double nn[6], de_i, de_j;
      link_prediction(h, del, tag[i] < tag[j], pred_stiffness[i], pred_stiffness[j], nn, de_i,
                      de_j);
      predictor_add(fabric_atom[i], pred_strain[i], nn, de_i);
      if (jlocal) predictor_add(fabric_atom[j], pred_strain[j], nn, de_j);
    }
  }

  for (int i = 0; i < nlocal; i++) {
    const bool interacting = link_count[i] > 0.0 && packing[i] != PACKING_NONE;
    mean_stress_prediction(interacting, setup_pass, links->smean_step[i], links->smean_law[i],
                           fabric_atom[i], pred_strain[i], bulk[type[i]], smean_pred[i], dsmean[i]);
  }

  comm_stage = STAGE_MEAN;
  MCACompat::forward_comm(comm, this);
}

/* ---------------------------------------------------------------------- */

void PairMCA::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  if (!links->created) error->all(FLERR, "Pair mca: compute() before the links were made");
  grow_peratom();

  // local and ghost indices change only when LAMMPS reneighbors; the
  // partner copies were brought up to date before the atoms moved
  if (neighbor->ago == 0 || cache_nlocal != atom->nlocal) {
    if (partner_rows_stale)
      error->one(FLERR, "Pair mca: atoms were reordered while link rows were out of date");
    build_partner_cache();
    // link states (and so the predictor stiffness, sent to the ghost
    // atoms) change only here in the elastic model: a style that breaks
    // links must count again when it does
    count_links();
  }

  // the history advances only in steps of a run, not in its setup, so that
  // a run 0 or a restarted run sees the same state
  const bool commit = (update->setupflag == 0);
  // a step advances a local link only in the row of its lower ID (the
  // partner's copy follows in sync_link_rows()) unless a fix that runs
  // before the links fix at pre-exchange could move atoms first
  const bool lazy = links->lazy_rows && links->row_sync == this;

  predict_mean_stress();

  double **x = atom->x;
  double **omega = atom->omega;
  double **f = atom->f;
  double **torque = atom->torque;
  const int *type = atom->type;
  const tagint *tag = atom->tag;
  const int nlocal = atom->nlocal;
  // spins turn the automata only in steps of a run: a setup (or run 0)
  // sees the positions of the last step plus any displacement since, but
  // no rotation
  const double dt = commit ? update->dt : 0.0;
  const double cutsq_global = cut_global * cut_global;
  double hist[H_SIZE];
  bigint nlong = 0;

  for (int i = 0; i < nlocal; i++) {
    for (int k = 0; k < 9; k++) bmat_atom[i][k] = 0.0;
  }

  // each link is evaluated once per processor that owns one of its
  // automata: by the lower ID when both are local (and both rows are
  // updated), by each owner when the partner is a ghost atom

  for (int i = 0; i < nlocal; i++) {
    for (int m = 0; m < links->nlinks[i]; m++) {
      double *row = &links->history[i][m * H_SIZE];
      if (static_cast<int>(row[H_STATE]) != LINK_LINKED) continue;
      const int j = partner_cache[i][m];
      const bool jlocal = j < nlocal;
      const bool ilo = tag[i] < tag[j];
      if (jlocal && !ilo) continue;
      const int lo = ilo ? i : j, hi = ilo ? j : i;
      const int tlo = type[lo], thi = type[hi];

      // a step updates the row in place; a setup works on a copy
      double *h = row;
      if (!commit) {
        memcpy(hist, row, H_SIZE * sizeof(double));
        h = hist;
      }
      double fpair[3], tq_lo[3], tq_hi[3], trac[3], nvec[3], sig, r;
      linked_pair(h, x[lo], x[hi], omega[lo], omega[hi], shear[tlo], shear[thi], coupling[tlo],
                  coupling[thi], bulk[tlo], bulk[thi], dsmean[lo], dsmean[hi], smean_pred[lo],
                  smean_pred[hi], face_moment_factor(avec->packing[lo]), dt, fpair, tq_lo, tq_hi,
                  sig, trac, r, nvec);
      // counted once per owner: the warning halves the sum
      if (r * r > cutsq_global) nlong += jlocal ? 2 : 1;

      // force on lo is fpair, on hi -fpair; T n^T is the same for both
      const double sign = ilo ? 1.0 : -1.0;
      const double *tq = ilo ? tq_lo : tq_hi;
      for (int k = 0; k < 3; k++) {
        f[i][k] += sign * fpair[k];
        torque[i][k] += tq[k];
      }
      traction_add(bmat_atom[i], trac, nvec);
      if (jlocal) {
        for (int k = 0; k < 3; k++) {
          f[j][k] -= fpair[k];
          torque[j][k] += tq_hi[k];
        }
        traction_add(bmat_atom[j], trac, nvec);
      }

      // energy and virial: the whole pair, or this owner's half of it
      if (evflag) {
        const double delx = x[i][0] - x[j][0], dely = x[i][1] - x[j][1], delz = x[i][2] - x[j][2];
        const double share = jlocal ? 1.0 : 0.5;
        ev_tally_xyz(i, jlocal ? j : i, nlocal, 0, share * h[H_WORK], 0.0, share * sign * fpair[0],
                     share * sign * fpair[1], share * sign * fpair[2], delx, dely, delz);
      }
      if (commit && jlocal && !lazy)
        memcpy(&links->history[j][row_cache[i][m] * H_SIZE], row, H_SIZE * sizeof(double));
    }
  }
  if (commit && lazy) partner_rows_stale = 1;

  for (int i = 0; i < nlocal; i++) {
    // per-automaton outputs; the mean stress is tension positive
    double smean;
    automaton_stress(bmat_atom[i], fabric_atom[i], shear[type[i]], avec->stress[i], smean,
                     avec->seq[i], avec->eeq[i]);
    avec->smean[i] = smean;
    if (commit) {
      links->smean_step[i] = smean;
      links->smean_law[i] = smean_pred[i];
    }
  }

  nstretched = nlong;
  if (neighbor->ago == 0) stretched_warning();
}

/* ----------------------------------------------------------------------
   copy each local link's current row (lower ID) to the partner's row;
   called by the links fix before atoms move (pre-exchange), at the end of
   a run and before a restart file is written.  Costs one pass over the
   links, against a copy per link and step if done in compute()
------------------------------------------------------------------------- */

void PairMCA::sync_link_rows()
{
  if (!partner_rows_stale) return;
  const int nlocal = atom->nlocal;
  const tagint *tag = atom->tag;
  if (cache_nlocal != nlocal)
    error->one(FLERR, "Pair mca: atoms were reordered while link rows were out of date");
  for (int i = 0; i < nlocal; i++)
    for (int m = 0; m < links->nlinks[i]; m++) {
      const int j = partner_cache[i][m];
      if (j < nlocal && tag[j] < tag[i])
        memcpy(&links->history[i][m * H_SIZE], &links->history[j][row_cache[i][m] * H_SIZE],
               H_SIZE * sizeof(double));
    }
  partner_rows_stale = 0;
}

/* ----------------------------------------------------------------------
   index of every link's partner (closest image) and, for a local partner,
   the row of the same link in the partner's table
------------------------------------------------------------------------- */

void PairMCA::build_partner_cache()
{
  const int nlocal = atom->nlocal;
  const tagint *tag = atom->tag;
  if (cache_rows < atom->nmax || cache_cols < links->maxlinks) {
    cache_rows = atom->nmax;
    cache_cols = links->maxlinks;
    allocate_partner_cache();
  }
  for (int i = 0; i < nlocal; i++)
    for (int m = 0; m < links->nlinks[i]; m++) {
      const int j = partner_index(i, links->partner[i][m]);
      partner_cache[i][m] = j;
      row_cache[i][m] = -1;
      if (j < nlocal)
        for (int k = 0; k < links->nlinks[j]; k++)
          if (links->partner[j][k] == tag[i]) row_cache[i][m] = k;
      if (j < nlocal && row_cache[i][m] < 0)
        error->one(FLERR, "Pair mca: automaton {} is linked to {} but not the other way", tag[i],
                   tag[j]);
    }
  cache_nlocal = nlocal;
}

void PairMCA::allocate_partner_cache()
{
  memory->destroy(partner_cache);
  memory->destroy(row_cache);
  memory->create(partner_cache, cache_rows, cache_cols, "pair:partner_cache");
  memory->create(row_cache, cache_rows, cache_cols, "pair:row_cache");
}

/* ----------------------------------------------------------------------
   a link longer than the cutoff still acts (its partner is found through
   the atom map) but may be lost when it stretches beyond the ghost shell;
   reported on reneighboring steps (and at setup)
------------------------------------------------------------------------- */

void PairMCA::stretched_warning()
{
  bigint nall;
  MPI_Allreduce(&nstretched, &nall, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (nall > 0 && comm->me == 0)
    error->warning(FLERR,
                   "Pair mca: {} links are longer than the cutoff {} at step {}; a link "
                   "whose partner leaves the ghost atoms stops the run",
                   nall / 2, cut_global, update->ntimestep);
}

/* ---------------------------------------------------------------------- */

int PairMCA::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  int m = 0;
  if (comm_stage == STAGE_COUNT) {
    for (int i = 0; i < n; i++) buf[m++] = pred_stiffness[list[i]];
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
  int m = 0;
  const int last = first + n;
  if (comm_stage == STAGE_COUNT) {
    for (int i = first; i < last; i++) pred_stiffness[i] = buf[m++];
  } else {
    for (int i = first; i < last; i++) {
      dsmean[i] = buf[m++];
      smean_pred[i] = buf[m++];
    }
  }
}

/* ----------------------------------------------------------------------
   proc 0 writes to restart file
------------------------------------------------------------------------- */

void PairMCA::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++) {
    fwrite(&material_set[i], sizeof(int), 1, fp);
    fwrite(&youngs[i], sizeof(double), 1, fp);
    fwrite(&poisson[i], sizeof(double), 1, fp);
    fwrite(&density[i], sizeof(double), 1, fp);
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      fwrite(&link_allowed[i][j], sizeof(int), 1, fp);
      fwrite(&link_tolerance[i][j], sizeof(double), 1, fp);
    }
  }
}

/* ----------------------------------------------------------------------
   proc 0 reads from restart file, bcasts
------------------------------------------------------------------------- */

void PairMCA::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  const int me = comm->me;
  for (int i = 1; i <= atom->ntypes; i++) {
    if (me == 0) {
      utils::sfread(FLERR, &material_set[i], sizeof(int), 1, fp, nullptr, error);
      utils::sfread(FLERR, &youngs[i], sizeof(double), 1, fp, nullptr, error);
      utils::sfread(FLERR, &poisson[i], sizeof(double), 1, fp, nullptr, error);
      utils::sfread(FLERR, &density[i], sizeof(double), 1, fp, nullptr, error);
    }
    MPI_Bcast(&material_set[i], 1, MPI_INT, 0, world);
    MPI_Bcast(&youngs[i], 1, MPI_DOUBLE, 0, world);
    MPI_Bcast(&poisson[i], 1, MPI_DOUBLE, 0, world);
    MPI_Bcast(&density[i], 1, MPI_DOUBLE, 0, world);
    if (material_set[i]) {
      shear[i] = shear_modulus(youngs[i], poisson[i]);
      bulk[i] = bulk_modulus(youngs[i], poisson[i]);
      coupling[i] = mean_stress_coupling(shear[i], bulk[i]);
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
}

/* ---------------------------------------------------------------------- */

void PairMCA::write_restart_settings(FILE *fp)
{
  fwrite(&tolerance_default, sizeof(double), 1, fp);
  fwrite(&cutoff_user, sizeof(double), 1, fp);
  fwrite(&capacity_user, sizeof(int), 1, fp);
}

/* ---------------------------------------------------------------------- */

void PairMCA::read_restart_settings(FILE *fp)
{
  if (comm->me == 0) {
    utils::sfread(FLERR, &tolerance_default, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &cutoff_user, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &capacity_user, sizeof(int), 1, fp, nullptr, error);
  }
  MPI_Bcast(&tolerance_default, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&cutoff_user, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&capacity_user, 1, MPI_INT, 0, world);
}

/* ---------------------------------------------------------------------- */

void *PairMCA::extract(const char *str, int &dim)
{
  dim = 1;
  if (strcmp(str, "E") == 0) return (void *) youngs;
  if (strcmp(str, "nu") == 0) return (void *) poisson;
  if (strcmp(str, "rho") == 0) return (void *) density;
  return nullptr;
}

/* ---------------------------------------------------------------------- */

double PairMCA::memory_usage()
{
  // link_count, pred_stiffness, dsmean, smean_pred, bmat, fabric, pred_strain
  return (4.0 + 9.0 + 6.0 + 6.0) * nmax * sizeof(double) +
      2.0 * cache_rows * cache_cols * sizeof(int);
}
