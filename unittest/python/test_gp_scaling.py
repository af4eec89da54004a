"""GP scale levels of pair_style gp/morse and gp/lj/cut (doc/src/pair_gp.rst;
the GP digest, sec. 1.1, 1.3 and 4.1: Cu, Morse and Lennard-Jones, k = 2).

* scale independence: pure level-1, 2 and 3 periodic crystals of the same
  size, strained alike, have the same energy per atom represented and the
  same stress (energy-consistent scaling: exact but for round-off; bound
  1e-12, the sums over 2048 and 32 particles differ in their order), for
  both potentials; the kk variants give the same;
* dynamics: a level-n system is the atomic one with lengths and times
  scaled by s (the period of a wave at level 3 is 4 times that of the
  level-1 box a quarter the size, to 1e-5); the period of a long P
  standing wave in a box of the same size at levels 1-3 is the same with
  the energy-consistent scaling (within 2 %: the coarser lattices have
  fewer planes per wavelength, 1.1 % at level 3), 1/sqrt(s)
  with the thesis's force l f (pmap) and 1/s with l s f (pmap_invmap),
  the wave speeds the digest derives (within 2 %);
* bad input: clear errors naming the argument and the allowed values.
"""

import re

import pytest

import mcatest

CU = "0.3429 1.3588 2.866"    # Girifalco-Weizer Morse of Cu: D0 (eV), alpha (1/A), r0 (A)
POTENTIALS = {"morse": ("gp/morse 6.5", CU), "lj/cut": ("gp/lj/cut 5.5", "0.4093 2.338")}

CRYSTAL = """
variable        s equal 2^({level}-1)
variable        l equal v_s^3
units           metal
boundary        p p p
lattice         fcc $(3.615*v_s)
region          box block 0 $({nx}/v_s) 0 $({ny}/v_s) 0 $({ny}/v_s)
create_box      1 box
create_atoms    1 box
mass            1 $(63.546*v_l)
pair_style      {style} ratio 2 scaling {scaling}
pair_coeff      1 1 {coeffs} level {level}
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
    style, coeffs = POTENTIALS[potential]
    return CRYSTAL.format(level=level, nx=nx, ny=ny, scaling=scaling, style=style, coeffs=coeffs)


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
    kk = static(build, tmp_path / "kk", 3, extra=("-k", "on", "t", "2", "-sf", "kk"),
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
variable        ux atom 0.01*sin(v_k*x)
displace_atoms  all move v_ux 0 0 units box
variable        proj atom c_d[1]*sin(v_k*x)
compute         proj all reduce sum v_proj
fix             nve all nve
timestep        0.001
variable        t equal time
variable        p equal c_proj
fix             out all print 10 "${{t}} ${{p}}" file wave.dat screen no
run             {steps}
"""


def wave_period(build, directory, level, scaling, nx=32):
    """The first zero of the projection A cos(omega t) of the displacement on
    the standing wave: a quarter period (ps)."""
    script = crystal(level, nx, 4, scaling) + WAVE.format(steps=1000)
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


def test_level_is_the_atomic_system_scaled(build, tmp_path):
    """Energy-consistent scaling: a level-n system is the atomic one with
    lengths and times scaled by s (m0 r'' = -phi'(r) / s^2 in the mapped
    coordinates), so the wave of the box L at level 3 has 4 times the
    period of the wave of the box L/4 at level 1, the same number of
    lattice planes per wavelength (bound 1e-5: the zero is interpolated
    between samples, and level 3 integrates with the step of 1/4 fs at
    level 1)."""
    t3 = wave_period(build, tmp_path / "l3", 3, "energy", nx=32)
    t1 = wave_period(build, tmp_path / "l1", 1, "energy", nx=8)
    print(f"\nlevel 3, 32 cells: {t3:.8f} ps; 4 x level 1, 8 cells: {4 * t1:.8f} ps")
    assert t3 == pytest.approx(4.0 * t1, rel=1e-5)


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
])
def test_bad_input(build, tmp_path, commands, message):
    result = build.run(BASE + commands + "\n", tmp_path, check=False)
    output = result.stdout + result.stderr
    assert 0 < result.returncode < 128, output[-2000:]
    assert re.search(message, output), output[-2000:]

