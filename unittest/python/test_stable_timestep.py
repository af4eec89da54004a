"""The stable time step of pair mca (doc/src/pair_mca.rst, "Stable time
step"; compute mca/timestep).

* the estimate against the limit measured by bisection (bench/stability.py,
  reduced to 2000 steps): within 10 % below and 3 % above it on the scenes
  where the linear limit of the scheme holds (Poisson's ratios, packings,
  material and mass contrasts, damping, the mean-stress lag of a nearly
  incompressible solid); the recommended time step runs stable;
* the same estimate from the CPU and the kk styles (bit for bit, it is the
  same host code) and on 2 and 4 MPI ranks (to round-off of the Lanczos
  sums);
* the estimate is made again when the stiffness grew (a block squeezed by
  30 %: a warning during the run once the time step is above it) and
  only then: a free vibration run three times makes it once;
* the warning above the estimate names the time step to use, and the
  messages of a run that blows up (stretched, lost links) compare the time
  step with the estimate;
* compute mca/timestep without pair mca: a clear error (before the links
  exist: test_python_module.py, the only way to ask for it then).
"""

import math
import pathlib
import re
import sys
import tempfile

import pytest

import mcatest

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "bench"))
import stability  # noqa: E402

STEPS = 2000
TOL = 0.01
# the measured limit in units of the estimate: estimate at most 3 % above
# the limit and at most 10 % below it
LOWEST, HIGHEST = 1.0 / 1.03, 1.0 / 0.9

SCENES = ["fcc nu=0.3", "fcc nu=0.45", "sc nu=0.3", "periodic fcc nu=0.49",
          "two materials E x100 rho /10", "a tenth 10x lighter", "damping eta=4e6"]


def scene_script(name):
    return stability.HEADER + stability.SCENES[name] + stability.MOTION.format(radius="0.254")


@pytest.mark.parametrize("scene", SCENES)
def test_estimate_against_measured_limit(build, scene):
    script = scene_script(scene)
    estimate, lo, hi = stability.measure(str(build.lmp), scene, script, STEPS, TOL, 1)
    print(f"\n{build.name} {scene}: estimate {estimate:.6g} s, measured limit "
          f"{lo:.3f} - {hi:.3f} of it")
    assert lo >= LOWEST - TOL, f"the estimate is more than 3 % above the limit ({lo:.3f})"
    assert hi <= HIGHEST, f"the estimate is more than 10 % below the limit ({hi:.3f})"
    with tempfile.TemporaryDirectory() as tmp:
        ok, _ = stability.stable(str(build.lmp), script, 0.7, 2 * STEPS, 1, tmp)
    assert ok, "the recommended time step (0.7 of the estimate) is not stable"


def estimate_line(output):
    lines = [line for line in output.splitlines() if "pair mca: stable time step" in line]
    assert lines, output[-3000:]
    return lines


def estimate_value(line):
    return float(re.search(r"stable time step (\S+)", line).group(1))


def test_same_estimate_on_cpu_kk_and_ranks(tmp_path):
    build = mcatest.kokkos_build()
    script = scene_script("fcc nu=0.45").replace("run             ${nsteps}", "")
    values = {}
    if mcatest.on_gpu():
        # a GPU build is serial: the estimate on the GPU against the CPU style
        modes = [("cpu", 1, ()), ("kk2", 1, mcatest.kokkos_args())]
    else:
        modes = [("cpu", 1, ()), ("kk1", 1, mcatest.kokkos_args(1)),
                 ("kk2", 1, mcatest.kokkos_args(2)), ("cpu2", 2, ()), ("cpu4", 4, ())]
    for name, nprocs, args in modes:
        result = build.run(script, tmp_path / name, nprocs=nprocs, extra_args=args,
                           variables={"f": 0.5, "nsteps": 0})
        line = estimate_line(result.stdout)[0]
        values[name] = (line, estimate_value(line))
    print("\n" + "\n".join(f"{k}: {v[1]!r}" for k, v in values.items()))
    for name in ("kk1", "kk2"):
        if name in values:
            assert values[name][0] == values["cpu"][0]
    for name in ("cpu2", "cpu4"):
        if name in values:
            assert math.isclose(values[name][1], values["cpu"][1], rel_tol=1.0e-6)


SQUEEZE = """
units           si
atom_style      mca
atom_modify     map array
boundary        f f f
lattice         fcc 0.7184
region          box block -1 5 -1 5 -1 5
create_box      1 box
region          blk block -0.01 3.01 -0.01 3.01 -0.01 3.01
create_atoms    1 region blk
comm_modify     vel yes
pair_style      mca plasticity mises
pair_coeff      * * E 70e9 nu 0.3 rho 2700 yield 200e6 hardening 1e9
region          base block INF INF INF INF INF 0.01
region          top block INF INF INF INF 2.99 INF
group           base region base
group           top region top
fix             hold base mca/setvelocity NULL NULL 0
fix             push top mca/setvelocity NULL NULL -${v}
fix             nve all nve/mca
fix             calm all mca/damping 2000
compute         dt all mca/timestep
thermo_style    custom step c_dt
run             0
variable        dt equal 0.97*c_dt
timestep        ${dt}
thermo_style    custom step c_dt c_dt[3]
thermo_modify   format float %.10g
thermo          500
run             ${nsteps}
"""


def test_estimate_follows_the_stiffness(build, tmp_path):
    """A plastic block squeezed at its grips at 0.97 of its first estimate:
    its links stiffen (the areas grow as they shorten, the halves shorten),
    compute mca/timestep follows the estimate down in the thermo output,
    and when LAMMPS reneighbours the estimate is made again: once it is
    below the time step a warning says so (then the run blows up, as it
    must: the messages of the lost link name the time step too)."""
    nsteps = 4000
    length = 3 * 0.7184
    result = build.run(SQUEEZE, tmp_path / "squeeze",
                       variables={"v": 0.3 * length / (nsteps * 5.66e-5), "nsteps": nsteps},
                       check=False)
    t = mcatest.read_thermo(tmp_path / "squeeze" / "log.lammps")
    print(f"\nestimate {t['c_dt'][0]:.6g} -> {t['c_dt'][-1]:.6g} (step {t['Step'][-1]:.0f})")
    assert t["c_dt[3]"][0] == pytest.approx(0.97, rel=1e-6)
    assert t["c_dt"][-1] < 0.98 * t["c_dt"][0]
    warnings = [line for line in result.stdout.splitlines()
                if "is above the stable time step" in line]
    assert warnings, result.stdout[-3000:]
    match = re.search(r"Time step \S+ is above the stable time step (\S+) of pair mca at step "
                      r"(\d+) \(the stiffness changed by up to (\S+) %\) \((\S+) times it\)",
                      warnings[0])
    assert match, warnings
    assert 0 < int(match.group(2)) < nsteps
    assert float(match.group(3)) > 2.0 and float(match.group(4)) >= 1.0
    assert len(warnings) < 20, "a warning at every reneighbouring"


FREE = """
units           si
atom_style      mca
atom_modify     map array
boundary        f f f
lattice         fcc 0.7184
region          box block -1 5 -1 5 -1 5
create_box      1 box
region          blk block -0.01 3.01 -0.01 3.01 -0.01 3.01
create_atoms    1 region blk
comm_modify     vel yes
pair_style      mca
pair_coeff      * * E 70e9 nu 0.3 rho 2700
variable        vx atom 0.01*normal(0,1,1234)
velocity        all set v_vx 0 0 units box
fix             nve all nve/mca
timestep        2.0e-5
run             300
run             300
pair_coeff      * * E 140e9 nu 0.3 rho 2700
run             300
"""


def test_estimate_is_made_again_only_when_needed(build, tmp_path):
    result = build.run(FREE, tmp_path / "free")
    lines = estimate_line(result.stdout)
    print("\n" + "\n".join(lines))
    # once for the first two runs (nothing changed), again after E doubled:
    # the limit scales as 1/sqrt(E)
    assert len(lines) == 2
    ratio = estimate_value(lines[1]) / estimate_value(lines[0])
    assert math.isclose(ratio, 1.0 / math.sqrt(2.0), rel_tol=1.0e-4)


def test_warning_above_the_estimate(build, tmp_path):
    script = scene_script("fcc nu=0.3")
    quiet = build.run(script, tmp_path / "quiet", variables={"f": 0.7, "nsteps": 100})
    assert "above the stable time step" not in quiet.stdout
    estimate = estimate_value(estimate_line(quiet.stdout)[0])
    loud = build.run(script.replace("timestep        $(v_f*v_dtc)", "timestep ${dt}"),
                     tmp_path / "loud", variables={"f": 1.0, "nsteps": 0, "dt": 1.2 * estimate})
    warnings = [line for line in loud.stdout.splitlines() if line.startswith("WARNING")]
    assert any(re.search(r"Time step \S+ is above the stable time step \S+ of pair mca "
                         r"\(1\.2 times it\); use a time step <= (\S+) \(0\.7 of the stable "
                         r"time step\)", w) for w in warnings), warnings


def test_blowup_messages_name_the_time_step(build, tmp_path):
    """Above the limit the run blows up: the links stretch beyond the cutoff
    (a warning) until one is lost (an error); both compare the time step
    with the estimate."""
    script = scene_script("fcc nu=0.3").replace("thermo          $(v_nsteps/20)", "thermo 10")
    result = build.run(script, tmp_path / "blowup", variables={"f": 1.5, "nsteps": 3000},
                       check=False)
    output = result.stdout + result.stderr
    messages = [line for line in output.splitlines()
                if "longer than the cutoff" in line or "is lost" in line]
    assert messages, output[-3000:]
    assert all(re.search(r"the time step \S+ is \S+ times the stable time step \S+ of pair "
                         r"mca: a run that blows up stretches and loses links, use a time step "
                         r"<= \S+", m) for m in messages), messages


NO_PAIR_MCA = """
units           si
atom_style      mca
atom_modify     map array
lattice         fcc 0.7184
region          box block 0 3 0 3 0 3
create_box      1 box
create_atoms    1 box
comm_modify     vel yes
pair_style      zero 1.0
pair_coeff      * *
compute         dt all mca/timestep
thermo_style    custom step c_dt
run             0
"""


def test_compute_needs_pair_mca(build, tmp_path):
    result = build.run(NO_PAIR_MCA, tmp_path, check=False)
    output = result.stdout + result.stderr
    assert result.returncode != 0
    assert re.search(r"ERROR: Compute mca/timestep requires pair_style mca \(or mca/kk\), not "
                     r"zero", output), output[-2000:]
