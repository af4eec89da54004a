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

#ifndef LMP_MCA_MATERIALS_H
#define LMP_MCA_MATERIALS_H

#include "mca_material.h"
#include "mca_plasticity.h"
#include "pointers.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   the materials of the atom types of pair_style mca: one MCAMaterial per
   type, parsed and checked here from the pair_coeff keywords of the
   keyword table (mca_materials.cpp), written to and read from restart
   files by keyword name, and handed to the kernels as one array
------------------------------------------------------------------------- */

class MCAMaterials : protected Pointers {
  typedef MCAKernels::MCAMaterial MCAMaterial;
  typedef MCAKernels::MCAHardening MCAHardening;

 public:
  MCAMaterials(class LAMMPS *);
  ~MCAMaterials() override;

  void allocate(int ntypes);
  // what one pair_coeff gives: the values of the keywords it names
  struct Input {
    MCAMaterial values{};    // keywords not given stay 0
    unsigned given = 0;      // bit k: keyword k of the table was given
    // hardening table: its points (eps_p, sigma_y), empty if none
    std::vector<double> table_eps, table_sig;
  };
  // parse "key value" into in; false if key is no material keyword
  bool parse(const std::string &key, const char *value, Input &in);
  // "hardening table file keyword": the section keyword of file into in
  void read_hardening_table(const std::string &file, const std::string &keyword, Input &in);
  // the material of types lo..hi, all keywords needed
  void assign(int lo, int hi, const Input &in);
  // an error naming the first type without a material, if any
  void check_all_set() const;
  // "E, nu, rho and eta" (all keywords) or those every material needs
  std::string keyword_list(bool required_only = false) const;

  void write_restart(FILE *) const;
  // with_tables: the file holds the hardening tables after the values
  void read_restart(FILE *, bool with_tables);
  // the layout of restart files before materials were written by name
  void read_restart_values(int type, const double *youngs_nu_rho, int set_flag);

  // per-type column of one input keyword (pair extract), nullptr if none
  double *column(const char *keyword);

  int ntypes;
  MCAMaterial *type;          // [ntypes + 1]
  int *set;                   // [ntypes + 1]: 1 once the type has a material
  MCAHardening *hardening;    // [ntypes + 1]: hardening curve of each type
  int *tabulated;             // [ntypes + 1]: 1 if its curve is a table
  // is any type plastic (has a yield stress)?
  bool any_plastic() const;

 private:
  std::vector<double> columns;
  // an error if the moduli the law forms from E and nu would overflow
  void check_moduli(const MCAMaterial &) const;
  // the hardening curve of type i from its values (and table)
  void set_curve(int i, const std::vector<double> &eps, const std::vector<double> &sig);
};

}    // namespace LAMMPS_NS

#endif
