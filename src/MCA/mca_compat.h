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
   The one place where the MCA package deals with differences between
   LAMMPS versions (29 Sep 2021 ... 4 Jul 2026).  The MCA_HAVE_* macros come
   from mca_config.h, which cmake/Modules/Packages/MCA.cmake writes after
   probing the headers of the LAMMPS tree being built.  Everything else in
   the package is written against the interface defined here.
------------------------------------------------------------------------- */

#ifndef LMP_MCA_COMPAT_H
#define LMP_MCA_COMPAT_H

#include "mca_config.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "modify.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "utils.h"

#ifdef MCA_HAVE_TYPE_LABELS
#include "label_map.h"
#endif

#include <cstring>
#include <string>

// Pair::extract_peratom() (for fix pair) exists since 2022
#ifdef MCA_HAVE_EXTRACT_PERATOM
#define MCA_EXTRACT_PERATOM_OVERRIDE override
#else
#define MCA_EXTRACT_PERATOM_OVERRIDE
#endif

namespace LAMMPS_NS {

class Fix;
class Pair;
class NeighList;

// argument-checking helpers that newer LAMMPS versions provide in utils::
namespace utils {
#ifndef MCA_HAVE_MISSING_CMD_ARGS
  inline void missing_cmd_args(const std::string &file, int line, const std::string &cmd,
                               Error *error)
  {
    if (error) error->all(file, line, "Illegal {} command: missing argument(s)", cmd);
  }
#endif
#ifndef MCA_HAVE_UTILS_LOGICAL
  inline int logical(const char *file, int line, const std::string &str, bool do_abort, LAMMPS *lmp)
  {
    if (str == "yes" || str == "on" || str == "true" || str == "1") return 1;
    if (str == "no" || str == "off" || str == "false" || str == "0") return 0;
    const std::string msg = "Expected boolean parameter instead of '" + str + "' in input script";
    if (do_abort)
      lmp->error->one(file, line, msg);
    else
      lmp->error->all(file, line, msg);
    return 0;
  }
#endif
}    // namespace utils

namespace MCACompat {

// lists of per-atom fields in AtomVec: space separated words
#ifdef MCA_HAVE_FIELD_VECTORS
  inline std::vector<std::string> fields(const char *words)
  {
    return utils::split_words(words);
  }
#else
  inline char *fields(const char *words)
  {
    return const_cast<char *>(words);
  }
#endif

// argument type of AtomVec::property_atom()
#ifdef MCA_HAVE_PROPERTY_ATOM_STR
  typedef const std::string &property_name_t;
  inline bool same_name(property_name_t name, const char *word)
  {
    return name == word;
  }
#else
  typedef char *property_name_t;
  inline bool same_name(property_name_t name, const char *word)
  {
    return strcmp(name, word) == 0;
  }
#endif

  /* register a per-atom array owned by an atom style with the Atom class,
     so that the generic AtomVec machinery grows, copies, communicates and
     writes it; an existing entry of the same name (a previous instance of the
     same atom style) is re-pointed at the new storage */

  inline void register_peratom(Atom *atom, const char *name, void *address, int datatype, int cols)
  {
#ifdef MCA_HAVE_PERATOM_VECTOR
    for (auto &entry : atom->peratom)
      if (entry.name == name) {
        entry.address = address;
        entry.datatype = datatype;
        entry.cols = cols;
        return;
      }
#else
    for (int i = 0; i < atom->nperatom; i++)
      if (strcmp(atom->peratom[i].name, name) == 0) {
        atom->peratom[i].address = address;
        atom->peratom[i].datatype = datatype;
        atom->peratom[i].cols = cols;
        return;
      }
#endif
    atom->add_peratom(name, address, datatype, cols);
  }

  // fix lookup by ID; nullptr if there is none
  inline Fix *fix_by_id(Modify *modify, const std::string &id)
  {
#ifdef MCA_HAVE_GET_FIX_BY_ID
    return modify->get_fix_by_id(id);
#else
    const int ifix = modify->find_fix(id);
    return (ifix < 0) ? nullptr : modify->fix[ifix];
#endif
  }

  // an occasional full neighbor list for a fix (built on demand with
  // build_one), with its own cutoff if cutoff > 0 (else the pair style's)
  inline void request_full_occasional(Neighbor *neighbor, Fix *fix, int instance,
                                      double cutoff = 0.0)
  {
#ifdef MCA_HAVE_ADD_REQUEST
    (void) instance;
    auto request = neighbor->add_request(fix, NeighConst::REQ_FULL | NeighConst::REQ_OCCASIONAL);
    if (cutoff > 0.0) request->set_cutoff(cutoff);
#else
    const int irequest = neighbor->request(fix, instance);
    neighbor->requests[irequest]->pair = 0;
    neighbor->requests[irequest]->fix = 1;
    neighbor->requests[irequest]->half = 0;
    neighbor->requests[irequest]->full = 1;
    neighbor->requests[irequest]->occasional = 1;
    if (cutoff > 0.0) {
      neighbor->requests[irequest]->cut = 1;
      neighbor->requests[irequest]->cutoff = cutoff;
    }
#endif
  }

  // build an occasional list now unless it was built since the last
  // neighbor list build; before LAMMPS 2022 build_one() takes a flag that
  // tells a list built earlier in this step, before a build, from one
  // built after it (as fix bond/create does)
  template <class N>
  inline auto build_occasional_impl(N *neighbor, NeighList *list, int)
      -> decltype(neighbor->build_one(list, 1), void())
  {
    neighbor->build_one(list, 1);
  }
  template <class N> inline void build_occasional_impl(N *neighbor, NeighList *list, long)
  {
    neighbor->build_one(list);
  }
  inline void build_occasional(Neighbor *neighbor, NeighList *list)
  {
    build_occasional_impl(neighbor, list, 0);
  }

  // whether the neighbor list of a pair style holds bonded pairs whatever
  // the special weights: the size lists of granular pair styles before the
  // NPair rewrite of 2023 (checked during init, after the pair style's)
  inline bool pair_list_keeps_special_pairs(Neighbor *neighbor, Pair *pair)
  {
#ifdef MCA_HAVE_SIZE_LIST_SPECIALS
    (void) neighbor;
    (void) pair;
    return false;
#else
    for (int i = 0; i < neighbor->nrequest; i++)
      if (neighbor->requests[i]->requestor == pair && neighbor->requests[i]->size) return true;
    return false;
#endif
  }

  // a perpetual full neighbor list of a pair style, with an id that tells
  // it from the style's other lists in init_list()
  inline void request_full_list(Neighbor *neighbor, Pair *pair, int instance, int id)
  {
#ifdef MCA_HAVE_ADD_REQUEST
    (void) instance;
    neighbor->add_request(pair, NeighConst::REQ_FULL)->set_id(id);
#else
    const int irequest = neighbor->request(pair, instance);
    neighbor->requests[irequest]->half = 0;
    neighbor->requests[irequest]->full = 1;
    neighbor->requests[irequest]->id = id;
#endif
  }

  // forward communication of per-atom data of a pair style
  inline void forward_comm(Comm *comm, Pair *pair)
  {
#ifdef MCA_HAVE_COMM_OVERLOADS
    comm->forward_comm(pair);
#else
    comm->forward_comm_pair(pair);
#endif
  }

  // forward communication of per-atom data of a fix
  inline void forward_comm(Comm *comm, Fix *fix)
  {
#ifdef MCA_HAVE_COMM_OVERLOADS
    comm->forward_comm(fix);
#else
    comm->forward_comm_fix(fix);
#endif
  }

  // reverse communication of per-atom data of a fix
  inline void reverse_comm(Comm *comm, Fix *fix)
  {
#ifdef MCA_HAVE_COMM_OVERLOADS
    comm->reverse_comm(fix);
#else
    comm->reverse_comm_fix(fix);
#endif
  }

  // minimum image convention for a separation vector
  inline void minimum_image(Domain *domain, double *delta)
  {
#ifdef MCA_HAVE_MINIMUM_IMAGE_FLERR
    domain->minimum_image(FLERR, delta);
#else
    domain->minimum_image(delta);
#endif
  }

  // an atom type as written to data files: its label where labels are in use
  inline std::string type_name(Atom *atom, int type)
  {
#ifdef MCA_HAVE_TYPE_LABELS
    if (atom->types_style == Atom::LABELS) return atom->lmap->find_label(type, Atom::ATOM);
#else
    (void) atom;
#endif
    return std::to_string(type);
  }

}    // namespace MCACompat
}    // namespace LAMMPS_NS

#endif
