"""Plasticity of pair mca ("pair_style mca plasticity mises", pair_coeff
keywords yield, hardening; doc/src/pair_mca.rst, "Plasticity").

* the periodic box of examples/plasticity sheared past yield, unloaded and
  yielded in reverse follows the continuum J2 solution (radial return,
  exact for this proportional loading; examples/plasticity/shear_model.py)
  with linear and with tabulated hardening: yield, post-yield slope,
  unloading slope and the whole curve, plastic strain and plastic work;
  the elastic energy is that of the stress, 1/2 V tau^2 / G;
* the plastic work of the links equals that of the automata, and the work
  done on the box is elastic + plastic + kinetic energy;
* a cube pulled past yield between grips (non-uniform plastic strain)
  runs the same on 4 MPI ranks, with the kk styles on 1 and 2 threads and
  across a restart file;
* bad input gives errors that name the argument and the allowed values.
"""

import math
import pathlib
import sys

import numpy as np
import pytest

from mcatest import FCC_CUBE_DATA, field_difference, kokkos_args, read_thermo

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "plasticity"
sys.path.insert(0, str(EXAMPLE))
from shear_model import Hardening, bilinear_yield, shear_response  # noqa: E402

E, NU = 70.0e9, 0.3
G = E / (2 * (1 + NU))
SY, H = 2.0e6, 10.0e9
VOLUME = (4 * 0.7184) ** 3


def shear_box(build, directory, hardening, extra=None):
    """examples/plasticity/in.plastic_box at a reduced strain (2.4e-4, still
    past reverse yield on unloading); the columns of its .dat file."""
    directory.mkdir(parents=True, exist_ok=True)
    (directory / "hardening.table").write_text((EXAMPLE / "hardening.table").read_text())
    variables = {"hardening": hardening, "gmax": 2.4e-4}
    if extra:
        (directory / "extra").write_text(extra)
        variables["extra"] = "extra"
    build.run((EXAMPLE / "in.plastic_box").read_text(), directory, variables=variables,
              name="in.plastic_box")
    return np.loadtxt(directory / f"box.{hardening}.dat", unpack=True)


def slope(x, y):
    return np.polyfit(x, y, 1)[0]


@pytest.mark.parametrize("hardening", ["linear", "table"])
def test_shear_box_follows_the_continuum_solution(build, tmp_path, hardening):
    """Tolerances: the curve within 1 % of sigma_y everywhere (issue: the
    tabulated curve to 1 %; measured 0.26 % linear, 0.28 % table, the shear
    waves of the start from rest); slopes within 1 % (elastic loading and
    unloading: G; post-yield: G H / (H + 3G) for linear hardening); the
    mean plastic strain and plastic work at the end within 0.5 % of the
    continuum model's."""
    t, gamma, tau, epsp, elastic, wplastic = shear_box(build, tmp_path, hardening)
    law = Hardening.linear(SY, H) if hardening == "linear" else \
        Hardening.table(EXAMPLE / "hardening.table", "AL_V4")
    model_tau, model_ep = shear_response(gamma, G, law)
    error = np.max(np.abs(tau - model_tau)) / SY
    print(f"\n{hardening}: max |tau - J2 model| / sigma_y = {error:.2e}")
    assert error < 0.01

    peak = np.argmax(gamma)
    tau_y = SY / math.sqrt(3)
    elastic_load = (tau < 0.8 * tau_y) & (np.arange(len(t)) < peak) & (gamma > 0.2e-5)
    g_load = slope(gamma[elastic_load], tau[elastic_load])
    # unloading: from the peak until the stress has fallen by 1.6 tau_y
    # (reverse yield starts at 2 tau(peak) below for isotropic hardening)
    unload = (np.arange(len(t)) > peak) & (tau > tau[peak] - 1.6 * tau_y)
    g_unload = slope(gamma[unload], tau[unload])
    print(f"elastic slope {g_load / G:.5f} G, unloading slope {g_unload / G:.5f} G")
    assert abs(g_load / G - 1) < 0.01 and abs(g_unload / G - 1) < 0.01
    if hardening == "linear":
        plastic = (np.arange(len(t)) < peak) & (gamma > 1.5 * tau_y / G)
        expected = G * H / (H + 3 * G)
        measured = slope(gamma[plastic], tau[plastic])
        print(f"post-yield slope {measured / expected:.5f} of G H/(H + 3G)")
        assert abs(measured / expected - 1) < 0.01

    ep_end = model_ep[-1]
    print(f"mean eps_p {epsp[-1]:.6e}, model {ep_end:.6e}")
    assert abs(epsp[-1] / ep_end - 1) < 0.005
    # plastic work: V int sigma_y(eps_p) d eps_p along the model's history
    dep = np.diff(model_ep, prepend=0.0)
    flow = np.array([law(e) for e in model_ep])
    work = VOLUME * np.sum(flow * dep)
    print(f"plastic work {wplastic[-1]:.6e}, model {work:.6e}")
    assert abs(wplastic[-1] / work - 1) < 0.005


def test_energy_of_the_plastic_box(build, tmp_path):
    """The elastic energy (pe: work of the link forces less their plastic
    work) is 1/2 V tau^2 / G within 1 % of the largest (a homogeneous
    shear; the start from rest adds a little kinetic energy); the plastic
    work of the links equals that of the automata (full isotropic shells,
    doc/src/pair_mca.rst: equal but for the geometry, the current one of
    the links against the reference cell volume of the automata, an
    O(strain) effect: bound 1e-5, measured 5e-7); the work done on the box,
    V int tau d gamma, equals elastic energy + plastic work + kinetic
    energy within 0.5 % of the total work (trapezoidal sums of 50-step
    samples)."""
    extra = """compute L all mca/link plastic_work
compute Lsum all reduce sum c_L{inputs}
thermo_style custom step v_strain v_stress pe ke v_wplastic c_Lsum press
thermo_modify format float %.17g
thermo 50
"""
    inputs = "" if build.name == "kokkos" else " inputs local"
    t, gamma, tau, epsp, elastic, wplastic = shear_box(build, tmp_path, "linear",
                                                       extra=extra.format(inputs=inputs))
    expected = 0.5 * VOLUME * tau ** 2 / G
    error = np.max(np.abs(elastic - expected)) / np.max(expected)
    print(f"\nelastic energy vs 1/2 V tau^2/G: {error:.2e} of the largest")
    assert error < 0.01

    thermo = read_thermo(tmp_path / "log.lammps")
    links, atoms = thermo["c_Lsum"], thermo["v_wplastic"]
    print(f"plastic work: links {links[-1]:.9e}, automata {atoms[-1]:.9e}")
    print(f"relative difference {np.max(np.abs(links - atoms)) / np.max(atoms):.2e}")
    assert np.max(np.abs(links - atoms)) <= 1e-5 * np.max(atoms)

    work_done = VOLUME * np.concatenate(([0.0], np.cumsum(0.5 * (tau[1:] + tau[:-1]) *
                                                         np.diff(gamma))))
    # (the kinetic energy of the shear waves is not in the samples: part
    # of the tolerance)
    balance = work_done - (elastic + wplastic)
    print(f"work done {work_done[-1]:.6e}, elastic + plastic {elastic[-1] + wplastic[-1]:.6e}")
    assert np.max(np.abs(balance)) < 0.005 * np.max(work_done)


# ---------------------------------------------------------------------------
# the thesis cube (V3) loaded past yield and unloaded, frictionless grips

def test_cube_loading_unloading_in_tension(build, tmp_path):
    """examples/plasticity/in.load_unload at reduced size (6a cube, 1099
    automata; the example: 10a, 4631) with frictionless grips: uniaxial
    stress.  The yield stress (where the fitted elastic and post-yield
    lines meet) within 2 % of sigma_y (issue); the post-yield slope within
    3 % of the uniaxial tangent modulus E H/(E + H) (the surface automata
    return approximately); the unloading slope within 1 % of E (issue)."""
    if build.name == "kokkos":
        pytest.skip("one LAMMPS version suffices for this scene (the law is the same code)")
    variables = {"n": 6, "nload": 2600, "nrev": 500, "nunload": 1300}
    build.run((EXAMPLE / "in.load_unload").read_text(), tmp_path, variables=variables,
              name="in.load_unload")
    t, strain, stress, epsp, elastic_energy, wplastic, ke = \
        np.loadtxt(tmp_path / "cube.free.tension.dat", unpack=True)
    dt = 2.0e-5
    t1, t2 = 2600 * dt, 3100 * dt
    ey = SY / E
    loading = (t < t1) & (t > 0.006)
    sy, e_load, e_plastic = bilinear_yield(
        strain, stress, loading & (stress > 0.2 * SY) & (stress < 0.8 * SY),
        loading & (strain > 1.5 * ey))
    unload = t > t2 + 0.005
    e_unload = slope(strain[unload], stress[unload])
    tangent = E * H / (E + H)
    print(f"\nyield {sy / SY:.4f} sigma_y, elastic slope {e_load / E:.4f} E, post-yield "
          f"{e_plastic / tangent:.4f} E H/(E+H), unloading {e_unload / E:.4f} E")
    assert abs(sy / SY - 1) < 0.02
    assert abs(e_plastic / tangent - 1) < 0.03
    assert abs(e_unload / E - 1) < 0.01
    assert epsp[-1] > 0 and np.all(np.diff(epsp) >= 0)


# ---------------------------------------------------------------------------
# NIST Al-6061 (as received) in tension at reduced size

def test_nist_tension_at_reduced_size(build, tmp_path):
    """examples/nist_tension/in.nist, sample AR, linear hardening, a 6a
    cube (1099 automata; the example: 14a, 12195), 4000 steps, slow start
    over a fifth of the run (quasi-static in the elastic part): E within
    1 % and sigma_y within 2 % of the inputs; the engineering stress at
    5 % strain within 4 % of the input curve's (measured +2.0 %; the
    example +2.2 %: the law's stress measure is that of small strains,
    doc/src/pair_mca.rst)."""
    if build.name == "kokkos":
        pytest.skip("one LAMMPS version suffices for this scene (the law is the same code)")
    sys.path.insert(0, str(ROOT / "examples" / "nist_tension"))
    from analysis import SAMPLES, figures, input_curve
    build.run((ROOT / "examples" / "nist_tension" / "in.nist").read_text(), tmp_path,
              variables={"n": 6, "nsteps": 4000, "ramp": 0.2}, name="in.nist")
    t, strain, stress, epsp = np.loadtxt(tmp_path / "nist.AR.linear.n6.dat", unpack=True)
    f = figures("AR", strain, stress)
    e, sy, _, _ = SAMPLES["AR"]
    ref5 = input_curve("AR", np.array([0.05]))[0]
    print(f"\nAR: E {f['E'] / e:.4f} E, sigma_y {f['sigma_y'] / sy:.4f}, stress at 5 % "
          f"{f['stress_5'] / 1e6:.1f} MPa (input {ref5 / 1e6:.1f})")
    assert abs(f["E"] / e - 1) < 0.01
    assert abs(f["sigma_y"] / sy - 1) < 0.02
    assert abs(f["stress_5"] / ref5 - 1) < 0.04
    assert strain.max() > 0.06    # past the 5 % point (the slow start costs some strain)


# ---------------------------------------------------------------------------
# a cube pulled past yield between grips: the same results on any number of
# ranks and threads, and across a restart file

CUBE = """
units           si
atom_style      mca
atom_modify     map array sort 0 0
boundary        f f f
read_data       cube.data
comm_modify     vel yes
pair_style      mca plasticity mises
pair_coeff      * * E 70e9 nu 0.3 rho 2700 yield 2e6 hardening 1e9
"""
LOAD = """
region          top block INF INF INF INF 2.8 INF units box
region          bot block INF INF INF INF INF 0.1 units box
group           top region top
group           bot region bot
fix             top top mca/setvelocity NULL NULL 0.05
fix             bot bot mca/setvelocity NULL NULL 0
fix             nve all nve/mca
compute         P all mca/atom epsp plastic_work
compute         Ps all reduce sum c_P[1] c_P[2]
thermo_style    custom step pe ke c_Ps[1] c_Ps[2] f_top[3]
thermo_modify   format float %.17g
thermo          50
timestep        2.0e-5
"""
FINAL = """
write_dump      all custom final.txt id x y z vx vy vz fx fy fz c_P[1] c_P[2] &
                modify sort id format float %.17g
"""


def pulled_cube(build, directory, extra_args=(), nprocs=1, split=None, nsteps=400,
                table=False):
    """A 4a fcc cube (365 automata, from one data file: the same atom IDs
    on any number of ranks), its top pulled at 0.05 m/s: plastic from step
    85 on.  split: 'memory' (two runs) or 'restart' (through a file)."""
    build.run(FCC_CUBE_DATA, directory, name="in.create")
    cube = CUBE
    if table:
        # the restart file must carry the table: it is removed before the
        # second half
        (directory / "cube.table").write_text("CUBE\nN 3\n\n1 0.0 2e6\n2 2e-5 2.2e6\n"
                                              "3 1e-4 2.3e6\n")
        cube = CUBE.replace("yield 2e6 hardening 1e9", "hardening table cube.table CUBE")
    half = nsteps // 2
    if split == "restart":
        build.run(cube + LOAD + f"run {half}\nwrite_restart half.restart\n", directory,
                  extra_args=extra_args, nprocs=nprocs)
        if table:
            (directory / "cube.table").unlink()
        # the restart file holds the pair style, its materials and links;
        # groups, fixes and computes are given again
        script = ("units si\natom_modify map array sort 0 0\nread_restart half.restart\n"
                  "comm_modify vel yes\n" + LOAD + f"run {half}\n")
    elif split == "memory":
        script = cube + LOAD + f"run {half}\nrun {half}\n"
    else:
        script = cube + LOAD + f"run {nsteps}\n"
    build.run(script + FINAL, directory, extra_args=extra_args, nprocs=nprocs, name="in.cube")
    return np.loadtxt(directory / "final.txt", skiprows=9), read_thermo(directory / "log.lammps")


# the force of a link at yield, sigma_y A (fcc face sqrt(2) R^2): the scale
# of the force differences (the net force of an automaton of this slowly
# pulled cube is a small remainder of its link forces)
LINK_FORCE = 2.0e6 * math.sqrt(2) * 0.254 ** 2


# the columns of the final dumps
FIELDS = (("x", slice(1, 4)), ("v", slice(4, 7)), ("f", slice(7, 10)),
          ("epsp", slice(10, 11)), ("wp", slice(11, 12)))


def test_pulled_cube_yields_unevenly(build, tmp_path):
    """The cube yields (mean plastic strain > 0) but not uniformly: the
    scene of the consistency tests below exercises the return with
    different M on the two ends of links."""
    final, thermo = pulled_cube(build, tmp_path)
    epsp = final[:, 10]
    print(f"\neps_p: mean {epsp.mean():.3e}, min {epsp.min():.3e}, max {epsp.max():.3e}")
    # (measured: mean 1.1e-4, from 0 to 1.8e-4)
    assert epsp.mean() > 0 and epsp.max() - epsp.min() > 0.5 * epsp.mean()
    assert np.all(epsp >= 0)


@pytest.mark.parametrize("hardening", ["linear", "table"])
def test_pulled_cube_restart_is_exact(build, tmp_path, hardening):
    """Plastic strain (atom style), plastic work (links fix), the rows and
    the hardening table are in the restart file: the split run is bit for
    bit the same."""
    table = hardening == "table"
    memory, t_memory = pulled_cube(build, tmp_path / "memory", split="memory", table=table)
    restart, t_restart = pulled_cube(build, tmp_path / "restart", split="restart", table=table)
    assert np.array_equal(memory, restart)
    assert np.array_equal(t_memory["c_Ps[2]"], t_restart["c_Ps[2]"])
    if table:
        return
    # a run split in two continues as one run but for the setup between
    # them (doc/src/pair_mca.rst, Restart): printed for the record
    whole, _ = pulled_cube(build, tmp_path / "whole")
    print(f"\nsplit vs whole run: {field_difference(whole, memory, FIELDS, LINK_FORCE)}")


def test_pulled_cube_on_four_ranks(build, tmp_path):
    one, _ = pulled_cube(build, tmp_path / "one")
    four, _ = pulled_cube(build, tmp_path / "four", nprocs=4)
    diff = field_difference(one, four, FIELDS, LINK_FORCE)
    print(f"\n4 ranks vs 1: {diff}")
    # summation order only, grown over 400 steps (the elastic and damped
    # cubes: 1e-10 .. 3e-10 in 200 steps; here measured 1.4e-9 in f, 8e-10
    # in v: the return adds kinks to the law)
    assert max(diff.values()) < 5e-9


@pytest.mark.parametrize("threads", [1, 2])
def test_pulled_cube_kk_matches_cpu(build, tmp_path, threads):
    if build.name not in ("kokkos", "kokkos5"):
        pytest.skip("the kk styles are in the kokkos builds")
    cpu, _ = pulled_cube(build, tmp_path / "cpu")
    kk, _ = pulled_cube(build, tmp_path / "kk", extra_args=kokkos_args(threads))
    diff = field_difference(cpu, kk, FIELDS, LINK_FORCE)
    print(f"\nkk {threads} thread(s) vs CPU: {diff}")
    # one thread: the CPU style's order, bit for bit today (bound of the
    # elastic kk tests); two: summation order, as on several ranks
    assert max(diff.values()) < (5e-13 if threads == 1 else 5e-9)


# ---------------------------------------------------------------------------
# bad input

TABLES = {
    "short": "AL\nN 1\n\n1 0.0 2e6\n",
    "decreasing": "AL\nN 3\n\n1 0.0 2e6\n2 1e-3 3e6\n3 2e-3 2.5e6\n",
    "eps_order": "AL\nN 3\n\n1 0.0 2e6\n2 1e-3 3e6\n3 1e-3 3.5e6\n",
    "first": "AL\nN 2\n\n1 1e-3 2e6\n2 2e-3 3e6\n",
    "truncated": "AL\nN 4\n\n1 0.0 2e6\n2 1e-3 3e6\n",
    "columns": "AL\nN 2\n\n1 0.0 2e6\n2 1e-3\n",
    "noheader": "AL\n\n1 0.0 2e6\n2 1e-3 3e6\n",
    "negative": "AL\nN 2\n\n1 0.0 -2e6\n2 1e-3 3e6\n",
    "good": "AL\nN 2\n\n1 0.0 2e6\n2 1e-3 3e6\n",
}
SINGLE = """
units           si
atom_style      mca
atom_modify     map array
region          box block -2 2 -2 2 -2 2 units box
create_box      1 box
create_atoms    1 single 0 0 0 units box
comm_modify     vel yes
pair_style      mca plasticity mises
pair_coeff      * * E 70e9 nu 0.3 rho 2700 {coeff}
fix             nve all nve/mca
run             1
"""


@pytest.mark.parametrize("coeff,table,message", [
    ("yield -1e6", None, "yield stress must be > 0 and finite, got -1000000"),
    ("yield 0", None, "yield stress must be > 0 and finite, got 0"),
    ("yield 2e6 hardening -1e9", None, "hardening modulus must be >= 0 and finite"),
    ("hardening 1e9", None, "a hardening modulus needs a yield stress"),
    ("hardening table missing.table AL", None, "cannot open hardening table file missing.table"),
    ("hardening table t.table AL", "short", "gives N = 1; a table needs 2 to 64 points"),
    ("hardening table t.table AL", "decreasing", "sigma_y must not decrease (point 3"),
    ("hardening table t.table AL", "eps_order", "eps_p must increase from point to point"),
    ("hardening table t.table AL", "first", "the first point must be at eps_p = 0"),
    ("hardening table t.table AL", "truncated", "ends after 2 of its N = 4 points"),
    ("hardening table t.table AL", "columns", "point 2 has 2 values"),
    ("hardening table t.table AL", "noheader", "needs the line 'N n'"),
    ("hardening 1e9 hardening table t.table AL", "good", "a hardening table excludes"),
    ("hardening table t.table AL", "negative", "sigma_y of point 1 must be > 0"),
    ("hardening table t.table XX", "short", "has no section XX"),
    ("hardening table t.table", None, "Illegal pair_coeff hardening table"),
    ("yield 2e6 hardening tabel", None, "hardening takes a modulus (a number >= 0) or 'table "
                                        "file keyword', got tabel"),
])
def test_bad_plasticity_input(build, tmp_path, coeff, table, message):
    tmp_path.mkdir(parents=True, exist_ok=True)
    if table:
        (tmp_path / "t.table").write_text(TABLES[table])
    result = build.run(SINGLE.format(coeff=coeff), tmp_path, check=False, timeout=120)
    output = result.stdout + result.stderr
    assert result.returncode != 0
    assert "ERROR" in output and "Segmentation" not in output
    if message:
        assert message in output, output[-2000:]


def test_yield_and_table_exclude_each_other(build, tmp_path):
    (tmp_path / "t.table").write_text("AL\nN 2\n\n1 0.0 2e6\n2 1e-3 3e6\n")
    result = build.run(SINGLE.format(coeff="yield 2e6 hardening table t.table AL"), tmp_path,
                       check=False, timeout=120)
    assert result.returncode != 0
    assert "a hardening table excludes yield and a hardening modulus" in \
        result.stdout + result.stderr


@pytest.mark.parametrize("style,coeff,message", [
    ("mca plasticity mises", "", "plasticity mises without a yield stress"),
    ("mca", "yield 2e6", "has no plasticity part"),
])
def test_plasticity_without_yield_warns(build, tmp_path, style, coeff, message):
    script = SINGLE.format(coeff=coeff).replace("pair_style      mca plasticity mises",
                                               f"pair_style      {style}")
    result = build.run(script, tmp_path)
    assert message in result.stdout + result.stderr
