"""The Kokkos styles compile against the KOKKOS package of the current
LAMMPS and Kokkos 5.

tools/mca-kk-api compiles each KOKKOS_MCA source with -fsyntax-only and the
package's warnings as errors against the LAMMPS 4 Jul 2026 headers (with its
KOKKOS package) and the headers of Debian's Kokkos >= 5.1 package that
'tools/mca setup' unpacks.  An interface that changed since 2021 and is not
hidden by mca_kokkos_compat.h shows up as an error, as the 1d send list of
the forward communication and the AtomVecKokkos of 2023 (virtual base, 64-bit
masks, abstract sort_kokkos and sync_pinned) did.  This is the check CI
runs; the kokkos5 build (tools/mca test-kokkos5) links and runs the styles.
"""

import re
import subprocess

import pytest

from mcatest import ROOT, build_named

STYLES = ("atom_vec_mca_kokkos.cpp", "pair_mca_kokkos.cpp", "fix_nve_mca_kokkos.cpp",
          "fix_mca_setvelocity_kokkos.cpp", "fix_mca_links_kokkos.cpp")


def test_kokkos_styles_compile_against_current_kokkos_headers():
    current = build_named("current")
    if current is None or current.tree is None:
        pytest.skip("needs the tree and build of LAMMPS 4 Jul 2026")
    result = subprocess.run(["bash", str(ROOT / "tools" / "mca-kk-api")], capture_output=True,
                            text=True, timeout=600)
    output = result.stdout + result.stderr
    counts = {m.group(1): int(m.group(2))
              for m in re.finditer(r"^(\S+\.cpp)\s+(\d+) errors$", output, re.M)}
    for name in STYLES:
        assert name in counts, f"{name} was not checked:\n{output[-3000:]}"
        assert counts[name] == 0, f"{name} does not compile against the 2026 headers:\n{output}"
    assert result.returncode == 0, output[-3000:]
