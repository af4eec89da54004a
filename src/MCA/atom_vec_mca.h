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

class AtomVecMCA : public AtomVec {
 public:
  // columns of the per-automaton stress tensor (Voigt order)
  enum { SXX, SYY, SZZ, SXY, SXZ, SYZ, NSTRESS };

  AtomVecMCA(class LAMMPS *);
  ~AtomVecMCA() override;

  void process_args(int, char **) override;
  void init() override;

  void grow_pointers() override;
  void create_atom_post(int) override;
  void data_atom_post(int) override;
  void unpack_restart_init(int) override;
  void write_data(FILE *, int, double **) override;
  void pack_data_pre(int) override;
  void pack_data_post(int) override;

  int property_atom(MCACompat::property_name_t) override;
  void pack_property_atom(int, double *, int, int) override;

  // set the derived geometry (volume, inertia) of automaton i from its
  // packing, radius and mass; shared with the mca_set command
  void derive_geometry(int i, bool keep_volume, bool keep_inertia);

  // per-automaton data: the common sphere fields live in Atom, the MCA
  // fields are owned here and registered with Atom under "mca_*" names

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

 private:
  int *num_bond, **nspecial;
  double radius_one;

  // cached geometry of the lattice last used by create_atoms
  const void *lattice_seen;
  double lattice_key[4];
  int lattice_packing;
  double lattice_radius;

  void lattice_geometry(int &, double &);
};

}    // namespace LAMMPS_NS

#endif
#endif
