"""The LAMMPS unit-test programs run the package's YAML force-style tests.

unittest/force-styles/tests holds YAML files in the format of LAMMPS's
unittest/force-styles; each runs with the tester of both LAMMPS versions.
The testers compare positions, velocities, torques (and forces, energies,
stress for pair and bond styles) against the reference data in the file for
a plain run, a run split by write_restart/read_restart, r-RESPA, and more.
A tester that skips its main test (e.g. a missing prerequisite style) fails
here: a skipped test proves nothing.
"""

import re
import subprocess

import pytest

from mcatest import UNITTEST

TESTS = UNITTEST / "force-styles" / "tests"
PROGRAMS = {"fix-timestep-": ("test_fix_timestep", "FixTimestep.plain"),
            "atomic-pair-": ("test_pair_style", "PairStyle.plain"),
            "manybody-pair-": ("test_pair_style", "PairStyle.plain"),
            "bond-": ("test_bond_style", "BondStyle.plain")}
YAML_FILES = sorted(TESTS.glob("*.yaml"))


def program_for(path):
    for prefix, program in PROGRAMS.items():
        if path.name.startswith(prefix):
            return program
    raise AssertionError(f"no LAMMPS tester for {path.name}")


@pytest.mark.parametrize("yaml_file", YAML_FILES, ids=[p.stem for p in YAML_FILES])
def test_yaml(build, tmp_path, yaml_file):
    program, main_test = program_for(yaml_file)
    result = subprocess.run([str(build.tester(program)), str(yaml_file), "-d", str(TESTS)],
                            cwd=tmp_path, capture_output=True, text=True, timeout=600,
                            env=build.environment())
    output = result.stdout + result.stderr
    failures = [line for line in output.splitlines() if "Failure" in line or "[  FAILED  ]" in line]
    assert result.returncode == 0, "\n".join(failures[:40]) or output[-3000:]
    assert re.search(rf"\[       OK \] {re.escape(main_test)}", output), \
        f"{main_test} did not run and pass:\n{output[-3000:]}"
