"""KOKKOS_MCA: the kk styles (atom_style mca/kk, pair_style mca/kk, fix
nve/mca/kk, the internal links fix) against the CPU styles, in the build
that has the KOKKOS package (LAMMPS 29 Sep 2021, Kokkos OpenMP).

Scenes (the examples' inputs, 2000 steps each): the free-grip tension and
the clamped shear of a 5a fcc cube, the P-wave bar (10 planes per
wavelength) and a periodic box sheared to 10 % by fix deform.  Each is run
with the CPU styles, with -k on -sf kk on 1 and 2 threads, and on 2 MPI
ranks x 1 thread; every atom's displacement, velocity, spin, force, torque,
mean stress and stress tensor are dumped at every step up to 100 and every
100 steps after that.

What is compared, and why these tolerances:
- every field is scaled by its natural magnitude over the run (see SCALES):
  forces by the largest link force (largest stress x (2R)^2), torques by
  that times R, velocities by the larger of the largest velocity and the
  particle velocity sigma/(rho c_p) that carries the largest stress.  In
  the quasi-static scenes the net force on an automaton is a residual of
  1e-4 .. 1e-6 of its link forces, so scaling by the net force would
  measure the cancellation, not the agreement.
- up to step 100: 1e-12.  On 2 threads the kk kernels sum the same
  per-link terms in another order (two ScatterView copies, one per thread,
  added at the end), which changes the last bits (measured <= 5e-13).
- after 2000 steps: 1e-8, or 128 units in the last place of the
  coordinates relative to the peak displacement where that is larger.
  Once a position differs by one unit in the last place (ulp 4.4e-16 m at
  3.6 m), the strain of its links differs by ulp / r0 ~ 1e-15: 1e-10 of
  the strains of 1e-5 of the cube and the box (measured <= 6e-10), but
  5e-10 of the 1.7e-6 of the wave (amplitude 1e-6 m), whose differences
  reach 1.5e-8 = 70 ulp / peak displacement.  The ulp floor is what double
  precision coordinates can resolve.
- kk on 1 thread: the same bits as the CPU styles (the same order of
  every sum) in the orthogonal scenes.
- 2 MPI ranks vs 1: atoms are numbered by rank, so the lower ID of a link
  (which computes it) differs; same tolerances, atoms matched by position.
- on a GPU (MCA_TEST_GPU=nofma or fma, a build of Kokkos for the GPU made
  by tools/mca-gpu): the four scenes, the migrating flight and a restart
  continuation against the CPU styles of the same executable.  Without
  fused multiply-adds in the MCA kernels, the tolerances of 2 threads
  (atomic sums in a varying order); with them (the default build), the
  positions differ by ulps from the first step on and ulp_floor bounds
  what that does to each field.
"""

import functools
import os
import pathlib

import numpy as np
import pytest

from mcatest import kokkos_build, on_gpu, read_dump

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "examples"

E, NU, RHO, A = 70.0e9, 0.3, 2700.0, 0.7184
RADIUS = A / (2.0 * np.sqrt(2.0))
G = E / (2 * (1 + NU))
K = E / (3 * (1 - 2 * NU))
C_P = np.sqrt((K + 4 * G / 3) / RHO)

NSTEPS = 2000
EARLY = 100
EARLY_TOL = 1.0e-12
LATE_TOL = 1.0e-8

SCENES = {
    "cube_tension": ("tension_cube", "in.tension_cube",
                     {"n": 5, "grips": "free", "load": "tension"}),
    "cube_shear": ("tension_cube", "in.tension_cube",
                   {"n": 5, "grips": "clamped", "load": "shear"}),
    "wave_bar": ("waves", "in.wave", {"m": 10, "pol": "p"}),
    "box_shear": ("tension_cube", "in.shear_box", {"erate": 2.5}),
}

MODES = {
    "cpu": (1, ()),
    "kk1": (1, ("-k", "on", "t", "1", "-sf", "kk")),
    "kk2": (1, ("-k", "on", "t", "2", "-sf", "kk")),
    "kk_mpi2": (2, ("-k", "on", "t", "1", "-sf", "kk")),
    "kk_gpu": (1, ("-k", "on", "g", "1", "-sf", "kk")),
}

# the GPU tests need a build of Kokkos for a GPU (tools/mca-gpu), which CI
# does not have.  MCA_TEST_GPU=nofma: an executable whose KOKKOS_MCA kernels
# are compiled without fused multiply-adds (-D MCA_KOKKOS_FMAD=off), held
# to the tolerances of 2 threads; MCA_TEST_GPU=fma: the default executable,
# whose positions may differ from the CPU's by a few units in the last
# place from the first step on (see ulp_floor)
GPU = os.environ.get("MCA_TEST_GPU", "")

DUMP = """
compute         mcaprop all property/atom smean sxx syy szz sxy sxz syz
variable        dumpnext equal "(step < {early})*(step + 1) + (step >= {early})*(step + {early})"
dump            cmp all custom 1 cmp.dump id xu yu zu ix iy iz vx vy vz fx fy fz &
                omegax omegay omegaz tqx tqy tqz c_mcaprop[*]
dump_modify     cmp format float %.17g sort id every v_dumpnext
""".format(early=EARLY)


@functools.lru_cache(maxsize=None)
def run_scene(scene, mode, workdir):
    """Run a scene in a mode once per session; snapshots by timestep."""
    build = kokkos_build()
    example, script, variables = SCENES[scene]
    nprocs, args = MODES[mode]
    directory = pathlib.Path(workdir) / scene / mode
    directory.mkdir(parents=True, exist_ok=True)
    (directory / "extra_cmds").write_text(DUMP)
    variables = dict(variables, nsteps=NSTEPS, extra="extra_cmds")
    text = (EXAMPLES / example / script).read_text()
    build.run(text, directory, nprocs=nprocs, variables=variables, extra_args=args,
              name=script)
    snapshots = read_dump(directory / "cmp.dump")
    return {snap["timestep"]: snap for snap in snapshots}


@pytest.fixture(scope="module")
def workdir(tmp_path_factory):
    return str(tmp_path_factory.mktemp("kokkos"))


def stack(snap, names, order):
    return np.stack([snap[n][order] for n in names], axis=1)


def fields(snap, first, order, first_order):
    """Compared quantities of a snapshot, rows in the order given."""
    u = stack(snap, ("xu", "yu", "zu"), order) - stack(first, ("xu", "yu", "zu"), first_order)
    return {
        "displacement": u,
        "velocity": stack(snap, ("vx", "vy", "vz"), order),
        "force": stack(snap, ("fx", "fy", "fz"), order),
        "spin": stack(snap, ("omegax", "omegay", "omegaz"), order),
        "torque": stack(snap, ("tqx", "tqy", "tqz"), order),
        "stress": stack(snap, [f"c_mcaprop[{k}]" for k in range(1, 8)], order),
    }


def position_order(run):
    """Atom rows sorted by initial position (IDs depend on the rank count)."""
    first = run[min(run)]
    key = np.round(np.stack([first["xu"], first["yu"], first["zu"]], axis=1) / A, 6)
    return np.lexsort(key.T[::-1])


def scales(reference):
    """Natural magnitude of each field over the whole reference run."""
    order = np.arange(len(reference[min(reference)]["id"]))
    first = reference[min(reference)]
    peak = {}
    for snap in reference.values():
        for name, value in fields(snap, first, order, order).items():
            peak[name] = max(peak.get(name, 0.0), float(np.abs(value).max()))
    link_force = peak["stress"] * (2 * RADIUS) ** 2
    velocity = max(peak["velocity"], peak["stress"] / (RHO * C_P))
    return {
        "displacement": peak["displacement"],
        "velocity": velocity,
        "spin": velocity / RADIUS,
        "force": link_force,
        "torque": link_force * RADIUS,
        "stress": peak["stress"],
    }


def late_tolerance(reference):
    """1e-8, or 128 ulp of the coordinates per peak displacement."""
    return max(LATE_TOL, ulp_floor(reference)["displacement"])


def ulp_floor(reference):
    """The scaled difference that 128 ulp of the coordinates make in each
    field: in the displacement 128 ulp / peak displacement; in the strain of
    a link (length 2R) 128 ulp / 2R, which relative to the peak strain
    sigma_peak / E bounds the stresses, forces, torques and (through
    sigma / (rho c_p)) the velocities and spins.  Where positions differ by
    ulps from the start (the device compiler fuses x + dt v, the KOKKOS
    package's own triclinic transforms round their own way), this is what
    double precision coordinates resolve."""
    first = reference[min(reference)]
    extent = max(float(np.abs(first[c]).max()) for c in ("xu", "yu", "zu"))
    dx = 128 * np.spacing(extent)
    scale = scales(reference)
    strain = dx / (2 * RADIUS) / (scale["stress"] / E)
    return {"displacement": dx / scale["displacement"], "velocity": strain, "spin": strain,
            "force": strain, "torque": strain, "stress": strain}


def compare(reference, other, by_position=False):
    """Worst scaled difference of each field up to step EARLY and after it."""
    scale = scales(reference)
    if by_position:
        ref_order, other_order = position_order(reference), position_order(other)
    else:
        ref_order = other_order = np.arange(len(reference[min(reference)]["id"]))
    first_ref, first_other = reference[min(reference)], other[min(other)]
    worst = {"early": {}, "late": {}}
    assert sorted(reference) == sorted(other)
    for step in sorted(reference):
        a = fields(reference[step], first_ref, ref_order, ref_order)
        b = fields(other[step], first_other, other_order, other_order)
        stage = worst["early" if step <= EARLY else "late"]
        for name in a:
            diff = float(np.abs(a[name] - b[name]).max()) / scale[name]
            stage[name] = max(stage.get(name, 0.0), diff)
    return worst


def assert_agree(reference, worst, floor=None):
    """Every field within EARLY_TOL up to step EARLY and within
    late_tolerance after it; floor (per field, see ulp_floor) raises both
    where positions may differ by ulps from the start."""
    floor = floor or {}
    for name, value in worst["early"].items():
        tolerance = max(EARLY_TOL, floor.get(name, 0.0))
        assert value <= tolerance, f"{name} differs by {value:.2e} before step {EARLY}"
    late = late_tolerance(reference)
    for name, value in worst["late"].items():
        tolerance = max(late, floor.get(name, 0.0))
        assert value <= tolerance, f"{name} differs by {value:.2e} after step {EARLY}"


def scene_table(workdir, scene, mode):
    """Path of the output table of a cube scene (fix print of in.tension_cube)."""
    name = "cube.{grips}.{load}.dat".format(**SCENES[scene][2])
    return pathlib.Path(workdir) / scene / mode / name


def report(scene, what, worst):
    text = ", ".join(f"{k} {v:.1e}" for k, v in sorted(worst["early"].items()))
    late = ", ".join(f"{k} {v:.1e}" for k, v in sorted(worst["late"].items()))
    print(f"\n{scene} {what}: steps <= {EARLY}: {text}\n   after: {late}")


@pytest.mark.parametrize("scene", sorted(SCENES))
@pytest.mark.parametrize("mode", ["kk1", "kk2"])
def test_kk_matches_cpu(scene, mode, workdir):
    reference = run_scene(scene, "cpu", workdir)
    other = run_scene(scene, mode, workdir)
    worst = compare(reference, other)
    report(scene, f"{mode} vs cpu", worst)
    assert_agree(reference, worst)


def require_gpu():
    if not on_gpu():
        pytest.skip("no GPU build: see tools/mca-gpu (MCA_TEST_GPU=nofma or fma)")


@pytest.mark.parametrize("scene", sorted(SCENES))
def test_kk_gpu_matches_cpu(scene, workdir):
    """On a GPU (-k on g 1) the sums are atomic additions in an order that
    changes from step to step: the last bits differ as on 2 threads, with
    the same tolerances (MCA_TEST_GPU=nofma).  The default executable
    (MCA_TEST_GPU=fma) also fuses x + dt v into one rounding, so positions
    differ by ulps from the first step and ulp_floor raises the tolerances.
    The cubes' reaction force (fix mca/setvelocity/kk, a reduction on the
    device) is compared too."""
    require_gpu()
    reference = run_scene(scene, "cpu", workdir)
    other = run_scene(scene, "kk_gpu", workdir)
    worst = compare(reference, other)
    report(scene, f"kk on the GPU ({GPU}) vs cpu", worst)
    floor = ulp_floor(reference) if GPU == "fma" else {}
    assert_agree(reference, worst, floor)
    if scene.startswith("cube"):
        tables = [np.loadtxt(scene_table(workdir, scene, mode), ndmin=2)
                  for mode in ("cpu", "kk_gpu")]
        assert tables[0].shape == tables[1].shape
        tolerance = max(late_tolerance(reference), floor.get("stress", 0.0))
        # columns: time, strain, stress, lateral strain.  The stress is the
        # reaction force of fix mca/setvelocity/kk over the area, a sum of
        # link forces: scaled by its peak, as the forces are.  (The strains
        # come from the positions, compared above; the lateral strain of
        # the shear scene is round-off around zero.)
        stress = [t[:, 2] for t in tables]
        diff = float(np.abs(stress[0] - stress[1]).max() / np.abs(stress[0]).max())
        print(f"{scene} reaction stress: kk on the GPU vs cpu {diff:.1e}")
        assert diff <= tolerance


@pytest.mark.parametrize("scene", ["cube_shear", "cube_tension", "wave_bar"])
def test_kk_one_thread_is_cpu(scene, workdir):
    """On one thread the kk styles add every term in the order of the CPU
    styles (one ScatterView copy, filled in the CPU loop order): the same
    bits for all 2000 steps.  Not so in the triclinic box_shear scene, where
    the KOKKOS package's own coordinate transforms at reneighbouring
    (x2lamda / lamda2x) round differently from the CPU ones by one unit in
    the last place (measured: first difference 4e-16 m at step 10)."""
    cpu = run_scene(scene, "cpu", workdir)
    one = run_scene(scene, "kk1", workdir)
    assert sorted(cpu) == sorted(one)
    for step in cpu:
        for name in cpu[step]:
            if name in ("timestep", "box"):
                continue
            assert np.array_equal(cpu[step][name], one[step][name]), (step, name)
    # the scene's own output: for the cubes the reaction force of fix
    # mca/setvelocity (mca/setvelocity/kk here) and the strains
    if scene.startswith("cube"):
        text = {mode: scene_table(workdir, scene, mode).read_text() for mode in ("cpu", "kk1")}
        assert text["cpu"] == text["kk1"]


@pytest.mark.parametrize("scene", sorted(SCENES))
def test_kk_mpi_ranks(scene, workdir):
    """2 ranks x 1 thread against 1 rank x 1 thread (both kk)."""
    reference = run_scene(scene, "kk1", workdir)
    other = run_scene(scene, "kk_mpi2", workdir)
    worst = compare(reference, other, by_position=True)
    report(scene, "kk 2 ranks vs kk 1 rank", worst)
    assert_agree(reference, worst)


# ---------------------------------------------------------------------------
# links that migrate between ranks, and restart files across the variants

@pytest.mark.mpi
def test_kk_links_migrate_between_ranks(tmp_path):
    """The flight of test_pair_mca.test_links_migrate_between_ranks (a
    vibrating cluster crossing ranks and the periodic boundary at 100 m/s,
    reneighbouring every step or two) with the kk styles on 2 ranks x 1
    thread, 1 rank x 2 threads and 2 ranks x 2 threads (MPI and threads
    together), against the CPU styles on 1 rank, with
    the tolerances of that test (round-off of the periodic images)."""
    from test_pair_mca import MIGRATE, assert_same_flight, migrate_final

    build = kokkos_build()
    _, cpu = migrate_final(build, tmp_path / "cpu", MIGRATE, 1)
    modes = (("mpi2", 2, "1"), ("threads2", 1, "2"), ("mpi2_threads2", 2, "2"))
    for name, nprocs, threads in modes:
        step, kk = migrate_final(build, tmp_path / name, MIGRATE, nprocs,
                                 extra_args=("-k", "on", "t", threads, "-sf", "kk"))
        assert step == 3000
        assert_same_flight(cpu, kk)


def test_kk_gpu_links_migrate(tmp_path):
    """The migrating flight on the GPU: atoms cross the periodic boundary
    and are reneighboured every step or two, so the link table goes to the
    host (exchange, sorting) and back to the device over and over."""
    require_gpu()
    from test_pair_mca import MIGRATE, assert_same_flight, migrate_final

    build = kokkos_build()
    _, cpu = migrate_final(build, tmp_path / "cpu", MIGRATE, 1)
    step, kk = migrate_final(build, tmp_path / "gpu", MIGRATE, 1,
                             extra_args=MODES["kk_gpu"][1])
    assert step == 3000
    assert_same_flight(cpu, kk)


CONTINUE = """
read_restart    half.restart
pair_style      mca
pair_coeff      * * E 70.0e9 nu 0.3 rho 2700
fix             integrate all nve/mca
include         extra_cmds
run             50
"""


def continue_from(build, directory, restart, mode):
    directory.mkdir(exist_ok=True)
    (directory / "half.restart").write_bytes(restart.read_bytes())
    (directory / "extra_cmds").write_text(DUMP.replace("every v_dumpnext", "every 1"))
    return build.run(CONTINUE, directory, extra_args=MODES[mode][1], name="in.continue",
                     check=False)


@pytest.mark.parametrize("mode", ["kk1", "kk_gpu"])
def test_kk_reads_cpu_restart_file(tmp_path, mode):
    """A restart file of a CPU run continues with the kk styles (on one
    thread, and on the GPU where one is built for): the link rows come back
    (the internal fix has one style name for both variants) and 50 steps
    agree with the CPU continuation to the per-step tolerance."""
    if mode == "kk_gpu":
        require_gpu()
    build = kokkos_build()
    text = (EXAMPLES / "tension_cube" / "in.shear_box").read_text()
    text += "write_restart   half.restart\n"
    build.run(text, tmp_path, variables={"nsteps": 200}, name="in.shear_box")
    runs = {}
    for run in ("cpu", mode):
        result = continue_from(build, tmp_path / run, tmp_path / "half.restart", run)
        assert result.returncode == 0, result.stdout[-2000:]
        log = (tmp_path / run / "log.lammps").read_text()
        assert "links made" not in log, "the links were made again instead of read"
        runs[run] = {s["timestep"]: s for s in read_dump(tmp_path / run / "cmp.dump")}
    assert max(runs["cpu"]) == 250
    worst = compare(runs["cpu"], runs[mode])
    report("restarted box", f"{mode} vs cpu", worst)
    # 50 steps (200 .. 250): the per-step tolerance.  On the GPU the
    # KOKKOS package's triclinic transforms at the setup of the run round
    # some coordinates one ulp apart from the CPU's (measured: 4.4e-16 m at
    # step 200, before any MCA kernel ran), and the stress of this lightly
    # sheared box is small, so the ulp floor applies there
    floor = ulp_floor(runs["cpu"])
    for name, value in {**worst["early"], **worst["late"]}.items():
        tolerance = EARLY_TOL if mode != "kk_gpu" else max(EARLY_TOL, floor[name])
        assert value <= tolerance, f"{name} differs by {value:.2e}"


def test_kk_restart_file_in_cpu_run(tmp_path):
    """LAMMPS 2021 writes the style names with their suffix: a restart file
    of a kk run names atom_style mca/kk, which a run without -k on cannot
    build.  It stops with an error that says how to read it (no crash).
    Later versions write the names without the suffix: a CPU run continues
    the kk run's file, and 50 steps agree with the kk continuation to the
    per-step tolerance."""
    build = kokkos_build()
    text = (EXAMPLES / "tension_cube" / "in.shear_box").read_text()
    text += "write_restart   half.restart\n"
    build.run(text, tmp_path, variables={"nsteps": 20}, extra_args=MODES["kk1"][1],
              name="in.shear_box")
    result = continue_from(build, tmp_path / "kk1", tmp_path / "half.restart", "kk1")
    assert result.returncode == 0, result.stdout[-2000:]
    result = continue_from(build, tmp_path / "cpu", tmp_path / "half.restart", "cpu")
    output = result.stdout + result.stderr
    if build.name == "kokkos":
        assert result.returncode != 0
        assert "Atom style mca/kk requires the KOKKOS package" in output, output[-2000:]
        assert "-k on -sf kk" in output
        return
    assert result.returncode == 0, output[-2000:]
    assert "links made" not in (tmp_path / "cpu" / "log.lammps").read_text()
    runs = {run: {s["timestep"]: s for s in read_dump(tmp_path / run / "cmp.dump")}
            for run in ("cpu", "kk1")}
    assert max(runs["cpu"]) == 70
    worst = compare(runs["kk1"], runs["cpu"])
    report("restarted box", "cpu vs kk1", worst)
    for name, value in {**worst["early"], **worst["late"]}.items():
        assert value <= EARLY_TOL, f"{name} differs by {value:.2e}"


# ---------------------------------------------------------------------------
# bad input on the kk path: clear errors, no silent fallback

BAD_BASE = """
units           si
atom_style      mca
atom_modify     map array
lattice         fcc 0.7184
region          b block 0 2 0 2 0 2
create_box      1 b
create_atoms    1 box
comm_modify     vel yes
"""

BAD_CASES = {
    # a Kokkos style in a run without the KOKKOS package enabled
    "pair_without_kokkos": (
        BAD_BASE + "pair_style mca/kk\npair_coeff * * E 70e9 nu 0.3 rho 2700\nrun 0\n", (),
        "Pair style mca/kk requires the KOKKOS package enabled with the command-line "
        "switch '-k on'"),
    "fix_without_kokkos": (
        BAD_BASE + "pair_style mca\npair_coeff * * E 70e9 nu 0.3 rho 2700\n"
        "fix 1 all nve/mca/kk\nrun 0\n", (),
        "Fix nve/mca/kk requires the KOKKOS package enabled"),
    # -k on without -sf kk: the plain atom style cannot run on the Kokkos path
    "kokkos_with_plain_atom_style": (
        BAD_BASE + "pair_style mca\npair_coeff * * E 70e9 nu 0.3 rho 2700\nrun 0\n",
        ("-k", "on", "t", "1"), "KOKKOS package requires a kokkos enabled atom_style"),
    # links made by the CPU pair style, continued by the kk one in the same run
    "mixed_variants": (
        BAD_BASE + "suffix off\npair_style mca\npair_coeff * * E 70e9 nu 0.3 rho 2700\n"
        "run 0\npair_style mca/kk\npair_coeff * * E 70e9 nu 0.3 rho 2700\nrun 0\n",
        ("-k", "on", "t", "1", "-sf", "kk"),
        "the links of this system were made by pair_style mca without the Kokkos suffix"),
}


@pytest.mark.parametrize("case", sorted(BAD_CASES))
def test_kk_bad_input(tmp_path, case):
    build = kokkos_build()
    script, args, message = BAD_CASES[case]
    result = build.run(script, tmp_path, extra_args=args, check=False)
    output = result.stdout + result.stderr
    assert result.returncode != 0, f"{case}: LAMMPS did not stop"
    # LAMMPS's own messages changed case and hyphens since 2021
    # ("kokkos enabled atom_style" is "Kokkos-enabled atom_style" in 2026)
    def plain(text):
        return text.lower().replace("-", " ")
    assert "ERROR" in output and plain(message) in plain(output), output[-1500:]
    assert "Segmentation" not in output and "signal" not in output.lower()
