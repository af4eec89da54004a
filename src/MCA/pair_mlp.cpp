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

#include "pair_mlp.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_mlp_frame.h"
#include "force.h"
#include "math_const.h"
#include "mca_compat.h"
#include "mca_largest_row.h"
#include "memory.h"
#include "mlp_passes.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <cmath>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;
using namespace MLPKernels;
using MathConst::MY_PI;

/* ---------------------------------------------------------------------- */

PairMLP::PairMLP(LAMMPS *lmp) :
    Pair(lmp), cut_global(0.0), taper_width(0.0), return_style(MLP_LITERAL), freturn_flag(0),
    nmax_freturn(0), freturn(nullptr), frame(nullptr)
{
  // the force is not central: no single(), and the virial is tallied pair
  // by pair (a full list leaves the ghosts without forces for fdotr)
  single_enable = 0;
  restartinfo = 1;
  writedata = 1;
  no_virial_fdotr_compute = 1;
}

/* ---------------------------------------------------------------------- */

PairMLP::~PairMLP()
{
  if (copymode) return;
  memory->destroy(freturn);
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
  }
}

/* ---------------------------------------------------------------------- */

void PairMLP::allocate()
{
  allocated = 1;
  const int np1 = atom->ntypes + 1;
  memory->create(setflag, np1, np1, "pair:setflag");
  memory->create(cutsq, np1, np1, "pair:cutsq");
  for (int i = 0; i < np1; i++)
    for (int j = 0; j < np1; j++) setflag[i][j] = 0;
  coeff_table.assign(np1 * np1, MLPCoeff());
}

MLPCoeff &PairMLP::coeff_of(int i, int j)
{
  return coeff_table[i * (atom->ntypes + 1) + j];
}

const MLPCoeff &PairMLP::coefficients(int i, int j) const
{
  return coeff_table[i * (atom->ntypes + 1) + j];
}

/* ----------------------------------------------------------------------
   pair_style mlp cutoff [return literal|conservative] [taper width]
                         [frame fix-ID|none]
------------------------------------------------------------------------- */

void PairMLP::settings(int narg, char **arg)
{
  if (narg < 1) utils::missing_cmd_args(FLERR, "pair_style mlp", error);
  cut_global = utils::numeric(FLERR, arg[0], false, lmp);
  if (cut_global <= 0.0) error->all(FLERR, "Pair style mlp: cutoff must be > 0, not {}", arg[0]);
  return_style = MLP_LITERAL;
  taper_width = 0.0;
  frame_id.clear();
  int iarg = 1;
  while (iarg < narg) {
    if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, "pair_style mlp", error);
    if (strcmp(arg[iarg], "return") == 0) {
      if (strcmp(arg[iarg + 1], "literal") == 0)
        return_style = MLP_LITERAL;
      else if (strcmp(arg[iarg + 1], "conservative") == 0)
        return_style = MLP_CONSERVATIVE;
      else
        error->all(FLERR, "Pair style mlp: return must be literal or conservative, not {}",
                   arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "taper") == 0) {
      taper_width = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (taper_width < 0.0 || taper_width >= cut_global)
        error->all(FLERR, "Pair style mlp: taper width must be >= 0 and < the cutoff {}, not {}",
                   cut_global, arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "frame") == 0) {
      frame_id = (strcmp(arg[iarg + 1], "none") == 0) ? "" : arg[iarg + 1];
    } else {
      error->all(FLERR, "Pair style mlp: unknown keyword {} (allowed: return, taper, frame)",
                 arg[iarg]);
    }
    iarg += 2;
  }

  // a new global cutoff resets the explicitly set ones (as lj/cut does)
  if (allocated) {
    for (int i = 1; i <= atom->ntypes; i++)
      for (int j = i; j <= atom->ntypes; j++)
        if (setflag[i][j]) coeff_of(i, j).cut = cut_global;
  }
}

/* ----------------------------------------------------------------------
   pair_coeff I J harmonic K r0        f0 n theta0 [cutoff]
   pair_coeff I J morse D0 alpha r0    f0 n theta0 [cutoff]
   pair_coeff I J lj epsilon sigma     f0 n theta0 [cutoff]
------------------------------------------------------------------------- */

void PairMLP::coeff(int narg, char **arg)
{
  if (narg < 3) utils::missing_cmd_args(FLERR, "pair_coeff", error);
  if (!allocated) allocate();

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  MLPCoeff p = MLPCoeff();
  int nparam;
  if (strcmp(arg[2], "harmonic") == 0) {
    p.central = MLP_HARMONIC;
    nparam = 2;
  } else if (strcmp(arg[2], "morse") == 0) {
    p.central = MLP_MORSE;
    nparam = 3;
  } else if (strcmp(arg[2], "lj") == 0) {
    p.central = MLP_LJ;
    nparam = 2;
  } else {
    error->all(FLERR, "Pair coeff mlp: central potential must be harmonic, morse or lj, not {}",
               arg[2]);
    return;
  }
  if (narg != 3 + nparam + 3 && narg != 3 + nparam + 4)
    error->all(FLERR,
               "Pair coeff mlp {}: expected I J {} {} f0 n theta0 [cutoff] ({} or {} arguments), "
               "got {}",
               arg[2], arg[2],
               p.central == MLP_HARMONIC
                   ? "K r0"
                   : (p.central == MLP_MORSE ? "D0 alpha r0" : "epsilon sigma"),
               3 + nparam + 3, 3 + nparam + 4, narg);

  double v[3] = {0.0, 0.0, 0.0};
  for (int k = 0; k < nparam; k++) v[k] = utils::numeric(FLERR, arg[3 + k], false, lmp);
  const char *names[3][3] = {{"K", "r0", ""}, {"D0", "alpha", "r0"}, {"epsilon", "sigma", ""}};
  for (int k = 0; k < nparam; k++) {
    // energies may be 0 (a return force alone), lengths and alpha not
    const bool energy = (k == 0);
    if (energy ? v[k] < 0.0 : v[k] <= 0.0)
      error->all(FLERR, "Pair coeff mlp {}: {} must be {} 0, not {}", arg[2], names[p.central][k],
                 energy ? ">=" : ">", arg[3 + k]);
  }
  p.a = v[0];
  p.b = v[1];
  p.c = v[2];

  int iarg = 3 + nparam;
  p.f0 = utils::numeric(FLERR, arg[iarg], false, lmp);
  if (p.f0 < 0.0)
    error->all(FLERR,
               "Pair coeff mlp: f0 must be >= 0 (a restoring return force; rotate the axes with "
               "theta0 instead), not {}",
               arg[iarg]);
  p.n = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
  if (p.n != 4 && p.n != 6)
    error->all(FLERR, "Pair coeff mlp: n must be 4 (square lattice) or 6 (hexagonal), not {}",
               arg[iarg + 1]);
  p.theta0 = utils::numeric(FLERR, arg[iarg + 2], false, lmp);
  double cut = cut_global;
  if (narg == iarg + 4) {
    cut = utils::numeric(FLERR, arg[iarg + 3], false, lmp);
    if (cut <= 0.0) error->all(FLERR, "Pair coeff mlp: cutoff must be > 0, not {}", arg[iarg + 3]);
  }

  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      coeff_of(i, j) = p;
      set_derived(coeff_of(i, j), cut);
      setflag[i][j] = 1;
      count++;
    }
  }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients (no type pair set)");
}

/* ---------------------------------------------------------------------- */

void PairMLP::set_derived(MLPCoeff &p, double cut)
{
  const double nt0 = p.n * p.theta0 * MY_PI / 180.0;
  p.cos_nt0 = cos(nt0);
  p.sin_nt0 = sin(nt0);
  if (p.central == MLP_HARMONIC)
    p.r_ref = p.b;
  else if (p.central == MLP_MORSE)
    p.r_ref = p.c;
  else
    p.r_ref = pow(2.0, 1.0 / 6.0) * p.b;
  p.cut = cut;
}

/* ---------------------------------------------------------------------- */

void PairMLP::init_style()
{
  if (domain->dimension != 2)
    error->all(FLERR,
               "Pair style mlp requires dimension 2 (the return force toward the lattice axes "
               "is defined in the plane; doc/src/pair_mlp.rst)");
  MCACompat::request_full_list(neighbor, this, instance_me, 0);
  find_frame();
}

/* ----------------------------------------------------------------------
   the fix mlp/frame named by the frame keyword (init_style of both styles)
------------------------------------------------------------------------- */

void PairMLP::find_frame()
{
  frame = nullptr;
  if (!frame_id.empty()) {
    Fix *fix = MCACompat::fix_by_id(modify, frame_id);
    if (!fix) error->all(FLERR, "Pair style mlp: frame {}: there is no fix with that ID", frame_id);
    frame = dynamic_cast<FixMLPFrame *>(fix);
    if (!frame || strcmp(fix->style, "mlp/frame") != 0)
      error->all(FLERR, "Pair style mlp: frame {} must be a fix mlp/frame, not fix {}", frame_id,
                 fix->style);
  }
}

/* ---------------------------------------------------------------------- */

double PairMLP::init_one(int i, int j)
{
  if (setflag[i][j] == 0)
    error->all(FLERR,
               "Pair style mlp: no coefficients for types {} {} (set them with pair_coeff; "
               "this style has no mixing rule)",
               i, j);
  MLPCoeff &p = coeff_of(i, j);
  if (taper_width >= p.cut)
    error->all(FLERR, "Pair style mlp: taper width {} must be < the cutoff {} of types {} {}",
               taper_width, p.cut, i, j);
  p.taper_start = p.cut - taper_width;
  p.cutsq = p.cut * p.cut;
  coeff_of(j, i) = p;
  return p.cut;
}

/* ---------------------------------------------------------------------- */

void PairMLP::grow_freturn()
{
  if (atom->nmax > nmax_freturn) {
    nmax_freturn = atom->nmax;
    memory->destroy(freturn);
    memory->create(freturn, nmax_freturn, "pair:freturn");
  }
}

/* ---------------------------------------------------------------------- */

void PairMLP::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  if (freturn_flag) grow_freturn();
  if (frame) {
    frame_half_turns();
    eval<1>();
  } else {
    eval<0>();
  }
  if (update->setupflag && update->whichflag == 1) check_stable_timestep();
}

/* ----------------------------------------------------------------------
   (cos a/2, sin a/2) of each atom's body angle a (0 outside the bodies)
------------------------------------------------------------------------- */

void PairMLP::frame_half_turns()
{
  const int nall = atom->nlocal + atom->nghost;
  half_turn.resize(2 * (size_t) nall);
  for (int i = 0; i < nall; i++) {
    const double a = frame->atom_angle(i);
    half_turn[2 * i] = cos(0.5 * a);
    half_turn[2 * i + 1] = sin(0.5 * a);
  }
}

/* ---------------------------------------------------------------------- */

template <int FRAME> void PairMLP::eval()
{
  const HostAtoms a = host_atoms();
  double **f = atom->f;
  const int inum = list->inum;
  const int *ilist = list->ilist;
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const MLPAtomSums s = atom_forces<FRAME>(a, i);
    f[i][0] += s.fx;
    f[i][1] += s.fy;
    if (freturn_flag) freturn[i] = sqrt(s.rx * s.rx + s.ry * s.ry);
    if (evflag) tally_atom(i, s);
  }
}

// an atom's half of its pairs' energy and virial (ev_tally_xyz_full's
// sums, made per atom first, as mlp/kk does)
void PairMLP::tally_atom(int i, const MLPAtomSums &s)
{
  if (eflag_global) eng_vdwl += s.energy;
  if (eflag_atom) eatom[i] += s.energy;
  if (vflag_global)
    for (int k = 0; k < 6; k++) virial[k] += s.v[k];
  if (vflag_atom)
    for (int k = 0; k < 6; k++) vatom[i][k] += s.v[k];
}

PairMLP::HostAtoms PairMLP::host_atoms() const
{
  HostAtoms a;
  a.xp = atom->x;
  a.typep = atom->type;
  a.rmass = atom->rmass;
  a.mass = atom->mass;
  a.table = coeff_table.data();
  a.numneighp = list->numneigh;
  a.firstneigh = list->firstneigh;
  a.special_lj = force->special_lj;
  a.turn = half_turn.data();
  a.ntypes1 = atom->ntypes + 1;
  a.return_style = return_style;
  return a;
}

/* ----------------------------------------------------------------------
   the stable time step (doc/src/pair_mlp.rst, "Stable time step"): the
   Gershgorin bound of each local atom's two rows of M^-1/2 K M^-1/2 from
   its full neighbour list (the masses of ghosts are communicated), at the
   present positions and lattice axes (a frame's body angles held)
------------------------------------------------------------------------- */

template <int FRAME> bigint PairMLP::row_bounds(std::vector<double> &bound)
{
  const HostAtoms a = host_atoms();
  bigint pairs = 0;
  bound.assign(atom->nlocal, 0.0);
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    bound[i] = atom_row_bound<FRAME>(a, i, pairs);
  }
  return pairs;
}

bool PairMLP::stable_timestep(StableStep &out)
{
  if (!list || neighbor->lastcall < 0) return false;
  std::vector<double> bound;
  bigint pairs;
  if (frame) {
    frame_half_turns();
    pairs = row_bounds<1>(bound);
  } else {
    pairs = row_bounds<0>(bound);
  }
  out = reduce_stable_timestep(bound.data(), pairs);
  return true;
}

// bound: omega^2 of each local atom's rows; pairs_twice: the pairs as
// the full lists count them (each from both sides)
PairMLP::StableStep PairMLP::reduce_stable_timestep(const double *bound, bigint pairs_twice)
{
  StableStep out;
  const MCALargestRow largest = mca_largest_row(world, atom->nlocal, bound, atom->tag);
  bigint all_pairs;
  MPI_Allreduce(&pairs_twice, &all_pairs, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  out.pairs = all_pairs / 2;
  out.atom = largest.atom;
  if (!(largest.value > 0.0)) {
    out.dt = INFINITY;
    out.omega = 0.0;
    return out;
  }
  out.omega = sqrt(largest.value);
  out.dt = 2.0 / out.omega;
  return out;
}

void PairMLP::check_stable_timestep()
{
  StableStep s;
  if (!stable_timestep(s) || comm->me != 0) return;
  if (!std::isfinite(s.dt)) {
    utils::logmesg(lmp, "pair mlp: no pair acts, so pair mlp sets no limit to the time step\n");
    return;
  }
  utils::logmesg(lmp,
                 "pair mlp: stable time step {:.6g} (Gershgorin bound of the fastest mode: omega "
                 "<= {:.6g}; {} pairs; stiffest row: atom {})\n",
                 s.dt, s.omega, s.pairs, s.atom);
  if (update->dt > s.dt)
    error->warning(FLERR,
                   "Time step {} is above the stable time step {:.6g} of pair_style mlp ({:.4g} "
                   "times it; Gershgorin's bound, below which the pairs are stable): use a time "
                   "step <= {:.6g}",
                   update->dt, s.dt, update->dt / s.dt, s.dt);
}

/* ---------------------------------------------------------------------- */

void PairMLP::write_restart_settings(FILE *fp)
{
  fwrite(&cut_global, sizeof(double), 1, fp);
  fwrite(&taper_width, sizeof(double), 1, fp);
  fwrite(&return_style, sizeof(int), 1, fp);
  const int n = (int) frame_id.size();
  fwrite(&n, sizeof(int), 1, fp);
  fwrite(frame_id.data(), sizeof(char), n, fp);
}

void PairMLP::read_restart_settings(FILE *fp)
{
  if (comm->me == 0) {
    utils::sfread(FLERR, &cut_global, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &taper_width, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &return_style, sizeof(int), 1, fp, nullptr, error);
  }
  MPI_Bcast(&cut_global, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&taper_width, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&return_style, 1, MPI_INT, 0, world);
  int n = 0;
  if (comm->me == 0) utils::sfread(FLERR, &n, sizeof(int), 1, fp, nullptr, error);
  MPI_Bcast(&n, 1, MPI_INT, 0, world);
  std::vector<char> id(n + 1, '\0');
  if (comm->me == 0 && n > 0) utils::sfread(FLERR, id.data(), sizeof(char), n, fp, nullptr, error);
  MPI_Bcast(id.data(), n, MPI_CHAR, 0, world);
  frame_id = id.data();
}

/* ----------------------------------------------------------------------
   per set type pair: the coefficients as given (central, a, b, c, f0, n,
   theta0 in degrees, cutoff); the rest is derived again on reading
------------------------------------------------------------------------- */

void PairMLP::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (!setflag[i][j]) continue;
      const MLPCoeff &p = coeff_of(i, j);
      const int ints[2] = {p.central, p.n};
      const double doubles[6] = {p.a, p.b, p.c, p.f0, p.theta0, p.cut};
      fwrite(ints, sizeof(int), 2, fp);
      fwrite(doubles, sizeof(double), 6, fp);
    }
}

void PairMLP::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  const int me = comm->me;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      if (!setflag[i][j]) continue;
      int ints[2];
      double doubles[6];
      if (me == 0) {
        utils::sfread(FLERR, ints, sizeof(int), 2, fp, nullptr, error);
        utils::sfread(FLERR, doubles, sizeof(double), 6, fp, nullptr, error);
      }
      MPI_Bcast(ints, 2, MPI_INT, 0, world);
      MPI_Bcast(doubles, 6, MPI_DOUBLE, 0, world);
      MLPCoeff p = MLPCoeff();
      p.central = ints[0];
      p.n = ints[1];
      p.a = doubles[0];
      p.b = doubles[1];
      p.c = doubles[2];
      p.f0 = doubles[3];
      p.theta0 = doubles[4];
      set_derived(p, doubles[5]);
      coeff_of(i, j) = p;
    }
}

/* ---------------------------------------------------------------------- */

std::string PairMLP::coeff_args(int i, int j)
{
  const MLPCoeff &p = coeff_of(i, j);
  std::string central;
  if (p.central == MLP_HARMONIC)
    central = fmt::format("harmonic {:.17g} {:.17g}", p.a, p.b);
  else if (p.central == MLP_MORSE)
    central = fmt::format("morse {:.17g} {:.17g} {:.17g}", p.a, p.b, p.c);
  else
    central = fmt::format("lj {:.17g} {:.17g}", p.a, p.b);
  return fmt::format("{} {:.17g} {} {:.17g} {:.17g}\n", central, p.f0, p.n, p.theta0, p.cut);
}

void PairMLP::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++)
    if (setflag[i][i]) fputs(fmt::format("{} {}", i, coeff_args(i, i)).c_str(), fp);
}

void PairMLP::write_data_all(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j]) fputs(fmt::format("{} {} {}", i, j, coeff_args(i, j)).c_str(), fp);
}

/* ----------------------------------------------------------------------
   "freturn_flag": fix pair's trigger (1: compute |F_return| per atom)
------------------------------------------------------------------------- */

void *PairMLP::extract(const char *name, int &dim)
{
  dim = 0;
  if (strcmp(name, "freturn_flag") == 0) return (void *) &freturn_flag;
  return nullptr;
}

void *PairMLP::extract_peratom(const char *name, int &ncol)
{
  if (strcmp(name, "freturn") == 0) {
    ncol = 0;
    return (void *) freturn;
  }
  return nullptr;
}

/* ---------------------------------------------------------------------- */

double PairMLP::memory_usage()
{
  double bytes = Pair::memory_usage();
  bytes += (double) coeff_table.size() * sizeof(MLPCoeff);
  bytes += (double) nmax_freturn * sizeof(double);
  return bytes;
}
