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

#include "mca_materials.h"

#include "comm.h"
#include "error.h"
#include "memory.h"
#include "text_file_reader.h"
#include "tokenizer.h"

#include <cmath>
#include <cstring>
#include <limits>

using namespace LAMMPS_NS;
using namespace MCAKernels;

namespace {

/* ----------------------------------------------------------------------
   the pair_coeff keywords of a material.  A new parameter is a field of
   MCAMaterial, a line here and a line in doc/src/pair_mca.rst; restart
   files name their keywords, so older files read the others as unset
------------------------------------------------------------------------- */

struct Keyword {
  const char *name;
  double MCAMaterial::*field;
  const char *what;    // for error messages
  // allowed values: lo < v < hi (open) or lo <= v (closed lower bound)
  double lo, hi;
  bool lo_closed;
  const char *range;    // as the error message says it
  bool required;        // in every material (else 0 unless given)
};

constexpr double INF = std::numeric_limits<double>::infinity();

const Keyword KEYWORDS[] = {
    {"E", &MCAMaterial::youngs, "Young's modulus E", 0.0, INF, false, "> 0", true},
    {"nu", &MCAMaterial::poisson, "Poisson's ratio nu", -1.0, 0.5, false, "in (-1, 0.5)", true},
    {"rho", &MCAMaterial::density, "density rho", 0.0, INF, false, "> 0", true},
    {"eta", &MCAMaterial::viscosity, "viscosity eta", 0.0, INF, true, ">= 0 and finite", false},
    {"yield", &MCAMaterial::yield, "yield stress", 0.0, INF, false, "> 0 and finite", false},
    {"hardening", &MCAMaterial::hardening, "hardening modulus", 0.0, INF, true,
     ">= 0 and finite (or: hardening table file keyword)", false},
};
constexpr int NKEYWORDS = sizeof(KEYWORDS) / sizeof(KEYWORDS[0]);

// the bit of Input::given of the keyword of a field
unsigned keyword_bit(double MCAMaterial::*field)
{
  for (int k = 0; k < NKEYWORDS; k++)
    if (KEYWORDS[k].field == field) return 1u << k;
  return 0;
}

// further limits of the model, beyond the physical range of a keyword
void check_model(Error *error, const Keyword &key, double value)
{
  // the mean-stress term D = 3 nu/(1 + nu) feeds each step's prediction
  // error into the next with factor D; it must stay below 1 in size
  if (key.field == &MCAMaterial::poisson && value <= -0.25)
    error->all(FLERR,
               "Pair mca: Poisson's ratio nu = {} is not supported: the mean-stress "
               "predictor needs nu > -0.25 (|3 nu/(1 + nu)| < 1)",
               value);
}

}    // namespace

/* ---------------------------------------------------------------------- */

MCAMaterials::MCAMaterials(LAMMPS *lmp) :
    Pointers(lmp), ntypes(0), type(nullptr), set(nullptr), hardening(nullptr), tabulated(nullptr)
{
}

MCAMaterials::~MCAMaterials()
{
  memory->sfree(type);
  memory->destroy(set);
  memory->sfree(hardening);
  memory->destroy(tabulated);
}

void MCAMaterials::allocate(int n)
{
  ntypes = n;
  memory->sfree(type);
  memory->destroy(set);
  memory->sfree(hardening);
  memory->destroy(tabulated);
  type = (MCAMaterial *) memory->smalloc((n + 1) * sizeof(MCAMaterial), "pair:material");
  hardening = (MCAHardening *) memory->smalloc((n + 1) * sizeof(MCAHardening), "pair:hardening");
  memory->create(set, n + 1, "pair:material_set");
  memory->create(tabulated, n + 1, "pair:material_tabulated");
  for (int i = 0; i <= n; i++) {
    type[i] = MCAMaterial();
    hardening[i] = MCAHardening();
    set[i] = 0;
    tabulated[i] = 0;
  }
}

bool MCAMaterials::any_plastic() const
{
  for (int i = 1; i <= ntypes; i++)
    if (set[i] && hardening[i].npoints > 0) return true;
  return false;
}

// the curve of type i: the table if given, else linear from yield and
// hardening, else none (the type stays elastic)
void MCAMaterials::set_curve(int i, const std::vector<double> &eps, const std::vector<double> &sig)
{
  MCAHardening &h = hardening[i];
  h = MCAHardening();
  tabulated[i] = eps.empty() ? 0 : 1;
  if (tabulated[i]) {
    h.npoints = eps.size();
    for (int k = 0; k < h.npoints; k++) {
      h.eps[k] = eps[k];
      h.sig[k] = sig[k];
    }
    h.slope_end = 0.0;
  } else if (type[i].yield > 0.0) {
    h.npoints = 1;
    h.eps[0] = 0.0;
    h.sig[0] = type[i].yield;
    h.slope_end = type[i].hardening;
  }
}

/* ----------------------------------------------------------------------
   a hardening table: the section "keyword" of a text file, as the table
   styles of LAMMPS write them

     # comments
     KEYWORD
     N n

     1 eps_p sigma_y
     ...
     n eps_p sigma_y

   with n >= 2 points, eps_p starting at 0 and increasing, sigma_y > 0 and
   not decreasing.  Read on proc 0; every error names the file and keyword
------------------------------------------------------------------------- */

void MCAMaterials::read_hardening_table(const std::string &file, const std::string &keyword,
                                        Input &in)
{
  std::string message;
  std::vector<double> eps, sig;
  if (comm->me == 0) {
    try {
      TextFileReader reader(file, "hardening table");
      char *line;
      bool found = false;
      while ((line = reader.next_line())) {
        ValueTokenizer words(line);
        if (words.count() > 0 && words.next_string() == keyword) {
          found = true;
          break;
        }
      }
      if (!found) throw FileReaderException("has no section " + keyword);
      line = reader.next_line();
      ValueTokenizer header(line ? line : "");
      if (!line || header.count() != 2 || header.next_string() != "N")
        throw FileReaderException(
            "needs the line 'N n' (the number of points, nothing else) after the keyword");
      const int n = header.next_int();
      if (n < 2 || n > MAX_HARDENING_POINTS)
        throw FileReaderException(
            fmt::format("gives N = {}; a table needs 2 to {} points", n, MAX_HARDENING_POINTS));
      for (int k = 0; k < n; k++) {
        line = reader.next_line();
        if (!line)
          throw FileReaderException(fmt::format("ends after {} of its N = {} points", k, n));
        ValueTokenizer values(line);
        if (values.count() != 3)
          throw FileReaderException(fmt::format(
              "point {} has {} values; each line is: index eps_p sigma_y", k + 1, values.count()));
        values.next_int();
        eps.push_back(values.next_double());
        sig.push_back(values.next_double());
      }
    } catch (std::exception &e) {
      message = e.what();
      if (message.empty()) message = "cannot be read";
    }
  }
  int len = message.size();
  MPI_Bcast(&len, 1, MPI_INT, 0, world);
  if (len > 0) {
    message.resize(len);
    MPI_Bcast(&message[0], len, MPI_CHAR, 0, world);
    error->all(FLERR, "Pair mca: hardening table {} {}: {}", file, keyword, message);
  }
  int n = eps.size();
  MPI_Bcast(&n, 1, MPI_INT, 0, world);
  eps.resize(n);
  sig.resize(n);
  MPI_Bcast(eps.data(), n, MPI_DOUBLE, 0, world);
  MPI_Bcast(sig.data(), n, MPI_DOUBLE, 0, world);

  if (eps[0] != 0.0)
    error->all(FLERR,
               "Pair mca: hardening table {} {}: the first point must be at eps_p = 0 (the "
               "yield stress), got eps_p = {}",
               file, keyword, eps[0]);
  for (int k = 0; k < n; k++) {
    if (!(sig[k] > 0.0) || !std::isfinite(sig[k]))
      error->all(FLERR,
                 "Pair mca: hardening table {} {}: sigma_y of point {} must be > 0 and "
                 "finite, got {}",
                 file, keyword, k + 1, sig[k]);
    if (k == 0) continue;
    if (!(eps[k] > eps[k - 1]) || !std::isfinite(eps[k]))
      error->all(FLERR,
                 "Pair mca: hardening table {} {}: eps_p must increase from point to point "
                 "(point {}: {} after {})",
                 file, keyword, k + 1, eps[k], eps[k - 1]);
    if (sig[k] < sig[k - 1])
      error->all(FLERR,
                 "Pair mca: hardening table {} {}: sigma_y must not decrease (point {}: {} "
                 "after {}); softening is not supported",
                 file, keyword, k + 1, sig[k], sig[k - 1]);
  }
  in.table_eps = eps;
  in.table_sig = sig;
}

/* ---------------------------------------------------------------------- */

bool MCAMaterials::parse(const std::string &key, const char *value, Input &in)
{
  for (int k = 0; k < NKEYWORDS; k++) {
    const Keyword &kw = KEYWORDS[k];
    if (key != kw.name) continue;
    const double v = utils::numeric(FLERR, value, false, lmp);
    const bool ok = (kw.lo_closed ? v >= kw.lo : v > kw.lo) && v < kw.hi;
    if (!ok) error->all(FLERR, "Pair mca: {} must be {}, got {}", kw.what, kw.range, v);
    check_model(error, kw, v);
    in.values.*kw.field = v;
    in.given |= 1u << k;
    return true;
  }
  return false;
}

void MCAMaterials::assign(int lo, int hi, const Input &in)
{
  unsigned required = 0;
  for (int k = 0; k < NKEYWORDS; k++)
    if (KEYWORDS[k].required) required |= 1u << k;
  if ((in.given & required) != required)
    error->all(FLERR, "Pair mca: a material needs all of {} in one pair_coeff", keyword_list(true));
  check_moduli(in.values);
  const bool table = !in.table_eps.empty();
  const unsigned yield_bit = keyword_bit(&MCAMaterial::yield);
  const unsigned hardening_bit = keyword_bit(&MCAMaterial::hardening);
  if (table && (in.given & (yield_bit | hardening_bit)))
    error->all(FLERR,
               "Pair mca: a hardening table excludes yield and a hardening modulus (the "
               "table's first point is the yield stress, its segments the hardening)");
  if (!table && (in.given & hardening_bit) && !(in.given & yield_bit))
    error->all(FLERR, "Pair mca: a hardening modulus needs a yield stress: add 'yield value'");
  MCAMaterial values = in.values;
  if (table) values.yield = in.table_sig[0];
  for (int i = lo; i <= hi; i++) {
    type[i] = values;
    derive_material(type[i]);
    set[i] = 1;
    set_curve(i, in.table_eps, in.table_sig);
  }
}

/* ----------------------------------------------------------------------
   the law forms moduli up to 3K + 4G = E (1/(1 - 2 nu) + 2/(1 + nu)) and
   squares stresses of that order (energies, the equivalent stress): a
   material whose 3K + 4G exceeds sqrt(DBL_MAX) would give inf or NaN in
   the run, so it is refused here, with the largest E allowed at its nu
------------------------------------------------------------------------- */

void MCAMaterials::check_moduli(const MCAMaterial &m) const
{
  const double factor = 1.0 / (1.0 - 2.0 * m.poisson) + 2.0 / (1.0 + m.poisson);
  const double limit = std::sqrt(std::numeric_limits<double>::max());
  if (m.youngs * factor < limit) return;
  error->all(FLERR,
             "Pair mca: Young's modulus E = {} with nu = {} is too large: the law squares "
             "stresses of the order of 3K + 4G = {:.4g} E, which must stay below sqrt(DBL_MAX) "
             "= {:.4g}; E must be < {:.4g} at this nu",
             m.youngs, m.poisson, factor, limit, limit / factor);
}

void MCAMaterials::check_all_set() const
{
  for (int i = 1; i <= ntypes; i++)
    if (!set[i])
      error->all(FLERR,
                 "Pair mca: no material (E, nu, rho) for atom type {}: use pair_coeff {} {} "
                 "E value nu value rho value",
                 i, i, i);
}

std::string MCAMaterials::keyword_list(bool required_only) const
{
  std::vector<std::string> names;
  for (const auto &kw : KEYWORDS)
    if (kw.required || !required_only) names.push_back(kw.name);
  std::string list;
  for (size_t k = 0; k < names.size(); k++) {
    if (k) list += k + 1 < names.size() ? ", " : " and ";
    list += names[k];
  }
  return list;
}

/* ----------------------------------------------------------------------
   restart files: the keyword names once, then per type its flag and the
   values in that order
------------------------------------------------------------------------- */

void MCAMaterials::write_restart(FILE *fp) const
{
  std::string names;
  for (int k = 0; k < NKEYWORDS; k++) names += std::string(k ? " " : "") + KEYWORDS[k].name;
  const int nkey = NKEYWORDS, len = names.size() + 1;
  fwrite(&nkey, sizeof(int), 1, fp);
  fwrite(&len, sizeof(int), 1, fp);
  fwrite(names.c_str(), sizeof(char), len, fp);
  for (int i = 1; i <= ntypes; i++) {
    fwrite(&set[i], sizeof(int), 1, fp);
    for (int k = 0; k < NKEYWORDS; k++)
      fwrite(&(type[i].*KEYWORDS[k].field), sizeof(double), 1, fp);
  }
  // the hardening tables: per type the number of points (0: none) and
  // the points
  for (int i = 1; i <= ntypes; i++) {
    const int n = tabulated[i] ? hardening[i].npoints : 0;
    fwrite(&n, sizeof(int), 1, fp);
    fwrite(hardening[i].eps, sizeof(double), n, fp);
    fwrite(hardening[i].sig, sizeof(double), n, fp);
  }
}

void MCAMaterials::read_restart(FILE *fp, bool with_tables)
{
  int nkey = 0, len = 0;
  if (comm->me == 0) {
    utils::sfread(FLERR, &nkey, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &len, sizeof(int), 1, fp, nullptr, error);
  }
  MPI_Bcast(&nkey, 1, MPI_INT, 0, world);
  MPI_Bcast(&len, 1, MPI_INT, 0, world);
  std::vector<char> names(len);
  if (comm->me == 0) utils::sfread(FLERR, names.data(), sizeof(char), len, fp, nullptr, error);
  MPI_Bcast(names.data(), len, MPI_CHAR, 0, world);

  // which keyword of this version each value of the file is
  std::vector<int> which;
  for (const auto &name : utils::split_words(std::string(names.data()))) {
    int found = -1;
    for (int k = 0; k < NKEYWORDS; k++)
      if (name == KEYWORDS[k].name) found = k;
    if (found < 0)
      error->all(FLERR,
                 "Restart file holds the material parameter {} of pair mca, which this "
                 "version does not know (it knows {})",
                 name, keyword_list());
    which.push_back(found);
  }
  if ((int) which.size() != nkey) error->all(FLERR, "Invalid pair mca materials in restart file");

  std::vector<double> values(nkey);
  for (int i = 1; i <= ntypes; i++) {
    if (comm->me == 0) {
      utils::sfread(FLERR, &set[i], sizeof(int), 1, fp, nullptr, error);
      utils::sfread(FLERR, values.data(), sizeof(double), nkey, fp, nullptr, error);
    }
    MPI_Bcast(&set[i], 1, MPI_INT, 0, world);
    MPI_Bcast(values.data(), nkey, MPI_DOUBLE, 0, world);
    type[i] = MCAMaterial();
    for (int v = 0; v < nkey; v++) type[i].*KEYWORDS[which[v]].field = values[v];
    if (set[i]) derive_material(type[i]);
  }
  for (int i = 1; i <= ntypes; i++) {
    int n = 0;
    if (with_tables && comm->me == 0) utils::sfread(FLERR, &n, sizeof(int), 1, fp, nullptr, error);
    MPI_Bcast(&n, 1, MPI_INT, 0, world);
    if (n < 0 || n > MAX_HARDENING_POINTS)
      error->all(FLERR, "Invalid pair mca hardening table in restart file");
    std::vector<double> eps(n), sig(n);
    if (n > 0 && comm->me == 0) {
      utils::sfread(FLERR, eps.data(), sizeof(double), n, fp, nullptr, error);
      utils::sfread(FLERR, sig.data(), sizeof(double), n, fp, nullptr, error);
    }
    MPI_Bcast(eps.data(), n, MPI_DOUBLE, 0, world);
    MPI_Bcast(sig.data(), n, MPI_DOUBLE, 0, world);
    set_curve(i, eps, sig);
  }
}

void MCAMaterials::read_restart_values(int i, const double *youngs_nu_rho, int set_flag)
{
  type[i] = MCAMaterial();
  type[i].youngs = youngs_nu_rho[0];
  type[i].poisson = youngs_nu_rho[1];
  type[i].density = youngs_nu_rho[2];
  set[i] = set_flag;
  if (set[i]) derive_material(type[i]);
}

/* ---------------------------------------------------------------------- */

double *MCAMaterials::column(const char *keyword)
{
  for (int k = 0; k < NKEYWORDS; k++) {
    if (strcmp(keyword, KEYWORDS[k].name) != 0) continue;
    columns.assign(ntypes + 1, 0.0);
    for (int i = 1; i <= ntypes; i++) columns[i] = type[i].*KEYWORDS[k].field;
    return columns.data();
  }
  return nullptr;
}
