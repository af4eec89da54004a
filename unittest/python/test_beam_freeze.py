"""fix beam/freeze: new beams between particles that come within the
capture distance (NUMFRAC's freezing and contact-formation criterion;
doc/src/fix_beam_freeze.rst; digest A.8 and R4).

* two unbonded particles that approach bond at the first attempt at which
  they are within dc (the step read off the dump), stress-free: the bond's
  energy is 0 there; from then on the pair style leaves them out (evdwl
  exactly 0) and the bond's energy is EA (r - r_f)^2 / 2 r_f with r_f the
  distance at freezing (to 1e-9), the total energy conserved;
* the mutual choice: in a row A - B - C (distances 1 and 1.05), B and A
  pick each other first, then B and C; with maxbond 1 or a full special
  list (the warning) C stays free; on 2 ranks the same;
* a disordered scene (thermal particles with elastic contacts in a
  periodic box, which bond when they meet, prob 0.6 per attempt, while
  their bonds melt) makes the same bonds at the same steps, and the same
  trajectory to round-off, on 1, 2 and 4 ranks, newton_bond on and off,
  continued from a restart file, and with the Kokkos styles (the fix on
  the host) on 1 and 2 threads;
* the example examples/beam_flow at reduced size: a sheared layer whose
  melted bonds re-bond with new neighbours flows steadily to large
  strains, keeping its bonds; without the fix it comes apart;
* bad input gives clear errors.
"""

import importlib.util
import re

import numpy as np
import pytest

import mcatest
import test_bond_beam as beam2d
from mcatest import read_dump

E_, A_, I_ = 100.0, 0.1, 0.001    # EA = 10
LJ_SIGMA, LJ_CUT = 0.95, 2.5


def free_data(path, positions, box, velocities=None):
    """A 2-D atom_style mca data file of particles without bonds (one
    bond type); read it with extra/bond/per/atom and extra/special/per/atom."""
    lines = ["freeze test data", "", f"{len(positions)} atoms", "1 atom types",
             "0 bonds", "1 bond types", "",
             f"{box[0][0]} {box[0][1]} xlo xhi", f"{box[1][0]} {box[1][1]} ylo yhi",
             "-0.5 0.5 zlo zhi", "", "Atoms # mca", ""]
    for k, (x, y) in enumerate(positions):
        lines.append(f"{k + 1} 1 1 0 0.5 1.0 1.0 0.1 {x:.17g} {y:.17g} 0")
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines) + "\n")
    return path


def reading(data, bonds=4, specials=4):
    return f"{data} extra/bond/per/atom {bonds} extra/special/per/atom {specials}"


# ---------------------------------------------------------------------------
# two particles that approach

DC, V = 1.1, 0.25    # relative speed 0.5
DT, STEPS = 0.002, 600


def approach(build, directory, nevery=1, nprocs=1, newton="on", extra_args=()):
    data = free_data(directory / "two.data", [(-0.65, 0.0), (0.65, 0.0)], ((-3, 3), (-3, 3)))
    script = beam2d.header(reading(data), newton=newton).replace(
        "read_data", "processors      * 1 1\nread_data") + f"""
special_bonds   lj/coul 0 1 1
pair_style      lj/cut {LJ_CUT}
pair_coeff      * * 1.0 {LJ_SIGMA}
bond_style      beam
bond_coeff      1 {E_} {A_} {I_}
velocity        all set 0.0 0.0 0.0
set             atom 1 vx {V}
set             atom 2 vx {-V}
fix             1 all nve/mca
fix             2 all enforce2d
fix             3 all beam/freeze {nevery} 1 {DC}
timestep        {DT}
thermo_style    custom step evdwl ebond ke etotal bonds f_3[1] f_3[2]
thermo_modify   norm no format float %.17g
thermo          1
dump            d all custom 1 two.dump id x y vx
dump_modify     d format float %.17g sort id
run             {STEPS}
"""
    build.run(script, directory, nprocs=nprocs, extra_args=extra_args)
    thermo = mcatest.read_thermo(directory / "log.lammps")
    frames = read_dump(directory / "two.dump")
    r = np.array([f["x"][1] - f["x"][0] for f in frames])
    return thermo, r


@pytest.mark.parametrize("nevery", [1, 10])
def test_approaching_particles_freeze_stress_free(build, tmp_path, nevery):
    thermo, r = approach(build, tmp_path, nevery)
    steps = thermo["Step"].astype(int)
    bonded = thermo["Bonds"] > 0
    made = int(np.argmax(bonded))
    # the first attempt step at which they are within dc
    expected = next(s for s in range(1, STEPS + 1) if s % nevery == 0 and r[s] <= DC)
    print(f"N = {nevery}: bonded at step {steps[made]} (predicted {expected}), "
          f"r = {r[made]:.9f}")
    assert steps[made] == expected
    assert np.all(bonded[made:]) and not np.any(bonded[:made])
    assert thermo["f_3[2]"][-1] == 1 and thermo["f_3[1]"][made] == 1
    # stress-free where it formed; the pair style leaves the bonded pair out
    assert thermo["E_bond"][made] == 0.0
    assert np.all(thermo["E_vdwl"][made:] == 0.0) and np.all(thermo["E_vdwl"][:made] != 0.0)
    # an axial spring of rest length r_f: EA (r - r_f)^2 / 2 r_f
    rf = r[made]
    after = slice(made, None)
    predicted = 0.5 * E_ * A_ * (r[after] - rf) ** 2 / rf
    err = np.abs(thermo["E_bond"][after] - predicted).max() / predicted.max()
    drift = np.ptp(thermo["TotEng"][after]) / thermo["KinEng"][made]
    print(f"bond energy to {err:.1e} of EA (r - r_f)^2 / 2 r_f (largest {predicted.max():.4f}); "
          f"total energy within {drift:.1e} of the kinetic energy")
    assert predicted.max() > 0.01 and err < 1e-9
    # (velocity Verlet at omega dt = 0.009: the energy oscillates by ~(omega dt)^2 / 8)
    assert drift < 1e-4


@pytest.mark.mpi
@pytest.mark.parametrize("newton", ["on", "off"])
def test_approaching_particles_on_two_ranks(build, tmp_path, newton):
    ref, r_ref = approach(build, tmp_path / "one")
    thermo, r = approach(build, tmp_path / "two", nprocs=2, newton=newton)
    assert "2 by 1 by 1 MPI processor grid" in (tmp_path / "two" / "log.lammps").read_text()
    print(f"2 ranks, newton_bond {newton}: distance to {np.abs(r - r_ref).max():.1e}")
    assert np.array_equal(thermo["Bonds"], ref["Bonds"])
    assert np.abs(r - r_ref).max() < 1e-13
    assert np.abs(thermo["E_bond"] - ref["E_bond"]).max() < 1e-13


def test_kokkos_approaching_particles_freeze(tmp_path):
    kk = mcatest.kokkos_build()
    ref, r_ref = approach(kk, tmp_path / "cpu")
    for threads in mcatest.kokkos_thread_counts():
        thermo, r = approach(kk, tmp_path / f"kk{threads}", extra_args=mcatest.kokkos_args(threads))
        log = (tmp_path / f"kk{threads}" / "log.lammps").read_text()
        assert "pair lj/cut/kk" in log    # (the Kokkos styles)
        print(f"kk {threads} thread(s): distance to {np.abs(r - r_ref).max():.1e}")
        assert np.array_equal(thermo["Bonds"], ref["Bonds"])
        assert np.abs(r - r_ref).max() < 1e-13


# ---------------------------------------------------------------------------
# the mutual choice: a row A - B - C at rest

def row(build, directory, keywords="", specials=4, nprocs=1):
    data = free_data(directory / "row.data", [(0.0, 0.0), (1.0, 0.0), (2.05, 0.0)],
                     ((-3, 5), (-3, 3)))
    script = beam2d.header(reading(data, specials=specials)).replace(
        "read_data", "processors      * 1 1\nread_data") + f"""
special_bonds   lj/coul 0 1 1
pair_style      zero 1.2
pair_coeff      * *
bond_style      beam
bond_coeff      1 {E_} {A_} {I_}
fix             1 all nve/mca
fix             2 all enforce2d
fix             3 all beam/freeze 1 1 1.1 {keywords}
thermo_style    custom step bonds f_3[1]
thermo          1
compute         b all property/local batom1 batom2
dump            d all local 3 row.bonds c_b[1] c_b[2]
run             3
"""
    build.run(script, directory, nprocs=nprocs)
    thermo = mcatest.read_thermo(directory / "log.lammps")
    text = (directory / "row.bonds").read_text().split("ITEM: ENTRIES c_b[1] c_b[2]")[-1]
    pairs = sorted(tuple(sorted(map(int, line.split()))) for line in text.strip().splitlines())
    return thermo["Bonds"].astype(int).tolist(), pairs, (directory / "log.lammps").read_text()


@pytest.mark.parametrize("nprocs", [1, pytest.param(2, marks=pytest.mark.mpi)])
def test_mutual_choice_bonds_the_closest_pairs_first(build, tmp_path, nprocs):
    bonds, pairs, _ = row(build, tmp_path / "free", nprocs=nprocs)
    # step 0, then A-B (the closest pair) at step 1, B-C at step 2
    assert bonds == [0, 1, 2, 2] and pairs == [(1, 2), (2, 3)]
    bonds, pairs, _ = row(build, tmp_path / "maxbond", "maxbond 1", nprocs=nprocs)
    assert bonds == [0, 1, 1, 1] and pairs == [(1, 2)]
    # B's special list is full after A-B: no B-C, and a warning that says why
    # (about B and C, which both had a partner within dc but no room)
    bonds, pairs, log = row(build, tmp_path / "full", specials=0, nprocs=nprocs)
    assert bonds == [0, 1, 1, 1] and pairs == [(1, 2)]
    assert re.search(r"WARNING: Fix beam/freeze: 2 particles at step 2 had a partner within the "
                     r"capture distance but no room", log)


# ---------------------------------------------------------------------------
# a disordered scene: a gas of particles that meet, bond, melt and meet others

SCENE_STEPS, SCENE_N = 500, 8


def scene_sites():
    """8 x 8 particles on a jittered grid of spacing 1.5 (none within dc)."""
    rng = np.random.default_rng(31)
    grid = [(1.5 * (c + 0.5), 1.5 * (r + 0.5)) for r in range(SCENE_N) for c in range(SCENE_N)]
    return np.array(grid) + rng.uniform(-0.12, 0.12, (SCENE_N * SCENE_N, 2))


# (elastic contacts between unbonded particles: a bond lets its pair come
# closer than the contact distance, and a stiff LJ core would throw a pair
# whose compressed bond melts apart)
SCENE_SETUP = f"""
special_bonds   lj/coul 0 1 1
comm_modify     vel yes
pair_style      gran/hooke 30.0 NULL 0.0 NULL 0.0 0
pair_coeff      * *
bond_style      beam
bond_coeff      1 {E_} {A_} {I_} melt rate 0.5 77
"""


def scene(build, directory, nprocs=1, newton="on", extra_args=(), restart_at=None):
    """Thermal particles with contacts in a periodic box: pairs that come
    within dc = 1.15 bond (prob 0.6 per attempt every 5 steps), bonds melt
    at the rate 0.5 and break; the bonds at the end (as pairs) and the
    positions and velocities at the end."""
    box = 1.5 * SCENE_N
    data = free_data(directory / "gas.data", scene_sites(), ((0, box), (0, box)))
    setup = beam2d.header(reading(data, bonds=6, specials=10), boundary="p p p",
                          newton=newton) + SCENE_SETUP + "velocity        all create 0.5 4928 loop geom\n"
    body = f"""
fix             1 all nve/mca
fix             2 all enforce2d
fix             3 all beam/freeze 5 1 1.15 prob 0.6 91
timestep        0.005
thermo_style    custom step bonds f_3[2] pe ke
thermo_modify   norm no format float %.17g
thermo          50
"""
    output = f"""
compute         b all property/local batom1 batom2
dump            b all local {SCENE_STEPS} bonds.local c_b[1] c_b[2]
dump            d all custom {SCENE_STEPS} end.dump id x y vx vy
dump_modify     d format float %.17g sort id
"""
    if restart_at is None:
        build.run(setup + body + output + f"run {SCENE_STEPS}\n", directory, nprocs=nprocs,
                  extra_args=extra_args)
    else:
        build.run(setup + body + f"run {restart_at}\nwrite_restart   half.restart\n", directory,
                  nprocs=nprocs, extra_args=extra_args)
        again = f"""
units           lj
dimension       2
atom_style      mca
atom_modify     map array
newton          on {newton}
read_restart    half.restart
comm_modify     cutoff 2.5
""" + SCENE_SETUP + body + output + f"run {SCENE_STEPS - restart_at}\n"
        build.run(again, directory, nprocs=nprocs, extra_args=extra_args, name="in.again")
    frames = read_dump(directory / "end.dump")
    text = (directory / "bonds.local").read_text().split("ITEM: ENTRIES c_b[1] c_b[2]")[-1]
    pairs = sorted(tuple(sorted(map(int, line.split()))) for line in text.strip().splitlines())
    thermo = mcatest.read_thermo(directory / "log.lammps")
    return frames[-1], pairs, thermo


def compare_scenes(ref, other, label, tol=1e-10):
    (f0, p0, t0), (f1, p1, t1) = ref, other
    dx = max(np.abs(f1[k] - f0[k]).max() for k in ("x", "y"))
    print(f"{label}: {len(p1)} bonds at the end ({int(t1['f_3[2]'][-1])} made), positions to "
          f"{dx:.1e}")
    assert p1 == p0
    # (a continued run prints from its first step on)
    common = np.isin(t0["Step"], t1["Step"])
    assert np.array_equal(t1["Bonds"][np.isin(t1["Step"], t0["Step"])], t0["Bonds"][common])
    assert dx < tol


@pytest.fixture(scope="module")
def scene_reference(tmp_path_factory):
    build = mcatest.builds()[0]
    return build, scene(build, tmp_path_factory.mktemp("scene_ref"))


def test_scene_melts_and_freezes_new_pairs(scene_reference):
    _, (frame, pairs, thermo) = scene_reference
    made = int(thermo["f_3[2]"][-1])
    bonds = thermo["Bonds"].astype(int)
    print(f"{made} bonds made, {made - bonds[-1]} of them melted, {bonds[-1]} at the end "
          f"({len(pairs)} listed)")
    # the scene exercises both: many bonds form (every one a pair that met
    # during the run) and many melt (rate 0.5 over 2.5 time units)
    assert made >= 30 and made - bonds[-1] >= 10 and len(pairs) == bonds[-1]


@pytest.mark.mpi
@pytest.mark.parametrize("nprocs,newton", [(2, "on"), (2, "off"), (4, "on")])
def test_scene_on_ranks(scene_reference, tmp_path, nprocs, newton):
    build, ref = scene_reference
    compare_scenes(ref, scene(build, tmp_path, nprocs=nprocs, newton=newton),
                   f"{nprocs} ranks newton_bond {newton}")


def test_scene_continued_from_a_restart(scene_reference, tmp_path):
    build, ref = scene_reference
    compare_scenes(ref, scene(build, tmp_path, restart_at=SCENE_STEPS // 2 + 22), "restart")


def test_kokkos_scene(tmp_path):
    kk = mcatest.kokkos_build()
    ref = scene(kk, tmp_path / "cpu")
    for threads in mcatest.kokkos_thread_counts():
        compare_scenes(ref, scene(kk, tmp_path / f"kk{threads}",
                                  extra_args=mcatest.kokkos_args(threads)),
                       f"kk {threads} thread(s)")


# ---------------------------------------------------------------------------
# the example examples/beam_flow at reduced size (12 x 6 cells, tau = 0.2,
# 800 time units of melting; the example: 24 x 12, three stresses)

EXAMPLE = mcatest.ROOT / "examples" / "beam_flow"


def test_flow_example_keeps_its_bonds_to_large_strains(build, tmp_path):
    """The sheared beam layer of examples/beam_glen with a fast Glen
    factor: its melted bonds freeze again as the same pairs while they are
    no longer than 1.2, which the rows that slide past each other outgrow
    at a shear strain of about 0.4.  With fix beam/freeze the particles
    bond with their new neighbours: the layer flows to a strain of 2 and
    more and keeps 85 % of its bonds or more at every step, at a late rate
    (strain 0.5 to 2.5) within a factor 2 of the early one (0.05 to 0.35:
    a steady flow; measured 1.3 here, 1.2 at full size).  Without the fix
    its broken bonds are lost: it comes apart (below 75 % of its bonds,
    and more than twice the strain in the same time)."""
    spec = importlib.util.spec_from_file_location("flow_plot", EXAMPLE / "plot.py")
    plot = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(plot)
    runs = {}
    for freeze in (1, 0):
        d = tmp_path / f"freeze{freeze}"
        build.run((EXAMPLE / "in.flow").read_text(), d, name="in.flow",
                  variables={"tau": 0.2, "nx": 12, "ny": 6, "time": 800, "freeze": freeze})
        if "keeps bonded pairs in its neighbor list" in (d / "log.lammps").read_text():
            pytest.skip("the contacts of this LAMMPS version (2021) act between bonded particles "
                        "too: another model (bond style beam's warning)")
        runs[freeze] = plot.summary(d / "log.lammps")
    kept, lost = runs[1], runs[0]
    for r in (kept, lost):
        print(f"freeze {int(r['freeze'])}: strain {r['strain'][-1]:.3f}, bonds "
              f"{r['bonds'].min() / r['bonds'][0]:.1%} at the fewest, {r['bonds'][-1]:.0f} of "
              f"{r['bonds'][0]:.0f} at the end, {r['made'][-1]:.0f} made; rate early "
              f"{r['early']}, late {r['late']}")
    assert kept["strain"][-1] > 2.5 and kept["made"][-1] > 100
    assert kept["bonds"].min() >= 0.85 * kept["bonds"][0]
    assert 1.0 / 2.0 < kept["late"] / kept["early"] < 2.0
    assert lost["made"][-1] == 0 and lost["bonds"][-1] < 0.75 * lost["bonds"][0]
    assert lost["strain"][-1] > 2.0 * kept["strain"][-1]


# ---------------------------------------------------------------------------
# bad input

BAD = [
    ("fix f all beam/freeze 0 1 1.1", "N (steps between attempts) must be >= 1, not 0"),
    ("fix f all beam/freeze 1 2 1.1", "btype 2 is not a bond type (1 to 1)"),
    ("fix f all beam/freeze 1 1 0.0", "dc (capture distance) must be > 0"),
    ("fix f all beam/freeze 1 1 1.1 prob 1.5 3", "prob P must be in (0, 1]"),
    ("fix f all beam/freeze 1 1 1.1 prob 0.5 0", "prob seed must be > 0"),
    ("fix f all beam/freeze 1 1 1.1 prob 0.5", "fix beam/freeze prob (P seed)"),
    ("fix f all beam/freeze 1 1 1.1 maxbond 0", "maxbond must be >= 1, not 0"),
    ("fix f all beam/freeze 1 1 1.1 capture 2", "Unknown fix beam/freeze keyword capture"),
    ("fix f all beam/freeze 1 1", "fix beam/freeze (N btype dc)"),
    ("fix f all beam/freeze 1 1 3.0\nrun 0", "dc + skin = 3.3 exceeds the ghost cutoff 2.8"),
    ("special_bonds lj 0 1 1\nfix f all beam/freeze 1 1 1.1\nrun 0",
     "requires special_bonds lj/coul 0 1 1 (or lj 0 1 1 coul 1 1 1)"),
    ("pair_style none\nfix f all beam/freeze 1 1 1.1\nrun 0", "requires a pair style"),
    ("bond_style harmonic\nbond_coeff 1 1.0 1.0\nfix f all beam/freeze 1 1 1.1\nrun 0",
     "requires bond_style beam"),
    ("run_style respa 2 2\nfix f all beam/freeze 1 1 1.1\nrun 0", "does not support run_style respa"),
]


@pytest.mark.parametrize("line,message", BAD, ids=[b[1][:40] for b in BAD])
def test_bad_input_gives_clear_errors(build, tmp_path, line, message):
    data = free_data(tmp_path / "two.data", [(-0.6, 0.0), (0.6, 0.0)], ((-3, 3), (-3, 3)))
    script = beam2d.header(reading(data)) + f"""
special_bonds   lj/coul 0 1 1
pair_style      lj/cut {LJ_CUT}
pair_coeff      * * 1.0 {LJ_SIGMA}
bond_style      beam
bond_coeff      1 {E_} {A_} {I_}
fix             1 all nve/mca
{line}
"""
    result = build.run(script, tmp_path, check=False)
    out = result.stdout + result.stderr
    assert result.returncode != 0 and "ERROR" in out, out[-2000:]
    assert message in out, out[-2000:]
