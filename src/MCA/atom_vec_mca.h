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

#ifdef ATOM_CLASS
// clang-format off
AtomStyle(mca,AtomVecMCA);
// clang-format on
#else

#ifndef LMP_ATOM_VEC_MCA_H
#define LMP_ATOM_VEC_MCA_H

#include "atom_vec.h"
#include "mca_compat.h"

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   the MCA per-automaton data as the other MCA styles see it, whichever
   atom style holds it (atom_style mca, or mca/kk of the KOKKOS package):
   host pointers, valid after sync_host(); a style that changes them on
   the host says so with modified_host()
------------------------------------------------------------------------- */

class MCAAtomFields {
 public:
  // columns of the per-automaton stress tensor (Voigt order)
  enum { SXX, SYY, SZZ, SXY, SXZ, SYZ, NSTRESS };

  double *radius, *rmass;
  double **omega, **quat;

  int *packing;       // coordination number N_c of the virtual cell: 0, 6 or 12
  double *volume;     // volume Omega of the virtual cell
  double *inertia;    // moment of inertia J (isotropic)
  double *smean;      // mean stress (tension positive)
  double **stress;    // averaged stress tensor, Voigt order xx yy zz xy xz yz
  double *seq;        // von Mises equivalent stress
  double *eeq;        // equivalent strain
  double *epsp;       // accumulated equivalent plastic strain
  double *damage;     // damage 0 (intact) ... 1 (all links broken)
  // what the user gave an automaton (mca_set): its mass (or density),
  // its moment of inertia; pair mca derives the others from the material.
  // FROM_DATA: read from a data file, whose masses pair mca replaces
  // (and says so) at its next run
  int *given;
  enum { GIVEN_MASS = 1, GIVEN_INERTIA = 2, FROM_DATA = 4 };

  // set the derived geometry (volume, inertia) of automaton i from its
  // packing, radius and mass; shared with the mca_set command
  virtual void derive_geometry(int i, bool keep_volume, bool keep_inertia) = 0;

  // the host copy of all per-atom data is current / was changed on the host
  virtual void sync_host() {}
  virtual void modified_host() {}
  // the same for the orientations (quat) alone
  virtual void orientation_to_host() {}
  virtual void orientation_changed_on_host() {}

  // the MCA atom style of this system (also inside atom_style hybrid), or nullptr
  static MCAAtomFields *find(class Atom *atom);

  // an integrator's check: every automaton of the group has a positive
  // mass and moment of inertia (an error naming the style and the group)
  void require_mass_and_inertia(class LAMMPS *lmp, int igroup, const char *style);

 protected:
  MCAAtomFields();
  ~MCAAtomFields() = default;    // owned and deleted as an AtomVec
};

/* ----------------------------------------------------------------------
   atom_style mca, written once for both AtomVec bases: AtomVec (this
   style) and AtomVecKokkos (mca/kk); see atom_vec_mca_impl.h
------------------------------------------------------------------------- */

template <class AtomVecBase> class AtomVecMCAStyle : public AtomVecBase, public MCAAtomFields {
 public:
  AtomVecMCAStyle(class LAMMPS *);
  ~AtomVecMCAStyle() override;

  void process_args(int, char **) override;
  void init() override;

  void grow_pointers() override;
  void create_atom_post(int) override;
  void data_atom_post(int) override;
  void unpack_restart_init(int) override;
  void write_data(FILE *, int, double **) override;
  void pack_data_pre(int) override;
  void pack_data_post(int) override;
  void pack_restart_pre(int) override;
  void pack_restart_post(int) override;

  int property_atom(MCACompat::property_name_t) override;
  void pack_property_atom(int, double *, int, int) override;

  void derive_geometry(int i, bool keep_volume, bool keep_inertia) override;

 protected:
  using AtomVecBase::atom;
  using AtomVecBase::domain;
  using AtomVecBase::error;
  using AtomVecBase::memory;

  int *num_bond, **nspecial;
  // 1 if this class allocates the MCA arrays itself (the Kokkos style
  // keeps them in its own views)
  int owns_arrays;

 private:
  double radius_one;

  // cached geometry of the lattice last used by create_atoms
  const void *lattice_seen;
  double lattice_key[4];
  int lattice_packing;
  double lattice_radius;

  void lattice_geometry(int &, double &);
};

class AtomVecMCA : public AtomVecMCAStyle<AtomVec> {
 public:
  AtomVecMCA(class LAMMPS *lmp) : AtomVecMCAStyle<AtomVec>(lmp) {}
};

}    // namespace LAMMPS_NS

#endif
#endif
