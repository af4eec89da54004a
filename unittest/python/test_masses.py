"""Masses and moments of inertia under pair mca (doc/src/pair_mca.rst,
"Masses"; doc/src/mca_set.rst).

* pair mca sets mass = rho Omega of the type and the inertia of the cell,
  unless mca_set gave them: a mass, density or inertia given per automaton
  survives runs, a new pair_coeff density, restart files, MPI exchanges
  and the kk styles (exact: the values are copied, never recomputed);
* an inertia given alone keeps the mass from the density; a mass given
  alone gets the inertia of its cell from that mass;
* masses read from a data file are replaced by rho Omega with a warning
  that says how to keep them;
* the stable time step sees the given masses (a tenth of the automata
  ten times lighter: the estimate within 1 % of the measured limit,
  test_stable_timestep.py).
"""

import math

import numpy as np
import pytest

import mcatest
from mca_inputs import lattice_box

A = 0.7184
R = A / (2.0 * math.sqrt(2.0))
OMEGA = 4.0 * math.sqrt(2.0) * R**3    # fcc cell volume
RHO = 2700.0

SCENE = lattice_box("fcc", A, 3) + """
comm_modify     vel yes
pair_style      mca
pair_coeff      * * E 70e9 nu 0.3 rho 2700
group           light id <= 20
group           spun id 21:40
mca_set         light mass {mass}
mca_set         spun inertia {inertia}
velocity        all set 10.0 -4.0 3.0 units box
fix             nve all nve/mca
timestep        1.0e-5
compute         p all property/atom mass inertia
dump            d all custom 100 dump.{name}.txt id c_p[1] c_p[2]
dump_modify     d sort id format float %.17g
run             100
"""

MASS = 0.1 * RHO * OMEGA
INERTIA = 7.0


def check(snapshot, rho=RHO):
    ids, mass, inertia = snapshot["id"], snapshot["c_p[1]"], snapshot["c_p[2]"]
    light, spun = ids <= 20, (ids >= 21) & (ids <= 40)
    other = ~light & ~spun
    material = rho * OMEGA
    assert np.all(mass[light] == MASS), "a given mass was replaced"
    assert np.all(inertia[spun] == INERTIA), "a given inertia was replaced"
    assert np.allclose(mass[spun | other], material, rtol=1e-14, atol=0)
    # the cell inertia (rhombic dodecahedron: m R^2 / 2) of the mass it has
    assert np.allclose(inertia[light], 0.5 * MASS * R**2, rtol=1e-14, atol=0)
    assert np.allclose(inertia[other], 0.5 * material * R**2, rtol=1e-14, atol=0)


def test_given_masses_survive_runs_and_a_new_density(build, tmp_path):
    script = SCENE.format(mass=MASS, inertia=INERTIA, name="a") + """
run             100
pair_coeff      * * E 70e9 nu 0.3 rho 5400
dump            e all custom 100 dump.b.txt id c_p[1] c_p[2]
dump_modify     e sort id format float %.17g
run             100
"""
    build.run(script, tmp_path)
    # (the masses of the third run are set at its start, step 200)
    for snap in mcatest.read_dump(tmp_path / "dump.a.txt"):
        if snap["timestep"] != 200:
            check(snap, rho=RHO if snap["timestep"] < 200 else 2 * RHO)
    check(mcatest.read_dump(tmp_path / "dump.b.txt")[-1], rho=2 * RHO)


def test_given_masses_survive_a_restart_file(build, tmp_path):
    build.run(SCENE.format(mass=MASS, inertia=INERTIA, name="a") + "write_restart r.restart\n",
              tmp_path)
    build.run("""
read_restart    r.restart
fix             nve all nve/mca
compute         p all property/atom mass inertia
dump            d all custom 100 dump.c.txt id c_p[1] c_p[2]
dump_modify     d sort id format float %.17g
timestep        1.0e-5
run             100
""", tmp_path)
    for snap in mcatest.read_dump(tmp_path / "dump.c.txt"):
        check(snap)


@pytest.mark.mpi
def test_given_masses_move_between_ranks(build, tmp_path):
    """The block flies through the periodic box across 4 ranks: automata
    change owners and keep what was given to them."""
    build.run(SCENE.format(mass=MASS, inertia=INERTIA, name="a").replace("run             100",
                                                                         "run             2000"),
              tmp_path, nprocs=4)
    snaps = mcatest.read_dump(tmp_path / "dump.a.txt")
    assert len(snaps) == 21
    for snap in snaps:
        check(snap)


def test_given_masses_with_kk(tmp_path):
    build = mcatest.kokkos_build()
    build.run(SCENE.format(mass=MASS, inertia=INERTIA, name="a"), tmp_path,
              extra_args=mcatest.kokkos_args())
    for snap in mcatest.read_dump(tmp_path / "dump.a.txt"):
        check(snap)


def test_data_file_masses_are_replaced_with_a_warning(build, tmp_path):
    """create_atoms gives unit density: a data file written before pair mca
    holds masses Omega, which pair mca replaces by rho Omega and says so;
    a file written after a run holds rho Omega and reads without a word."""
    build.run(lattice_box("fcc", A, 3) + "write_data before.data\n", tmp_path)
    read = """
units           si
atom_style      mca
atom_modify     map array
read_data       {file}
comm_modify     vel yes
pair_style      mca
pair_coeff      * * E 70e9 nu 0.3 rho 2700
fix             nve all nve/mca
run             0
write_data      after.data
"""
    first = build.run(read.format(file="../before.data"), tmp_path / "first")
    (tmp_path / "second").mkdir()
    (tmp_path / "second" / "after.data").write_text((tmp_path / "first" / "after.data").read_text())
    second = build.run(read.format(file="after.data").replace("write_data      after.data", ""),
                       tmp_path / "second")
    message = ("Pair mca: the masses of 108 automata read from a data file differ from rho "
               "Omega of their type and are set to it; to keep an automaton's own mass, give "
               "it with mca_set mass (or density) after read_data")
    assert message in first.stdout, first.stdout[-2000:]
    assert "read from a data file differ" not in second.stdout
