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
   Layout of a link's history row and of an automaton's law state.
------------------------------------------------------------------------- */

#ifndef LMP_MCA_LINK_LAYOUT_H
#define LMP_MCA_LINK_LAYOUT_H

#include "mca_inline.h"

#include <cmath>

namespace LAMMPS_NS {
namespace MCAKernels {

  /* ----------------------------------------------------------------------
     A link's history row is made of the blocks of the parts of the link
     model (mca_link_model.h), each declared by its part: the elastic part
     always, first, at offset 0; the blocks of optional parts (plasticity,
     fracture, damping, ...) follow in the order they are selected, at
     offsets the model computes at run time (MCALinkLayout).  The same holds
     for the per-automaton state of the law.  A row is in canonical order;
     the two ends of a link between local automata share it (FixMCALinks).

     Conventions of the elastic block (see doc/src/pair_mca.rst):
     - a pair is stored and computed in canonical order: "lo" is the
       automaton with the lower atom ID, "hi" the other; n points lo -> hi
     - tractions are tension positive; sigma is the normal traction and t
       the shear traction vector acting on lo (on hi they act with opposite
       sign), both per unit contact area
     - each automaton keeps its half of the pair state (strain, tractions;
       the couple is shared: H_COUPLE); the Newton-3 splits make the two
       halves' tractions equal
     - q0 = reference distance from an automaton's centre to the contact
       plane (q0_lo + q0_hi = reference length r0), q = q0 (1 + eps)
  ------------------------------------------------------------------------- */

  // the elastic block of a row (doubles).  What the mean-stress predictor
  // reads comes first (up to the normal tractions of both halves), so that
  // its pass touches few cache lines.  The couple is kept once: the halves'
  // couples take the same increments and turn alike, so they are equal
  // unless plasticity scales them apart, and then its block keeps the
  // couple of hi (P_COUPLE_HI, couple_hi_offset in mca_link_law.h).  H_LAYOUT
  // numbers this order in restart files (1000 H_LAYOUT + H_SIZE); layout
  // 1 (27 values: a couple in each half) is read and converted
  // (convert_layout1_row); blocks are recorded by name (FixMCALinks)
  enum { H_LAYOUT = 2 };
  enum LinkHistory {
    H_STATE = 0,    // link state (LINKED)
    H_RPREV,        // length at the last step
    H_Q0LO,         // reference half lengths
    H_Q0HI,
    H_LO,                     // half of lo: sigma, eps, t(3)
    H_HI = H_LO + 5,          // half of hi
    H_COUPLE = H_HI + 5,      // couple of the halves (3; of lo's with plasticity)
    H_R0 = H_COUPLE + 3,      // reference length r0
    H_A0,                     // reference contact area
    H_NPREV,                  // unit normal lo -> hi at the last step (3)
    H_APREV = H_NPREV + 3,    // contact area at the last step
    H_WORK,                   // elastic energy of the link
    H_SIZE                    // size of the elastic block
  };
  // the slots of the elastic block that a row in precision mixed keeps in
  // double (MCALinkPartInfo, mca_row_codec.h)
  constexpr unsigned ELASTIC_EXACT_SLOTS =
      1u << H_RPREV | 1u << H_Q0LO | 1u << H_Q0HI | 1u << H_R0 | 7u << H_NPREV;
  // offsets inside a half (ints: C++20 deprecates adding them to the
  // LinkHistory enumerators if they were another enumeration)
  constexpr int HALF_SIG = 0, HALF_EPS = 1, HALF_T = 2, HALF_SIZE = 5;
  enum LinkState { LINK_NONE = 0, LINK_LINKED = 1, LINK_BROKEN = 2, LINK_CONTACT = 3 };

  // the elastic block of an automaton's law state (enumerators, not
  // constexpr variables: a Kokkos view takes its indices by reference, and
  // CUDA device code cannot refer to a host variable)
  enum AtomLawState {
    A_SMEAN_STEP = 0,    // mean stress from the tractions at the last step
    A_SMEAN_LAW,         // mean stress the normal law used at the last step
    A_SIZE               // size of the elastic block
  };

  // the longest row a pass copies on the stack (a setup works on a copy)
  constexpr int MAX_ROW_SIZE = 128;

  // most parts a link model can be made of (their ids: LinkPart in
  // mca_link_law.h)
  constexpr int MAX_PARTS = 8;

  /* where the blocks of a model lie, as the kernels read it: plain ints,
     copied into every kernel; a part that is not in the model has the
     offset -1.  The elastic block is always at 0, so its slots (H_*, A_*)
     are compile-time offsets.                                            */

  struct MCALinkLayout {
    int row_size;                  // values per link row, as the law reads it
    int atom_size;                 // doubles of law state per automaton
    int link_offset[MAX_PARTS];    // where each part's block starts in a row
    int atom_offset[MAX_PARTS];    // and in an automaton's state
    // how a row is stored (mca_row_codec.h): in row_size doubles, or with
    // "precision mixed" its exact slots (a bit each in exact) in doubles
    // and the others in floats after them; stored_size doubles in all
    int mixed;
    int stored_size;
    int exact_count;
    unsigned exact[MAX_ROW_SIZE / 32];
  };

}    // namespace MCAKernels
}    // namespace LAMMPS_NS

#endif
