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

#ifdef FIX_CLASS
// clang-format off
FixStyle(beam/freeze,FixBeamFreeze);
// clang-format on
#else

#ifndef LMP_FIX_BEAM_FREEZE_H
#define LMP_FIX_BEAM_FREEZE_H

#include "fix.h"

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   fix beam/freeze: new beams between particles that come close (NUMFRAC's
   freezing and contact-formation criterion, digest A.8 and R4).  Every N
   steps each particle of the group picks the closest unbonded particle
   of the group within the capture distance; a pair whose two particles
   picked each other gets a bond of the given type, which bond_style beam
   makes stress-free in its present geometry.  The decisions are made by
   the particles' owners and exchanged with the ghosts, so that every
   rank makes the same bonds
------------------------------------------------------------------------- */

class FixBeamFreeze : public Fix {
 public:
  FixBeamFreeze(class LAMMPS *, int, char **);
  ~FixBeamFreeze() override;
  int setmask() override;
  void init() override;
  void init_list(int, class NeighList *) override;
  void setup(int) override;
  void post_integrate() override;
  double compute_vector(int) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  double memory_usage() override;

 private:
  int btype;             // type of the new bonds
  double capture;        // capture distance
  double probability;    // of a pair's freezing at an attempt
  int seed;              // of the pairs' draws (prob)
  int maxbond;           // a particle with this many bonds takes no more (0: no limit)
  class NeighList *list;
  class FixBeamState *fix_state;

  // per atom (local and ghost), for one attempt: STATUS_* bits, then the
  // ID of the chosen partner (0: none)
  enum { STATUS_TAKES = 1, STATUS_ROOM_BOND = 2, STATUS_ROOM_SPECIAL = 4 };
  double *status, *choice;
  int nmax;
  double *sending;    // the array forward_comm sends

  bigint made_last, made_total;    // bonds made at the last attempt, since the fix was defined
  int warned_room;

  decltype(Fix::datamask_read) datamask_read_attempt, datamask_modify_attempt;
  void set_datamasks(bigint next_step);
  void attempt();
  bigint make_bonds();
  void add_bond(int i, tagint partner, bool store);
};

}    // namespace LAMMPS_NS

#endif
#endif
