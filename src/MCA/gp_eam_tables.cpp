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

#include "gp_eam_tables.h"

#include "comm.h"
#include "error.h"
#include "memory.h"
#include "pair_eam.h"
#include "utils.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

using namespace LAMMPS_NS;
using namespace GPKernels;

// the largest grid the tables may take (rows of 56 bytes per table)
static constexpr double MAX_ROWS = 5.0e7;

/* ---------------------------------------------------------------------- */

void GPEAMTables::check_elements(const char *style, const char *file, int nelements,
                                 char **elements)
{
  // line 4 of a setfl file: the number of elements and their names
  char line[1024] = {0};
  if (comm->me == 0) {
    FILE *fp = utils::open_potential(file, lmp, nullptr);
    if (fp) {
      for (int k = 0; k < 4; k++)
        if (!fgets(line, sizeof(line), fp)) line[0] = 0;
      fclose(fp);
    }
  }
  MPI_Bcast(line, sizeof(line), MPI_CHAR, 0, world);
  const std::vector<std::string> words = utils::split_words(line);
  if (words.size() < 2) return;
  std::string known;
  for (std::size_t w = 1; w < words.size(); w++) known += (w > 1 ? " " : "") + words[w];
  for (int k = 0; k < nelements; k++) {
    if (strcmp(elements[k], "NULL") == 0) continue;
    if (std::find(words.begin() + 1, words.end(), elements[k]) == words.end())
      error->all(FLERR,
                 "Pair_coeff for pair style {}: element {} (type {}) is not in the potential file "
                 "{} (its elements: {})",
                 style, elements[k], k + 1, file, known);
  }
}

/* ---------------------------------------------------------------------- */

void GPEAMTables::expand(PairEAM &pair, const GPLevels &levels, double cut, double ***rhor_spline,
                         double ***z2r_spline)
{
  const int ntypes = static_cast<int>(levels.level.size()) - 1;
  int nlevels = 1;
  for (int t = 1; t <= ntypes; t++) nlevels = std::max(nlevels, levels.level[t]);
  const double smax = level_length(levels.ratio, nlevels);
  const int nr_atomic = pair.nr;
  const double dr = pair.dr;

  // the grid reaches the last atomic row of the highest level and its
  // cutoff; the row after is zero, so that the kernel's clamp to the last
  // row (R beyond the grid) gives nothing
  const double last = std::max(smax * (nr_atomic - 1), std::ceil(smax * cut / dr));
  if (last + 2.0 > MAX_ROWS)
    error->all(
        FLERR,
        "Pair style EAM of the GP levels: level {} of ratio {} needs tables of {:.0f} rows "
        "(s = {:g} times the atomic {}); at most {:.0f}: use fewer levels or a smaller ratio",
        nlevels, levels.ratio, last + 2.0, smax, nr_atomic, MAX_ROWS);
  const int nr = static_cast<int>(last) + 2;
  rows = nr + 1;

  // rhor and z2r: the atomic tables of every level, then one zero table
  const int nrhor_atomic = pair.nrhor, nz2r_atomic = pair.nz2r, nfrho_atomic = pair.nfrho;
  ntab_rhor = nrhor_atomic * nlevels + 1;
  ntab_z2r = nz2r_atomic * nlevels + 1;
  rhor_rows.assign(static_cast<std::size_t>(ntab_rhor) * rows * 7, 0.0);
  z2r_rows.assign(static_cast<std::size_t>(ntab_z2r) * rows * 7, 0.0);
  for (int l = 1; l <= nlevels; l++) {
    const double s = level_length(levels.ratio, l);
    const double c = level_energy_factor(levels.ratio, l, levels.scaling);
    // rho(R/s); R c phi(R/s) = c s z2r(R/s)
    for (int t = 0; t < nrhor_atomic; t++)
      level_rows(rhor_spline[t], nr_atomic, dr, cut, s, 1.0,
                 &rhor_rows[static_cast<std::size_t>((l - 1) * nrhor_atomic + t) * rows * 7]);
    for (int t = 0; t < nz2r_atomic; t++)
      level_rows(z2r_spline[t], nr_atomic, dr, cut, s, c * s,
                 &z2r_rows[static_cast<std::size_t>((l - 1) * nz2r_atomic + t) * rows * 7]);
  }

  // the arrays the base style splines: the level functions at the grid
  // points (their spline is replaced by the rows above), and c F(rho)
  double **frho = nullptr, **rhor = nullptr, **z2r = nullptr;
  memory->create(frho, nfrho_atomic * nlevels, pair.nrho + 1, "pair:frho");
  memory->create(rhor, ntab_rhor, nr + 1, "pair:rhor");
  memory->create(z2r, ntab_z2r, nr + 1, "pair:z2r");
  for (int l = 1; l <= nlevels; l++) {
    const double c = level_energy_factor(levels.ratio, l, levels.scaling);
    for (int t = 0; t < nfrho_atomic; t++)
      for (int m = 0; m <= pair.nrho; m++)
        frho[(l - 1) * nfrho_atomic + t][m] = c * pair.frho[t][m];
  }
  for (int t = 0; t < ntab_rhor; t++)
    for (int m = 0; m <= nr; m++) rhor[t][m] = rhor_row(t, m, 6);
  for (int t = 0; t < ntab_z2r; t++)
    for (int m = 0; m <= nr; m++) z2r[t][m] = z2r_row(t, m, 6);
  memory->destroy(pair.frho);
  memory->destroy(pair.rhor);
  memory->destroy(pair.z2r);
  pair.frho = frho;
  pair.rhor = rhor;
  pair.z2r = z2r;
  pair.nfrho = nfrho_atomic * nlevels;
  pair.nrhor = ntab_rhor;
  pair.nz2r = ntab_z2r;
  pair.nr = nr;

  // each type reads the tables of its level; types of different levels
  // the zero table (the base's -1 of types it does not handle stays)
  for (int i = 1; i <= ntypes; i++) {
    const int li = levels.level[i] - 1;
    pair.type2frho[i] += li * nfrho_atomic;
    for (int j = 1; j <= ntypes; j++) {
      const bool same = levels.same_level(i, j);
      int &rho_index = pair.type2rhor[i][j];
      if (rho_index >= 0) rho_index = same ? li * nrhor_atomic + rho_index : ntab_rhor - 1;
      int &z2r_index = pair.type2z2r[i][j];
      if (z2r_index >= 0) z2r_index = same ? li * nz2r_atomic + z2r_index : ntab_z2r - 1;
    }
  }
}

/* ----------------------------------------------------------------------
   the rows of factor f(R/s) on the grid (rows 1 .. nr-1 of out; row 0
   and the last are zero): row m covers R in [(m-1) dr, m dr], inside
   atomic row M = (m-1)/s + 1 at P = (j + p)/s, j = (m-1) mod s.  Beyond
   the atomic rows, what the atomic kernel gives there (its clamp to the
   end of the last row) up to s times the cutoff, then zero
------------------------------------------------------------------------- */

void GPEAMTables::level_rows(double **atomic, int nr_atomic, double dr, double cut, double s,
                             double factor, double *out) const
{
  const long scale = std::lround(s);
  const int nr = rows - 1;
  for (int m = 1; m < nr; m++) {
    double *row = out + static_cast<std::size_t>(m) * 7;
    const long q = m - 1, atomic_row = q / scale + 1, j = q % scale;
    if (atomic_row <= nr_atomic - 1) {
      spline_row_mapped(atomic[atomic_row], j / s, 1.0 / s, factor, row);
      spline_row_derivative(row, dr);
    } else if ((m - 1) * dr < s * cut) {
      const double *end = atomic[nr_atomic - 1];
      row[6] = factor * (((end[3] + end[4]) + end[5]) + end[6]);
      row[2] = factor / s * ((end[0] + end[1]) + end[2]);
    }
  }
}

/* ---------------------------------------------------------------------- */

void GPEAMTables::write_rows(double ***rhor_spline, double ***z2r_spline) const
{
  for (int t = 0; t < ntab_rhor; t++)
    for (int m = 0; m < rows; m++)
      for (int k = 0; k < 7; k++) rhor_spline[t][m][k] = rhor_row(t, m, k);
  for (int t = 0; t < ntab_z2r; t++)
    for (int m = 0; m < rows; m++)
      for (int k = 0; k < 7; k++) z2r_spline[t][m][k] = z2r_row(t, m, k);
}

void GPEAMTables::release()
{
  std::vector<double>().swap(rhor_rows);
  std::vector<double>().swap(z2r_rows);
}
