"""bond_style beam with break, and a pair style that leaves bonded
particles out (special_bonds lj 0 1 1; doc/src/bond_beam.rst, Breaking):
a broken bond leaves the special lists of its two atoms on every rank and
the neighbor lists are built again at the next step (BPM's fix
update/special/bonds, here with newton_bond on or off), so that

* two bonded particles pulled apart feel no pair force while bonded
  (evdwl exactly 0) and the pair force from the step after the break on
  (evdwl = the Lennard-Jones energy at their distance, to 1e-12), with the
  neighbor lists otherwise never rebuilt (neigh_modify every 1000 check
  no): the same thermo output as a run that rebuilds them every step;
* the same on 2 MPI ranks with the particles on different ranks, newton_bond
  on (the bond is evaluated on one rank, the other learns of the break)
  and off, and with the Kokkos variant (Kokkos neighbor lists, on OpenMP
  here);
* a torn strip with an attractive pair between broken neighbours: the
  same bonds broken at every step and the same trajectory on 1 and 2 ranks,
  newton_bond on and off;
* special weights that are neither 1 1 1 nor 0 1 1 are refused.
"""

import re

import numpy as np
import pytest

import mcatest
import test_bond_beam as beam2d
from mcatest import read_dump

E_, A_, I_ = 100.0, 0.1, 0.001
SIGMA0, TAU0 = 0.2, 0.1
LJ_SIGMA, LJ_CUT = 0.95, 2.5
STEPS = 40


def lj_energy(r):
    s6 = (LJ_SIGMA / r) ** 6
    return 4.0 * (s6 * s6 - s6)


def pulled_pair(build, directory, rebuild="every 1000 delay 0 check no", special="lj 0 1 1 coul 0 1 1",
                nprocs=1, newton="on", extra_args=()):
    """Two particles bonded at distance 1, pulled apart at relative speed
    0.1: the bond breaks at N / A = sigma0 (u = 0.002, after about 10
    steps); thermo and positions at every step."""
    # (the bond stored by atom 2: with newton_bond on it is evaluated on the
    # second rank, while the first builds the pair's neighbor list entry
    # from atom 1's special list, which it learns to change from the other)
    data = beam2d.beam_data(directory / "pair.data", [(-0.5, 0.0), (0.5, 0.0)], [(1, 0)],
                            ((-3, 3), (-3, 3)))
    # (the two particles on two ranks when there are two)
    script = beam2d.header(data, newton=newton).replace(
        "read_data", "processors      * 1 1\nread_data") + f"""
special_bonds   {special}
pair_style      lj/cut {LJ_CUT}
pair_coeff      * * 1.0 {LJ_SIGMA}
bond_style      beam
bond_coeff      1 {E_} {A_} {I_} break {SIGMA0} {TAU0}
neigh_modify    {rebuild}
velocity        all set 0.0 0.0 0.0
set             atom 1 vx -0.05
set             atom 2 vx 0.05
fix             1 all nve/mca
fix             2 all enforce2d
timestep        0.002
thermo_style    custom step evdwl ebond bonds
thermo_modify   norm no format float %.17g
thermo          1
dump            d all custom 1 pair.dump id x y vx
dump_modify     d format float %.17g sort id
run             {STEPS}
"""
    build.run(script, directory, nprocs=nprocs, extra_args=extra_args)
    thermo = mcatest.read_thermo(directory / "log.lammps")
    frames = read_dump(directory / "pair.dump")
    distance = np.array([f["x"][1] - f["x"][0] for f in frames])
    return thermo, distance


def test_broken_pair_meets_the_pair_style_at_the_next_step(build, tmp_path):
    thermo, r = pulled_pair(build, tmp_path / "a")
    bonds, evdwl = thermo["Bonds"], thermo["E_vdwl"]
    broke = int(np.argmax(bonds == 0))    # the first step without the bond
    assert 5 < broke < STEPS - 5
    # bonded (and at the breaking step, whose pair forces came first): no pair
    assert np.all(evdwl[:broke + 1] == 0.0)
    after = slice(broke + 1, None)
    err = np.abs(evdwl[after] - lj_energy(r[after])).max() / np.abs(lj_energy(r[after])).max()
    print(f"bond broke at step {broke}; pair energy after it: {evdwl[broke + 1]:.6e} "
          f"(LJ at r = {r[broke + 1]:.6f}: {lj_energy(r[broke + 1]):.6e}), largest error {err:.1e}")
    assert err < 1e-12
    # the lists built again when the bond broke, and only then: the same as
    # building them at every step
    every, r_every = pulled_pair(build, tmp_path / "b", rebuild="every 1 delay 0 check no")
    assert np.array_equal(every["Bonds"], bonds)
    assert np.abs(every["E_vdwl"] - evdwl).max() <= 1e-14 * np.abs(evdwl).max()
    assert np.abs(r_every - r).max() < 1e-14
    neighbor_builds = lambda d: int(re.search(r"Neighbor list builds = (\d+)",
                                              (d / "log.lammps").read_text()).group(1))
    print(f"neighbor list builds: {neighbor_builds(tmp_path / 'a')} (every step: "
          f"{neighbor_builds(tmp_path / 'b')})")
    assert neighbor_builds(tmp_path / "a") == 1
    # with the pair style acting on bonded particles too (overlay): pair energy from the start
    overlay, _ = pulled_pair(build, tmp_path / "c", special="lj/coul 1 1 1")
    assert overlay["E_vdwl"][0] == pytest.approx(lj_energy(1.0), rel=1e-12)


@pytest.mark.mpi
@pytest.mark.parametrize("newton", ["on", "off"])
def test_broken_pair_across_ranks(build, tmp_path, newton):
    ref, r_ref = pulled_pair(build, tmp_path / "one")
    thermo, r = pulled_pair(build, tmp_path / "two", nprocs=2, newton=newton)
    log = (tmp_path / "two" / "log.lammps").read_text()
    assert re.search(r"2 by 1 by 1 MPI processor grid", log)
    diff = np.abs(thermo["E_vdwl"] - ref["E_vdwl"]).max() / np.abs(ref["E_vdwl"]).max()
    print(f"2 ranks, newton_bond {newton}: pair energy to {diff:.1e}, "
          f"distance to {np.abs(r - r_ref).max():.1e}")
    assert np.array_equal(thermo["Bonds"], ref["Bonds"])
    assert diff < 1e-13 and np.abs(r - r_ref).max() < 1e-13


def test_kokkos_broken_pair_meets_the_pair_style(tmp_path):
    kk = mcatest.kokkos_build()
    ref, r_ref = pulled_pair(kk, tmp_path / "cpu")
    for threads in mcatest.kokkos_thread_counts():
        thermo, r = pulled_pair(kk, tmp_path / f"kk{threads}",
                                extra_args=mcatest.kokkos_args(threads))
        log = (tmp_path / f"kk{threads}" / "log.lammps").read_text()
        assert "pair lj/cut/kk" in log    # (Kokkos neighbor lists)
        diff = np.abs(thermo["E_vdwl"] - ref["E_vdwl"]).max() / np.abs(ref["E_vdwl"]).max()
        print(f"kk {threads} thread(s): pair energy to {diff:.1e}, distance to "
              f"{np.abs(r - r_ref).max():.1e}")
        assert np.array_equal(thermo["Bonds"], ref["Bonds"])
        assert diff < 1e-13 and np.abs(r - r_ref).max() < 1e-13


# a weak cohesion between broken neighbours: the LJ minimum at the lattice
# spacing (sigma 2^(-1/6)), the largest pull 2.4 eps / sigma = 0.013, below
# the bonds' tensile strength sigma0 A = 0.02
STRIP_PAIR = """
special_bonds   lj 0 1 1 coul 1 1 1
pair_style      lj/cut 1.5
pair_coeff      * * 0.005 0.8908987181403393
"""


def test_torn_strip_with_a_pair_style_is_the_same_on_ranks_and_newton(tmp_path):
    """The torn strip of test_bond_beam (the right edge pulled): broken
    neighbours attract and repel through lj/cut (cutoff 1.5: bonded
    neighbours only, none at sqrt(3)); one LAMMPS version suffices (the
    bookkeeping is the same code in both; the two-particle tests run both)."""
    build = mcatest.build_named("current") or mcatest.builds()[0]
    ref = beam2d.strip_run(build, tmp_path / "ref", extra=STRIP_PAIR)
    first, last = ref[0]["Bonds"][0], ref[0]["Bonds"][-1]
    assert last < first - 5    # it does tear
    plain = beam2d.strip_run(build, tmp_path / "plain")
    moved = max(np.abs(ref[1][-1][c] - plain[1][-1][c]).max() for c in ("x", "y"))
    print(f"{first - last:.0f} bonds broken; the pair moved the particles by up to {moved:.1e}")
    assert moved > 1e-6    # the broken neighbours do interact
    for nprocs, newton in ((2, "on"), (2, "off"), (4, "on")):
        beam2d.compare_strips(ref, beam2d.strip_run(build, tmp_path / f"{nprocs}{newton}", nprocs,
                                                    newton, extra=STRIP_PAIR),
                              f"with lj/cut: {nprocs} ranks, newton_bond {newton}")


def test_special_weights_must_be_overlay_or_exclusion(build, tmp_path):
    sites, bonds = beam2d.hex_patch(1.1)
    data = beam2d.beam_data(tmp_path / "patch.data", sites, bonds, ((-3, 3), (-3, 3)))
    script = beam2d.header(data) + """
pair_style      zero 1.0
pair_coeff      * *
bond_style      beam
bond_coeff      1 1.0 0.1 0.001 break 1 1
run             0
"""
    result = build.run(script, tmp_path / "a", check=False)
    out = result.stdout + result.stderr
    assert result.returncode != 0
    assert re.search(r"with break and a pair style requires special_bonds lj/coul 1 1 1 .*"
                     r"found lj 0 0 0 coul 0 0 0", out), out[-800:]
    for k, weights in enumerate(("lj/coul 1.0 1.0 1.0", "lj 0 1 1 coul 0 1 1",
                                 "lj 0 1 1 coul 1 1 1")):
        build.run(script.replace("pair_style ", f"special_bonds   {weights}\npair_style "),
                  tmp_path / f"ok{k}")
    bad = build.run(script.replace("pair_style ", "special_bonds   lj 0 0.5 1\npair_style "),
                    tmp_path / "b", check=False)
    assert bad.returncode != 0 and re.search(r"found lj 0 0.5 1 coul 0 0 0",
                                             bad.stdout + bad.stderr)



def test_granular_lists_that_keep_bonded_pairs_are_reported(build, tmp_path):
    """Two bonded discs of diameter 1 at distance 0.9 (the bond stress-free
    there) with gran/hooke contacts (k_n = 30) and special_bonds lj 0 1 1:
    where the pair style's neighbor list leaves the bonded pair out (LAMMPS
    2023 and later) the force is exactly 0; LAMMPS 2021 builds the size
    lists of granular styles without the special pairs, so the discs also
    push each other apart by k_n (1 - 0.9) = 3, and the bond style says so
    in a warning.  Either way the warning appears exactly when the contact
    acts."""
    data = beam2d.beam_data(tmp_path / "pair.data", [(-0.45, 0.0), (0.45, 0.0)], [(1, 0)],
                            ((-3, 3), (-3, 3)), radius=1.0)
    script = beam2d.header(data).replace("comm_modify     cutoff 2.5",
                                         "comm_modify     cutoff 2.5 vel yes") + f"""
special_bonds   lj/coul 0 1 1
pair_style      gran/hooke 30.0 NULL 0.0 NULL 0.0 0
pair_coeff      * *
bond_style      beam
bond_coeff      1 {E_} {A_} {I_} break {SIGMA0} {TAU0}
dump            d all custom 1 pair.dump id fx fy
dump_modify     d format float %.17g sort id
run             0
"""
    build.run(script, tmp_path)
    force = read_dump(tmp_path / "pair.dump")[0]["fx"]
    warned = "keeps bonded pairs in its neighbor list" in (tmp_path / "log.lammps").read_text()
    print(f"{build.name}: force on the discs {force}, warning {warned}")
    assert force[0] == -force[1]
    if warned:
        assert force[0] == pytest.approx(-3.0, rel=1e-12)
    else:
        assert force[0] == 0.0
