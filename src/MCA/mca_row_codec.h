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
   How a link's row is stored.  The law reads and writes a row as
   row_size doubles (mca_link_layout.h); the links fix stores it

   - in precision double (the default): as those doubles; a pass that
     updates a row works on the stored row itself
   - in precision mixed (pair_style mca ... precision mixed): its exact
     slots (the lengths and the normal, step numbers: MCALinkPartInfo) in
     doubles, in slot order, then the other slots in floats, in slot
     order, two to a double: 128 bytes instead of 192 for the elastic
     row.  A pass decodes a row into doubles, works on them and encodes
     the result, so the arithmetic stays in double; what is rounded is what
     a step leaves in the row (bench/README.md: its errors)

   A float is read and written with memcpy: the pool is an array of
   doubles, and memcpy is the access that C++ and CUDA allow to the bytes
   of one type as another (compilers make it a single load or store).
   Decoding then encoding a row gives back the same bytes (a float widened
   to double and rounded back is itself), so restart files hold rows as
   doubles in both precisions and a restart may change the precision.
------------------------------------------------------------------------- */

#ifndef LMP_MCA_ROW_CODEC_H
#define LMP_MCA_ROW_CODEC_H

#include "mca_link_layout.h"

#include <cstring>

namespace LAMMPS_NS {
namespace MCAKernels {

  // is slot k of a row kept in double by a mixed row?
  MCA_INLINE bool exact_slot(const MCALinkLayout &l, int k)
  {
    return (l.exact[k / 32] >> (k % 32)) & 1u;
  }

  // float f of a mixed row (after its exact_count doubles)
  MCA_FORCE_INLINE double stored_float(const MCALinkLayout &l, const double *stored, int f)
  {
    float v;
    memcpy(&v, reinterpret_cast<const char *>(stored + l.exact_count) + f * sizeof(float),
           sizeof(float));
    return static_cast<double>(v);
  }
  MCA_FORCE_INLINE void store_float(const MCALinkLayout &l, double *stored, int f, double value)
  {
    const float v = static_cast<float>(value);
    memcpy(reinterpret_cast<char *>(stored + l.exact_count) + f * sizeof(float), &v, sizeof(float));
  }

  /* the elastic block of a mixed row, written out (it is always first, and
     its exact slots are ELASTIC_EXACT_SLOTS): doubles 0-6 are
     H_RPREV, H_Q0LO, H_Q0HI, H_R0, H_NPREV(3); floats 0-16 are H_STATE,
     the halves and the couple (H_LO to H_COUPLE + 2), H_A0, H_APREV,
     H_WORK.  The slots of the other blocks follow, exact ones in doubles
     from 7 and the others in floats from 17                               */
  constexpr int MIXED_ELASTIC_DOUBLES = 7, MIXED_ELASTIC_FLOATS = H_SIZE - 7;
  constexpr int MIXED_HALVES_FLOAT = 1, MIXED_HALVES = H_R0 - H_LO;
  static_assert(ELASTIC_EXACT_SLOTS ==
                    (1u << H_RPREV | 1u << H_Q0LO | 1u << H_Q0HI | 1u << H_R0 | 7u << H_NPREV),
                "the elastic block of a mixed row is written out below");
  static_assert(H_Q0LO == H_RPREV + 1 && H_Q0HI == H_RPREV + 2 && H_COUPLE + 3 == H_R0 &&
                    H_A0 == H_R0 + 1 && H_NPREV == H_A0 + 1 && H_WORK == H_APREV + 1 &&
                    H_SIZE == H_WORK + 1,
                "the order of the elastic block (mca_link_layout.h)");

  // the state of a stored row (H_STATE: the first float of a mixed row)
  MCA_FORCE_INLINE int stored_state(const MCALinkLayout &l, const double *stored)
  {
    return static_cast<int>(l.mixed ? stored_float(l, stored, 0) : stored[H_STATE]);
  }

  // a stored row as the law reads it: slots [0, end) into h (the whole row,
  // or its head: what the mean-stress predictor reads, H_PREDICTOR_END)
  constexpr int H_PREDICTOR_END = H_HI + HALF_SIG + 1;
  MCA_INLINE void decode_row(const MCALinkLayout &l, const double *stored, double *h, int end)
  {
    if (!l.mixed) {
      for (int k = 0; k < end; k++) h[k] = stored[k];
      return;
    }
    h[H_STATE] = stored_float(l, stored, 0);
    for (int k = 0; k < 3; k++) h[H_RPREV + k] = stored[k];
    const int halves = (end < H_R0 ? end : H_R0) - H_LO;
    for (int k = 0; k < halves; k++) h[H_LO + k] = stored_float(l, stored, MIXED_HALVES_FLOAT + k);
    if (end <= H_R0) return;
    h[H_R0] = stored[3];
    h[H_A0] = stored_float(l, stored, MIXED_HALVES_FLOAT + MIXED_HALVES);
    for (int k = 0; k < 3; k++) h[H_NPREV + k] = stored[4 + k];
    h[H_APREV] = stored_float(l, stored, MIXED_HALVES_FLOAT + MIXED_HALVES + 1);
    h[H_WORK] = stored_float(l, stored, MIXED_HALVES_FLOAT + MIXED_HALVES + 2);
    int nd = MIXED_ELASTIC_DOUBLES, nf = MIXED_ELASTIC_FLOATS;
    for (int k = H_SIZE; k < end; k++)
      h[k] = exact_slot(l, k) ? stored[nd++] : stored_float(l, stored, nf++);
  }
  MCA_INLINE void decode_row(const MCALinkLayout &l, const double *stored, double *h)
  {
    decode_row(l, stored, h, l.row_size);
  }

  // the law's row h to its stored form (the floats rounded to nearest)
  MCA_INLINE void encode_row(const MCALinkLayout &l, const double *h, double *stored)
  {
    if (!l.mixed) {
      for (int k = 0; k < l.row_size; k++) stored[k] = h[k];
      return;
    }
    store_float(l, stored, 0, h[H_STATE]);
    for (int k = 0; k < 3; k++) stored[k] = h[H_RPREV + k];
    for (int k = 0; k < MIXED_HALVES; k++)
      store_float(l, stored, MIXED_HALVES_FLOAT + k, h[H_LO + k]);
    stored[3] = h[H_R0];
    store_float(l, stored, MIXED_HALVES_FLOAT + MIXED_HALVES, h[H_A0]);
    for (int k = 0; k < 3; k++) stored[4 + k] = h[H_NPREV + k];
    store_float(l, stored, MIXED_HALVES_FLOAT + MIXED_HALVES + 1, h[H_APREV]);
    store_float(l, stored, MIXED_HALVES_FLOAT + MIXED_HALVES + 2, h[H_WORK]);
    int nd = MIXED_ELASTIC_DOUBLES, nf = MIXED_ELASTIC_FLOATS;
    for (int k = H_SIZE; k < l.row_size; k++)
      if (exact_slot(l, k))
        stored[nd++] = h[k];
      else
        store_float(l, stored, nf++, h[k]);
  }

  // the row a pass works on: a double row that the pass updates (commit)
  // is worked on where it is stored; otherwise a decoded copy in work (a
  // setup works on a copy: its rows do not advance)
  MCA_FORCE_INLINE double *open_row(const MCALinkLayout &l, double *stored, double *work,
                                    bool commit)
  {
    if (commit && !l.mixed) return stored;
    decode_row(l, stored, work);
    return work;
  }
  // after a pass that updates the row it opened
  MCA_FORCE_INLINE void close_row(const MCALinkLayout &l, const double *h, double *stored)
  {
    if (l.mixed) encode_row(l, h, stored);
  }
  // a row to read only: the stored row, or a decoded copy in work (of
  // slots [0, end): the head that the predictor reads, H_PREDICTOR_END)
  MCA_FORCE_INLINE const double *read_row(const MCALinkLayout &l, const double *stored,
                                          double *work, int end)
  {
    if (!l.mixed) return stored;
    decode_row(l, stored, work, end);
    return work;
  }
  MCA_FORCE_INLINE const double *read_row(const MCALinkLayout &l, const double *stored,
                                          double *work)
  {
    return read_row(l, stored, work, l.row_size);
  }

}    // namespace MCAKernels
}    // namespace LAMMPS_NS

#endif
