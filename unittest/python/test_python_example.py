"""examples/python/poisson_study.py run as its README says (python3 with the
current build's Python module), on a small cube: 4 cells across, 365
automata, nu = 0 and 0.3.

What it must find (tolerances from bench/pareto.py's cube at n = 4, whose
apparent E is 0.82 % low and nu 0.25 % low): the apparent E within 1.5 % of
70 GPa and the apparent nu within 0.01 of the input, for both ratios; the
mean stress of the interior automata (compute mca/atom, read as a numpy
array) within 5 % of the grip's stress (the stress of the uniform state
the loading approaches; the cube still rings about it); a CSV row per run
and the plot, the final state of each run as a dump sorted by ID; bad
arguments refused with the reason.
"""

import csv
import os
import subprocess
import sys

import numpy as np
import pytest

import mcatest

SCRIPT = mcatest.ROOT / "examples" / "python" / "poisson_study.py"


def environment():
    build = mcatest.build_named("current")
    if build is None:
        pytest.skip("the Python module belongs to the current build")
    env = build.environment()
    if build.tree is not None:
        env["PYTHONPATH"] = str(build.tree / "python") + os.pathsep + env.get("PYTHONPATH", "")
    env["LD_LIBRARY_PATH"] = str(build.path) + os.pathsep + env.get("LD_LIBRARY_PATH", "")
    return env


def test_poisson_study_finds_the_continuum_moduli(tmp_path):
    result = subprocess.run([sys.executable, str(SCRIPT), "--nu", "0.0", "0.3", "--n", "4",
                             "--out", str(tmp_path)], env=environment(), capture_output=True,
                            text=True, timeout=600)
    assert result.returncode == 0, result.stdout[-2000:] + result.stderr[-3000:]
    print(result.stdout)
    with open(tmp_path / "poisson_study.csv") as f:
        rows = list(csv.DictReader(f))
    assert [float(r["nu"]) for r in rows] == [0.0, 0.3]
    for r in rows:
        assert int(r["automata"]) == 365
        assert abs(float(r["E_error"])) < 0.015, r
        assert abs(float(r["nu_error"])) < 0.01, r
        assert abs(float(r["inner_vs_grip"])) < 0.05, r
        assert int(r["inner_automata"]) > 0
    assert (tmp_path / "poisson_study.png").stat().st_size > 10000
    final = mcatest.read_dump(tmp_path / "cube.nu0.3.dump")[-1]
    assert len(final["id"]) == 365 and np.all(np.diff(final["id"]) > 0)
    assert np.mean(final["c_stress[3]"]) > 0.0    # pulled along z, tension positive


@pytest.mark.parametrize("args, message", [
    (["--nu", "0.5"], "--nu 0.5: Poisson's ratio must lie in (-1, 0.5)"),
    (["--n", "1"], "--n 1: the cube needs at least 2 cells across"),
    (["--fraction", "1.5"], "--fraction 1.5: must lie in (0, 1]"),
])
def test_poisson_study_refuses_bad_arguments(tmp_path, args, message):
    result = subprocess.run([sys.executable, str(SCRIPT), "--out", str(tmp_path)] + args,
                            env=environment(), capture_output=True, text=True, timeout=60)
    assert result.returncode == 2 and message in result.stderr, result.stderr
    assert not (tmp_path / "poisson_study.csv").exists()
