"""pair_style mca batch yes|no: the elastic link pass over batches of links
(src/MCA/mca_link_batch.h, pair_mca_batch.cpp: the law on several links at
once in a vectorized loop) computes what the pass link by link computes.

* bit for bit: the positions, velocities, forces, spins, torques, mean
  stresses, link counts and the energy, pressure and fracture counts of
  the thermo output of a periodic box of two materials with fracture and
  contacts (rows with blocks after the elastic one, which the batch does
  not carry), sheared until links break, are the
  same to the last digit written (%.17g) with batch yes and no, on 1 and
  on 2 MPI ranks;
* the same for a spinning cluster whose twist per step is beyond the range
  where the batch's series of cos and sin equals the functions to
  round-off: those links are evaluated again with cos() and sin(), and a
  batch that kept the series would differ in the last digits (the series
  leaves out phi^6/720, above 1e-15 of the cosine for phi > 0.03; the
  test checks the twist of the first step from the data);
* the batch applies only where it computes the same law: with damping,
  plasticity or precision mixed the pass goes link by link (the runs with
  batch yes and no are then the same program; checked for damping).
"""

import numpy as np
import pytest

from mcatest import read_dump, read_thermo

NSTEPS = 150

BOX = """
units           si
atom_style      mca
atom_modify     map array
boundary        p p p
lattice         fcc 0.7184 origin 0.25 0.25 0.25
region          box prism 0 3 0 3 0 3 0 0 0
create_box      2 box
create_atoms    1 box
set             group all type/fraction 2 0.3 4321
comm_modify     vel yes
neighbor        0.05 bin
neigh_modify    delay 0 every 1 check yes
pair_style      mca fracture links contacts coulomb {extra} batch {batch}
pair_coeff      1 1 E 70e9 nu 0.3 rho 2700 eta 2e4 break strain 0.012
pair_coeff      2 2 E 200e9 nu 0.25 rho 7800 eta 2e4 break strain 0.012
pair_coeff      * * friction 0.3
velocity        all create 1.0e-2 8765 loop geom
fix             integrate all nve/mca
fix             strain all deform 1 xy erate 10.0 remap v
timestep        2.0e-5
"""

# a free fcc cluster spinning about x at 0.06 rad per step
SPIN_DT = 2.0e-5
SPIN_OMEGA = 3000.0
SPIN = f"""
units           si
atom_style      mca
atom_modify     map array
boundary        s s s
lattice         fcc 0.7184 origin 0.25 0.25 0.25
region          box block 0 3 0 3 0 3
create_box      1 box
create_atoms    1 box
comm_modify     vel yes
neighbor        0.05 bin
neigh_modify    delay 0 every 1 check yes
pair_style      mca batch {{batch}}
pair_coeff      1 1 E 70e9 nu 0.3 rho 2700
set             group all omega {SPIN_OMEGA} 0 0
fix             integrate all nve/mca
timestep        {SPIN_DT}
"""

OUTPUT = """compute         s all mca/atom smean seq links contacts
dump            d all custom {every} dump.txt id x y z vx vy vz fx fy fz omegax omegay omegaz &
                tqx tqy tqz c_s[*]
dump_modify     d sort id format float %.17g
thermo_style    custom step pe press pxy
thermo_modify   format float %.17g
thermo          {every}
run             {steps}
"""


def run(build, directory, script, batch, steps, nprocs=1, every=20, **fields):
    text = script.format(batch=batch, **fields) + OUTPUT.format(every=every, steps=steps)
    build.run(text, directory, nprocs=nprocs)
    return (directory / "dump.txt").read_text(), read_thermo(directory / "log.lammps")


def assert_same(yes, no, what):
    dump_yes, thermo_yes = yes
    dump_no, thermo_no = no
    # (%.17g: a double read back from its text is that double)
    assert thermo_yes.keys() == thermo_no.keys()
    for name in thermo_yes:
        assert np.array_equal(thermo_yes[name], thermo_no[name]), f"{what}: thermo {name} differs"
    assert dump_yes == dump_no, f"{what}: dumps differ"


@pytest.mark.parametrize("nprocs", [1, 2])
def test_batch_is_the_pass_link_by_link(build, tmp_path, nprocs):
    yes = run(build, tmp_path / "yes", BOX, "yes", NSTEPS, nprocs, extra="")
    no = run(build, tmp_path / "no", BOX, "no", NSTEPS, nprocs, extra="")
    assert_same(yes, no, f"sheared box, {nprocs} ranks")
    # the scene does what it is meant to: links break (their rows leave
    # the batches for the pass of broken pairs)
    last = read_dump(tmp_path / "yes" / "dump.txt")[-1]
    first = read_dump(tmp_path / "yes" / "dump.txt")[0]
    assert last["c_s[3]"].sum() < first["c_s[3]"].sum() - 20, "fewer than 20 links broke"


def test_batch_evaluates_large_twists_with_cos_and_sin(build, tmp_path):
    yes = run(build, tmp_path / "yes", SPIN, "yes", 40, every=5)
    no = run(build, tmp_path / "no", SPIN, "no", 40, every=5)
    assert_same(yes, no, "spinning cluster")
    # the twist of the first step, 0.5 dt (w_lo + w_hi) . n, of the links
    # along a lattice direction with an x component: beyond the series'
    # round-off range (phi > 0.03)
    snap = read_dump(tmp_path / "yes" / "dump.txt")[0]
    x = np.stack([snap["x"], snap["y"], snap["z"]], axis=1)
    w = np.stack([snap["omegax"], snap["omegay"], snap["omegaz"]], axis=1)
    d = np.linalg.norm(x[:, None, :] - x[None, :, :], axis=2)
    nearest = d[d > 0].min()
    i, j = np.nonzero(np.triu((d > 0) & (d < 1.1 * nearest)))
    n = (x[j] - x[i]) / d[i, j][:, None]
    phi = 0.5 * SPIN_DT * np.einsum("ij,ij->i", w[i] + w[j], n)
    assert np.count_nonzero(np.abs(phi) > 0.03) >= len(phi) // 3, \
        f"twists of the first step: largest {np.abs(phi).max():.3g}"
    values = np.stack([snap[k] for k in ("fx", "fy", "fz", "tqx", "tqy", "tqz")])
    assert np.all(np.isfinite(values))


def test_batch_keyword_with_damping_is_a_no_op(build, tmp_path):
    extra = "damping viscous"
    yes = run(build, tmp_path / "yes", BOX, "yes", 40, extra=extra)
    no = run(build, tmp_path / "no", BOX, "no", 40, extra=extra)
    assert_same(yes, no, "damped box")


def test_batch_keyword_takes_yes_or_no(build, tmp_path):
    result = build.run(BOX.format(batch="maybe", extra=""), tmp_path, check=False)
    text = result.stdout + result.stderr
    assert result.returncode != 0
    assert "Expected boolean parameter instead of 'maybe'" in text, text[-2000:]
