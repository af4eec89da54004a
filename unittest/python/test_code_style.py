"""The package sources follow the LAMMPS code style.

clang-format with the LAMMPS settings (src/.clang-format of the LAMMPS tree
of the "current" build) must leave every C++ file of src/MCA and
src/KOKKOS_MCA unchanged.
"""

import shutil
import subprocess

import pytest

from mcatest import ROOT, build_named

SOURCES = sorted(p for d in ("MCA", "KOKKOS_MCA") for ext in ("*.h", "*.cpp")
                 for p in (ROOT / "src" / d).glob(ext))


@pytest.mark.parametrize("source", SOURCES, ids=[p.name for p in SOURCES])
def test_clang_format_clean(source):
    current = build_named("current")
    if current is None or current.tree is None:
        pytest.skip("needs the LAMMPS tree of the current build for its .clang-format")
    clang_format = shutil.which("clang-format")
    assert clang_format, "clang-format is not installed (tools/mca installs it)"
    style = current.tree / "src" / ".clang-format"
    formatted = subprocess.run([clang_format, f"--style=file:{style}", str(source)],
                               capture_output=True, text=True, check=True).stdout
    assert formatted == source.read_text(), \
        f"{source.name} is not clang-format clean: run clang-format -i --style=file:{style}"
