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

#include "gp_levels.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "memory.h"
#include "neighbor.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace GPKernels;

static const char *const scaling_names[GP_NSCALING] = {"energy", "pmap", "pmap_invmap"};
// the largest level: k^(3(n-1)) stays exact in a double and far below
// anything a model needs (3^(3*9) = 7.6e12 atoms per particle)
static constexpr int MAX_LEVEL = 10;

/* ---------------------------------------------------------------------- */

GPLevels::GPLevels(LAMMPS *lmp, const char *style_name) :
    Pointers(lmp), ratio(2), scaling(GP_ENERGY), style(style_name)
{
}

int GPLevels::settings(int narg, char **arg)
{
  int first = narg;
  for (int i = 0; i < narg; i++)
    if (strcmp(arg[i], "ratio") == 0 || strcmp(arg[i], "scaling") == 0) {
      first = i;
      break;
    }
  ratio = 2;
  scaling = GP_ENERGY;
  int iarg = first;
  while (iarg < narg) {
    const std::string key = arg[iarg];
    if (iarg + 2 > narg) error->all(FLERR, "Pair style {}: keyword {} needs a value", style, key);
    const std::string value = arg[iarg + 1];
    if (key == "ratio") {
      const int k = utils::inumeric(FLERR, value.c_str(), false, lmp);
      if (k < 2 || k > 10)
        error->all(FLERR, "Pair style {}: ratio must be an integer from 2 to 10, got {}", style,
                   value);
      ratio = k;
    } else if (key == "scaling") {
      int found = -1;
      for (int s = 0; s < GP_NSCALING; s++)
        if (value == scaling_names[s]) found = s;
      if (found < 0)
        error->all(FLERR, "Pair style {}: unknown scaling {} (allowed: energy, pmap, pmap_invmap)",
                   style, value);
      scaling = found;
    } else {
      error->all(FLERR, "Pair style {}: unknown keyword {} (allowed: ratio, scaling)", style, key);
    }
    iarg += 2;
  }
  return first;
}

void GPLevels::allocate(int ntypes)
{
  level.assign(ntypes + 1, 0);
}

int GPLevels::coeff(int narg, char **arg, int ilo, int ihi, int jlo, int jhi)
{
  if (narg < 2 || strcmp(arg[narg - 2], "level") != 0)
    error->all(FLERR,
               "Pair_coeff for pair style {} needs the scale level of the two types at its end: "
               "'level n' (n = 1 for atoms)",
               style);
  const int n = utils::inumeric(FLERR, arg[narg - 1], false, lmp);
  if (n < 1 || n > MAX_LEVEL)
    error->all(FLERR, "Pair_coeff for pair style {}: level must be from 1 to {}, got {}", style,
               MAX_LEVEL, arg[narg - 1]);
  for (int lo_hi = 0; lo_hi < 2; lo_hi++) {
    const int lo = lo_hi ? jlo : ilo, hi = lo_hi ? jhi : ihi;
    for (int t = lo; t <= hi; t++) {
      if (level[t] != 0 && level[t] != n)
        error->all(FLERR,
                   "Pair_coeff for pair style {}: type {} has level {}, not {}; types of different "
                   "levels never interact (give no coefficients for such pairs)",
                   style, t, level[t], n);
      level[t] = n;
    }
  }
  return narg - 2;
}

int GPLevels::coeff_types(int narg, char **arg, int first)
{
  const int ntypes = static_cast<int>(level.size()) - 1;
  if (narg != first + 1 + ntypes || strcmp(arg[first], "level") != 0)
    error->all(FLERR,
               "Pair_coeff for pair style {}: * * file, the {} element names, then the scale level "
               "of each type: 'level n_1 ... n_{}' (n = 1 for atoms); got {} arguments",
               style, ntypes, ntypes, narg);
  for (int t = 1; t <= ntypes; t++) {
    const char *word = arg[first + t];
    const int n = utils::inumeric(FLERR, word, false, lmp);
    if (n < 1 || n > MAX_LEVEL)
      error->all(FLERR,
                 "Pair_coeff for pair style {}: the level of type {} must be from 1 to {}, got {}",
                 style, t, MAX_LEVEL, word);
    level[t] = n;
  }
  return first;
}

void GPLevels::check_all_set() const
{
  for (std::size_t t = 1; t < level.size(); t++)
    if (level[t] == 0)
      error->all(FLERR,
                 "Pair style {}: atom type {} has no scale level (set it with 'level n' at the end "
                 "of one of its pair_coeff commands)",
                 style, t);
}

void GPLevels::exclude_other_levels() const
{
  const int ntypes = static_cast<int>(level.size()) - 1;
  int added = 0;
  for (int i = 1; i <= ntypes; i++)
    for (int j = i + 1; j <= ntypes; j++) {
      if (level[i] == level[j]) continue;
      bool listed = false;
      for (int k = 0; k < neighbor->nex_type && !listed; k++)
        listed = (neighbor->ex1_type[k] == i && neighbor->ex2_type[k] == j) ||
            (neighbor->ex1_type[k] == j && neighbor->ex2_type[k] == i);
      if (listed) continue;
      neighbor->modify_params(fmt::format("exclude type {} {}", i, j));
      added++;
    }
  if (added && comm->me == 0)
    utils::logmesg(lmp,
                   "{}: neighbor lists exclude {} pairs of atom types of different levels "
                   "(neigh_modify exclude type)\n",
                   style, added);
}

const char *GPLevels::scaling_name() const
{
  return scaling_names[scaling];
}

/* ----------------------------------------------------------------------
   restart files: ratio, scaling, the level of each type
------------------------------------------------------------------------- */

void GPLevels::write_restart(FILE *fp) const
{
  const int ntypes = static_cast<int>(level.size()) - 1;
  fwrite(&ratio, sizeof(int), 1, fp);
  fwrite(&scaling, sizeof(int), 1, fp);
  fwrite(&ntypes, sizeof(int), 1, fp);
  fwrite(level.data() + 1, sizeof(int), ntypes, fp);
}

void GPLevels::read_restart(FILE *fp)
{
  int ntypes = 0;
  if (comm->me == 0) {
    utils::sfread(FLERR, &ratio, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &scaling, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &ntypes, sizeof(int), 1, fp, nullptr, error);
  }
  MPI_Bcast(&ratio, 1, MPI_INT, 0, world);
  MPI_Bcast(&scaling, 1, MPI_INT, 0, world);
  MPI_Bcast(&ntypes, 1, MPI_INT, 0, world);
  level.assign(ntypes + 1, 0);
  if (comm->me == 0)
    utils::sfread(FLERR, level.data() + 1, sizeof(int), ntypes, fp, nullptr, error);
  MPI_Bcast(level.data() + 1, ntypes, MPI_INT, 0, world);
}

/* ---------------------------------------------------------------------- */

GPPairCoeffs::GPPairCoeffs(LAMMPS *lmp, const char *style_name,
                           const std::vector<std::string> &param_names) :
    Pointers(lmp),
    levels(lmp, style_name), cut_global(0.0), style(style_name), names(param_names),
    nparams(static_cast<int>(param_names.size())), ntypes(0), values(nullptr), cut(nullptr),
    set(nullptr)
{
}

GPPairCoeffs::~GPPairCoeffs()
{
  memory->destroy(values);
  memory->destroy(cut);
  memory->destroy(set);
}

void GPPairCoeffs::settings(int narg, char **arg)
{
  const int nbase = levels.settings(narg, arg);
  if (nbase != 1)
    error->all(FLERR,
               "Pair style {} takes the atomic cutoff, then the keywords ratio and scaling; got {} "
               "arguments before them",
               style, nbase);
  cut_global = utils::numeric(FLERR, arg[0], false, lmp);
  if (!(cut_global > 0.0))
    error->all(FLERR, "Pair style {}: the atomic cutoff must be > 0, got {}", style, arg[0]);
  // (a new global cutoff resets the cutoffs already given, as in LAMMPS)
  for (int i = 1; i <= ntypes; i++)
    for (int j = i; j <= ntypes; j++)
      if (set[i][j]) cut[i][j] = cut_global;
}

void GPPairCoeffs::allocate(int n)
{
  ntypes = n;
  memory->destroy(values);
  memory->destroy(cut);
  memory->destroy(set);
  memory->create(values, n + 1, (n + 1) * nparams, "pair:gp_values");
  memory->create(cut, n + 1, n + 1, "pair:gp_cut");
  memory->create(set, n + 1, n + 1, "pair:gp_set");
  for (int i = 0; i <= n; i++)
    for (int j = 0; j <= n; j++) set[i][j] = 0;
  levels.allocate(n);
}

void GPPairCoeffs::coeff(int narg, char **arg, int **setflag)
{
  std::string usage = "I J";
  for (const auto &name : names) usage += " " + name;
  usage += " [cutoff] level n";
  if (narg < 2)
    error->all(FLERR, "Pair_coeff for pair style {}: {} (the atomic parameters)", style, usage);
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, ntypes, jlo, jhi, error);
  const int nargs = levels.coeff(narg, arg, ilo, ihi, jlo, jhi);
  if (nargs < 2 + nparams || nargs > 3 + nparams)
    error->all(FLERR, "Pair_coeff for pair style {}: {} (the atomic parameters)", style, usage);
  std::vector<double> given_values(nparams);
  for (int k = 0; k < nparams; k++) given_values[k] = utils::numeric(FLERR, arg[2 + k], false, lmp);
  const double cut_one =
      (nargs == 3 + nparams) ? utils::numeric(FLERR, arg[2 + nparams], false, lmp) : cut_global;
  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      for (int k = 0; k < nparams; k++) values[i][j * nparams + k] = given_values[k];
      cut[i][j] = cut_one;
      set[i][j] = 1;
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "Pair_coeff for pair style {}: no type pair I <= J", style);
}

/* ----------------------------------------------------------------------
   restart files: the levels, then the atomic coefficients of the pairs
   the user set
------------------------------------------------------------------------- */

void GPPairCoeffs::write_restart(FILE *fp)
{
  fwrite(&cut_global, sizeof(double), 1, fp);
  levels.write_restart(fp);
  std::vector<double> row(nparams + 1);
  for (int i = 1; i <= ntypes; i++)
    for (int j = i; j <= ntypes; j++) {
      fwrite(&set[i][j], sizeof(int), 1, fp);
      if (!set[i][j]) continue;
      for (int k = 0; k < nparams; k++) row[k] = values[i][j * nparams + k];
      row[nparams] = cut[i][j];
      fwrite(row.data(), sizeof(double), nparams + 1, fp);
    }
}

void GPPairCoeffs::read_restart(FILE *fp, int **setflag)
{
  const int me = comm->me;
  if (me == 0) utils::sfread(FLERR, &cut_global, sizeof(double), 1, fp, nullptr, error);
  MPI_Bcast(&cut_global, 1, MPI_DOUBLE, 0, world);
  levels.read_restart(fp);
  std::vector<double> row(nparams + 1);
  for (int i = 1; i <= ntypes; i++)
    for (int j = i; j <= ntypes; j++) {
      if (me == 0) utils::sfread(FLERR, &set[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&set[i][j], 1, MPI_INT, 0, world);
      setflag[i][j] = set[i][j];
      if (!set[i][j]) continue;
      if (me == 0)
        utils::sfread(FLERR, row.data(), sizeof(double), nparams + 1, fp, nullptr, error);
      MPI_Bcast(row.data(), nparams + 1, MPI_DOUBLE, 0, world);
      for (int k = 0; k < nparams; k++) values[i][j * nparams + k] = row[k];
      cut[i][j] = row[nparams];
    }
}

/* ----------------------------------------------------------------------
   data files: pair_coeff's form (the atomic coefficients and the level)
------------------------------------------------------------------------- */

std::string GPPairCoeffs::data_line(int i, int j) const
{
  std::string line;
  for (int k = 0; k < nparams; k++) line += fmt::format(" {:.17g}", values[i][j * nparams + k]);
  return line;
}

void GPPairCoeffs::write_data(FILE *fp)
{
  for (int i = 1; i <= ntypes; i++)
    fputs(fmt::format("{}{} level {}\n", i, data_line(i, i), levels.level[i]).c_str(), fp);
}

void GPPairCoeffs::write_data_all(FILE *fp)
{
  for (int i = 1; i <= ntypes; i++)
    for (int j = i; j <= ntypes; j++)
      if (set[i][j])
        fputs(fmt::format("{} {}{} {:.17g} level {}\n", i, j, data_line(i, j), cut[i][j],
                          levels.level[i])
                  .c_str(),
              fp);
}
