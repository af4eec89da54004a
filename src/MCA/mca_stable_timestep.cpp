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

#include "mca_stable_timestep.h"

#include "atom.h"
#include "mca_link_passes.h"
#include "memory.h"

#include <cmath>
#include <limits>

using namespace LAMMPS_NS;
using namespace MCAKernels;

namespace {

// the Lanczos iteration stops when the residual of its largest Ritz pair
// is below this fraction of the Ritz value (an eigenvalue lies that close
// to it), or after MAX_STEPS steps
constexpr double RESIDUAL_TOL = 1.0e-4;
constexpr int MAX_STEPS = 300;
constexpr int CHECK_EVERY = 4;
// or when the Ritz value has grown by less than this fraction over the
// last STALL_CHECKS checks (in a dense spectrum the value converges long
// before the residual of its vector)
constexpr double VALUE_TOL = 1.0e-4;
constexpr std::size_t STALL_CHECKS = 3;
// the Jacobi steps for the mean stress stop at this relative change, or
// after MAX_JACOBI steps
constexpr double JACOBI_TOL = 1.0e-7;
constexpr int MAX_JACOBI = 400;

/* ----------------------------------------------------------------------
   the symmetric tridiagonal matrix T of the Lanczos steps (diagonal alpha,
   off-diagonal beta): its largest eigenvalue by bisection on the Sturm
   count, and its eigenvector by inverse iteration
------------------------------------------------------------------------- */

// the number of eigenvalues of T below x
int count_below(const std::vector<double> &alpha, const std::vector<double> &beta, int k, double x)
{
  int count = 0;
  double d = 1.0;
  for (int j = 0; j < k; j++) {
    const double b2 = (j > 0) ? beta[j - 1] * beta[j - 1] : 0.0;
    d = alpha[j] - x - ((j > 0) ? b2 / d : 0.0);
    if (d == 0.0) d = -1.0e-300;
    if (d < 0.0) count++;
  }
  return count;
}

double largest_eigenvalue(const std::vector<double> &alpha, const std::vector<double> &beta, int k)
{
  double lo = alpha[0], hi = alpha[0];
  for (int j = 0; j < k; j++) {
    const double r = ((j > 0) ? fabs(beta[j - 1]) : 0.0) + ((j < k - 1) ? fabs(beta[j]) : 0.0);
    lo = std::min(lo, alpha[j] - r);
    hi = std::max(hi, alpha[j] + r);
  }
  for (int it = 0; it < 200; it++) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    if (count_below(alpha, beta, k, mid) == k)
      hi = mid;
    else
      lo = mid;
  }
  return hi;
}

// a unit eigenvector of T for its eigenvalue theta: two steps of inverse
// iteration, solved by Gaussian elimination with partial pivoting
std::vector<double> eigenvector(const std::vector<double> &alpha, const std::vector<double> &beta,
                                int k, double theta)
{
  std::vector<double> z(k, 1.0), u0(k), u1(k), u2(k), y(k);
  const double tiny = 1.0e-300 + 1.0e-15 * fabs(theta);
  for (int pass = 0; pass < 2; pass++) {
    // the row in work: its entries in columns i, i+1, i+2
    double r0 = alpha[0] - theta, r1 = (k > 1) ? beta[0] : 0.0, r2 = 0.0, rr = z[0];
    for (int i = 0; i < k; i++) {
      if (i == k - 1) {
        u0[i] = (r0 != 0.0) ? r0 : tiny;
        u1[i] = u2[i] = 0.0;
        y[i] = rr;
        break;
      }
      double s0 = beta[i], s1 = alpha[i + 1] - theta, s2 = (i + 1 < k - 1) ? beta[i + 1] : 0.0;
      double rs = z[i + 1];
      if (fabs(r0) < fabs(s0)) {
        std::swap(r0, s0);
        std::swap(r1, s1);
        std::swap(r2, s2);
        std::swap(rr, rs);
      }
      if (r0 == 0.0) r0 = tiny;
      const double f = s0 / r0;
      u0[i] = r0;
      u1[i] = r1;
      u2[i] = r2;
      y[i] = rr;
      r0 = s1 - f * r1;
      r1 = s2 - f * r2;
      r2 = 0.0;
      rr = rs - f * rr;
    }
    for (int i = k - 1; i >= 0; i--) {
      double v = y[i];
      if (i + 1 < k) v -= u1[i] * z[i + 1];
      if (i + 2 < k) v -= u2[i] * z[i + 2];
      z[i] = v / u0[i];
    }
    double norm = 0.0;
    for (double v : z) norm += v * v;
    norm = sqrt(norm);
    for (double &v : z) v /= norm;
  }
  return z;
}

}    // namespace

/* ---------------------------------------------------------------------- */

MCAStableTimestep::MCAStableTimestep(LAMMPS *lmp) :
    Pointers(lmp), stage(STAGE_SETUP), nmax(0), finv(nullptr), hpred(nullptr), predicted(nullptr),
    motion(nullptr), sums(nullptr)
{
}

MCAStableTimestep::~MCAStableTimestep()
{
  memory->destroy(finv);
  memory->destroy(hpred);
  memory->destroy(predicted);
  memory->destroy(motion);
  memory->destroy(sums);
}

void MCAStableTimestep::grow(int n)
{
  if (n <= nmax) return;
  nmax = n;
  memory->destroy(finv);
  memory->destroy(hpred);
  memory->destroy(predicted);
  memory->destroy(motion);
  memory->destroy(sums);
  memory->create(finv, 6 * nmax, "mca/timestep:finv");
  memory->create(hpred, nmax, "mca/timestep:hpred");
  memory->create(predicted, nmax, "mca/timestep:predicted");
  memory->create(motion, 6 * nmax, "mca/timestep:motion");
  memory->create(sums, 2 * nmax, "mca/timestep:sums");
}

void MCAStableTimestep::release()
{
  memory->destroy(finv);
  memory->destroy(hpred);
  memory->destroy(predicted);
  memory->destroy(motion);
  memory->destroy(sums);
  nmax = 0;
  for (auto *v : {&rhs_fwd, &rhs_tr, &diag, &next}) std::vector<double>().swap(*v);
  std::vector<JacobiEntry>().swap(jacobi);
}

/* ----------------------------------------------------------------------
   what every automaton's links need of it, sent to the ghosts: its
   inverse fabric tensor (over linked and broken pairs, as the predictor
   takes it; zero where its mean stress is not predicted) and its
   predictor stiffness
------------------------------------------------------------------------- */

void MCAStableTimestep::prepare(const Input &in, Comm *comm)
{
  grow(atom->nmax);
  const MCAHostLinks &d = in.links;
  const int nlocal = d.nlocal;
  for (int i = 0; i < nlocal; i++) {
    double fab[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    int nlinked = 0;
    double work[MAX_ROW_SIZE];
    for (int m = 0; m < d.nlinks(i); m++) {
      const double *row = read_row(d.layout, d.history_row(i, m), work);
      if (linked(row)) nlinked++;
      if (linked(row) || broken(row)) fabric_add(fab, row + H_NPREV);
    }
    const MCAMaterial &mat = in.material[in.type[i]];
    const int nc = in.packing[i];
    hpred[i] = (nc > 0) ? predictor_stiffness(mat.shear, mat.bulk, nc, nlinked) : 0.0;
    predicted[i] = (nlinked > 0 && nc != PACKING_NONE) ? 1.0 : 0.0;
    if (predicted[i] > 0.0)
      fabric_inverse(fab, finv_of(i));
    else
      for (int k = 0; k < 6; k++) finv_of(i)[k] = 0.0;
  }
  stage = STAGE_SETUP;
  comm->estimate_forward_comm();
  cache_jacobi_weights(in);
}

int MCAStableTimestep::pack_forward_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int ii = 0; ii < n; ii++) {
    const int i = list[ii];
    if (stage == STAGE_SETUP) {
      for (int k = 0; k < 6; k++) buf[m++] = finv_of(i)[k];
      buf[m++] = hpred[i];
    } else if (stage == STAGE_MOTION) {
      for (int k = 0; k < 6; k++) buf[m++] = motion_of(i)[k];
    } else {
      buf[m++] = sums_of(i)[0];
      buf[m++] = sums_of(i)[1];
    }
  }
  return m;
}

void MCAStableTimestep::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++) {
    if (stage == STAGE_SETUP) {
      for (int k = 0; k < 6; k++) finv_of(i)[k] = buf[m++];
      hpred[i] = buf[m++];
      predicted[i] = (finv_of(i)[0] + finv_of(i)[1] + finv_of(i)[2] > 0.0) ? 1.0 : 0.0;
    } else if (stage == STAGE_MOTION) {
      for (int k = 0; k < 6; k++) motion_of(i)[k] = buf[m++];
    } else {
      sums_of(i)[0] = buf[m++];
      sums_of(i)[1] = buf[m++];
    }
  }
}

/* ---------------------------------------------------------------------- */

inline void MCAStableTimestep::tangent_of(const Input &in, int i, int m, int &j,
                                          MCALinkTangent &t) const
{
  const MCAHostLinks &d = in.links;
  j = d.partner(i, m);
  double work[MAX_ROW_SIZE];
  const double *row = read_row(d.layout, d.history_row(i, m), work);
  const bool ilo = d.tag(i) < d.tag(j);
  const double chi = face_moment_factor(in.packing[ilo ? i : j]);
  link_tangent(row, ilo, in.material[in.type[i]], in.material[in.type[j]], chi, predicted[i] > 0.0,
               predicted[j] > 0.0, finv_of(i), finv_of(j), hpred[i], hpred[j], in.damping,
               in.friction, t);
}

double MCAStableTimestep::link_weight(int nlocal, int j)
{
  return (j >= nlocal) ? 0.5 : 1.0;
}

/* ----------------------------------------------------------------------
   the weights of the Jacobi steps (the inverse fabric tensors and
   predictor stiffnesses of the ghosts are known): an entry at each row of
   the pool, made by the end that evaluates its link (the rows of the pool
   are shared, FixMCALinks::share_rows)
------------------------------------------------------------------------- */

void MCAStableTimestep::cache_jacobi_weights(const Input &in)
{
  const MCAHostLinks &d = in.links;
  jacobi.assign(d.nrows, JacobiEntry{0.0f, 0.0f});
  MCALinkTangent t;
  int j;
  for (int i = 0; i < d.nlocal; i++)
    for (int m = 0; m < d.nlinks(i); m++) {
      if (partner_evaluates(d, i, d.partner(i, m))) continue;
      tangent_of(in, i, m, j, t);
      if (!t.linked) continue;
      // the weights of the partner's mean stress: gamma_i a_j / (A K_j) in
      // the row of i, gamma_j a_i / (A K_i) in the transposed system
      double fn[3];
      fabric_times(finv_of(i), t.n, fn);
      const double gamma_i = dot3(fn, t.n) / 3.0;
      fabric_times(finv_of(j), t.n, fn);
      const double gamma_j = dot3(fn, t.n) / 3.0;
      JacobiEntry &w = jacobi[d.slot(i, m)];
      w.fwd = gamma_i * t.a_j / (t.area * in.material[in.type[j]].bulk);
      w.tr = gamma_j * t.a_i / (t.area * in.material[in.type[i]].bulk);
    }
}

template <class F> void MCAStableTimestep::for_each_acting(const Input &in, F f) const
{
  const MCAHostLinks &d = in.links;
  MCALinkTangent t;
  int j;
  for (int i = 0; i < d.nlocal; i++)
    for (int m = 0; m < d.nlinks(i); m++) {
      if (partner_evaluates(d, i, d.partner(i, m))) continue;
      tangent_of(in, i, m, j, t);
      if (t.linked || t.kn != 0.0) f(i, j, t);
    }
}

inline void MCAStableTimestep::jacobi_weights(const MCAHostLinks &d, int i, int m, double &fwd,
                                              double &tr) const
{
  const JacobiEntry &e = jacobi[d.slot(i, m)];
  const bool swapped = partner_evaluates(d, i, d.partner(i, m));
  fwd = swapped ? e.tr : e.fwd;
  tr = swapped ? e.fwd : e.tr;
}

double MCAStableTimestep::dot(const std::vector<double> &a, const std::vector<double> &b) const
{
  double local = 0.0, all = 0.0;
  for (std::size_t k = 0; k < a.size(); k++) local += a[k] * b[k];
  MPI_Allreduce(&local, &all, 1, MPI_DOUBLE, MPI_SUM, world);
  return all;
}

void MCAStableTimestep::set_motion(const Input &in, Comm *comm, const double *x)
{
  for (int i = 0; i < in.links.nlocal; i++) {
    const double sm = sqrt(in.rmass[i]), sj = sqrt(in.inertia[i]);
    for (int k = 0; k < 3; k++) {
      motion_of(i)[k] = x[6 * i + k] / sm;
      motion_of(i)[3 + k] = x[6 * i + 3 + k] / sj;
    }
  }
  stage = STAGE_MOTION;
  comm->estimate_forward_comm();
}

/* ----------------------------------------------------------------------
   y = M^-1/2 K_s M^-1/2 x, K_s the symmetric part of the stiffness the
   automata meet in a motion that alternates from step to step (see
   mca_stability.h):
     K u = K_pair u + S_a^T K^-1 sm,   (I + D W) sm = R u = 2 K S u - Q u
   with S u (s) and S_a u (r) the two mean-stress sums of each automaton,
   Q u the part of the mean stress of its tractions that the link
   stretches and slips give, and W the weights of the automaton's own and
   its partners' mean stress in it; so
     K_s u = K_pair u + (S_a^T p + R^T y) / 2,
     p = K^-1 (I + D W)^-1 R u,   y = (I + D W)^-T K^-1 S_a u.
   The two systems are solved together by Jacobi steps (the diagonal of
   I + D W holds 1 + D/2 or so, the rest at most |D|/2), each with one
   forward communication; each automaton then takes all its links (no
   reverse communication)
------------------------------------------------------------------------- */

void MCAStableTimestep::apply(const Input &in, Comm *comm, const double *x, double keep, double *y)
{
  const MCAHostLinks &d = in.links;
  const int nlocal = d.nlocal;
  set_motion(in, comm, x);
  rhs_fwd.resize(nlocal);
  rhs_tr.resize(nlocal);
  diag.resize(nlocal);

  // the right-hand sides and the diagonal: the sums s, r and w of each
  // automaton in rhs_fwd, rhs_tr and diag, q in next
  next.resize(2 * static_cast<std::size_t>(nlocal));
  for (int i = 0; i < nlocal; i++) rhs_fwd[i] = rhs_tr[i] = diag[i] = next[2 * i] = 0.0;
  auto add_sums = [&](int i, int j, const MCALinkTangent &t) {
    if (!(predicted[i] > 0.0)) return;
    double dr, slip[3], fn[3];
    tangent_motion(t, motion_of(i), motion_of(i) + 3, motion_of(j), motion_of(j) + 3, dr, slip);
    fabric_times(finv_of(i), t.n, fn);
    const double gamma = dot3(fn, t.n) / 3.0;
    rhs_fwd[i] += t.beta_i * dr;
    rhs_tr[i] += t.a_i * dr;
    next[2 * i] += gamma * dr * t.inv_cn + dot3(slip, fn) * t.inv_ct / 3.0;
    // (the weight of i's own mean stress: gamma a_i / (A K_i) = gamma w_i D_i)
    diag[i] += gamma * t.a_i * t.inv_cn / (in.material[in.type[i]].bulk * t.kn);
  };
  for_each_acting(in, [&](int i, int j, MCALinkTangent &t) {
    if (!t.linked) return;
    add_sums(i, j, t);
    if (j >= nlocal) return;
    swap_sides(t);
    add_sums(j, i, t);
  });
  bool filter = false;
  for (int i = 0; i < nlocal; i++) {
    const double bulk = in.material[in.type[i]].bulk;
    const double w = diag[i];
    rhs_fwd[i] = 2.0 * bulk * rhs_fwd[i] - next[2 * i];
    rhs_tr[i] = rhs_tr[i] / bulk;
    diag[i] = 1.0 + w;
    if (w != 0.0) filter = true;
  }
  for (int i = 0; i < nlocal; i++) {
    sums_of(i)[0] = rhs_fwd[i] / diag[i];
    sums_of(i)[1] = rhs_tr[i] / diag[i];
  }

  // Jacobi steps on both systems (none if no automaton has D != 0)
  int any = filter ? 1 : 0, any_all = 0;
  MPI_Allreduce(&any, &any_all, 1, MPI_INT, MPI_MAX, world);
  for (int it = 0; any_all && it < MAX_JACOBI; it++) {
    stage = STAGE_SUMS;
    comm->estimate_forward_comm();
    double change = 0.0, size = 0.0;
    for (int i = 0; i < nlocal; i++) {
      double off_f = 0.0, off_t = 0.0;
      for (int m = 0; m < d.nlinks(i); m++) {
        const int j = d.partner(i, m);
        double w_fwd, w_tr;
        jacobi_weights(d, i, m, w_fwd, w_tr);
        off_f += w_fwd * sums_of(j)[0];
        off_t += w_tr * sums_of(j)[1];
      }
      next[2 * i] = (rhs_fwd[i] - off_f) / diag[i];
      next[2 * i + 1] = (rhs_tr[i] - off_t) / diag[i];
      change = std::max(
          change,
          std::max(fabs(next[2 * i] - sums_of(i)[0]), fabs(next[2 * i + 1] - sums_of(i)[1])));
      size = std::max(size, std::max(fabs(next[2 * i]), fabs(next[2 * i + 1])));
    }
    for (int i = 0; i < nlocal; i++) {
      sums_of(i)[0] = next[2 * i];
      sums_of(i)[1] = next[2 * i + 1];
    }
    double local[2] = {change, size}, all[2];
    MPI_Allreduce(local, all, 2, MPI_DOUBLE, MPI_MAX, world);
    if (all[0] <= JACOBI_TOL * all[1]) break;
  }
  // p = sm / K
  for (int i = 0; i < nlocal; i++) sums_of(i)[0] /= in.material[in.type[i]].bulk;
  stage = STAGE_SUMS;
  comm->estimate_forward_comm();

  // the forces and torques of the links (each once, from the end that
  // evaluates it, for both its local ends), summed in y on top of keep y
  // in units of force: y = -(keep M^1/2 y + f) / M^1/2
  for (int i = 0; i < nlocal; i++) {
    const double sm = sqrt(in.rmass[i]), sj = sqrt(in.inertia[i]);
    for (int k = 0; k < 3; k++) {
      y[6 * i + k] *= keep * sm;
      y[6 * i + 3 + k] *= keep * sj;
    }
  }
  auto add_force = [&](int i, int j, const MCALinkTangent &t) {
    double *fi = y + 6 * i;
    double tension_ms = 0.0, fl[3], tql[3];
    if (t.linked) {
      tension_ms = 0.5 * (t.a_i * sums_of(i)[0] + t.a_j * sums_of(j)[0]);
      // R^T y: the tension 2 K beta - gamma / c_n and the force across
      // -(1/3) (y_i F_i^-1 n + y_j F_j^-1 n) / c_t of each end
      double fn_i[3], fn_j[3], tau[3];
      fabric_times(finv_of(i), t.n, fn_i);
      fabric_times(finv_of(j), t.n, fn_j);
      const double yi = (predicted[i] > 0.0) ? sums_of(i)[1] : 0.0;
      const double yj = (predicted[j] > 0.0) ? sums_of(j)[1] : 0.0;
      const double tension_r =
          yi * (2.0 * in.material[in.type[i]].bulk * t.beta_i - dot3(fn_i, t.n) / 3.0 * t.inv_cn) +
          yj * (2.0 * in.material[in.type[j]].bulk * t.beta_j - dot3(fn_j, t.n) / 3.0 * t.inv_cn);
      for (int c = 0; c < 3; c++) tau[c] = -0.5 * t.inv_ct / 3.0 * (yi * fn_i[c] + yj * fn_j[c]);
      tangent_load(t, 0.5 * tension_r, tau, fl, tql);
      for (int c = 0; c < 3; c++) {
        fi[c] += fl[c];
        fi[3 + c] += tql[c];
      }
    }
    tangent_force(t, motion_of(i), motion_of(i) + 3, motion_of(j), motion_of(j) + 3, tension_ms, fl,
                  tql);
    for (int c = 0; c < 3; c++) {
      fi[c] += fl[c];
      fi[3 + c] += tql[c];
    }
  };
  for_each_acting(in, [&](int i, int j, MCALinkTangent &t) {
    add_force(i, j, t);
    if (j >= nlocal) return;
    swap_sides(t);
    add_force(j, i, t);
  });
  for (int i = 0; i < nlocal; i++) {
    const double sm = sqrt(in.rmass[i]), sj = sqrt(in.inertia[i]);
    for (int k = 0; k < 3; k++) {
      y[6 * i + k] = -y[6 * i + k] / sm;
      y[6 * i + 3 + k] = -y[6 * i + 3 + k] / sj;
    }
  }
}

/* ---------------------------------------------------------------------- */

MCAStableTimestep::Monitor MCAStableTimestep::monitor(const Input &in)
{
  grow(atom->nmax);
  const MCAHostLinks &d = in.links;
  // the mean-stress weights do not enter the trace
  for (int i = 0; i < atom->nmax; i++) predicted[i] = 0.0;
  std::vector<double> trace(d.nlocal, 0.0);
  double largest[NMONITOR + 1] = {0.0, 0.0, 0.0, 0.0, 0.0};
  auto meet = [&](const MCALinkTangent &t, int i) {
    const double m = in.rmass[i], jn = in.inertia[i];
    const double values[NMONITOR] = {t.kn / m, t.kt / m, t.kt * t.q_i * t.q_i / jn, t.kb / jn};
    for (int c = 0; c < NMONITOR; c++) largest[c] = std::max(largest[c], values[c]);
    return tangent_trace(t, m, jn);
  };
  // each link's tangent once, by the end that evaluates it; a local
  // partner meets it with the sides exchanged (swap_sides: every value is
  // symmetric in the sides, so that is what its own view of the row gives,
  // bit for bit).  Each end's part of its trace waits at the link's row
  // (the end that evaluates, then the partner) and is added in the order
  // of the end's links
  std::vector<double> row_trace(2 * static_cast<std::size_t>(d.nrows));
  MCALinkTangent t;
  int j;
  for (int i = 0; i < d.nlocal; i++)
    for (int k = 0; k < d.nlinks(i); k++) {
      if (partner_evaluates(d, i, d.partner(i, k))) continue;
      tangent_of(in, i, k, j, t);
      const int s = d.slot(i, k);
      row_trace[2 * s] = meet(t, i);
      if (j >= d.nlocal) continue;
      swap_sides(t);
      row_trace[2 * s + 1] = meet(t, j);
    }
  for (int i = 0; i < d.nlocal; i++) {
    for (int k = 0; k < d.nlinks(i); k++)
      trace[i] += row_trace[2 * d.slot(i, k) + (partner_evaluates(d, i, d.partner(i, k)) ? 1 : 0)];
    largest[NMONITOR] = std::max(largest[NMONITOR], trace[i]);
  }
  double all_largest[NMONITOR + 1];
  MPI_Allreduce(largest, all_largest, NMONITOR + 1, MPI_DOUBLE, MPI_MAX, world);
  Monitor mon;
  for (int c = 0; c < NMONITOR; c++) mon.value[c] = all_largest[c];

  // the automaton of the largest trace (the lowest ID among those within
  // round-off of it), its type and its stiffest link
  const double near = (1.0 - 1.0e-9) * all_largest[NMONITOR];
  tagint best = MAXTAGINT;
  for (int i = 0; i < d.nlocal; i++)
    if (trace[i] >= near) best = std::min(best, d.tag(i));
  MPI_Allreduce(&best, &mon.atom, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  int type = 0;
  tagint partner = 0;
  for (int i = 0; i < d.nlocal; i++) {
    if (d.tag(i) != mon.atom) continue;
    type = in.type[i];
    double stiffest = -1.0;
    for (int m = 0; m < d.nlinks(i); m++) {
      tangent_of(in, i, m, j, t);
      const double k = tangent_trace(t, in.rmass[i], in.inertia[i]);
      if (k > (1.0 + 1.0e-9) * stiffest || (k >= (1.0 - 1.0e-9) * stiffest && d.tag(j) < partner)) {
        stiffest = std::max(stiffest, k);
        partner = d.tag(j);
      }
    }
  }
  tagint found[2] = {static_cast<tagint>(type), partner}, all[2];
  MPI_Allreduce(found, all, 2, MPI_LMP_TAGINT, MPI_MAX, world);
  mon.atom_type = static_cast<int>(all[0]);
  mon.link_i = std::min(mon.atom, all[1]);
  mon.link_j = std::max(mon.atom, all[1]);
  release();
  return mon;
}

/* ----------------------------------------------------------------------
   the estimate: Lanczos on A = M^-1/2 K_s M^-1/2 from a start vector that
   depends only on the IDs of the automata, until its largest Ritz value
   has converged; the same steps again to build the Ritz vector (the mode)
------------------------------------------------------------------------- */

MCAStableTimestep::Result MCAStableTimestep::estimate(const Input &in, Comm *comm)
{
  const Result res = lanczos_estimate(in, comm);
  release();
  return res;
}

MCAStableTimestep::Result MCAStableTimestep::lanczos_estimate(const Input &in, Comm *comm)
{
  Result res;
  res.dt = std::numeric_limits<double>::infinity();
  res.omega = res.zeta = 0.0;
  res.iterations = 0;

  prepare(in, comm);
  const MCAHostLinks &d = in.links;
  const int nlocal = d.nlocal;

  // the links that act
  double acting_sum = 0.0;
  for_each_acting(in, [&](int, int j, const MCALinkTangent &) {
    acting_sum += link_weight(nlocal, j);
  });
  double acting_all = 0.0;
  MPI_Allreduce(&acting_sum, &acting_all, 1, MPI_DOUBLE, MPI_SUM, world);
  res.nlinks = static_cast<bigint>(acting_all + 0.5);
  if (res.nlinks == 0) return res;

  const std::size_t n = 6 * static_cast<std::size_t>(nlocal);
  // the Lanczos steps; with z given, the sum of z_k v_k over its steps.
  // Two vectors (Paige's form): v, and w, which holds v_old until A v -
  // beta v_old replaces it, then the next v until the two are swapped
  std::vector<double> alpha, beta, history;
  auto lanczos = [&](int steps, const std::vector<double> *z, std::vector<double> *ritz) {
    std::vector<double> v(n), w(n, 0.0);
    start_vector(in, v);
    double beta_old = 0.0, theta = 0.0;
    int k = 0;
    auto next_vector = [&](double b) {
      for (std::size_t q = 0; q < n; q++) w[q] /= b;
      std::swap(v, w);
      beta_old = b;
    };
    while (k < steps) {
      if (z)
        for (std::size_t q = 0; q < n; q++) (*ritz)[q] += (*z)[k] * v[q];
      apply(in, comm, v.data(), beta_old, w.data());
      const double a = dot(v, w);
      for (std::size_t q = 0; q < n; q++) w[q] -= a * v[q];
      const double b = sqrt(dot(w, w));
      k++;
      if (z) {
        if (k < steps) next_vector(b);
        continue;
      }
      alpha.push_back(a);
      beta.push_back(b);
      const bool last = (k == steps) || !(b > 1.0e-13 * fabs(alpha[0]) + 1.0e-300);
      if (last || k % CHECK_EVERY == 0) {
        theta = largest_eigenvalue(alpha, beta, k);
        history.push_back(theta);
        const std::vector<double> y = eigenvector(alpha, beta, k, theta);
        const std::size_t h = history.size();
        const bool settled =
            h > STALL_CHECKS && theta - history[h - 1 - STALL_CHECKS] <= VALUE_TOL * theta;
        if (last || settled || b * fabs(y[k - 1]) <= RESIDUAL_TOL * theta) break;
      }
      next_vector(b);
    }
    return k;
  };

  const int steps = lanczos(MAX_STEPS, nullptr, nullptr);
  const double theta = largest_eigenvalue(alpha, beta, steps);
  res.iterations = steps;
  res.omega = sqrt(std::max(theta, 0.0));
  // with damping, the mode (the same steps again) for its damping ratio
  if (in.damping) {
    const std::vector<double> z = eigenvector(alpha, beta, steps, theta);
    std::vector<double> mode(n, 0.0);
    lanczos(steps, &z, &mode);
    const double mnorm = sqrt(dot(mode, mode));
    if (mnorm > 0.0)
      for (double &v : mode) v /= mnorm;
    res.zeta = damping_ratio(in, comm, mode, res.omega);
  }
  res.dt = (res.omega > 0.0) ? critical_timestep(res.omega, res.zeta)
                             : std::numeric_limits<double>::infinity();
  return res;
}

/* ----------------------------------------------------------------------
   random components (from the IDs), plus the same spin of every automaton
   with as much weight: the fastest mode of a packing is often a spin that
   alternates from step to step and varies slowly across it.  Made again
   for each pass of the Lanczos steps (one vector less to keep)
------------------------------------------------------------------------- */

void MCAStableTimestep::start_vector(const Input &in, std::vector<double> &v) const
{
  const MCAHostLinks &d = in.links;
  double spin_local = 0.0, spin_all = 0.0;
  for (int i = 0; i < d.nlocal; i++)
    for (int k = 0; k < 6; k++) {
      v[6 * i + k] = start_component(d.tag(i), k);
      const double spin = (k >= 3) ? sqrt(in.inertia[i]) : 0.0;
      spin_local += spin * spin;
    }
  MPI_Allreduce(&spin_local, &spin_all, 1, MPI_DOUBLE, MPI_SUM, world);
  const double random_norm = sqrt(dot(v, v)), spin_norm = sqrt(spin_all);
  for (int i = 0; i < d.nlocal; i++)
    for (int k = 0; k < 6; k++) {
      const double spin = (k >= 3) ? sqrt(in.inertia[i]) : 0.0;
      v[6 * i + k] = v[6 * i + k] / random_norm + spin / spin_norm;
    }
  const double norm = sqrt(dot(v, v));
  for (double &c : v) c /= norm;
}

/* ----------------------------------------------------------------------
   the damping ratio of a mode x (a unit vector of M^1/2 u):
   u^T C u / u^T M u = 2 zeta omega, C the dashpots of the links
------------------------------------------------------------------------- */

double MCAStableTimestep::damping_ratio(const Input &in, Comm *comm, const std::vector<double> &x,
                                        double omega)
{
  set_motion(in, comm, x.data());
  const MCAHostLinks &d = in.links;
  double damping = 0.0, all = 0.0;
  for_each_acting(in, [&](int i, int j, const MCALinkTangent &t) {
    double energy, dissipation;
    tangent_energy(t, motion_of(i), motion_of(i) + 3, motion_of(j), motion_of(j) + 3, energy,
                   dissipation);
    damping += link_weight(d.nlocal, j) * dissipation;
  });
  MPI_Allreduce(&damping, &all, 1, MPI_DOUBLE, MPI_SUM, world);
  return omega > 0.0 ? all / (2.0 * omega) : 0.0;
}
