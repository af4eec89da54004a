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
   MCA_INLINE: how the MCA kernels (mca_*.h) are declared.  Plain
   arithmetic on doubles, no LAMMPS or STL objects, so that the CPU styles
   and the Kokkos styles (host or device) call the same functions.  In
   the sources of KOKKOS_MCA (compiled with MCA_KOKKOS_KERNELS, see
   cmake/Modules/Packages/MCA.cmake) MCA_INLINE is KOKKOS_INLINE_FUNCTION.
------------------------------------------------------------------------- */

#ifndef LMP_MCA_INLINE_H
#define LMP_MCA_INLINE_H

// A Kokkos style's source sees Kokkos' function macros whichever header
// came first: one whose header included its CPU style's header, and so
// the kernels, before Kokkos made them host functions, which CUDA device
// code cannot call (nvcc only warns, and the call computed nothing on the
// GPU: bond beam/kk, found on an H200 on 28 Nov 2026).  (The CPU styles'
// sources keep host functions: there the kernels are called with host
// accessors, which a host-and-device function may not call.)
#if defined(MCA_KOKKOS_KERNELS) && !defined(KOKKOS_INLINE_FUNCTION)
#include <Kokkos_Macros.hpp>
#endif

// internal linkage: the kernels are inlined and never called through the
// procedure linkage table of the shared library
#ifndef MCA_INLINE
#if defined(KOKKOS_INLINE_FUNCTION)
#define MCA_INLINE static KOKKOS_INLINE_FUNCTION
#else
#define MCA_INLINE static inline
#endif
#endif

// a kernel that must be inlined into its caller: the link law, whose
// struct arguments cost loads and stores where it is a call of its own
#ifndef MCA_FORCE_INLINE
#if defined(KOKKOS_FORCEINLINE_FUNCTION)
#define MCA_FORCE_INLINE static KOKKOS_FORCEINLINE_FUNCTION
#elif defined(__GNUC__)
#define MCA_FORCE_INLINE static inline __attribute__((always_inline))
#else
#define MCA_FORCE_INLINE static inline
#endif
#endif

// the same for member functions and templates that are not static
#ifndef MCA_FUNCTION
#if defined(KOKKOS_INLINE_FUNCTION)
#define MCA_FUNCTION KOKKOS_INLINE_FUNCTION
#else
#define MCA_FUNCTION inline
#endif
#endif

#endif
