# Add the MCA package (and KOKKOS_MCA) to a LAMMPS source tree.
#
#   cmake -D LAMMPS_DIR=/path/to/lammps [-D MODE=link|copy] -P cmake/mca-install.cmake
#   cmake -D LAMMPS_DIR=/path/to/lammps -D MODE=uninstall   -P cmake/mca-install.cmake
#
# What it changes in the LAMMPS tree (nothing else):
#   src/MCA, src/KOKKOS_MCA         symbolic links to this checkout (MODE=link, default)
#                                   or copies of it (MODE=copy)
#   cmake/Modules/Packages/MCA.cmake  link or copy of this checkout's file
#   cmake/CMakeLists.txt            two one-word edits: "MCA" is added to the
#                                   STANDARD_PACKAGES list (gives -D PKG_MCA=on) and
#                                   to the list of packages whose cmake file is
#                                   included after KOKKOS (registers the kk styles)
# The edits are idempotent: running the script twice changes nothing.
# Then configure LAMMPS as usual, adding -D PKG_MCA=on.

cmake_minimum_required(VERSION 3.16)

if(NOT LAMMPS_DIR)
  message(FATAL_ERROR "mca-install: set -D LAMMPS_DIR=<LAMMPS source tree>")
endif()
get_filename_component(LAMMPS_DIR "${LAMMPS_DIR}" ABSOLUTE)
if(NOT MODE)
  set(MODE link)
endif()
if(NOT MODE MATCHES "^(link|copy|uninstall)$")
  message(FATAL_ERROR "mca-install: MODE must be link, copy or uninstall, not '${MODE}'")
endif()
get_filename_component(MCA_ROOT "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)
set(_cmakelists ${LAMMPS_DIR}/cmake/CMakeLists.txt)
if(NOT EXISTS ${_cmakelists} OR NOT EXISTS ${LAMMPS_DIR}/src/lammps.cpp)
  message(FATAL_ERROR "mca-install: ${LAMMPS_DIR} is not a LAMMPS source tree")
endif()

# items linked or copied into the LAMMPS tree: <path in this checkout> <path in LAMMPS>
set(_items
  src/MCA src/MCA
  src/KOKKOS_MCA src/KOKKOS_MCA
  cmake/Modules/Packages/MCA.cmake cmake/Modules/Packages/MCA.cmake)

file(READ ${_cmakelists} _text)
set(_orig "${_text}")
set(_std_marker "set(STANDARD_PACKAGES\n  MCA # added by mca-install.cmake\n")
set(_incl_regex "(foreach\\(PKG_WITH_INCL [^\n]*KOKKOS[^\n)]*)\\)")

# remove a link without following it, or a copied file or directory
function(mca_remove path)
  if(IS_SYMLINK ${path})
    file(REMOVE ${path})
  elseif(EXISTS ${path})
    file(REMOVE_RECURSE ${path})
  endif()
endfunction()

if(MODE STREQUAL "uninstall")
  list(LENGTH _items _n)
  math(EXPR _last "${_n} - 1")
  foreach(_i RANGE 1 ${_last} 2)
    list(GET _items ${_i} _dst)
    mca_remove(${LAMMPS_DIR}/${_dst})
  endforeach()
  string(REPLACE "${_std_marker}" "set(STANDARD_PACKAGES\n" _text "${_text}")
  string(REPLACE " MCA)" ")" _text "${_text}")
  if(NOT _text STREQUAL _orig)
    file(WRITE ${_cmakelists} "${_text}")
  endif()
  message(STATUS "mca-install: removed MCA from ${LAMMPS_DIR}")
  return()
endif()

list(LENGTH _items _n)
math(EXPR _last "${_n} - 1")
foreach(_i RANGE 0 ${_last} 2)
  math(EXPR _j "${_i} + 1")
  list(GET _items ${_i} _src)
  list(GET _items ${_j} _dst)
  set(_src ${MCA_ROOT}/${_src})
  set(_dst ${LAMMPS_DIR}/${_dst})
  if(MODE STREQUAL "link" AND IS_SYMLINK ${_dst})
    file(READ_SYMLINK ${_dst} _target)
    if(_target STREQUAL _src)
      continue()
    endif()
  endif()
  mca_remove(${_dst})
  if(MODE STREQUAL "link")
    file(CREATE_LINK ${_src} ${_dst} SYMBOLIC RESULT _res)
    if(NOT _res EQUAL 0)
      message(FATAL_ERROR "mca-install: cannot link ${_dst} -> ${_src}: ${_res}")
    endif()
  else()
    if(IS_DIRECTORY ${_src})
      file(COPY ${_src}/ DESTINATION ${_dst})
    else()
      get_filename_component(_dir ${_dst} DIRECTORY)
      file(COPY ${_src} DESTINATION ${_dir})
    endif()
  endif()
endforeach()

# edit 1: MCA becomes a standard package (-D PKG_MCA=on)
string(FIND "${_text}" "${_std_marker}" _pos)
if(_pos EQUAL -1)
  string(FIND "${_text}" "set(STANDARD_PACKAGES\n" _pos)
  if(_pos EQUAL -1)
    message(FATAL_ERROR "mca-install: no 'set(STANDARD_PACKAGES' list in ${_cmakelists}")
  endif()
  string(REPLACE "set(STANDARD_PACKAGES\n" "${_std_marker}" _text "${_text}")
endif()

# edit 2: include Packages/MCA.cmake after Packages/KOKKOS.cmake
string(REGEX MATCH "${_incl_regex}" _line "${_text}")
if(NOT _line)
  message(FATAL_ERROR "mca-install: no 'foreach(PKG_WITH_INCL ... KOKKOS ...)' loop in ${_cmakelists}")
endif()
if(NOT _line MATCHES " MCA\\)$")
  string(REGEX REPLACE "${_incl_regex}" "\\1 MCA)" _text "${_text}")
endif()
# write only on change: a new time stamp would make every build re-run cmake
if(NOT _text STREQUAL _orig)
  file(WRITE ${_cmakelists} "${_text}")
endif()
message(STATUS "mca-install: MCA ${MODE}ed into ${LAMMPS_DIR}; configure with -D PKG_MCA=on")
