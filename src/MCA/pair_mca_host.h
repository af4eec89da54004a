/* -*- c++ -*- ----------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   LAMMPS development team: developers@lammps.org

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_MCA_HOST_H
#define LMP_PAIR_MCA_HOST_H

#include "mca_link_passes.h"
#include "pair_mca.h"

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   what the passes of mca_link_passes.h read and write on the host
------------------------------------------------------------------------- */

struct PairMCA::HostData : MCAHostLinks {
  double **x_, **omega_, **f_, **torque_;
  const int *type_, *packing_;
  const MCAKernels::MCAMaterial *material_;
  double *pred_stiffness_, *dsmean_, *smean_pred_;
  int *link_count_;
  double **fabric_, **stress_;
  double *smean_, *seq_, *eeq_;
  // plasticity
  const MCAKernels::MCAHardening *hardening_;
  double *epsp_, *volume_, *return_scale_, *return_smean_;
  // fracture: rules by type pair (row stride ntypes + 1), damage
  const MCAKernels::MCABreakRule *break_rules_;
  int break_stride;
  // contacts: rules by type pair (the same stride)
  const MCAKernels::MCAContactRule *contact_rules_;
  double *damage_;

  double x(int i, int k) const { return x_[i][k]; }
  const double *x_row(int i, double *) const { return x_[i]; }
  const double *omega_row(int i, double *) const { return omega_[i]; }
  double &f(int i, int k) const { return f_[i][k]; }
  double &torque(int i, int k) const { return torque_[i][k]; }
  int type(int i) const { return type_[i]; }
  int packing(int i) const { return packing_[i]; }
  const MCAKernels::MCAMaterial &material(int t) const { return material_[t]; }
  double &pred_stiffness(int i) const { return pred_stiffness_[i]; }
  double &dsmean(int i) const { return dsmean_[i]; }
  double &smean_pred(int i) const { return smean_pred_[i]; }
  int &link_count(int i) const { return link_count_[i]; }
  double &fabric(int i, int k) const { return fabric_[i][k]; }
  double &stress(int i, int k) const { return stress_[i][k]; }
  double &smean(int i) const { return smean_[i]; }
  double &seq(int i) const { return seq_[i]; }
  double &eeq(int i) const { return eeq_[i]; }
  const MCAKernels::MCAHardening &hardening(int t) const { return hardening_[t]; }
  double &epsp(int i) const { return epsp_[i]; }
  double volume(int i) const { return volume_[i]; }
  double &return_scale(int i) const { return return_scale_[i]; }
  double &return_smean(int i) const { return return_smean_[i]; }
  const MCAKernels::MCAContactRule &contact_rule(int ti, int tj) const
  {
    return contact_rules_[ti * break_stride + tj];
  }
  const MCAKernels::MCABreakRule &break_rule(int ti, int tj) const
  {
    return break_rules_[ti * break_stride + tj];
  }
  double &damage(int i) const { return damage_[i]; }
};

// per-automaton sums in plain arrays (predictor: PS_* columns), added in
// the loop order
struct PairMCA::HostSums {
  double **sums;
  typedef int Thread;
  Thread begin(int) const { return 0; }
  void own(Thread &, int i, int k, double value) const { sums[i][k] += value; }
  int partner_of(Thread &, int j) const { return j; }
  void partner(Thread &, int j, int k, double value) const { sums[j][k] += value; }
};

// the link pass's force and torque straight into LAMMPS's f and torque,
// its B (LS_BMAT columns) into an array of 9: no second pass over the
// forces.  The passes add with constant columns, so the choice folds away
struct PairMCA::HostLinkSums {
  double **f, **torque, **bmat;
  typedef int Thread;
  Thread begin(int) const { return 0; }
  double &at(int i, int k) const
  {
    using namespace MCAKernels;
    if (k < LS_TORQUE) return f[i][k - LS_FORCE];
    if (k < LS_BMAT) return torque[i][k - LS_TORQUE];
    return bmat[i][k - LS_BMAT];
  }
  void own(Thread &, int i, int k, double value) const { at(i, k) += value; }
  int partner_of(Thread &, int j) const { return j; }
  void partner(Thread &, int j, int k, double value) const { at(j, k) += value; }
};

// energy and virial of a link through Pair::ev_tally_xyz: the whole pair
// (both automata local) or this owner's half of it
struct PairMCA::HostTally {
  PairMCA *pair;
  bool evflag;
  bool wanted() const { return evflag; }
  template <class Totals>
  void link(Totals &, const HostData &d, int i, int j, bool jlocal, double sign, double work,
            const double *fpair) const
  {
    const double delx = d.x(i, 0) - d.x(j, 0), dely = d.x(i, 1) - d.x(j, 1),
                 delz = d.x(i, 2) - d.x(j, 2);
    const double share = jlocal ? 1.0 : 0.5;
    pair->ev_tally_xyz(i, jlocal ? j : i, d.nlocal, 0, share * work, 0.0, share * sign * fpair[0],
                       share * sign * fpair[1], share * sign * fpair[2], delx, dely, delz);
  }
};

struct MCAHostTotals {
  bigint nlong = 0;
  int nhealed = 0;    // contacts that became links (healing weld)
};

}    // namespace LAMMPS_NS

#endif
