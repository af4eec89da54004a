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
FixStyle(BEAM_STATE,FixBeamState);
// clang-format on
#else

#ifndef LMP_FIX_BEAM_STATE_H
#define LMP_FIX_BEAM_STATE_H

#include "beam_kernels.h"
#include "fix.h"
#include "mca_damping_fix.h"

#include <vector>

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   internal fix created by bond_style beam: the reference state of every
   bond (the stress-free geometry it had when first seen), kept in slots
   parallel to the bond arrays of its atom (bond_atom[i][m] <-> slot m of
   atom i).  A slot holds the partner's atom ID, so a slot whose bond was
   replaced (delete_bonds, create_bonds) is recognised as new.  Slots move
   with their atoms and are written to restart files.  The fix also sends
   the orientations of the owned atoms to their ghosts before the forces
   (atom_style mca sends them only with the ghost shells).  Its scalar is
   the energy the bonds' damping (bond_coeff ... damp) has taken out.
   With the particle criterion (bond_coeff ... criterion particle) it
   holds each particle's averaged stress and candidate bond: summed during
   the bond loop (ghosts' shares sent to their owners), kept per particle
   (its per-atom array: mean normal stress, sqrt(J2), the candidate's
   partner ID), sent to the ghosts with the orientations.
------------------------------------------------------------------------- */

class FixBeamState : public Fix {
 public:
  // a slot: the partner's ID, then the reference state (nslot values)
  enum { SLOT_PARTNER, SLOT_REF };

  FixBeamState(class LAMMPS *, int, char **);
  ~FixBeamState() override;
  int setmask() override;
  void init() override;
  void setup_pre_force(int) override;
  void pre_force(int) override;
  void min_pre_force(int) override;

  double compute_scalar() override;
  void write_restart(FILE *) override;
  void restart(char *) override;

  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;

  double memory_usage() override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;

  // the reference state of entry (i1, i2) of a bond list, i1 the local
  // atom that stores the bond, in the order lower atom ID first: set from
  // the present geometry if the bond is new (and in the partner's copy if
  // it is a local atom as well); returns the stored reference, or nullptr
  // if atom i1 has no such bond
  const double *reference(int i1, int i2, int newton_bond);

  // a new reference state of entry (i1, i2) of a bond list (a melted bond
  // that froze again), in the order lower atom ID first: into atom i1's
  // slot, and with newton_bond off into the partner's if it is local
  void set_reference(int i1, int i2, int newton_bond, const double *ref);

  // the reference of a bond as stored by atom i (local), or nullptr
  const double *stored_reference(int i, int j) const;

  // before bond m of local atom i is removed (num_bond[i] not yet lowered)
  void remove_slot(int i, int m);

  // before a bond is added as bond m of local atom i (fix beam/freeze): an
  // empty slot, so that the bond's reference is its geometry when listed
  void clear_slot(int i, int m);

  // a bond style that has the orientations on another memory space
  class MCAAtomFields *avec;

  // the energy the bonds' damping took out so far (the fix's scalar)
  MCAEnergyTally dissipated;

  // the particle criterion: sums (BeamKernels::PSUM_*) of local and ghost
  // atoms, made when a bond type uses it; what each particle keeps
  // (PSTATE_*: its array_atom, sent to the ghosts)
  int particle_criterion;
  double **sums, **pstate;
  void use_particle_criterion(int on);
  void clear_sums(int n);
  // a bond's share w of atom i's virial sum; with measure >= 0 the bond
  // is a candidate of atom i with the given partner ID
  void add_share(int i, const double *w, double measure, double partner)
  {
    double *s = sums[i];
    for (int k = 0; k < 6; k++) s[BeamKernels::PSUM_VIRIAL + k] += w[k];
    if (measure >= 0.0) BeamKernels::take_candidate(s, measure, partner);
  }
  // the ghosts' sums to their owners (newton_bond on), then each owned
  // particle's stress and candidate
  void decide_particles(int newton_bond);

  // the stable time step bound (BondBeam::stable_timestep_of): the
  // Gershgorin sums of the rows of each local and ghost atom
  // (BeamKernels::gershgorin_size values each), and with newton_bond on
  // the ghosts' sums added to their owners'
  std::vector<double> gershgorin;
  void sum_gershgorin();
  BeamKernels::ParticleState particle_state(int i) const
  {
    return {pstate[i][BeamKernels::PSTATE_SIGMA], pstate[i][BeamKernels::PSTATE_TAU],
            pstate[i][BeamKernels::PSTATE_PARTNER]};
  }

 private:
  int maxbond;          // bond slots per atom
  int reverse_stage;    // what pack_reverse_comm sends: REVERSE_*
  enum { REVERSE_PARTICLE, REVERSE_GERSHGORIN };
  int nslot;         // values per slot: SLOT_REF + the reference of the dimension
  double **state;    // maxbond * nslot values per atom
  int nmax_old;      // rows allocated
  void send_orientations();
  double *find_slot(int i, tagint partner) const;
  bool take_moved_state(int i, double *slot, tagint partner);
};

}    // namespace LAMMPS_NS

#endif
#endif
