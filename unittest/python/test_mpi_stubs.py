"""The package compiles for a serial LAMMPS (BUILD_MPI=off).

A serial build links LAMMPS's MPI stubs (src/STUBS/mpi.h), whose send
buffers are `void *` where MPI's are `const void *`: a const variable passed
as a send buffer compiles with MPI and fails there (this happened twice,
found by the CUDA build of tools/mca-gpu, which is serial).  Each source of
src/MCA is compiled, syntax only, against the stubs of each tested build's
LAMMPS tree, with that build's generated headers.  (The KOKKOS_MCA sources
need the Kokkos headers of a configured build and are compiled by it.)
"""

import shutil
import subprocess

import pytest

from mcatest import ROOT

SOURCES = sorted((ROOT / "src" / "MCA").glob("*.cpp"))


def test_sources_compile_against_the_mpi_stubs(build):
    if build.tree is None:
        pytest.skip(f"the {build.name} build names no LAMMPS tree")
    compiler = shutil.which("g++")
    assert compiler, "g++ is not installed"
    tree = build.tree / "src"
    includes = [tree, tree / "STUBS", ROOT / "src" / "MCA", tree / "MANYBODY",
                build.path / "styles", build.path / "mca", build.path / "includes" / "lammps"]
    cmd = [compiler, "-std=c++17", "-fsyntax-only", "-DLAMMPS_SMALLBIG"]
    cmd += [f"-I{path}" for path in includes if path.is_dir()]
    result = subprocess.run(cmd + [str(s) for s in SOURCES], capture_output=True, text=True)
    errors = [line for line in result.stderr.splitlines() if "error" in line]
    assert result.returncode == 0, \
        f"{len(errors)} errors against {tree / 'STUBS' / 'mpi.h'}:\n" + "\n".join(errors[:20])
