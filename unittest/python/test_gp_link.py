"""Imaginary particles of the GP method: fix gp/link (doc/src/fix_gp_link.rst;
the GP digest, sec. 1.4 and 4.2), on the two-level model of
examples/gp_interface/in.model (a periodic stack of atoms and level-2
particles, Fe EAM or Cu Morse, k = 2, imaginary particles of each level in
the other's region next to the two interfaces).

* patch test (coupling force, the default): linked in the perfect lattice
  and strained uniformly, every real particle feels the force of the
  strained perfect crystal, zero: the largest force is below 1e-8 of the
  rms force of the same model after random displacements of 0.02 A (the
  bound the issue sets; measured 4e-12 and 5e-12);
* EAM needs the imaginary shell to reach twice the density's cutoff: at
  half the depth of the rule (rc_n) the interface particles feel 1e-2
  eV/A in the perfect, unstrained lattice (more than 1e-2 of the scale);
* coupling energy: the forces on the imaginary particles go to their
  members (x_I = sum_j w_j x_j), the dynamics is Hamiltonian: over 4000
  steps of 1 fs at 100 K, pe + the kinetic energy of the real particles
  stays within 1e-3 of the initial kinetic energy (integrator error,
  measured 2e-4); its price, the ghost forces of the patch test, is in
  the doc and the example;
* fit quadratic: the patch test as above (the weights stay exact for
  affine motions); under a quadratic motion of the real particles
  (u_y = 0.5 A ((x - L/2) / (L/4))^2 about an interface) the imaginary
  atoms (linked to level-2 particles) are where the motion puts them
  (median error below 1e-5 of the linear fit's; the regularisation of
  the weights leaves 1e-6) except where their 12 members lie on two
  planes normal to x (the largest error still 5x smaller, measured 11x),
  the linear fit's error being more than 2e-3 A; the imaginary level-2
  particles (linked to atoms) keep the linear weights;
* the links: every imaginary particle linked, 12 members each; a Kokkos
  run (gp/eam/fs/kk) follows the CPU trajectory to round-off; the same
  trajectories on 1, 2 and 4 ranks (round-off, 1e-9 A over 100 steps) and
  across a restart file (the run split in memory, 1e-12 A: the file's
  atom order changes the order of the sums; measured 1.4e-14), with fit
  linear and fit quadratic;
* surface images (level same): a strained free level-2 slab has the
  energy per particle of the strained periodic crystal to round-off (Fe
  EAM, Cu Morse); at 300 K (a strong thermostat) the Cu Morse slab (the
  thesis's case) within 1 % of it;
* bad input: clear errors naming the argument and the allowed values.
"""

import re

import numpy as np
import pytest

import mcatest

MODEL = mcatest.ROOT / "examples" / "gp_interface" / "in.model"
PATCH = (mcatest.ROOT / "examples" / "gp_interface" / "in.patch").read_text() \
    .replace("include         in.model", f"include {MODEL}")


def printed(output, key):
    return float(re.search(rf"^{key} .* ([-+0-9.eE]+) eV/A$", output, re.M).group(1))


def patch(build, directory, **variables):
    result = build.run(PATCH, directory, variables=variables)
    return printed(result.stdout, "PATCH"), printed(result.stdout, "BULK"), result.stdout


@pytest.mark.parametrize("potential, fit", [("eam", "linear"), ("morse", "linear"),
                                            ("eam", "quadratic")])
def test_patch_test(build, tmp_path, potential, fit):
    largest, bulk, output = patch(build, tmp_path, potential=potential, fit=fit)
    print(f"\n{potential}, fit {fit}: largest force on a real particle {largest:.3e} eV/A, "
          f"{largest / bulk:.1e} of the rms force {bulk:.3f} eV/A of a displaced crystal")
    assert largest <= 1e-8 * bulk
    # every imaginary particle linked, to 12 members
    counts = re.search(r"fix gp/link: (\d+) imaginary particles linked to ([0-9.]+) real", output)
    nimaginary = re.search(r"(\d+) atoms in group imaginary", output)
    assert counts and nimaginary and counts.group(1) == nimaginary.group(1)
    assert float(counts.group(2)) == 12.0


CURVED = f"""
include {MODEL}
variable        A equal 0.5
variable        xc equal v_L/2
variable        w equal v_L/4
fix             ref all store/state 0 xu yu zu
run             0
# u_y = A ((x - L/2) / (L/4))^2 on the real particles: a quadratic motion
# about the interface at L/2 (the one at x = 0 lies beyond the window)
variable        uy atom v_A*((x-v_xc)/v_w)^2
displace_atoms  real move 0 v_uy 0 units box
compute         now all property/atom xu yu zu
variable        near atom abs(f_ref[1]-v_xc)<v_w
group           near variable near
group           nearimag intersect near imaginary
# (a per-atom compute is current between runs where the run invoked it)
compute         nowsum all reduce sum c_now[1] c_now[2] c_now[3]
thermo_style    custom step pe c_nowsum[1] c_nowsum[2] c_nowsum[3]
run             0
variable        err atom sqrt((c_now[1]-f_ref[1])^2+(c_now[2]-f_ref[2]-v_A*((f_ref[1]-v_xc)/v_w)^2)^2+(c_now[3]-f_ref[3])^2)
write_dump      nearimag custom errors.dump id type v_err modify sort id format float %.10g
"""


def curved_errors(build, directory, fit):
    build.run(CURVED, directory, variables={"fit": fit})
    lines = (directory / "errors.dump").read_text().splitlines()
    rows = np.array([line.split() for line in lines[9:]], dtype=float)
    return {t: rows[rows[:, 1] == t, 2] for t in (3, 4)}


def test_quadratic_fit_follows_a_curved_field(build, tmp_path):
    """fit quadratic under u_y = 0.5 A ((x - L/2) / (L/4))^2 (curvature
    1.9e-3 / A) about an interface: where the 12 members determine the
    quadratic the imaginary atoms (members: level-2 particles) are where
    the motion puts them to the regularisation's 1e-6 of the linear
    error (the median: below 1e-5 of the linear median); where they lie
    on two planes normal to x (their x^2 moment undetermined) the linear
    weight stays in that direction, and the largest error falls by 5x or
    more (measured 11x); the imaginary level-2 particles (members: atoms)
    keep the linear weights."""
    lin, quad = (curved_errors(build, tmp_path / fit, fit) for fit in ("linear", "quadratic"))
    print(f"\nimaginary atoms, largest / median error: fit linear {lin[3].max():.3e} / "
          f"{np.median(lin[3]):.3e} A, fit quadratic {quad[3].max():.3e} / {np.median(quad[3]):.3e} A "
          f"({np.mean(quad[3] < 1e-4):.0%} within 1e-4 A); imaginary level-2 particles "
          f"{lin[4].max():.3e} A, {quad[4].max():.3e} A")
    assert lin[3].max() > 2e-3
    assert np.median(quad[3]) < 1e-5 * np.median(lin[3])
    assert quad[3].max() < 0.2 * lin[3].max()
    assert np.array_equal(quad[4], lin[4])


def test_eam_needs_twice_the_density_cutoff(build, tmp_path):
    largest, bulk, _ = patch(build, tmp_path, potential="eam", depth_factor=0.5)
    print(f"\nimaginary depth rc_n: largest force {largest:.3e} eV/A ({largest / bulk:.1e} of the "
          "scale)")
    assert largest > 1e-2 * bulk


NVE = """
include {model}
velocity        real create 100 4928459 dist gaussian loop geom
compute         ke real ke/atom
compute         kereal real reduce sum c_ke
variable        etot equal pe+c_kereal
fix             nve real nve
timestep        0.001
thermo_style    custom step temp pe c_kereal v_etot
thermo_modify   temp treal format float %.15g
thermo          {every}
run             {steps}
"""


def test_energy_coupling_conserves_energy(build, tmp_path):
    build.run(NVE.format(model=MODEL, every=200, steps=4000), tmp_path,
              variables={"coupling": "energy", "nx": 12})
    rows = mcatest.read_thermo(tmp_path / "log.lammps")
    etot, ke0 = np.asarray(rows["v_etot"]), rows["c_kereal"][0]
    drift = np.abs(etot - etot[0]).max() / ke0
    print(f"\ncoupling energy: |E - E0| <= {drift:.2e} of the initial kinetic energy "
          f"{ke0:.3f} eV over 4000 steps")
    assert drift <= 1e-3


TRAJECTORY = """
include {model}
write_dump      all custom initial.dump id x y z modify sort id format float %.17g
velocity        real create 300 4928459 dist gaussian loop geom
fix             nve real nve
timestep        0.001
run             {first}
{middle}
run             {second}
write_dump      all custom final.dump id x y z modify sort id format float %.17g
"""

RESTART_MIDDLE = """
write_restart   split.restart
clear
read_restart    split.restart
pair_style      gp/eam/fs ratio 2
pair_coeff      * * Fe_mm.eam.fs Fe Fe Fe Fe level 1 2 1 2
neighbor        1.0 multi
group           real type 1 2
group           imaginary type 3 4
fix             link imaginary gp/link real fit {fit}
fix             nve real nve
timestep        0.001
"""


def final_positions(build, directory, middle="", nprocs=1, extra=(), fit="linear"):
    """Positions after 100 steps, in the order of the initial positions
    (create_atoms numbers the atoms in the order of the ranks)."""
    script = TRAJECTORY.format(model=MODEL, first=50, middle=middle.format(fit=fit), second=50)
    build.run(script, directory, nprocs=nprocs, variables={"nx": 12, "fit": fit},
              extra_args=extra)
    start, end = (mcatest.read_dump(directory / name)[0] for name in ("initial.dump", "final.dump"))
    order = np.lexsort(np.round([start["z"], start["y"], start["x"]], 6))
    return np.column_stack([end["x"], end["y"], end["z"]])[order]


@pytest.mark.parametrize("fit", ["linear", "quadratic"])
def test_ranks_and_restart(build, tmp_path, fit):
    """The links are the same on any number of ranks (nearest members, ties
    by tag) and move with their particles; a restart file holds them and
    their weights (to round-off: the file's atom order changes the order of
    the sums).  With fit quadratic the weights come from a linear system
    solved once per particle: the same on every rank."""
    one = final_positions(build, tmp_path / "one", fit=fit)
    for nprocs in (2, 4):
        other = final_positions(build, tmp_path / f"ranks{nprocs}", nprocs=nprocs, fit=fit)
        print(f"\nfit {fit}, {nprocs} ranks: largest position difference "
              f"{np.abs(other - one).max():.2e} A")
        assert np.abs(other - one).max() <= 1e-9
    split = final_positions(build, tmp_path / "split", middle="run 0", fit=fit)
    restarted = final_positions(build, tmp_path / "restart", middle=RESTART_MIDDLE, fit=fit)
    print(f"fit {fit}, restart: largest position difference "
          f"{np.abs(restarted - split).max():.2e} A")
    assert np.abs(restarted - split).max() <= 1e-12


def test_kk_run(tmp_path):
    """fix gp/link (a CPU fix) in a Kokkos run of gp/eam/fs/kk on 2 threads:
    the trajectory of the CPU styles to round-off (1e-9 A over 100 steps)."""
    build = mcatest.kokkos_build()
    cpu = final_positions(build, tmp_path / "cpu")
    kk = final_positions(build, tmp_path / "kk", extra=mcatest.kokkos_args())
    print(f"\nkk - CPU: largest position difference {np.abs(kk - cpu).max():.2e} A")
    assert np.abs(kk - cpu).max() <= 1e-9


IMAGES = (mcatest.ROOT / "examples" / "gp_interface" / "in.images").read_text()


def image_energy(build, directory, with_temperature=False, **variables):
    out = build.run(IMAGES, directory, variables=variables).stdout
    found = re.search(r"^IMAGES .*: mean potential energy per real particle (\S+) eV, mean "
                      r"temperature (\S+) K", out, re.M)
    energy, temperature = float(found.group(1)), float(found.group(2))
    return (energy, temperature) if with_temperature else energy


@pytest.mark.parametrize("potential", ["eam", "morse"])
def test_surface_images_static(build, tmp_path, potential):
    """A free level-2 slab with surface images (fix gp/link level same),
    linked in the perfect lattice and strained (1 % along y, -0.5 % along
    z): the energy per real particle of the strained periodic crystal to
    round-off (1e-12), where the free slab's surfaces cost several %."""
    values = {case: image_energy(build, tmp_path / case, case=case, potential=potential, T=0,
                                 steps=20, strain=0.01) for case in ("bulk", "free", "images")}
    print(f"\n{potential}: " + ", ".join(f"{k} {v:.10f}" for k, v in values.items()))
    assert values["images"] == pytest.approx(values["bulk"], rel=1e-12)
    assert abs(values["free"] - values["bulk"]) > 0.01 * abs(values["bulk"])


def test_surface_images_thermal(build, tmp_path):
    """The thesis's case (GP digest sec. 4.3, Cu Morse at level 2): at
    300 K (Langevin of 0.1 ps, as strong as the thesis's velocity
    rescaling) the mean configuration energy of the slab with images is
    within 1 % of the periodic crystal's (measured 0.05 %, the free slab
    7 %), and the thermostat holds the slab (mean temperature within 10 %
    of 300 K: the force coupling feeds the vibrations next to images)."""
    values = {case: image_energy(build, tmp_path / case, True, case=case, potential="morse",
                                 T=300, steps=2000) for case in ("bulk", "free", "images")}
    print("\n" + ", ".join(f"{k} {e:.6f} eV {t:.1f} K" for k, (e, t) in values.items()))
    assert values["images"][0] == pytest.approx(values["bulk"][0], rel=0.01)
    assert values["images"][1] == pytest.approx(300.0, rel=0.1)


BASE = f"""
include {MODEL}
unfix           link
"""


@pytest.mark.parametrize("command,message", [
    ("fix bad imaginary gp/link", r"Illegal fix gp/link command: missing argument|"
                                  r"missing argument"),
    ("fix bad imaginary gp/link nowhere", r"Fix gp/link: no group named nowhere"),
    ("fix bad imaginary gp/link imaginary", r"the real group imaginary is the fix's group"),
    ("fix bad imaginary gp/link real members 3", r"members must be from 4 to 12, got 3"),
    ("fix bad imaginary gp/link real members 13", r"members must be from 4 to 12, got 13"),
    ("fix bad imaginary gp/link real cutoff -1", r"cutoff must be > 0 \(distance units\), got -1"),
    ("fix bad imaginary gp/link real level next", r"level must be adjacent or same, got next"),
    ("fix bad imaginary gp/link real coupling both", r"coupling must be force or energy, got both"),
    ("fix bad imaginary gp/link real fit cubic", r"fit must be linear or quadratic, got cubic"),
    ("fix bad imaginary gp/link real size 3", r"unknown keyword size \(allowed: members, cutoff, "
                                              r"level, coupling, fit\)"),
    ("fix bad imaginary gp/link real cutoff 2.0\nrun 0",
     r"imaginary particle \d+ \(type \d, level \d\) has \d+ real particles of the adjacent level "
     r"within 2 \(needs at least 4\)"),
    ("fix bad imaginary gp/link real cutoff 15.0\nrun 0",
     r"the search distance 15 is at least half the periodic box length [0-9.]+ along y"),
    ("fix bad imaginary gp/link all\nrun 0", r"particle \d+ is in both the imaginary and the "
                                             r"real group"),
    ("pair_style zero 5.0\npair_coeff * *\nfix bad imaginary gp/link real\nrun 0",
     r"Fix gp/link needs a GP pair style"),
])
def test_bad_input(build, tmp_path, command, message):
    result = build.run(BASE + command + "\n", tmp_path, check=False, variables={"nx": 12})
    output = result.stdout + result.stderr
    assert 0 < result.returncode < 128, output[-2000:]
    assert re.search(message, output), output[-2000:]
