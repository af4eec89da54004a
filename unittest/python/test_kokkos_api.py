"""The Kokkos styles other than the atom style compile against the KOKKOS
package of the current LAMMPS.

No Kokkos >= 5.1 (which LAMMPS 4 Jul 2026's KOKKOS needs) can be had here, so
tools/mca-kk-api compiles each KOKKOS_MCA source with -fsyntax-only against
the 2026 LAMMPS headers and the Kokkos 3.4 headers of the "kokkos" build (see
its header and doc/src/Speed_kokkos_mca.rst, Restrictions).  pair mca/kk,
fix nve/mca/kk, fix mca/setvelocity/kk and the links fix must have no error
of their own: an interface that changed since 2021 and is not hidden by
mca_kokkos_compat.h shows up as one (as the 1d send list of the forward
communication did).  atom_style mca/kk is written against the AtomVecKokkos
of 2021; its errors are counted apart.
"""

import re
import subprocess

import pytest

from mcatest import ROOT, build_named

PORTED = ("pair_mca_kokkos.cpp", "fix_nve_mca_kokkos.cpp", "fix_mca_setvelocity_kokkos.cpp",
          "fix_mca_links_kokkos.cpp")


def test_kokkos_styles_compile_against_current_kokkos_headers():
    current, kokkos = build_named("current"), build_named("kokkos")
    if current is None or kokkos is None or current.tree is None or kokkos.tree is None:
        pytest.skip("needs the trees and builds of both LAMMPS versions")
    result = subprocess.run(["bash", str(ROOT / "tools" / "mca-kk-api")], capture_output=True,
                            text=True, timeout=600)
    output = result.stdout + result.stderr
    counts = {m.group(1): int(m.group(2)) for m in re.finditer(
        r"^(\S+\.cpp)\s+\d+ errors in atom_vec_mca_kokkos\.\*,\s+(\d+) elsewhere$", output, re.M)}
    for name in PORTED:
        assert name in counts, f"{name} was not checked:\n{output[-3000:]}"
        assert counts[name] == 0, f"{name} does not compile against the 2026 headers:\n{output}"
    assert result.returncode == 0, output[-3000:]
