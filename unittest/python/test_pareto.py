"""The MCA speed-against-error benchmark (bench/pareto.py): what its
errors and its front rest on, on small cases of its own scenes.

* front: the Pareto front is the set of runs no other run beats in both
  cost and error (by more than 1 % of the error: the same model run in
  another mode is not a new point), cheapest first, and the cheapest run
  within a tolerance is on it;
* wave: the measured phase speed is the MCA dispersion relation of
  examples/waves (the law's error in space, exact for the law) plus a
  time-step error of second order: at 0.1 of the stable step the speed is
  within 0.1 % of the relation (measured 0.065 % at m = 10), halving the
  step divides the rest by 4 +- 0.5 (3.87 measured: the higher orders),
  and the largest energy deviation by 4 +- 0.3 (4.0); at nu = 0, where
  the law has no mean stress, the time-step error is velocity Verlet's
  for a harmonic mode of the wave's frequency, sin(w dt/2) = Omega dt/2,
  to 2 % of itself (0.06 % measured); at nu = 0.3 the mean-stress
  predictor makes it 5 times that (measured 4.97: more than 3 times);
* wave amplitude: the loss per period of a sampled damped oscillator
  is its own to 1e-9 (the fitted recurrence is exact for it, also at 5
  samples a period); at nu = 0 the wave keeps its
  amplitude (velocity Verlet on a linear conservative law: measured 1.3e-11
  per period at m = 10, the round-off of displacements of 1e-6 m on
  positions of metres; below 1e-8), at nu = 0.3 it loses 2.5 % a period at
  0.1 and 4.7 % at 0.2 of the stable step, a first-order damping of the
  mean-stress predictor's one-step lag (doc/src/pair_mca.rst): the ratio
  is within 0.25 of 2 (1.85; 1.98 at 0.05 and 0.025);
* cube: the apparent E and nu of the elastic cube converge with the
  resolution (E -0.82 % at n = 4, -0.34 % at n = 6: within 1 % and 0.5 %)
  and do not depend on the time step (the loading is quasi-static: the
  errors at 0.3 and 0.9 of the stable step agree to 1e-4);
* plastic: the yield stress of the plastic cube at n = 4 is within 1 %
  of sigma_y (-0.56 %), the post-yield slope within 1 % of E H/(E + H);
* modes: 2 MPI ranks give the errors of 1 rank to round-off (1e-9);
* the tool writes its table, CSV and plot (with --repeat, each case's
  cheapest run), and bad arguments stop it with a message that names the
  argument.
"""

import csv
import math
import subprocess
import sys

import numpy as np
import pytest

import mcatest

sys.path.insert(0, str(mcatest.ROOT / "bench"))
import pareto  # noqa: E402


def run(build, tmp_path, scene, value, fraction, mode="cpu", nu=None):
    work = tmp_path / f"{scene}{value}.{fraction}.{mode}.{nu}"
    work.mkdir(parents=True, exist_ok=True)
    return pareto.run_case(scene, value, fraction, mode, work, str(build.lmp), None, nu=nu)


def test_pareto_front_and_cheapest():
    costs = [1.0, 2.0, 2.0, 3.0, 5.0, 8.0, 0.5]
    errors = [0.10, 0.05, 0.02, 0.04, 0.01, 0.01, 0.3]
    front = pareto.pareto_front(costs, errors)
    assert front == [6, 0, 2, 4]             # 1 and 3 are beaten by 2, 5 by 4
    for i in range(len(costs)):             # nothing on the front is beaten
        if i in front:
            assert not any(costs[j] <= costs[i] and errors[j] < errors[i] for j in range(len(costs)))
    rows = [{"core_seconds": c, "error": e} for c, e in zip(costs, errors)]
    assert pareto.cheapest_within(rows, "error", 0.03)["core_seconds"] == 2.0
    assert pareto.cheapest_within(rows, "error", 0.001) is None
    # the same model in another mode: the same error to round-off, dearer
    assert pareto.pareto_front(costs + [2.5], errors + [0.02 * (1 - 1e-12)]) == front
    assert pareto.pareto_front(costs + [2.5], errors + [0.019]) == [6, 0, 2, 7, 4]


def test_precision_table_pairs_the_cases():
    """The table of precision mixed against double pairs each mixed run
    with the double run of the same case (scene, resolution, fraction,
    mode) and reports the largest change of each error and the cost ratio;
    a mixed run without its double case is left out, and without mixed
    runs there is no table."""
    def row(n, precision, cost, e, nu, mode="cpu"):
        return {"scene": "cube", "resolution": n, "fraction": 0.9, "mode": mode,
                "precision": precision, "core_seconds": cost, "E_error": e, "nu_error": nu}
    rows = [row(4, "double", 1.0, -0.008, 0.002), row(4, "mixed", 1.1, -0.008 + 3e-8, 0.002),
            row(10, "double", 10.0, -0.001, 1e-4), row(10, "mixed", 12.0, -0.001, 1e-4 - 5e-8),
            row(6, "mixed", 1.0, 0.5, 0.5)]
    lines = pareto.precision_table(rows)
    cube = {line.split("|")[2].strip(): line.split("|")[3:7] for line in lines
            if line.startswith("| cube")}
    assert float(cube["E_error"][0]) == pytest.approx(3e-8, rel=1e-3)
    assert float(cube["nu_error"][0]) == pytest.approx(5e-8, rel=1e-3)
    assert cube["E_error"][1].strip() == "0.001 - 0.008"
    assert cube["E_error"][2].strip() == "2"
    assert cube["E_error"][3].strip() == "1.100 - 1.200"
    assert pareto.precision_table([r for r in rows if r["precision"] == "double"]) == []


@pytest.mark.parametrize("loss", [0.0, 0.004, 0.09])
def test_amplitude_loss_of_a_damped_oscillator(loss):
    period = 0.37
    t = np.linspace(0.0, 3.3 * period, 401)
    rate = -math.log(1.0 - loss) / period
    omega = 2 * math.pi / period
    # a damped oscillator released at rest, as the standing wave is
    amp = 1e-6 * np.exp(-rate * t) * (np.cos(omega * t) + rate / omega * np.sin(omega * t))
    assert pareto.amplitude_loss(t, amp) == pytest.approx(loss, abs=1e-9)
    # at 5 samples a period as well
    assert pareto.amplitude_loss(t[::25], amp[::25]) == pytest.approx(loss, abs=1e-9)


_WAVES = {}


def waves_m10(build, tmp_path_factory):
    """The wave at m = 10, f = 0.1 and 0.2, run once for the two tests that read it."""
    if build.name not in _WAVES:
        tmp_path = tmp_path_factory.mktemp("waves")
        _WAVES[build.name] = {f: run(build, tmp_path, "wave", 10, f) for f in (0.1, 0.2)}
    return _WAVES[build.name]


def test_wave_amplitude(build, tmp_path, tmp_path_factory):
    fine, coarse = (waves_m10(build, tmp_path_factory)[f] for f in (0.1, 0.2))
    chain = run(build, tmp_path, "wave", 10, 0.2, nu=0.0)
    print(f"amplitude lost per period: nu 0.3 {fine['amplitude_loss']:.4e} (f 0.1), "
          f"{coarse['amplitude_loss']:.4e} (f 0.2); nu 0 {chain['amplitude_loss']:.3e}")
    assert abs(chain["amplitude_loss"]) < 1e-8
    assert fine["amplitude_loss"] > 0.01
    assert coarse["amplitude_loss"] / fine["amplitude_loss"] == pytest.approx(2.0, abs=0.25)


def test_wave_speed_is_the_dispersion_relation_to_second_order_in_time(build, tmp_path,
                                                                        tmp_path_factory):
    fine, coarse = (waves_m10(build, tmp_path_factory)[f] for f in (0.1, 0.2))
    print(f"m 10: speed {fine['speed_error']:+.4e} (law {fine['law_speed_error']:+.4e}), "
          f"time part {fine['time_speed_error']:.3e} / {coarse['time_speed_error']:.3e}, "
          f"energy {fine['energy_error']:.3e} / {coarse['energy_error']:.3e}")
    assert fine["law_speed_error"] == pytest.approx(-0.0614, abs=5e-4)   # examples/waves
    assert abs(fine["time_speed_error"]) < 1e-3
    assert fine["time_speed_error"] > 0          # the time step speeds a mode up
    assert coarse["time_speed_error"] / fine["time_speed_error"] == pytest.approx(4.0, abs=0.5)
    assert coarse["energy_error"] / fine["energy_error"] == pytest.approx(4.0, abs=0.3)
    assert coarse["time_speed_error"] > 3 * coarse["verlet_speed_error"]
    chain = run(build, tmp_path, "wave", 10, 0.2, nu=0.0)
    print(f"nu 0: time part {chain['time_speed_error']:.5e}, Verlet {chain['verlet_speed_error']:.5e}")
    assert chain["time_speed_error"] == pytest.approx(chain["verlet_speed_error"], rel=0.02)


def test_cube_moduli_converge_and_do_not_depend_on_the_step(build, tmp_path):
    n4 = run(build, tmp_path, "cube", 4, 0.9)
    n4_fine = run(build, tmp_path, "cube", 4, 0.3)
    n6 = run(build, tmp_path, "cube", 6, 0.9)
    print(f"n 4: E {n4['E_error']:+.4e} nu {n4['nu_error']:+.4e}; n 6: E {n6['E_error']:+.4e} "
          f"nu {n6['nu_error']:+.4e}; n 4 at f 0.3: E {n4_fine['E_error']:+.4e}")
    assert n4["error"] < 0.01 and n6["error"] < 0.005
    assert n6["error"] < 0.6 * n4["error"]
    for key in ("E_error", "nu_error"):
        assert abs(n4[key] - n4_fine[key]) < 1e-4


def test_plastic_cube_yield(build, tmp_path):
    row = run(build, tmp_path, "plastic", 4, 0.9)
    print(f"n 4: yield {row['yield_error']:+.4e}, tangent {row['tangent_error']:+.4e}")
    assert abs(row["yield_error"]) < 0.01 and abs(row["tangent_error"]) < 0.01


@pytest.mark.mpi
def test_two_ranks_give_the_same_errors(build, tmp_path):
    one = run(build, tmp_path, "plastic", 4, 0.9)
    two = run(build, tmp_path, "plastic", 4, 0.9, mode="cpu_mpi2")
    for key in ("yield_error", "tangent_error"):
        assert two[key] == pytest.approx(one[key], abs=1e-9)
    assert two["core_seconds"] > 0 and two["automata"] == one["automata"]


def command(build, tmp_path, *args):
    return subprocess.run([sys.executable, str(mcatest.ROOT / "bench" / "pareto.py"),
                           "--lmp", str(build.lmp), "--out", str(tmp_path / "p"), *args],
                          capture_output=True, text=True, env=build.environment(), timeout=600)


def test_outputs(build, tmp_path):
    result = command(build, tmp_path, "--scenes", "wave", "--wave-m", "4", "6",
                     "--fractions", "0.5", "0.9", "--repeat", "2")
    assert result.returncode == 0, result.stdout[-2000:] + result.stderr[-2000:]
    with open(tmp_path / "p.csv") as f:
        rows = list(csv.DictReader(f))
    assert [(r["resolution"], r["fraction"]) for r in rows] == [
        ("4", "0.5"), ("4", "0.9"), ("6", "0.5"), ("6", "0.9")]
    table = (tmp_path / "p.md").read_text()
    assert "wave: phase speed against c_p" in table and "Cheapest within 10 %" in table
    assert (tmp_path / "p.png").stat().st_size > 10000
    # each case's cheapest of its two runs (the sweep runs twice, in order)
    runs = [float(line.split("core-s")[0].split()[-1]) for line in result.stdout.splitlines()
            if line.startswith("wave ") and "(repeat " in line]
    assert len(runs) == 8
    for k, r in enumerate(rows):
        assert float(r["core_seconds"]) == pytest.approx(min(runs[k], runs[k + 4]), abs=6e-4)


@pytest.mark.parametrize("args, message", [
    (("--fractions", "1.2"), "--fractions: 1.2 is outside (0, 1)"),
    (("--wave-m", "5"), "--wave-m: 5 must be even"),
    (("--cube-n", "1"), "--cube-n/--plastic-n: 1 must be at least 2"),
    (("--modes", "kk1"), "need --lmp-kokkos"),
    (("--repeat", "0"), "--repeat: 0 must be at least 1"),
])
def test_bad_arguments(build, tmp_path, args, message):
    result = command(build, tmp_path, *args)
    assert result.returncode == 2 and message in result.stderr
