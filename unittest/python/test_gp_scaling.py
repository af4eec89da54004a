"""GP scale levels of the pair styles gp/morse, gp/lj/cut, gp/eam/alloy and
gp/eam/fs (doc/src/pair_gp.rst; the GP digest, sec. 1.1, 1.3 and 4.1: Cu,
Morse, Lennard-Jones and EAM, Fe EAM, k = 2).

* scale independence: pure level-1, 2 and 3 periodic crystals of the same
  size, strained alike, have the same energy per atom represented and the
  same stress (energy-consistent scaling: exact but for round-off; bound
  1e-12, the sums over 2048 and 32 particles differ in their order), for
  each potential; the kk variants give the same;
* EAM: level 1 is the atomic style (eam/alloy, eam/fs: energy, forces and
  stress to round-off, 1e-13); types of different levels do not interact
  (two levels in one box: the energy of the two alone, densities
  included, to 1e-12);
* dynamics: a level-n system is the atomic one with lengths and times
  scaled by s (the period of a wave at level 3 is 4 times that of the
  level-1 box a quarter the size, to 1e-5; Morse and EAM); the period of a
  long P standing wave in a box of the same size at levels 1-3 is the
  same with the energy-consistent scaling (within 2 %: the coarser
  lattices have fewer planes per wavelength, 1.1 % at level 3), 1/sqrt(s)
  with the thesis's force l f (pmap) and 1/s with l s f (pmap_invmap),
  the wave speeds the digest derives (within 2 %);
* bad input: clear errors naming the argument and the allowed values.
"""

import re

import numpy as np
import pytest

import mcatest

CU = "0.3429 1.3588 2.866"    # Girifalco-Weizer Morse of Cu: D0 (eV), alpha (1/A), r0 (A)
# lattice, a0 (A), mass (g/mol), pair_style, pair_coeff of one type of the level
POTENTIALS = {
    "morse": ("fcc", 3.615, 63.546, "gp/morse 6.5", "1 1 " + CU + " level {level}"),
    "lj/cut": ("fcc", 3.615, 63.546, "gp/lj/cut 5.5", "1 1 0.4093 2.338 level {level}"),
    # (the EAM styles set the masses l m0 from the file's)
    "eam/alloy": ("fcc", 3.615, 63.546, "gp/eam/alloy",
                  "* * Cu_mishin1.eam.alloy Cu level {level}"),
    "eam/fs": ("bcc", 2.855324, 55.845, "gp/eam/fs", "* * Fe_mm.eam.fs Fe level {level}"),
}
EAM = ["eam/alloy", "eam/fs"]

CRYSTAL = """
variable        s equal 2^({level}-1)
variable        l equal v_s^3
units           metal
boundary        p p p
lattice         {lattice} $({a0}*v_s)
region          box block 0 $({nx}/v_s) 0 $({ny}/v_s) 0 $({ny}/v_s)
create_box      1 box
create_atoms    1 box
mass            1 $({m0}*v_l)
pair_style      {style} ratio 2 scaling {scaling}
pair_coeff      {coeffs}
"""

STATIC = """
thermo_style    custom step pe pxx pyy pzz pxy atoms
change_box      all triclinic
change_box      all x scale 1.01 y scale 0.995 xy final 0.3 remap units box
run             0
variable        e equal pe/atoms/v_l
print           "RESULT $(v_e:%.17g) $(pxx:%.17g) $(pyy:%.17g) $(pzz:%.17g) $(pxy:%.17g)"
"""


def crystal(level, nx, ny, scaling, potential="morse"):
    lattice, a0, m0, style, coeffs = POTENTIALS[potential]
    return CRYSTAL.format(level=level, nx=nx, ny=ny, scaling=scaling, lattice=lattice, a0=a0,
                          m0=m0, style=style, coeffs=coeffs.format(level=level))


def static(build, directory, level, extra=(), potential="morse"):
    script = crystal(level, 8, 8, "energy", potential) + STATIC
    result = build.run(script, directory, extra_args=extra)
    return [float(v) for v in re.search(r"RESULT (.*)", result.stdout).group(1).split()]


@pytest.mark.parametrize("potential", list(POTENTIALS))
def test_pure_levels_have_the_same_energy_and_stress(build, tmp_path, potential):
    values = {level: static(build, tmp_path / f"l{level}", level, potential=potential)
              for level in (1, 2, 3)}
    print("\n" + "\n".join(f"level {k}: {v}" for k, v in values.items()))
    for level in (2, 3):
        for a, b in zip(values[level], values[1]):
            assert a == pytest.approx(b, rel=1e-12, abs=1e-9)


@pytest.mark.parametrize("potential", list(POTENTIALS))
def test_pure_levels_with_kk(tmp_path, potential):
    build = mcatest.kokkos_build()
    cpu = static(build, tmp_path / "cpu", 3, potential=potential)
    kk = static(build, tmp_path / "kk", 3, extra=mcatest.kokkos_args(),
                potential=potential)
    for a, b in zip(kk, cpu):
        assert a == pytest.approx(b, rel=1e-12, abs=1e-9)


WAVE = """
fix             relax all box/relax iso 0.0
minimize        0 1e-10 1000 10000
unfix           relax
reset_timestep  0
variable        k equal 2*PI/lx
compute         d all displace/atom
variable        ux atom {amplitude}*sin(v_k*x)
displace_atoms  all move v_ux 0 0 units box
variable        proj atom c_d[1]*sin(v_k*x)
compute         proj all reduce sum v_proj
fix             nve all nve
timestep        {dt}
variable        t equal time
variable        p equal c_proj
fix             out all print 10 "${{t}} ${{p}}" file wave.dat screen no
run             {steps}
"""


def wave_period(build, directory, level, scaling, nx=32, potential="morse", scaled=False):
    """The first zero of the projection A cos(omega t) of the displacement on
    the standing wave of amplitude 0.01 A: a quarter period (ps).  With
    scaled, amplitude and time step are s times those of level 1."""
    s = 2.0 ** (level - 1) if scaled else 1.0
    script = crystal(level, nx, 4, scaling, potential) + WAVE.format(
        steps=1000, amplitude=0.01 * s, dt=0.001 * s)
    build.run(script, directory)
    rows = [tuple(map(float, line.split())) for line in (directory / "wave.dat").read_text()
            .splitlines() if not line.startswith("#")]
    for (t1, p1), (t2, p2) in zip(rows, rows[1:]):
        if p1 > 0.0 >= p2:
            return 4.0 * (t1 + (t2 - t1) * p1 / (p1 - p2))
    raise AssertionError(f"the wave did not reach a quarter period in {rows[-1][0]} ps")


@pytest.mark.parametrize("scaling,exponent", [("energy", 0.0), ("pmap", -0.5),
                                              ("pmap_invmap", -1.0)])
def test_wave_period_of_each_scaling(build, tmp_path, scaling, exponent):
    period = {level: wave_period(build, tmp_path / f"{scaling}{level}", level, scaling)
              for level in (1, 2, 3)}
    print(f"\n{scaling}: periods (ps) " + ", ".join(f"{v:.5f}" for v in period.values()))
    for level in (2, 3):
        s = 2.0 ** (level - 1)
        ratio = period[level] / period[1]
        assert ratio == pytest.approx(s**exponent, rel=0.02), f"level {level}: {ratio:.4f}"


@pytest.mark.parametrize("potential", ["morse", "eam/fs"])
def test_level_is_the_atomic_system_scaled(build, tmp_path, potential):
    """Energy-consistent scaling: a level-n system is the atomic one with
    lengths and times scaled by s (m0 r'' = -phi'(r) / s^2 in the mapped
    coordinates), so the wave of the box L at level 3, of 4 times the
    amplitude, integrated with 4 times the time step, is the wave of the
    box L/4 at level 1, the same number of lattice planes per wavelength,
    in 4 times the time: its period is 4 times the other to round-off
    (the relaxations, the integration and the interpolated zero are the
    same; bound 1e-9)."""
    t3 = wave_period(build, tmp_path / "l3", 3, "energy", nx=32, potential=potential,
                     scaled=True)
    t1 = wave_period(build, tmp_path / "l1", 1, "energy", nx=8, potential=potential)
    print(f"\n{potential}: level 3, 32 cells: {t3:.12f} ps; 4 x level 1, 8 cells: "
          f"{4 * t1:.12f} ps (relative difference {abs(t3 / (4 * t1) - 1):.1e})")
    assert t3 == pytest.approx(4.0 * t1, rel=1e-9)


# ---------------------------------------------------------------------------
# EAM: level 1 is the atomic style; levels do not interact

PERTURBED = """
units           metal
boundary        p p p
lattice         {lattice} {a0}
region          box block 0 4 0 4 0 4
create_box      2 box
create_atoms    1 box
{second}
displace_atoms  all random 0.15 0.15 0.15 4321 units box
change_box      all triclinic
change_box      all x scale 1.01 y scale 0.995 xy final 0.3 remap units box
{delete}
pair_style      {style}
pair_coeff      * * {file} {element} {element}{levels}
thermo_style    custom step pe pxx pyy pzz pxy pxz pyz
thermo_modify   norm no
run             0
print           "RESULT $(pe:%.17g) $(pxx:%.17g) $(pyy:%.17g) $(pzz:%.17g) $(pxy:%.17g) $(pxz:%.17g) $(pyz:%.17g)"
write_dump      all custom forces.dump id x y z fx fy fz modify format float %.17g sort id
"""

EAM_FILES = {"eam/alloy": ("fcc", 3.615, "Cu_mishin1.eam.alloy", "Cu"),
             "eam/fs": ("bcc", 2.855324, "Fe_mm.eam.fs", "Fe")}


def perturbed(build, directory, potential, style, levels="", two_levels=False, delete="",
              extra=(), nprocs=1, by_position=False):
    """A crystal displaced at random and strained: energy, stress and forces
    (by atom ID, or by position: create_atoms numbers the atoms in the
    order of the ranks).  Its atoms are of types 1 and 2 at
    random, or, with two_levels, of type 1, and type 2 are particles on the
    lattice scaled by 2 in the same box."""
    lattice, a0, file, element = EAM_FILES[potential]
    second = (f"lattice {lattice} {2 * a0} origin 0.3 0.2 0.1\ncreate_atoms 2 box"
              if two_levels else "set type 1 type/fraction 2 0.5 1234")
    script = PERTURBED.format(lattice=lattice, a0=a0, second=second, style=style, file=file,
                              element=element, levels=levels, delete=delete)
    result = build.run(script, directory, extra_args=extra, nprocs=nprocs)
    values = np.array([float(v) for v in re.search(r"RESULT (.*)", result.stdout).group(1)
                       .split()])
    dump = mcatest.read_dump(directory / "forces.dump")[0]
    keys = (dump["id"].astype(int) if not by_position else
            [tuple(np.round([x, y, z], 6)) for x, y, z in zip(dump["x"], dump["y"], dump["z"])])
    forces = {k: np.array([fx, fy, fz]) for k, fx, fy, fz in
              zip(keys, dump["fx"], dump["fy"], dump["fz"])}
    return values, forces


def force_difference(a, b):
    """Largest force difference over the atoms of b, relative to b's largest."""
    assert sorted(a) == sorted(b)
    diff = max(np.abs(a[i] - b[i]).max() for i in b)
    return diff / max(np.abs(f).max() for f in b.values())


@pytest.mark.parametrize("potential", EAM)
def test_eam_level_one_is_the_atomic_style(build, tmp_path, potential):
    """Every type at level 1: the level tables are the atomic spline itself
    (each row re-expanded with a = 0, b = 1), evaluated by the same kernel:
    energy, stress and forces of the atomic style to round-off (1e-13 of
    the largest)."""
    gp, gp_f = perturbed(build, tmp_path / "gp", potential, f"gp/{potential}", " level 1 1")
    atomic, atomic_f = perturbed(build, tmp_path / "atomic", potential, potential)
    scale = np.abs(atomic).max()
    df = force_difference(gp_f, atomic_f)
    print(f"\n{potential}: energy and stress differ by {np.abs(gp - atomic).max() / scale:.2e}, "
          f"forces by {df:.2e} of the largest")
    assert np.abs(gp - atomic).max() <= 1e-13 * scale
    assert df <= 1e-13


@pytest.mark.parametrize("potential", EAM)
def test_eam_levels_do_not_interact(build, tmp_path, potential):
    """Atoms (level 1) and level-2 particles in one box: the energy, stress
    and forces are those of each level alone (pair terms and densities),
    to round-off (1e-12)."""
    both, both_f = perturbed(build, tmp_path / "both", potential, f"gp/{potential}", " level 1 2",
                             two_levels=True)
    alone = {}
    for keep, drop in ((1, 2), (2, 1)):
        alone[keep] = perturbed(build, tmp_path / f"only{keep}", potential, f"gp/{potential}",
                                " level 1 2", two_levels=True,
                                delete=f"group drop type {drop}\ndelete_atoms group drop compress no")
    total = alone[1][0] + alone[2][0]
    scale = np.abs(total).max()
    print(f"\n{potential}: the two levels together differ from the sum of each alone by "
          f"{np.abs(both - total).max() / scale:.2e} of the largest")
    assert np.abs(both - total).max() <= 1e-12 * scale
    df = force_difference(both_f, {**alone[1][1], **alone[2][1]})
    print(f"forces: {df:.2e} of the largest")
    assert df <= 1e-12


COINCIDENT = """
units           metal
boundary        p p p
lattice         bcc 2.855324
region          box block 0 4 0 4 0 4
create_box      2 box
create_atoms    1 box
lattice         bcc 5.710648
create_atoms    2 box
mass            * 55.845
neighbor        1.0 {neighbor}
{pair}
thermo_style    custom step pe
run             0
print           "RESULT $(pe:%.17g)"
"""
COINCIDENT_PAIRS = {"eam/fs": "pair_style gp/eam/fs\npair_coeff * * Fe_mm.eam.fs Fe Fe level 1 2",
                    "morse": "pair_style gp/morse 6.5\npair_coeff 1 1 0.4172 1.389 2.845 level 1\n"
                             "pair_coeff 2 2 0.4172 1.389 2.845 level 2"}


@pytest.mark.parametrize("potential", list(COINCIDENT_PAIRS))
@pytest.mark.parametrize("neighbor", ["bin", "multi"])
def test_coincident_levels(build, tmp_path, potential, neighbor):
    """Every level-2 site is a level-1 site: pairs of different levels at
    distance 0 are left out of the neighbor lists (a zero cutoff would
    still list them, and the EAM kernel divides by r): the energy is that
    of the two lattices alone (1e-12)."""
    pair = COINCIDENT_PAIRS[potential]
    script = COINCIDENT.format(neighbor=neighbor, pair=pair)
    both = float(re.search(r"RESULT (\S+)", build.run(script, tmp_path / "both").stdout).group(1))
    alone = 0.0
    for drop in (1, 2):
        text = script.replace("thermo_style", f"group drop type {drop}\ndelete_atoms group drop\n"
                                              "thermo_style")
        out = build.run(text, tmp_path / f"drop{drop}").stdout
        alone += float(re.search(r"RESULT (\S+)", out).group(1))
    print(f"\n{potential}, neighbor {neighbor}: {both:.12g} eV, alone {alone:.12g} eV")
    assert both == pytest.approx(alone, rel=1e-12)


@pytest.mark.parametrize("potential", EAM)
def test_eam_levels_on_4_ranks(build, tmp_path, potential):
    """Atoms and level-2 particles on 4 MPI ranks: the energy, stress and
    forces of 1 rank to round-off (1e-12; the level-2 cutoff of 11 A is
    more than half the box: the ghosts of many images)."""
    one, one_f = perturbed(build, tmp_path / "one", potential, f"gp/{potential}", " level 1 2",
                           two_levels=True, by_position=True)
    four, four_f = perturbed(build, tmp_path / "four", potential, f"gp/{potential}",
                             " level 1 2", two_levels=True, nprocs=4, by_position=True)
    df = force_difference(four_f, one_f)
    print(f"\n{potential}: 4 ranks - 1 rank {np.abs(four - one).max() / np.abs(one).max():.2e} "
          f"(energy, stress), {df:.2e} (forces)")
    assert np.abs(four - one).max() <= 1e-12 * np.abs(one).max()
    assert df <= 1e-12


@pytest.mark.parametrize("potential", EAM)
def test_eam_level_one_with_kk(tmp_path, potential):
    """gp/eam/.../kk at level 1 and at levels 1 and 2 against the CPU style
    (the Kokkos kernels of the base style with the level tables; 1e-12)."""
    build = mcatest.kokkos_build()
    kk = mcatest.kokkos_args()
    for levels, two in ((" level 1 1", False), (" level 1 2", True)):
        cpu, cpu_f = perturbed(build, tmp_path / f"cpu{levels[-1]}", potential,
                               f"gp/{potential}", levels, two_levels=two)
        dev, dev_f = perturbed(build, tmp_path / f"kk{levels[-1]}", potential,
                               f"gp/{potential}", levels, two_levels=two, extra=kk)
        df = force_difference(dev_f, cpu_f)
        print(f"\n{potential},{levels}: kk - CPU {np.abs(dev - cpu).max() / np.abs(cpu).max():.2e}"
              f" (energy, stress), {df:.2e} (forces)")
        assert np.abs(dev - cpu).max() <= 1e-12 * np.abs(cpu).max()
        assert df <= 1e-12


BASE = """
units           metal
lattice         fcc 3.615
region          box block 0 2 0 2 0 2
create_box      2 box
create_atoms    1 box
mass            * 63.546
"""


@pytest.mark.parametrize("commands,message", [
    ("pair_style gp/morse 6.5 ratio 1", r"ratio must be an integer from 2 to 10, got 1"),
    ("pair_style gp/morse 6.5 ratio 2 scaling atoms",
     r"unknown scaling atoms \(allowed: energy, pmap, pmap_invmap\)"),
    ("pair_style gp/morse 6.5 size 2", r"Pair style gp/morse takes the atomic cutoff, then the "
                                       r"keywords ratio and scaling; got 3 arguments"),
    ("pair_style gp/morse 6.5\npair_coeff 1 1 " + CU, r"needs the scale level of the two types "
                                                      r"at its end: 'level n'"),
    ("pair_style gp/morse 6.5\npair_coeff 1 1 " + CU + " level 0", r"level must be from 1 to 10, "
                                                                   r"got 0"),
    ("pair_style gp/morse 6.5\npair_coeff 1 1 " + CU + " level 1\npair_coeff 1 2 " + CU +
     " level 2", r"type 1 has level 1, not 2; types of different levels never interact"),
    # (LAMMPS checks the coefficients of every type before the style)
    ("pair_style gp/morse 6.5\npair_coeff 1 1 " + CU + " level 1\nrun 0",
     r"All pair coeffs are not set"),
    ("pair_style gp/eam/alloy 5.0", r"Pair style gp/eam/alloy takes only the keywords ratio and "
                                    r"scaling; got 1 arguments before them"),
    ("pair_style gp/eam/alloy ratio 11", r"ratio must be an integer from 2 to 10, got 11"),
    ("pair_style gp/eam/alloy\npair_coeff * * Cu_mishin1.eam.alloy Cu Cu",
     r"\* \* file, the 2 element names, then the scale level of each type: "
     r"'level n_1 \.\.\. n_2' \(n = 1 for atoms\); got 5 arguments"),
    ("pair_style gp/eam/alloy\npair_coeff * * Cu_mishin1.eam.alloy Cu Cu level 1",
     r"then the scale level of each type"),
    ("pair_style gp/eam/fs\npair_coeff * * Fe_mm.eam.fs Fe Fe level 1 0",
     r"the level of type 2 must be from 1 to 10, got 0"),
    ("pair_style gp/eam/fs\npair_coeff * * Fe_mm.eam.fs Fe Cu level 1 2",
     r"element Cu \(type 2\) is not in the potential file Fe_mm.eam.fs \(its elements: Fe\)"),
    # 3^9 = 19683 times the 10000 rows of the file
    ("pair_style gp/eam/fs ratio 3\npair_coeff * * Fe_mm.eam.fs Fe Fe level 1 10\nrun 0",
     r"level 10 of ratio 3 needs tables of \d+ rows \(s = 19683 times the atomic 10000\); "
     r"at most 50000000: use fewer levels or a smaller ratio"),
])
def test_bad_input(build, tmp_path, commands, message):
    result = build.run(BASE + commands + "\n", tmp_path, check=False)
    output = result.stdout + result.stderr
    assert 0 < result.returncode < 128, output[-2000:]
    assert re.search(message, output), output[-2000:]

