"""atom_style mca and the mca_set command.

Checks the geometry that create_atoms derives from a lattice against the
closed-form Voronoi cells, the mca_set rules, exact data-file and restart
round trips of every field, migration between MPI ranks, and that every
field can be dumped.
"""

import math

import numpy as np
import pytest

from mcatest import read_dump, relative_difference
from mca_inputs import (ALL_COLUMNS, MCA_PROPERTIES, VARIED_STATE, dump_all, lattice_box,
                        lattice_data_file, read_lattice)

# a lattice of edge a: packing, nearest-neighbour radius, cell volume, J/(m R^2)
LATTICES = {
    "sc": (6, lambda a: a / 2.0, lambda r: 8.0 * r**3, 2.0 / 3.0),
    "fcc": (12, lambda a: a / (2.0 * math.sqrt(2.0)), lambda r: 4.0 * math.sqrt(2.0) * r**3, 0.5),
    "hcp": (12, lambda a: a / 2.0, lambda r: 4.0 * math.sqrt(2.0) * r**3, 0.5),
}


@pytest.mark.parametrize("lattice", sorted(LATTICES))
def test_create_atoms_geometry_from_lattice(build, tmp_path, lattice):
    """Automata made on a lattice touch their neighbours and fill space.

    The radius is half the nearest-neighbour distance, the cell volume is that
    of the Voronoi cell, and the cells of a periodic box add up to the box
    volume.  Tolerance 1e-13: the values are a few floating-point operations
    from the lattice constant.
    """
    a = 0.7184
    n = 3
    script = lattice_box(lattice, a, n) + f"""
compute         p all property/atom packing volume inertia
dump            d all custom 1 geometry.dump id radius mass c_p[1] c_p[2] c_p[3]
dump_modify     d sort id format float %.17g
variable        vbox equal vol
print           "BOX_VOLUME ${{vbox}}"
run             0
"""
    result = build.run(script, tmp_path)
    snap = read_dump(tmp_path / "geometry.dump")[0]
    packing, radius_of, volume_of, inertia_factor = LATTICES[lattice]
    radius = radius_of(a)
    volume = volume_of(radius)
    assert np.all(snap["c_p[1]"] == packing)
    assert relative_difference(snap["radius"], radius) < 1e-13
    assert relative_difference(snap["c_p[2]"], volume) < 1e-13
    assert relative_difference(snap["mass"], snap["c_p[2]"]) == 0.0    # unit density
    assert relative_difference(snap["c_p[3]"], inertia_factor * snap["mass"] * radius**2) < 1e-13
    box_volume = float(result.stdout.split("BOX_VOLUME")[1].split()[0])
    assert abs(snap["c_p[2]"].sum() / box_volume - 1.0) < 1e-12


def test_unpacked_automata_are_spheres(build, tmp_path):
    """Without a lattice an automaton is a sphere of radius 0.5 (as atom_style sphere)."""
    script = """
units           lj
atom_style      mca
region          box block 0 4 0 4 0 4 units box
create_box      1 box
create_atoms    1 single 1 1 1 units box
create_atoms    1 single 2 2 2 units box
compute         p all property/atom packing volume inertia
dump            d all custom 1 sphere.dump id radius mass c_p[1] c_p[2] c_p[3]
dump_modify     d sort id format float %.17g
run             0
"""
    build.run(script, tmp_path)
    snap = read_dump(tmp_path / "sphere.dump")[0]
    assert np.all(snap["c_p[1]"] == 0)
    assert np.all(snap["radius"] == 0.5)
    assert relative_difference(snap["c_p[2]"], 4.0 / 3.0 * math.pi * 0.125) < 1e-15
    assert relative_difference(snap["c_p[3]"], 0.4 * snap["mass"] * 0.25) < 1e-15


def test_mca_set_rules(build, tmp_path):
    """mca_set keeps volume, mass and inertia consistent.

    density sets m = rho*Omega; a new packing or radius keeps the density;
    an explicit inertia is kept; atom-style variables give per-atom values.
    Tolerance 1e-14: a few roundings of the closed forms.
    """
    a = 0.7184
    r = a / (2.0 * math.sqrt(2.0))
    script = lattice_box("fcc", a, 2) + """
group           first id 1:8
group           second id 9:16
mca_set         all density 2700
mca_set         first packing sc
mca_set         second radius 0.3
mca_set         second inertia 12.5
variable        dmg atom 0.01*id
mca_set         all damage v_dmg
compute         p all property/atom packing volume inertia damage
dump            d all custom 1 set.dump id radius mass c_p[1] c_p[2] c_p[3] c_p[4]
dump_modify     d sort id format float %.17g
run             0
"""
    build.run(script, tmp_path)
    s = read_dump(tmp_path / "set.dump")[0]
    ids = s["id"].astype(int)
    first = ids <= 8
    second = (ids >= 9) & (ids <= 16)
    rest = ids > 16
    # untouched fcc automata: m = rho * 4 sqrt(2) R^3, J = m R^2 / 2
    assert relative_difference(s["mass"][rest], 2700 * 4 * math.sqrt(2) * r**3) < 1e-14
    assert relative_difference(s["c_p[3]"][rest], 0.5 * s["mass"][rest] * r**2) < 1e-14
    # sc packing: cube of edge 2R, same density
    assert np.all(s["c_p[1]"][first] == 6)
    assert relative_difference(s["c_p[2]"][first], 8 * r**3) < 1e-14
    assert relative_difference(s["mass"][first], 2700 * 8 * r**3) < 1e-14
    assert relative_difference(s["c_p[3]"][first], 2.0 / 3.0 * s["mass"][first] * r**2) < 1e-14
    # new radius, same density; inertia as given
    assert np.all(s["radius"][second] == 0.3)
    assert relative_difference(s["mass"][second], 2700 * 4 * math.sqrt(2) * 0.3**3) < 1e-14
    assert np.all(s["c_p[3]"][second] == 12.5)
    assert relative_difference(s["c_p[4]"], 0.01 * ids) < 1e-15


def _varied_system(data_file):
    # reneighboring every step wraps the periodic images at the same steps in
    # every run, so positions can be compared bit for bit
    return read_lattice(data_file) + VARIED_STATE + """
pair_style      zero 1.0
pair_coeff      * *
neighbor        0.1 bin
neigh_modify    every 1 delay 0 check no
fix             integrate all nve/mca
timestep        1.0e-3
"""


def _compare_dumps(path_a, path_b, columns=ALL_COLUMNS, exact=True):
    a = read_dump(path_a)[-1]
    b = read_dump(path_b)[-1]
    for name in columns:
        if name not in a:
            continue
        if exact:
            assert np.array_equal(a[name], b[name]), f"column {name} differs"
        else:
            assert relative_difference(a[name], b[name]) < 1e-13, f"column {name} differs"


def test_data_file_round_trip_is_exact(build, tmp_path):
    """write_data -> read_data -> write_data reproduces every value bit for bit."""
    first = _varied_system(lattice_data_file(build, tmp_path)) + """
run             20
write_data      first.data nocoeff
""" + dump_all("first.dump") + """
run             0
"""
    build.run(first, tmp_path / "first")
    second = """
units           si
atom_style      mca
atom_modify     map array
read_data       ../first/first.data
write_data      second.data nocoeff
""" + dump_all("second.dump") + """
run             0
"""
    build.run(second, tmp_path / "second")
    body = [p.read_text().split("\n", 1)[1]
            for p in (tmp_path / "first" / "first.data", tmp_path / "second" / "second.data")]
    assert body[0] == body[1]
    # what a data file holds: geometry, mass, positions, velocities
    columns = ["id", "type", "mol", "x", "y", "z", "vx", "vy", "vz", "radius", "mass", "omegax",
               "omegay", "omegaz", "c_mca[1]", "c_mca[2]", "c_mca[3]"]
    _compare_dumps(tmp_path / "first" / "first.dump", tmp_path / "second" / "second.dump",
                   columns)


@pytest.mark.parametrize("nprocs", [1, 2])
def test_restart_round_trip_is_exact(build, tmp_path, nprocs):
    """A run split by write_restart/read_restart equals the uninterrupted run.

    Every field, the MCA state and the orientation included, must match bit
    for bit: the integration of free automata is the same arithmetic in both.
    """
    data = lattice_data_file(build, tmp_path)
    whole = _varied_system(data) + dump_all("whole.dump", every=40) + """
run             40
"""
    build.run(whole, tmp_path / "whole", nprocs=nprocs)
    split_a = _varied_system(data) + """
run             20
write_restart   half.restart
"""
    build.run(split_a, tmp_path / "split", nprocs=nprocs)
    split_b = """
read_restart    half.restart
pair_style      zero 1.0
pair_coeff      * *
neighbor        0.1 bin
neigh_modify    every 1 delay 0 check no
fix             integrate all nve/mca
""" + dump_all("split.dump", every=20) + """
run             20
"""
    build.run(split_b, tmp_path / "split", nprocs=nprocs, name="in.continue")
    _compare_dumps(tmp_path / "whole" / "whole.dump", tmp_path / "split" / "split.dump")


@pytest.mark.mpi
def test_migration_between_ranks_is_exact(build, tmp_path):
    """Automata crossing sub-domain and periodic boundaries keep all their data.

    Free automata (pair zero) with velocities that carry them through several
    sub-domains: 1, 2 and 4 MPI ranks must give identical values of every
    field, bit for bit, because each automaton's arithmetic is unchanged by
    the decomposition.
    """
    script = _varied_system(lattice_data_file(build, tmp_path)) + dump_all("final.dump", every=300) + """
run             300
"""
    for nprocs in (1, 2, 4):
        build.run(script, tmp_path / f"np{nprocs}", nprocs=nprocs)
    reference = read_dump(tmp_path / "np1" / "final.dump")[-1]
    # the fastest automata must have crossed the periodic box (edge 3a)
    assert np.max(np.abs(reference["vx"])) * 300 * 1.0e-3 > 3 * 0.7184
    for nprocs in (2, 4):
        _compare_dumps(tmp_path / "np1" / "final.dump", tmp_path / f"np{nprocs}" / "final.dump")


def test_every_field_can_be_dumped(build, tmp_path):
    """compute property/atom reports every MCA field with the value that was set."""
    script = _varied_system(lattice_data_file(build, tmp_path, n=2)) + dump_all("fields.dump") + """
run             0
"""
    build.run(script, tmp_path)
    s = read_dump(tmp_path / "fields.dump")[0]
    ids = s["id"]
    col = {name: s[f"c_mca[{k + 1}]"] for k, name in enumerate(MCA_PROPERTIES)}
    assert relative_difference(s["radius"], 0.25 + 0.002 * (ids % 7)) < 1e-15
    assert relative_difference(col["smean"], -1.0e6 * np.sin(ids)) < 1e-14
    assert relative_difference(col["seq"], 2.0e6 * (1 + np.cos(ids))) < 1e-14
    assert relative_difference(col["eeq"], 1.0e-4 * ids) < 1e-15
    assert relative_difference(col["epsp"], 1.0e-5 * (ids % 3)) < 1e-15
    assert relative_difference(col["damage"], 0.01 * (ids % 11)) < 1e-15
    sc = ids <= 10
    stress = np.array([col[k] for k in ("sxx", "syy", "szz", "sxy", "sxz", "syz")]).T
    assert np.all(stress[sc] == [1.0e5, -2.0e5, 3.0e5, 4.0e4, -5.0e4, 6.0e4])
    assert np.all(stress[~sc] == 0.0)
    assert np.all(col["packing"][sc] == 6) and np.all(col["packing"][~sc] == 12)
    density = s["mass"] / col["volume"]
    assert relative_difference(density, 2000 + 10 * (ids % 5)) < 1e-14
    quat = np.array([col[k] for k in ("orientw", "orienti", "orientj", "orientk")]).T
    assert np.all(quat == [1.0, 0.0, 0.0, 0.0])
    assert relative_difference(s["omegax"], 3.0 * np.sin(ids)) < 1e-15
    assert np.all(s["mol"][s["type"] == 1] == 3)
