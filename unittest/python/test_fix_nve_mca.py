"""fix nve/mca: velocity-Verlet integration of translation, spin and orientation."""

import math

import numpy as np
import pytest

from mcatest import read_dump, read_thermo, relative_difference

FREE_AUTOMATA = """
units           si
atom_style      mca
atom_modify     map array
boundary        p p p
region          box block -5 5 -5 5 -5 5 units box
create_box      1 box
create_atoms    1 single 0 0 0 units box
create_atoms    1 single 1 -2 3 units box
create_atoms    1 single -3 2 -1 units box
mca_set         all packing fcc radius 0.254 density 2700
velocity        all set 0.7 -0.3 0.2 units box
set             atom 1 omega 5.0 0.0 0.0
set             atom 2 omega 1.0 -2.0 3.5
set             atom 3 omega -0.02 0.03 0.01
pair_style      zero 1.0
pair_coeff      * *
fix             integrate all nve/mca
timestep        1.0e-3
compute         q all property/atom orientw orienti orientj orientk inertia
dump            d all custom ${nsteps} free.dump id xu yu zu vx vy vz omegax omegay omegaz mass &
                c_q[1] c_q[2] c_q[3] c_q[4] c_q[5]
dump_modify     d sort id format float %.17g
run             ${nsteps}
"""


def test_free_automata_rotate_exactly(build, tmp_path):
    """Free automata keep v, omega, momentum and kinetic energy, and turn as exp(t omega/2).

    Torque-free rotation of an isotropic body is rotation at constant omega,
    q(t) = (cos(|w|t/2), sin(|w|t/2) w/|w|) for q(0) = 1.  After 10^4 steps
    (up to 50 rad) the quaternion may differ from that only by accumulated
    round-off: bound 1e-11 (10^4 steps x a few 1e-16).  Velocities and spins
    must be unchanged bit for bit, so linear and angular momentum and kinetic
    energy are conserved to round-off.
    """
    nsteps = 10000
    build.run(FREE_AUTOMATA, tmp_path, variables={"nsteps": nsteps})
    snaps = read_dump(tmp_path / "free.dump")
    start, end = snaps[0], snaps[-1]
    t = nsteps * 1.0e-3
    for name in ("vx", "vy", "vz", "omegax", "omegay", "omegaz"):
        assert np.array_equal(start[name], end[name])
    omega = np.array([end["omegax"], end["omegay"], end["omegaz"]]).T
    quat = np.array([end[f"c_q[{k}]"] for k in range(1, 5)]).T
    for w, q in zip(omega, quat):
        angle = np.linalg.norm(w) * t
        expected = np.concatenate([[math.cos(angle / 2)], math.sin(angle / 2) * w / np.linalg.norm(w)])
        assert np.max(np.abs(q - expected)) < 1e-11
        assert abs(np.dot(q, q) - 1.0) < 1e-15
    # x advances by 10^4 additions of dt*v: at most one rounding of |x| each
    position = np.array([end["xu"], end["yu"], end["zu"]]).T
    expected = np.array([start["xu"], start["yu"], start["zu"]]).T + t * np.array([0.7, -0.3, 0.2])
    bound = nsteps * np.finfo(float).eps * np.max(np.abs(expected))
    assert np.max(np.abs(position - expected)) < bound
    # kinetic energy and angular momentum (spin part; orbital part follows from v, x)
    mass, inertia = end["mass"], end["c_q[5]"]
    kinetic = 0.5 * mass * np.sum(np.array([end["vx"], end["vy"], end["vz"]]) ** 2, axis=0) \
        + 0.5 * inertia * np.sum(omega.T ** 2, axis=0)
    kinetic0 = 0.5 * start["mass"] * np.sum(np.array([start["vx"], start["vy"], start["vz"]]) ** 2, axis=0) \
        + 0.5 * start["c_q[5]"] * np.sum(np.array([start["omegax"], start["omegay"], start["omegaz"]]) ** 2, axis=0)
    assert np.array_equal(kinetic, kinetic0)


CLUSTER_ATOMS = """
units           lj
atom_style      ${style}
atom_modify     map array
boundary        p p p
comm_modify     vel yes
lattice         sc 0.97
region          box block 0 4 0 4 0 4
create_box      1 box
create_atoms    1 box
${geometry}
"""

CLUSTER_READ = """
units           lj
atom_style      ${style}
atom_modify     map array
comm_modify     vel yes
read_data       ${data}
"""

CLUSTER_RUN = """
variable        vx atom 0.3*sin(1.7*id)
variable        vy atom 0.2*cos(0.9*id)
variable        vz atom 0.25*sin(0.4*id+1)
variable        wx atom 0.5*sin(id)
variable        wy atom -0.4*cos(2*id)
variable        wz atom 0.3*sin(0.3*id)
velocity        all set v_vx v_vy v_vz units box
set             group all omega v_wx v_wy v_wz
pair_style      gran/hooke/history 200.0 NULL 5.0 NULL 0.5 1
pair_coeff      * *
neighbor        0.3 bin
fix             integrate all ${integrator}
timestep        0.002
dump            d all custom ${nsteps} cluster.dump id x y z vx vy vz omegax omegay omegaz
dump_modify     d sort id format float %.17g
thermo          100
run             ${nsteps}
"""
GRANULAR_CLUSTER = CLUSTER_ATOMS + CLUSTER_RUN

AS_SPHERE = {"style": "sphere", "integrator": "nve/sphere",
             "geometry": "set group all diameter 1.0 density 1.0"}
AS_MCA = {"style": "mca", "integrator": "nve/mca",
          "geometry": "mca_set all packing none diameter 1.0 density 1.0"}


def test_matches_nve_sphere(build, tmp_path):
    """An unpacked automaton is a sphere: nve/mca must follow nve/sphere.

    64 overlapping spheres with frictional history contacts exchange momentum
    and spin.  Both integrators do the same arithmetic up to the order of a
    few operations (mass, inertia), so after 300 steps positions, velocities
    and spins agree to 1e-10 relative (the contacts amplify 1e-16 differences
    by a few orders of magnitude over this time).
    """
    nsteps = 300
    build.run(GRANULAR_CLUSTER, tmp_path / "sphere", variables=dict(AS_SPHERE, nsteps=nsteps))
    build.run(GRANULAR_CLUSTER, tmp_path / "mca", variables=dict(AS_MCA, nsteps=nsteps))
    sphere = read_dump(tmp_path / "sphere" / "cluster.dump")
    mca = read_dump(tmp_path / "mca" / "cluster.dump")
    # the contacts must have changed the spins substantially
    assert relative_difference(sphere[0]["omegax"], sphere[-1]["omegax"]) > 0.1
    for name in ("x", "y", "z", "vx", "vy", "vz", "omegax", "omegay", "omegaz"):
        assert relative_difference(sphere[-1][name], mca[-1][name]) < 1e-10, name


@pytest.mark.mpi
def test_mpi_ranks_give_the_same_trajectory(build, tmp_path):
    """The contact-coupled cluster on 1, 2 and 4 ranks agrees to round-off.

    Forces are summed in a different order on different decompositions;
    after 300 steps the differences stay below 1e-10 relative.
    """
    nsteps = 300
    # create_atoms numbers atoms by rank: all runs read one data file
    build.run(CLUSTER_ATOMS + "write_data cluster.data\n", tmp_path, variables=AS_MCA)
    for nprocs in (1, 2, 4):
        build.run(CLUSTER_READ + CLUSTER_RUN, tmp_path / f"np{nprocs}", nprocs=nprocs,
                  variables=dict(AS_MCA, nsteps=nsteps, data=tmp_path / "cluster.data"))
    reference = read_dump(tmp_path / "np1" / "cluster.dump")[-1]
    for nprocs in (2, 4):
        other = read_dump(tmp_path / f"np{nprocs}" / "cluster.dump")[-1]
        for name in ("x", "y", "z", "vx", "vy", "vz", "omegax", "omegay", "omegaz"):
            assert relative_difference(reference[name], other[name]) < 1e-10, (nprocs, name)


ROLLING = """
units           lj
atom_style      mca
atom_modify     map array
boundary        p p f
comm_modify     vel yes
region          box block -50 50 -2 2 0 4 units box
create_box      1 box
create_atoms    1 single -40 0 0.5 units box
mca_set         all packing ${packing} radius 0.5 density 1.0
velocity        all set 1.0 0.0 0.0 units box
fix             gravity all gravity 1.0 vector 0 0 -1
fix             wall all wall/gran hooke/history 1.0e5 NULL 50.0 NULL 0.4 1 zplane 0.0 NULL
pair_style      zero 1.0
pair_coeff      * *
fix             integrate all nve/mca
timestep        2.0e-4
compute         p all property/atom inertia radius omegay
compute         one all reduce sum c_p[1] c_p[2] c_p[3]
variable        ratio equal c_one[1]/(mass[1]*c_one[2]^2)
variable        vx equal vx[1]
variable        wy equal c_one[3]*c_one[2]
thermo_style    custom step v_vx v_wy v_ratio
thermo_modify   format float %22.16g
thermo          1000
run             20000
"""


@pytest.mark.parametrize("packing,inertia_ratio", [("none", 0.4), ("sc", 2.0 / 3.0),
                                                   ("fcc", 0.5)])
def test_sliding_to_rolling_uses_the_cell_inertia(build, tmp_path, packing, inertia_ratio):
    """A sliding automaton on a frictional floor ends up rolling at v0/(1 + J/(m R^2)).

    The friction force F at the contact point changes m v by F dt and J omega
    by -R F dt in the same kicks, so m v R + J omega is conserved exactly by
    the integrator; once the contact point is at rest (v = R omega) the speed
    is v0/(1 + J/(m R^2)): 5/7 for a sphere, 3/5 for the sc cube, 2/3 for the
    fcc rhombic dodecahedron.  The tangential contact spring is damped, so
    after 20000 steps the slip has decayed to round-off; tolerance 1e-9.
    """
    result = build.run(ROLLING, tmp_path, variables={"packing": packing}, check=False)
    if "Fix wall/gran requires atom style sphere" in result.stdout:
        pytest.skip("fix wall/gran of this LAMMPS version accepts atom_style sphere only")
    assert result.returncode == 0, result.stdout[-3000:]
    thermo = read_thermo(tmp_path / "log.lammps")
    assert abs(thermo["v_ratio"][-1] - inertia_ratio) < 1e-14
    expected = 1.0 / (1.0 + inertia_ratio)
    assert abs(thermo["v_vx"][-1] - expected) < 1e-9 * expected
    # rolling: contact point at rest
    assert abs(thermo["v_vx"][-1] - thermo["v_wy"][-1]) < 1e-9 * expected
    # it did slide first: friction 0.4 m g decelerates it to 0.84 by t = 0.4
    sliding = thermo["Step"] == 2000
    assert abs(thermo["v_vx"][sliding][0] - (1.0 - 0.4 * 0.4)) < 1e-3


def test_fix_respects_its_group(build, tmp_path):
    """Automata outside the fix group are not moved."""
    script = FREE_AUTOMATA.replace("fix             integrate all nve/mca",
                                   "group           moving id 1 3\n"
                                   "fix             integrate moving nve/mca")
    build.run(script, tmp_path, variables={"nsteps": 100})
    start, end = read_dump(tmp_path / "free.dump")
    still = end["id"] == 2
    for name in ("xu", "yu", "zu", "c_q[1]", "c_q[2]"):
        assert np.array_equal(start[name][still], end[name][still])
    assert not np.array_equal(start["xu"][~still], end["xu"][~still])
