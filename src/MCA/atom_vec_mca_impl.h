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
   Contributing authors: MCA package developers

   Definitions of AtomVecMCAStyle<AtomVecBase>, included by exactly the two
   translation units that instantiate it: atom_vec_mca.cpp (AtomVec) and
   KOKKOS_MCA/atom_vec_mca_kokkos.cpp (AtomVecKokkos)
------------------------------------------------------------------------- */

#ifndef LMP_ATOM_VEC_MCA_IMPL_H
#define LMP_ATOM_VEC_MCA_IMPL_H

#include "atom_vec_mca.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "lattice.h"
#include "mca_geometry.h"
#include "memory.h"

#include <cmath>
#include <cstdio>

namespace LAMMPS_NS {

/* ---------------------------------------------------------------------- */

template <class AtomVecBase>
AtomVecMCAStyle<AtomVecBase>::AtomVecMCAStyle(LAMMPS *_lmp) :
    AtomVecBase(_lmp), num_bond(nullptr), nspecial(nullptr), owns_arrays(1), radius_one(0.0),
    lattice_seen(nullptr), lattice_packing(0), lattice_radius(0.5)
{
  this->mass_type = AtomVec::PER_ATOM;
  this->molecular = Atom::MOLECULAR;    // links may be stored as LAMMPS bonds
  this->bonds_allow = 1;

  atom->molecule_flag = 1;
  atom->radius_flag = atom->rmass_flag = atom->omega_flag = atom->torque_flag = 1;
  for (double &k : lattice_key) k = 0.0;

  // the MCA fields are owned by this class; Atom only holds their addresses

  MCACompat::register_peratom(atom, "mca_packing", &packing, Atom::INT, 0);
  MCACompat::register_peratom(atom, "mca_volume", &volume, Atom::DOUBLE, 0);
  MCACompat::register_peratom(atom, "mca_inertia", &inertia, Atom::DOUBLE, 0);
  MCACompat::register_peratom(atom, "mca_smean", &smean, Atom::DOUBLE, 0);
  MCACompat::register_peratom(atom, "mca_stress", &stress, Atom::DOUBLE, NSTRESS);
  MCACompat::register_peratom(atom, "mca_seq", &seq, Atom::DOUBLE, 0);
  MCACompat::register_peratom(atom, "mca_eeq", &eeq, Atom::DOUBLE, 0);
  MCACompat::register_peratom(atom, "mca_epsp", &epsp, Atom::DOUBLE, 0);
  MCACompat::register_peratom(atom, "mca_damage", &damage, Atom::DOUBLE, 0);
  MCACompat::register_peratom(atom, "mca_given", &given, Atom::INT, 0);

  // orientation: LAMMPS has a per-atom quaternion since 2022, before that
  // this style provides its own array under the same name

#ifdef MCA_HAVE_ATOM_QUAT
  atom->quat_flag = 1;
#else
  MCACompat::register_peratom(atom, "quat", &quat, Atom::DOUBLE, 4);
#endif

  // strings with peratom variables to include in each AtomVec method
  // order of fields in a string does not matter
  // except: fields_data_atom & fields_data_vel must match data file
  // positions and velocities (x, v, omega) of ghosts are sent every step;
  // all other fields reach the ghosts when they are (re)built

#define MCA_PERATOM                                                                    \
  "radius rmass quat mca_packing mca_volume mca_inertia mca_smean mca_stress mca_seq " \
  "mca_eeq mca_epsp mca_damage"
#define MCA_BONDS "num_bond bond_type bond_atom nspecial special"

  // mca_given moves with its automaton; restart files carry it in the
  // signs of volume and inertia (pack_restart_pre), which keeps the
  // layout of files written before it existed
  this->fields_grow =
      MCACompat::fields("molecule " MCA_BONDS " omega torque mca_given " MCA_PERATOM);
  this->fields_copy = MCACompat::fields("molecule " MCA_BONDS " omega mca_given " MCA_PERATOM);
  this->fields_comm = MCACompat::fields("");
  this->fields_comm_vel = MCACompat::fields("omega");
  this->fields_reverse = MCACompat::fields("torque");
  this->fields_border = MCACompat::fields("molecule " MCA_PERATOM);
  this->fields_border_vel = MCACompat::fields("molecule omega " MCA_PERATOM);
  this->fields_exchange = MCACompat::fields("molecule " MCA_BONDS " omega mca_given " MCA_PERATOM);
  this->fields_restart =
      MCACompat::fields("molecule num_bond bond_type bond_atom omega " MCA_PERATOM);
  this->fields_create =
      MCACompat::fields("molecule num_bond nspecial omega mca_given " MCA_PERATOM);
  this->fields_data_atom =
      MCACompat::fields("id molecule type mca_packing radius mca_volume rmass mca_inertia x");
  this->fields_data_vel = MCACompat::fields("id v omega");

#undef MCA_PERATOM
#undef MCA_BONDS
}

/* ---------------------------------------------------------------------- */

template <class AtomVecBase> AtomVecMCAStyle<AtomVecBase>::~AtomVecMCAStyle()
{
  if (!owns_arrays) return;
  memory->destroy(packing);
  memory->destroy(volume);
  memory->destroy(inertia);
  memory->destroy(smean);
  memory->destroy(stress);
  memory->destroy(seq);
  memory->destroy(eeq);
  memory->destroy(epsp);
  memory->destroy(damage);
  memory->destroy(given);
#ifndef MCA_HAVE_ATOM_QUAT
  memory->destroy(quat);
#endif
}

/* ----------------------------------------------------------------------
   atom_style mca takes no arguments
------------------------------------------------------------------------- */

template <class AtomVecBase> void AtomVecMCAStyle<AtomVecBase>::process_args(int narg, char **arg)
{
  if (narg > 0)
    error->all(FLERR,
               "Illegal atom_style mca command: unexpected argument '{}' "
               "(atom_style mca takes no arguments)",
               arg[0]);
  this->setup_fields();
}

/* ---------------------------------------------------------------------- */

template <class AtomVecBase> void AtomVecMCAStyle<AtomVecBase>::init()
{
  AtomVecBase::init();
  // 2-D systems turn about z (bond_style beam); pair mca requires 3-D itself
}

/* ----------------------------------------------------------------------
   set local copies of all grow ptrs used by this class, except defaults
   needed in replicate when 2 atom classes exist and it calls pack_restart()
------------------------------------------------------------------------- */

template <class AtomVecBase> void AtomVecMCAStyle<AtomVecBase>::grow_pointers()
{
  radius = atom->radius;
  rmass = atom->rmass;
  omega = atom->omega;
#ifdef MCA_HAVE_ATOM_QUAT
  quat = atom->quat;
#endif
  num_bond = atom->num_bond;
  nspecial = atom->nspecial;
}

/* ----------------------------------------------------------------------
   packing and radius for an automaton made by create_atoms:
   from the current lattice if it is sc, fcc or hcp (the automata touch
   their nearest neighbours), else an unpacked sphere of radius 0.5
------------------------------------------------------------------------- */

template <class AtomVecBase>
void AtomVecMCAStyle<AtomVecBase>::lattice_geometry(int &ipacking, double &r)
{
  Lattice *lattice = domain->lattice;
  if (!lattice || lattice->style == Lattice::NONE) {
    ipacking = MCAKernels::PACKING_NONE;
    r = 0.5;
    return;
  }

  // recompute only when the lattice changed
  const double key[4] = {lattice->xlattice, lattice->ylattice, lattice->zlattice,
                         (double) lattice->nbasis};
  if (lattice == lattice_seen && key[0] == lattice_key[0] && key[1] == lattice_key[1] &&
      key[2] == lattice_key[2] && key[3] == lattice_key[3]) {
    ipacking = lattice_packing;
    r = lattice_radius;
    return;
  }

  // nearest-neighbour distance: shortest separation from a basis atom of the
  // unit cell at the origin to any basis atom of the 27 surrounding cells

  double dmin2 = -1.0;
  for (int m = 0; m < lattice->nbasis; m++) {
    double x0[3] = {lattice->basis[m][0], lattice->basis[m][1], lattice->basis[m][2]};
    lattice->lattice2box(x0[0], x0[1], x0[2]);
    for (int i = -1; i <= 1; i++)
      for (int j = -1; j <= 1; j++)
        for (int k = -1; k <= 1; k++)
          for (int n = 0; n < lattice->nbasis; n++) {
            if (i == 0 && j == 0 && k == 0 && n == m) continue;
            double x1[3] = {i + lattice->basis[n][0], j + lattice->basis[n][1],
                            k + lattice->basis[n][2]};
            lattice->lattice2box(x1[0], x1[1], x1[2]);
            const double dx = x1[0] - x0[0], dy = x1[1] - x0[1], dz = x1[2] - x0[2];
            const double d2 = dx * dx + dy * dy + dz * dz;
            if (dmin2 < 0.0 || d2 < dmin2) dmin2 = d2;
          }
  }

  if (lattice->style == Lattice::SC)
    lattice_packing = MCAKernels::PACKING_SC;
  else if (lattice->style == Lattice::FCC || lattice->style == Lattice::HCP)
    lattice_packing = MCAKernels::PACKING_FCC;
  else
    lattice_packing = MCAKernels::PACKING_NONE;
  lattice_radius = 0.5 * sqrt(dmin2);
  lattice_seen = lattice;
  for (int i = 0; i < 4; i++) lattice_key[i] = key[i];

  ipacking = lattice_packing;
  r = lattice_radius;
}

/* ----------------------------------------------------------------------
   volume and moment of inertia from packing, radius and mass
------------------------------------------------------------------------- */

template <class AtomVecBase>
void AtomVecMCAStyle<AtomVecBase>::derive_geometry(int i, bool keep_volume, bool keep_inertia)
{
  if (!keep_volume) volume[i] = MCAKernels::cell_volume(packing[i], radius[i]);
  if (!keep_inertia) inertia[i] = MCAKernels::cell_inertia(packing[i], rmass[i], radius[i]);
}

/* ----------------------------------------------------------------------
   initialize non-zero atom quantities of a new automaton:
   geometry from the lattice, unit density, identity orientation
------------------------------------------------------------------------- */

template <class AtomVecBase> void AtomVecMCAStyle<AtomVecBase>::create_atom_post(int ilocal)
{
  lattice_geometry(packing[ilocal], radius[ilocal]);
  volume[ilocal] = MCAKernels::cell_volume(packing[ilocal], radius[ilocal]);
  rmass[ilocal] = volume[ilocal];
  inertia[ilocal] = MCAKernels::cell_inertia(packing[ilocal], rmass[ilocal], radius[ilocal]);
  quat[ilocal][0] = 1.0;
  quat[ilocal][1] = quat[ilocal][2] = quat[ilocal][3] = 0.0;
}

/* ----------------------------------------------------------------------
   check what AtomVec::data_atom() just unpacked and complete it
   Atoms line: id molecule type packing diameter volume mass inertia x y z
   volume = 0 or inertia = 0 means: derive it from packing, radius and mass
------------------------------------------------------------------------- */

template <class AtomVecBase> void AtomVecMCAStyle<AtomVecBase>::data_atom_post(int ilocal)
{
  radius[ilocal] *= 0.5;    // the data file holds the diameter
  if (!MCAKernels::valid_packing(packing[ilocal]))
    error->one(FLERR,
               "Invalid packing {} in Atoms section of data file for atom_style mca "
               "(allowed: 0 = none, 6 = sc, 12 = fcc/hcp)",
               packing[ilocal]);
  if (radius[ilocal] <= 0.0)
    error->one(FLERR,
               "Invalid diameter {} in Atoms section of data file for atom_style mca "
               "(must be > 0)",
               2.0 * radius[ilocal]);
  if (rmass[ilocal] <= 0.0)
    error->one(FLERR,
               "Invalid mass {} in Atoms section of data file for atom_style mca "
               "(must be > 0)",
               rmass[ilocal]);
  if (volume[ilocal] < 0.0 || inertia[ilocal] < 0.0)
    error->one(FLERR,
               "Invalid volume {} or inertia {} in Atoms section of data file for "
               "atom_style mca (must be > 0, or 0 to derive it)",
               volume[ilocal], inertia[ilocal]);
  derive_geometry(ilocal, volume[ilocal] > 0.0, inertia[ilocal] > 0.0);

  omega[ilocal][0] = omega[ilocal][1] = omega[ilocal][2] = 0.0;
  quat[ilocal][0] = 1.0;
  quat[ilocal][1] = quat[ilocal][2] = quat[ilocal][3] = 0.0;
  smean[ilocal] = seq[ilocal] = eeq[ilocal] = epsp[ilocal] = damage[ilocal] = 0.0;
  for (int k = 0; k < NSTRESS; k++) stress[ilocal][k] = 0.0;
  given[ilocal] = FROM_DATA;    // pair mca replaces the mass by rho Omega, and says so
  num_bond[ilocal] = 0;
  nspecial[ilocal][0] = nspecial[ilocal][1] = nspecial[ilocal][2] = 0;
}

/* ----------------------------------------------------------------------
   the data file holds the diameter (exact: scaling by 2 is exact)
------------------------------------------------------------------------- */

template <class AtomVecBase> void AtomVecMCAStyle<AtomVecBase>::pack_data_pre(int ilocal)
{
  radius_one = radius[ilocal];
  radius[ilocal] = 2.0 * radius_one;
}

template <class AtomVecBase> void AtomVecMCAStyle<AtomVecBase>::pack_data_post(int ilocal)
{
  radius[ilocal] = radius_one;
}

/* ----------------------------------------------------------------------
   write the Atoms section; same columns as AtomVec::write_data() but every
   floating-point value in its shortest exact form, so that a data file
   written and read back reproduces every value bit for bit (newer LAMMPS
   versions print per-atom scalars with only 16 significant digits)
------------------------------------------------------------------------- */

template <class AtomVecBase>
void AtomVecMCAStyle<AtomVecBase>::write_data(FILE *fp, int n, double **buf)
{
  // buf row: id molecule type packing diameter volume mass inertia x y z ix iy iz
  for (int i = 0; i < n; i++) {
    const double *b = buf[i];
    const std::string type = MCACompat::type_name(atom, (int) ubuf(b[2]).i);
    const std::string line =
        fmt::format("{} {} {} {} {} {} {} {} {} {} {} {} {} {}\n", ubuf(b[0]).i, ubuf(b[1]).i, type,
                    ubuf(b[3]).i, b[4], b[5], b[6], b[7], b[8], b[9], b[10], ubuf(b[11]).i,
                    ubuf(b[12]).i, ubuf(b[13]).i);
    fputs(line.c_str(), fp);
  }
}

/* ----------------------------------------------------------------------
   restart files: what the user gave an automaton travels in the signs of
   its volume (mass given) and moment of inertia (inertia given), both > 0
   otherwise, so files of earlier versions read with nothing given
------------------------------------------------------------------------- */

template <class AtomVecBase> void AtomVecMCAStyle<AtomVecBase>::pack_restart_pre(int ilocal)
{
  if (given[ilocal] & GIVEN_MASS) volume[ilocal] = -volume[ilocal];
  if (given[ilocal] & GIVEN_INERTIA) inertia[ilocal] = -inertia[ilocal];
}

template <class AtomVecBase> void AtomVecMCAStyle<AtomVecBase>::pack_restart_post(int ilocal)
{
  if (given[ilocal] & GIVEN_MASS) volume[ilocal] = -volume[ilocal];
  if (given[ilocal] & GIVEN_INERTIA) inertia[ilocal] = -inertia[ilocal];
}

/* ----------------------------------------------------------------------
   special lists are rebuilt after reading a restart file; what was given
------------------------------------------------------------------------- */

template <class AtomVecBase> void AtomVecMCAStyle<AtomVecBase>::unpack_restart_init(int ilocal)
{
  nspecial[ilocal][0] = nspecial[ilocal][1] = nspecial[ilocal][2] = 0;
  given[ilocal] = 0;
  if (volume[ilocal] < 0.0) {
    volume[ilocal] = -volume[ilocal];
    given[ilocal] |= GIVEN_MASS;
  }
  if (inertia[ilocal] < 0.0) {
    inertia[ilocal] = -inertia[ilocal];
    given[ilocal] |= GIVEN_INERTIA;
  }
}

/* ----------------------------------------------------------------------
   names of the MCA per-atom quantities for compute property/atom;
   return -1 if name is unknown to this atom style
------------------------------------------------------------------------- */

static const char *const mca_property_names[] = {
    "packing", "volume", "inertia", "smean", "sxx",    "syy",     "szz",     "sxy",     "sxz",
    "syz",     "seq",    "eeq",     "epsp",  "damage", "orientw", "orienti", "orientj", "orientk"};
static constexpr int MCA_NPROPERTY = sizeof(mca_property_names) / sizeof(mca_property_names[0]);

template <class AtomVecBase>
int AtomVecMCAStyle<AtomVecBase>::property_atom(MCACompat::property_name_t name)
{
  for (int i = 0; i < MCA_NPROPERTY; i++)
    if (MCACompat::same_name(name, mca_property_names[i])) return i;
  return -1;
}

/* ----------------------------------------------------------------------
   pack per-atom data into buf for compute property/atom
   index maps to data specific to this atom style
------------------------------------------------------------------------- */

template <class AtomVecBase>
void AtomVecMCAStyle<AtomVecBase>::pack_property_atom(int index, double *buf, int nvalues,
                                                      int groupbit)
{
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;

  int n = 0;
  for (int i = 0; i < nlocal; i++, n += nvalues) {
    if (!(mask[i] & groupbit)) {
      buf[n] = 0.0;
      continue;
    }
    if (index == 0)
      buf[n] = packing[i];
    else if (index == 1)
      buf[n] = volume[i];
    else if (index == 2)
      buf[n] = inertia[i];
    else if (index == 3)
      buf[n] = smean[i];
    else if (index <= 9)
      buf[n] = stress[i][index - 4];
    else if (index == 10)
      buf[n] = seq[i];
    else if (index == 11)
      buf[n] = eeq[i];
    else if (index == 12)
      buf[n] = epsp[i];
    else if (index == 13)
      buf[n] = damage[i];
    else
      buf[n] = quat[i][index - 14];
  }
}

}    // namespace LAMMPS_NS

#endif
