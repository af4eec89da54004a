"""Fracture of links in pair mca ("pair_style mca fracture links", pair_coeff
keyword break; doc/src/pair_mca.rst, "Fracture of links").

* the periodic box of examples/fracture/in.box under a uniform stress
  growing along a load angle: every link sees the box stress, so the
  links break when the criterion of that stress is met: Drucker-Prager at
  sigma_t in uniaxial tension and sigma_c in uniaxial compression, the
  ultimate stress at sigma_u, the ultimate strain at eps_u (von Mises
  equivalent strain), the elliptic criterion on the failure envelope of
  the box at five load angles (examples/fracture/envelope.py);
* a broken pair pushes but never pulls: the box broken in tension carries
  no stress until it is compressed back past its stress-free length;
* a cube pulled between grips with scattered strengths breaks the same
  links at the same steps on 1, 2 and 4 ranks, with the kk styles on 1 and 2
  threads and across a restart file;
* a bar pulled apart: the broken pairs that separate are forgotten at
  reneighboring and the counts stay;
* bad input gives errors that name the argument and the allowed values.
"""

import math
import pathlib
import sys

import numpy as np
import pytest

from mcatest import FCC_CUBE_DATA, field_difference, kokkos_args, read_thermo

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "fracture"
sys.path.insert(0, str(EXAMPLE))
from envelope import elliptic_failure_load  # noqa: E402

E, NU = 70.0e9, 0.3


def box(build, directory, crit, p1, p2=0.0, angle=0, nsteps=2400, extra_args=()):
    """examples/fracture/in.box sampled every step: the columns of its .dat
    file (time eps_zz gamma_xz sigma_zz tau_xz sigma_lateral broken
    released pe ke)."""
    directory.mkdir(parents=True, exist_ok=True)
    variables = {"crit": crit, "p1": p1, "p2": p2, "angle": angle, "nsteps": nsteps,
                 "every": 1}
    build.run((EXAMPLE / "in.box").read_text(), directory, variables=variables, name="in.box",
              extra_args=extra_args)
    return np.loadtxt(directory / f"box.{crit}.{angle}.dat")


def at_first_break(data):
    """The row of the last step before the first break (the stress the
    breaking links were judged on) and the row of that step."""
    k = int(np.argmax(data[:, 6] > 0))
    assert data[k, 6] > 0, "no link broke"
    return data[k - 1], data[k]


# the stress grows by E eps_zz' dt = 1400 Pa per step: the break is located
# to 1400 / 2e6 = 7e-4 of the strength.  The tolerance of the issue is 3 %;
# measured 0.07 % (tension), 0.05 % (compression): the start from rest
# leaves the box stress 0.07 % behind its strain
@pytest.mark.parametrize("direction,angle,strength", [("tension", 0, 2.0e6),
                                                      ("compression", 180, 6.0e6)])
def test_drucker_prager_box_breaks_at_the_uniaxial_strengths(build, tmp_path, direction, angle,
                                                              strength):
    # (6e6 / 70e6 Pa/s = 4286 steps to the compressive strength)
    nsteps = 1600 if angle == 0 else 4500
    data = box(build, tmp_path, "drucker_prager", 2.0e6, 6.0e6, angle=angle, nsteps=nsteps)
    before, after = at_first_break(data)
    sigma = abs(before[3])
    print(f"\n{direction}: breaks at |sigma_zz| = {sigma:.6e}, strength {strength:.6e}, "
          f"ratio {sigma / strength:.5f}; lateral stress {before[5]:.3e}")
    assert abs(sigma / strength - 1) < 0.03
    # uniaxial: the lateral stress is a small remainder
    assert abs(before[5]) < 1e-3 * strength
    # the box softens: 20 steps after the break it carries less than before
    k = int(np.argmax(data[:, 6] > 0))
    assert abs(data[k + 20, 3]) < sigma


def test_stress_and_strain_criteria(build, tmp_path):
    """Uniaxial tension: the equivalent stress is sigma_zz (breaks at
    sigma_u), the von Mises equivalent strain of an elastic solid is
    2 (1 + nu) eps_zz / 3 (breaks at eps_u).  Tolerance 3 % (issue);
    measured 0.1 %."""
    data = box(build, tmp_path / "stress", "stress", 2.0e6, nsteps=1800)
    before, _ = at_first_break(data)
    print(f"\nstress: breaks at {before[3]:.6e}, ratio {before[3] / 2.0e6:.5f}")
    assert abs(before[3] / 2.0e6 - 1) < 0.03

    eps_u = 2.0e-5
    data = box(build, tmp_path / "strain", "strain", eps_u, nsteps=1800)
    before, _ = at_first_break(data)
    equivalent = 2.0 * (1.0 + NU) * before[1] / 3.0
    print(f"strain: breaks at eps_zz = {before[1]:.6e}, equivalent strain {equivalent:.6e}, "
          f"ratio {equivalent / eps_u:.5f}")
    assert abs(equivalent / eps_u - 1) < 0.03


ANGLES = (0, 45, 90, 135, 180)


@pytest.mark.parametrize("angle", ANGLES)
def test_elliptic_envelope(build, tmp_path, angle):
    """The load at the first break along five load angles (tension,
    tension + shear, shear, compression + shear, compression) against the
    failure envelope of the box (envelope.py: the largest index over the
    six fcc link directions).  Tolerance 3 % (issue); measured 0.08 %,
    0.6 %, 1.0 %, 0.6 %, 0.13 % (shear tractions of the links lag the box
    stress by up to 1 %: the shear law's error, doc/src/pair_mca.rst)."""
    data = box(build, tmp_path, "elliptic", 2.0e6, 1.5e6, angle=angle, nsteps=3000)
    before, _ = at_first_break(data)
    load = math.hypot(before[3], before[4])
    expected = elliptic_failure_load(angle, 2.0e6, 1.5e6)
    print(f"\ntheta {angle}: failure load {load:.6e}, envelope {expected:.6e}, "
          f"ratio {load / expected:.5f}")
    assert abs(load / expected - 1) < 0.03


def test_broken_pairs_push_but_never_pull(build, tmp_path):
    """The box broken in tension (Drucker-Prager), stretched on, then
    compressed to shorter than at the start: no broken pair ever pulls
    (compute mca/link normal <= 0 for state 2 in every dump), and at the
    end broken pairs push (the halves passed their stress-free length)."""
    extra = """
compute         L all mca/link state normal
dump            links all local 200 links.*.txt c_L[1] c_L[2]
dump_modify     links format float %.17g
run             1600
unfix           load
fix             load all deform 1 x erate $(-v_exx) y erate $(-v_exx) z erate $(-v_ezz) &
                remap v
run             4000
"""
    variables = {"crit": "drucker_prager", "p1": 2.0e6, "p2": 6.0e6, "angle": 0,
                 "nsteps": 0, "every": 100}
    build.run((EXAMPLE / "in.box").read_text() + extra, tmp_path, variables=variables,
              name="in.box")
    largest, last = -math.inf, None
    files = sorted(tmp_path.glob("links.*.txt"), key=lambda p: int(p.name.split(".")[1]))
    for path in files:
        rows = np.loadtxt(path, skiprows=9, ndmin=2)
        broken = rows[rows[:, 0] == 2]
        if len(broken):
            largest = max(largest, broken[:, 1].max())
        last = broken
    data = np.loadtxt(tmp_path / "box.drucker_prager.0.dat")
    print(f"\nlargest normal traction of a broken pair {largest:.3e}; at the end "
          f"eps_zz {data[-1, 1]:.2e}: {np.sum(last[:, 1] < 0)} of {len(last)} broken pairs "
          f"push, down to {last[:, 1].min():.3e}")
    assert largest <= 0.0
    assert data[-1, 1] < -5e-6
    assert len(last) > 0 and last[:, 1].min() < -0.1e6


# ---------------------------------------------------------------------------
# a cube pulled between grips with scattered strengths: the same broken
# links on any number of ranks and threads and across a restart file

CUBE = """
units           si
atom_style      mca
atom_modify     map array sort 0 0
boundary        f f f
read_data       cube.data
comm_modify     vel yes
pair_style      mca plasticity mises fracture links scatter 0.3 4257
pair_coeff      * * E 70e9 nu 0.3 rho 2700 yield 2e6 hardening 1e9 &
                break drucker_prager 3e6 9e6
"""
LOAD = """
region          top block INF INF INF INF 2.8 INF units box
region          bot block INF INF INF INF INF 0.1 units box
group           top region top
group           bot region bot
fix             top top mca/setvelocity NULL NULL 0.05
fix             bot bot mca/setvelocity NULL NULL 0
fix             nve all nve/mca
compute         F all mca/fracture
compute         D all mca/atom damage epsp
compute         Ds all reduce sum c_D[1] c_D[2]
thermo_style    custom step pe ke c_F[1] c_F[4] c_F[6] c_Ds[1] c_Ds[2] f_top[3]
thermo_modify   format float %.17g
thermo          50
timestep        2.0e-5
"""
FINAL = """
compute         L all mca/link id1 id2 state cause break_step
write_dump      all custom final.txt id x y z vx vy vz fx fy fz c_D[1] c_D[2] &
                modify sort id format float %.17g
dump            links all local 1 links.txt c_L[1] c_L[2] c_L[3] c_L[4] c_L[5]
dump_modify     links format float %.17g
run             0
"""


def pulled_cube(build, directory, extra_args=(), nprocs=1, split=None, nsteps=400):
    """A 4a fcc cube (365 automata from one data file), its top pulled at
    0.05 m/s; links break from step ~110 on (Drucker-Prager, strengths
    scattered by +-30 %), some automata yield first.  split: 'restart'
    (through a file).  The final fields, the links (sorted by IDs) and the
    thermo."""
    build.run(FCC_CUBE_DATA, directory, name="in.create")
    half = nsteps // 2
    if split == "restart":
        build.run(CUBE + LOAD + f"run {half}\nwrite_restart half.restart\n", directory,
                  extra_args=extra_args, nprocs=nprocs)
        script = ("units si\natom_modify map array sort 0 0\nread_restart half.restart\n"
                  "comm_modify vel yes\n" + LOAD + f"run {half}\n")
    else:
        script = CUBE + LOAD + f"run {half}\nrun {half}\n"
    build.run(script + FINAL, directory, extra_args=extra_args, nprocs=nprocs, name="in.cube")
    final = np.loadtxt(directory / "final.txt", skiprows=9)
    links = np.loadtxt(directory / "links.txt", skiprows=9, ndmin=2)
    links = links[np.lexsort((links[:, 1], links[:, 0]))]
    return final, links, read_thermo(directory / "log.lammps")


def broken_set(links):
    """(id1, id2, cause, step) of the broken links."""
    rows = links[links[:, 2] == 2]
    return {(int(a), int(b), int(c), int(s)) for a, b, _, c, s in rows}


LINK_FORCE = 3.0e6 * math.sqrt(2) * 0.254 ** 2


# the columns of the final dumps
FIELDS = (("x", slice(1, 4)), ("v", slice(4, 7)), ("f", slice(7, 10)),
          ("damage", slice(10, 11)), ("epsp", slice(11, 12)))


def test_pulled_cube_breaks_progressively(build, tmp_path):
    """The scene of the consistency tests: links break over many steps (not
    all at once), automata yield, the damage is the broken fraction."""
    final, links, thermo = pulled_cube(build, tmp_path)
    broken = broken_set(links)
    steps = {s for *_, s in broken}
    print(f"\n{len(broken)} of {len(links)} links broken over {len(steps)} steps; "
          f"eps_p max {final[:, 11].max():.2e}; damage max {final[:, 10].max():.3f}")
    assert len(broken) > 20 and len(steps) > 5
    assert final[:, 11].max() > 0    # some automata yield
    # compute mca/fracture counts what the links say
    assert thermo["c_F[1]"][-1] == len(broken) == thermo["c_F[4]"][-1]
    # damage: broken links of each automaton over its links
    count = {}
    for a, b, _, _ in broken:
        count[a] = count.get(a, 0) + 1
        count[b] = count.get(b, 0) + 1
    total = {}
    for a, b in links[:, :2].astype(int):
        total[a] = total.get(a, 0) + 1
        total[b] = total.get(b, 0) + 1
    for row in final:
        i = int(row[0])
        assert row[10] == pytest.approx(count.get(i, 0) / total[i], abs=1e-15)


def test_pulled_cube_restart_is_exact(build, tmp_path):
    """Rows (with their fracture block), the rules and the scatter seed are
    in the restart file: the same links break at the same steps, and the
    run continues as without the file (the setup between the halves of
    both runs is the same)."""
    memory, l_memory, _ = pulled_cube(build, tmp_path / "memory")
    restart, l_restart, _ = pulled_cube(build, tmp_path / "restart", split="restart")
    assert broken_set(l_memory) == broken_set(l_restart)
    assert np.array_equal(memory, restart)


@pytest.mark.parametrize("nprocs", [2, 4])
def test_pulled_cube_on_several_ranks(build, tmp_path, nprocs):
    """The same broken links at the same steps; fields to round-off (the
    summation order; 5e-9 as for the plastic cube)."""
    one, l_one, _ = pulled_cube(build, tmp_path / "one")
    many, l_many, _ = pulled_cube(build, tmp_path / "many", nprocs=nprocs)
    assert broken_set(l_one) == broken_set(l_many)
    diff = field_difference(one, many, FIELDS, LINK_FORCE)
    print(f"\n{nprocs} ranks vs 1: {diff}")
    assert max(diff.values()) < 5e-9


@pytest.mark.parametrize("threads", [1, 2])
def test_pulled_cube_kk_matches_cpu(build, tmp_path, threads):
    if build.name not in ("kokkos", "kokkos5"):
        pytest.skip("the kk styles are in the kokkos builds")
    cpu, l_cpu, _ = pulled_cube(build, tmp_path / "cpu")
    kk, l_kk, _ = pulled_cube(build, tmp_path / "kk",
                              extra_args=kokkos_args(threads))
    assert broken_set(l_cpu) == broken_set(l_kk)
    diff = field_difference(cpu, kk, FIELDS, LINK_FORCE)
    print(f"\nkk {threads} thread(s) vs cpu: {diff}")
    if threads == 1:
        # one thread adds in the CPU style's order
        assert max(diff.values()) == 0.0
    else:
        assert max(diff.values()) < 5e-9


# ---------------------------------------------------------------------------
# a bar pulled apart: broken pairs that separate are forgotten

BAR = """
units           si
atom_style      mca
atom_modify     map array sort 0 0
boundary        f f m
lattice         fcc 0.7184
region          box block -0.1 2.1 -0.1 2.1 -0.1 6.1 units lattice
create_box      1 box
create_atoms    1 region box
mca_set         all packing fcc radius 0.254
comm_modify     vel yes
pair_style      mca fracture links
pair_coeff      * * E 70e9 nu 0.3 rho 2700 break stress 2e6
region          top block INF INF INF INF 4.0 INF units box
region          bot block INF INF INF INF INF 0.1 units box
group           top region top
group           bot region bot
fix             top top mca/setvelocity 0 0 {speed}
fix             bot bot mca/setvelocity 0 0 0
fix             nve all nve/mca
compute         F all mca/fracture
compute         D all mca/atom damage
compute         Dmax all reduce max c_D
thermo_style    custom step pe ke c_F[1] c_F[6] c_Dmax
thermo_modify   format float %.17g
thermo          1
timestep        2.0e-5
run             {nsteps}
"""


def test_bar_pulled_apart_forgets_separated_pairs(build, tmp_path):
    """A 2a x 2a x 6a bar (213 automata) whose top layer is pulled at
    20 m/s from rest: the impact (rho c v, far above the strength) breaks
    the links to the top layer at once, and the layer moves away by 0.8 m,
    six times the room of the cutoff (0.5 R).  The run goes on (the
    separated broken pairs are dropped from the tables before their
    partners leave the ghost atoms) and the links stay counted once they
    are forgotten.  (An impact of one step has no trapezoidal work: the
    energy balance of breaking needs a smoothly loaded scene, the notched
    plate of issue #14's hard cases, not yet here.)"""
    speed, nsteps = 20.0, 2000
    build.run(BAR.format(speed=speed, nsteps=nsteps), tmp_path)
    t = read_thermo(tmp_path / "log.lammps")
    assert np.all(np.isfinite(t["PotEng"])) and np.all(np.isfinite(t["KinEng"]))
    broken = t["c_F[1]"]
    print(f"\n{broken[-1]:.0f} links broken, max damage {t['c_Dmax'][-1]:.3f}")
    assert broken[-1] > 0
    # once broken, links stay counted, forgotten or not
    assert np.all(np.diff(broken) >= 0)
    assert t["c_Dmax"][-1] == 1.0


# ---------------------------------------------------------------------------
# bad input

SINGLE = """
units           si
atom_style      mca
atom_modify     map array
lattice         fcc 0.7184
region          box block 0 2 0 2 0 2
create_box      1 box
create_atoms    1 box
comm_modify     vel yes
pair_style      {style}
pair_coeff      * * E 70e9 nu 0.3 rho 2700 {coeff}
{extra}
run             0
"""


@pytest.mark.parametrize("style,coeff,extra,message", [
    ("mca fracture links", "break brittle 1e6", "",
     "unknown break criterion brittle (allowed: none, strain eps_u, stress sigma_u, "
     "drucker_prager sigma_t sigma_c, elliptic sigma0 tau0)"),
    ("mca fracture links", "break strain -1e-3", "", "break strain eps_u must be > 0, got -1e-3"),
    ("mca fracture links", "break stress 0", "", "break stress sigma_u must be > 0, got 0"),
    ("mca fracture links", "break drucker_prager 2e6 1e6", "",
     "break drucker_prager sigma_c must be >= sigma_t (2000000), got 1e6"),
    ("mca fracture links", "break drucker_prager -2e6 6e6", "",
     "break drucker_prager sigma_t must be > 0, got -2e6"),
    ("mca fracture links", "break elliptic 2e6 0", "", "break elliptic tau0 must be > 0, got 0"),
    ("mca fracture links", "break elliptic 2e6", "", "Illegal pair_coeff break elliptic"),
    ("mca fracture cracks", "", "", "Unknown fracture part cracks for pair_style mca "
     "(allowed: links)"),
    ("mca fracture links scatter 1.5 7", "break stress 1e6", "",
     "scatter width must be in [0, 1), got 1.5"),
    ("mca fracture links scatter 0.1 -3", "break stress 1e6", "",
     "scatter seed must be a positive integer, got -3"),
    ("mca", "", "compute F all mca/fracture",
     "Compute mca/fracture requires the fracture part of pair_style mca"),
])
def test_bad_fracture_input(build, tmp_path, style, coeff, extra, message):
    result = build.run(SINGLE.format(style=style, coeff=coeff, extra=extra), tmp_path,
                       check=False, timeout=120)
    output = result.stdout + result.stderr
    assert result.returncode != 0
    assert message in output, output[-2000:]


@pytest.mark.parametrize("style,coeff,message", [
    ("mca fracture links", "", "fracture links without a break criterion"),
    ("mca", "break stress 1e6", "a break criterion is given but the link model has no fracture"),
    ("mca scatter 0.2 5", "", "scatter has no effect without 'fracture links'"),
])
def test_fracture_warnings(build, tmp_path, style, coeff, message):
    result = build.run(SINGLE.format(style=style, coeff=coeff, extra=""), tmp_path,
                       timeout=120)
    assert message in result.stdout + result.stderr
