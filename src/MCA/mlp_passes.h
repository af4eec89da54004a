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

/* ----------------------------------------------------------------------
   The passes of pair_style mlp over the full neighbour list of one local
   atom, written once for the CPU style (a loop over the local atoms) and
   mlp/kk (one kernel call per atom), as mca_link_passes.h does for pair
   mca.  A pass is a template over the atoms and the list A:
     a.x(i, k), a.type(i), a.coeff(index) (MLPCoeff of the pair types,
     row-major with a.ntypes1 columns), a.numneigh(i), a.neighbors(i, jj)
     (with the special bits), a.special_lj[4], a.return_style,
     a.half_turn(i, 0 or 1) (with FRAME: cos and sin of half the body
     angle), a.mass_of(i) (the stable time step's bound)
   Each atom sums its own share of its pairs: no atomic additions, and the
   sums in the order of the list on every build.
------------------------------------------------------------------------- */

#ifndef LMP_MLP_PASSES_H
#define LMP_MLP_PASSES_H

#include "lmptype.h"
#include "mlp_kernels.h"

namespace LAMMPS_NS {
namespace MLPKernels {

  // what an atom's pairs give it: the force, its return-force part, and
  // the atom's half of each pair's energy and virial (Pair::ev_tally_xyz_full)
  struct MLPAtomSums {
    double fx, fy, rx, ry;
    double energy;
    double v[6];
  };

  template <int FRAME, class A> MCA_FUNCTION MLPAtomSums atom_forces(const A &a, int i)
  {
    MLPAtomSums s = {0.0, 0.0, 0.0, 0.0, 0.0, {0.0, 0.0, 0.0, 0.0, 0.0, 0.0}};
    const double xi = a.x(i, 0), yi = a.x(i, 1);
    const int row = a.type(i) * a.ntypes1;
    const int jnum = a.numneigh(i);
    for (int jj = 0; jj < jnum; jj++) {
      int j = a.neighbors(i, jj);
      const double factor = a.special_lj[(j >> SBBITS) & 3];
      j &= NEIGHMASK;
      const double dx = xi - a.x(j, 0), dy = yi - a.x(j, 1);
      const double rsq = dx * dx + dy * dy;
      const MLPCoeff &p = a.coeff(row + a.type(j));
      if (rsq >= p.cutsq) continue;
      MLPPairForce out;
      if (FRAME) {
        double cos_nt, sin_nt;
        turned_axes(p, a.half_turn(i, 0), a.half_turn(i, 1), a.half_turn(j, 0), a.half_turn(j, 1),
                    cos_nt, sin_nt);
        out = pair_force(p, a.return_style, dx, dy, rsq, factor, cos_nt, sin_nt);
      } else {
        out = pair_force(p, a.return_style, dx, dy, rsq, factor);
      }
      s.fx += out.fx;
      s.fy += out.fy;
      s.rx += out.rx;
      s.ry += out.ry;
      s.energy += 0.5 * out.energy;
      s.v[0] += 0.5 * dx * out.fx;
      s.v[1] += 0.5 * dy * out.fy;
      s.v[3] += 0.5 * dx * out.fy;
    }
    return s;
  }

  // the stable time step: the Gershgorin bound of omega^2 from atom i's
  // rows of M^-1/2 K M^-1/2 (pairs: the pairs it counted, added to)
  template <int FRAME, class A>
  MCA_FUNCTION double atom_row_bound(const A &a, int i, LAMMPS_NS::bigint &pairs)
  {
    const int row = a.type(i) * a.ntypes1;
    MLPRowSums sums;
    gershgorin_clear(sums);
    const int jnum = a.numneigh(i);
    for (int jj = 0; jj < jnum; jj++) {
      int j = a.neighbors(i, jj);
      const double factor = a.special_lj[(j >> SBBITS) & 3];
      j &= NEIGHMASK;
      const double dx = a.x(i, 0) - a.x(j, 0), dy = a.x(i, 1) - a.x(j, 1);
      const double rsq = dx * dx + dy * dy;
      const MLPCoeff &p = a.coeff(row + a.type(j));
      if (rsq >= p.cutsq || factor == 0.0) continue;
      double cos_nt = p.cos_nt0, sin_nt = p.sin_nt0, jac[4];
      if (FRAME)
        turned_axes(p, a.half_turn(i, 0), a.half_turn(i, 1), a.half_turn(j, 0), a.half_turn(j, 1),
                    cos_nt, sin_nt);
      pair_jacobian(p, a.return_style, dx, dy, rsq, factor, cos_nt, sin_nt, jac);
      gershgorin_add(jac, 1.0 / sqrt(a.mass_of(j)), sums);
      pairs++;
    }
    return gershgorin_bound(sums, a.mass_of(i));
  }

}    // namespace MLPKernels
}    // namespace LAMMPS_NS

#endif
