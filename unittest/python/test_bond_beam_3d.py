"""bond_style beam in 3-D: the 12 x 12 co-rotational frame element on the
quaternions of atom_style mca (doc/src/bond_beam.rst; beam_kernels.h),
checked against the digest's reference cases
(../shared/reference/numfrac_lattice_particles_digest.md):

* cantilever (case 2): the Euler-Bernoulli (or Timoshenko) solution of a
  tip load along y (bending with I_z), along z (with I_y != I_z), and of a
  tip torque (twist T x / GJ), placed on the nodes of 4 elements, is an
  equilibrium: the tip resists with the load, the root carries the load
  and its moment, the inner nodes are free of force and torque to 1e-6
  of the load (the element is nodally exact);
* null space and objectivity (cases 1, 3): a deformed cluster turned
  rigidly about an oblique axis and moved has the same energy and its
  forces and torques turned, to 1e-12; undeformed and turned: no force;
* energy (case 5): NVE with fix nve/mca conserves energy with velocity
  Verlet's error (dt^2), linear and angular momentum (spin included) to
  round-off;
* breaking: tension at sigma0, torsion at the rim stress fibre T / J = tau0;
* newton_bond, MPI ranks, restart and the Kokkos variant: the same forces
  and trajectories to round-off.
"""

import math
import re

import numpy as np
import pytest

import mcatest
import test_bond_beam as beam2d
from mcatest import read_dump

DUMP = "id x y z fx fy fz tqx tqy tqz"
E_, A_, IY, IZ, J_, NU = 100.0, 0.1, 0.0008, 0.0012, 0.0016, 0.25
G_ = E_ / (2 * (1 + NU))
KS = 5.0 / 6.0
BEAM = f"{E_} {A_} 0.001 poisson {NU} section {IY} {IZ} {J_}"
TIMOSHENKO = f"{E_} {A_} 0.001 shear {G_} {KS} section {IY} {IZ} {J_}"
SPRINGS = "shearbeam 10.0 0.05 twist 0.03"


def beam_data(path, positions, bonds, box, radius=0.5, mass=1.0, inertia=0.1):
    """A 3-D atom_style mca data file with beams between the pairs of
    `bonds` (0-based indices)."""
    lines = ["3-D beam test data", "", f"{len(positions)} atoms", "1 atom types",
             f"{len(bonds)} bonds", "1 bond types", ""]
    lines += [f"{lo} {hi} {a}lo {a}hi" for (lo, hi), a in zip(box, "xyz")]
    lines += ["", "Atoms # mca", ""]
    for k, (x, y, z) in enumerate(positions):
        lines.append(f"{k + 1} 1 1 0 {radius} 1.0 {mass} {inertia} {x:.17g} {y:.17g} {z:.17g}")
    lines += ["", "Bonds", ""]
    lines += [f"{k + 1} 1 {i + 1} {j + 1}" for k, (i, j) in enumerate(bonds)]
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines) + "\n")
    return path


def header(data, boundary="f f f", newton="on"):
    return f"""
units           lj
atom_style      mca
atom_modify     map array
boundary        {boundary}
newton          on {newton}
read_data       {data}
comm_modify     cutoff 2.5
"""


def snapshot(build, directory, script, name="state", extra_args=(), nprocs=1):
    script += (f"run 0 post no\nwrite_dump all custom {name}.dump {DUMP} "
               "modify format float %.17g\n")
    build.run(script, directory, extra_args=extra_args, nprocs=nprocs)
    return read_dump(directory / f"{name}.dump")[0]


def columns(snap, names):
    return np.stack([snap[c] for c in names], axis=1)


# ---------------------------------------------------------------------------
# cantilever (case 2)

CANTILEVER_CASES = {
    # w(x) along y or z, the section's turn about z or y, the twist about x
    "load y": ("fy", "tqz"),
    "load z": ("fz", "tqy"),
    "torque x": ("tqx", None),
}


@pytest.mark.parametrize("case", list(CANTILEVER_CASES))
@pytest.mark.parametrize("model", ["euler", "timoshenko"])
def test_cantilever_solution_is_an_equilibrium(build, tmp_path, case, model):
    elements, length, load = 4, 1.0, 1.0e-6
    x = np.linspace(0.0, length, elements + 1)
    data = beam_data(tmp_path / "beam.data", [(v, 0.0, 0.0) for v in x],
                     [(k, k + 1) for k in range(elements)], ((-0.5, 1.5), (-1, 1), (-1, 1)))
    coeff = BEAM if model == "euler" else TIMOSHENKO
    shear = 0.0 if model == "euler" else load / (KS * G_ * A_)    # Timoshenko: w += P x / (ks G A)
    deg = 180.0 / math.pi
    if case == "load y":
        ei = E_ * IZ    # w_y = -P x^2 (3L - x) / 6EI, the section turns by w' about +z
        move = (f"variable w atom -{load}*x*x*(3*{length}-x)/(6*{ei})-{shear}*x\n"
                f"variable t atom -{load}*x*(2*{length}-x)/(2*{ei})*{deg}\n"
                "set group all y v_w\nmca_set all turnz v_t\n")
    elif case == "load z":
        ei = E_ * IY    # w_z the same with I_y; a turn about +y lowers z: turn y = -w'
        move = (f"variable w atom -{load}*x*x*(3*{length}-x)/(6*{ei})-{shear}*x\n"
                f"variable t atom {load}*x*(2*{length}-x)/(2*{ei})*{deg}\n"
                "set group all z v_w\nmca_set all turny v_t\n")
    else:
        gj = G_ * J_    # twist T x / GJ
        move = f"variable t atom -{load}*x/{gj}*{deg}\nmca_set all turnx v_t\n"
    script = header(data) + f"bond_style beam\nbond_coeff 1 {coeff}\nrun 0 post no\n" + move
    snap = snapshot(build, tmp_path, script)
    force, moment = CANTILEVER_CASES[case]
    inner = slice(1, elements)
    f = snap[force]
    all_f = columns(snap, ["fy", "fz"])    # (fx: below)
    all_t = columns(snap, ["tqx", "tqy", "tqz"])
    print(f"{model}, {case}: tip {f[-1] / load - 1:.1e} off the load, root {f[0] / load:.12f},"
          + (f" root moment / PL {snap[moment][0] / (load * length):.12f}," if moment else "")
          + f" inner |f|, |t| / P {np.abs(all_f[inner]).max() / load:.1e},"
          f" {np.abs(all_t[inner]).max() / load:.1e}")
    # a linear problem: round-off and second-order terms, far below 1e-6 P
    assert f[-1] == pytest.approx(load, rel=1e-6)
    assert f[0] == pytest.approx(-load, rel=1e-6)
    if moment:
        # the moment of the load about the root: L x (-P e_y) = -PL e_z,
        # L x (-P e_z) = +PL e_y
        sign = -1.0 if moment == "tqz" else 1.0
        assert snap[moment][0] == pytest.approx(sign * load * length, rel=1e-6)
    assert np.abs(all_f[inner]).max() < 1e-6 * load
    assert np.abs(all_t[inner]).max() < 1e-6 * load * length
    # nothing else, but the axial force of the second-order shortening
    # (N ~ EA w'^2 / 2, w' < 1e-5)
    others = [c for c in ("fy", "fz", "tqx", "tqy", "tqz") if c not in (force, moment)]
    assert max(np.abs(snap[c]).max() for c in others) < 1e-6 * load
    assert np.abs(snap["fx"]).max() < E_ * A_ * 1e-10


# ---------------------------------------------------------------------------
# null space and objectivity (cases 1, 3)


def cluster():
    """A cube of 3 x 3 x 3 sites with edge and face-diagonal bonds (every
    bond direction of an fcc cell, and bonds along the body z axis)."""
    sites = np.array([(i, j, k) for k in range(3) for j in range(3) for i in range(3)], float)
    d = np.linalg.norm(sites[:, None] - sites[None], axis=2)
    bonds = [(a, b) for a in range(len(sites)) for b in range(a + 1, len(sites))
             if d[a, b] < 1.5]
    return sites - 1.0, bonds


DEFORM = """
thermo_style    custom step pe ebond
thermo_modify   norm no format float %.17g
run             0 post no
variable        dx atom 0.03*sin(3.1*id)
variable        dy atom 0.04*cos(2.3*id)
variable        dz atom 0.02*sin(1.7*id+1)
variable        ax atom 5.0*sin(1.3*id)
variable        ay atom 4.0*cos(0.7*id)
variable        az atom 6.0*sin(2.9*id+0.5)
displace_atoms  all move v_dx v_dy v_dz
mca_set         all turnx v_ax turny v_ay turnz v_az
"""


def rotation(axis, degrees):
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    a = math.radians(degrees)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + math.sin(a) * k + (1 - math.cos(a)) * k @ k


def rigid_motion(axis, degrees, shift):
    """Commands that turn every particle (position about the origin, and
    orientation) by `degrees` about `axis` and shift it."""
    r = rotation(axis, degrees)
    rv = np.asarray(axis, float) / np.linalg.norm(axis) * degrees
    lines = ["fix             xyz all store/state 0 x y z"]
    for row, name in enumerate("xyz"):
        terms = "+".join(f"({r[row, c]:.17g})*f_xyz[{c + 1}]" for c in range(3))
        lines.append(f"variable        u{name} atom {terms}+({shift[row]:.17g})-f_xyz[{row + 1}]")
    lines.append("displace_atoms  all move v_ux v_uy v_uz")
    lines.append(f"mca_set         all turnx {rv[0]:.17g} turny {rv[1]:.17g} turnz {rv[2]:.17g}")
    return "\n".join(lines) + "\n", r


@pytest.mark.parametrize("coeff", [BEAM, TIMOSHENKO, SPRINGS],
                         ids=["euler", "timoshenko", "shearbeam"])
def test_rigid_motion_keeps_energy_and_turns_forces(build, tmp_path, coeff):
    sites, bonds = cluster()
    data = beam_data(tmp_path / "cluster.data", sites, bonds, ((-4, 4),) * 3)
    base = header(data) + f"bond_style beam\nbond_coeff 1 {coeff}\n" + DEFORM
    ref = snapshot(build, tmp_path / "a", base)
    e_ref = mcatest.read_thermo(tmp_path / "a" / "log.lammps")["PotEng"][-1]
    move, r = rigid_motion((1.0, -2.0, 0.5), 73.0, (0.3, -0.2, 0.1))
    rot = snapshot(build, tmp_path / "b", base + move)
    e_rot = mcatest.read_thermo(tmp_path / "b" / "log.lammps")["PotEng"][-1]

    f_ref, t_ref = columns(ref, ["fx", "fy", "fz"]), columns(ref, ["tqx", "tqy", "tqz"])
    f_rot, t_rot = columns(rot, ["fx", "fy", "fz"]), columns(rot, ["tqx", "tqy", "tqz"])
    fscale, tscale = np.abs(f_ref).max(), np.abs(t_ref).max()
    assert fscale > 1e-3 and tscale > 1e-4    # the cluster is deformed
    df = np.abs(f_rot - f_ref @ r.T).max() / fscale
    dt = np.abs(t_rot - t_ref @ r.T).max() / tscale
    print(f"energy {e_ref:.6e} / {e_rot:.6e}; turned force, torque differences {df:.1e}, {dt:.1e}")
    assert e_rot == pytest.approx(e_ref, rel=1e-12)
    assert df < 1e-12 and dt < 1e-12
    # momentum and angular momentum balance of the forces and torques
    x = columns(ref, ["x", "y", "z"])
    assert np.abs(f_ref.sum(axis=0)).max() < 1e-13 * fscale * len(x)
    assert np.abs(np.cross(x, f_ref).sum(axis=0) + t_ref.sum(axis=0)).max() \
        < 1e-13 * max(fscale, tscale) * len(x)

    # undeformed, turned and moved: no force, no torque
    still = header(data) + f"bond_style beam\nbond_coeff 1 {coeff}\nrun 0 post no\n" + move
    snap = snapshot(build, tmp_path / "c", still)
    f0 = np.abs(columns(snap, ["fx", "fy", "fz"])).max()
    t0 = np.abs(columns(snap, ["tqx", "tqy", "tqz"])).max()
    print(f"undeformed, turned: largest force {f0:.1e}, torque {t0:.1e}")
    assert f0 < 1e-12 * fscale and t0 < 1e-12 * tscale


# ---------------------------------------------------------------------------
# energy conservation (case 5)


def nve_run(build, directory, dt, steps, extra_args=(), nprocs=1, newton="on", tail="",
            coeff=TIMOSHENKO):
    """The deformed cluster let go in NVE; thermo pe, ke, rotational ke (J = 0.1)."""
    sites, bonds = cluster()
    data = beam_data(directory / "cluster.data", sites, bonds, ((-4, 4),) * 3)
    script = header(data, newton=newton) + f"bond_style beam\nbond_coeff 1 {coeff}\n" + DEFORM
    script += f"""
fix             1 all nve/mca
compute         w all property/atom omegax omegay omegaz
variable        er atom 0.5*0.1*(c_w[1]^2+c_w[2]^2+c_w[3]^2)
compute         rke all reduce sum v_er
variable        etot equal pe+ke+c_rke
timestep        {dt}
thermo_style    custom step pe ke c_rke v_etot
thermo_modify   norm no format float %.17g
thermo          {max(steps // 40, 1)}
dump            d all custom {steps} traj.dump id x y z vx vy vz omegax omegay omegaz
dump_modify     d format float %.17g
""" + (tail or f"run {steps}\n")
    build.run(script, directory, extra_args=extra_args, nprocs=nprocs)
    return mcatest.read_thermo(directory / "log.lammps"), read_dump(directory / "traj.dump")


def momenta(snap):
    """Linear and angular momentum (spin included; mass 1, J = 0.1) of a
    snapshot, its largest velocity component and its number of particles."""
    x, v = columns(snap, ["x", "y", "z"]), columns(snap, ["vx", "vy", "vz"])
    w = columns(snap, ["omegax", "omegay", "omegaz"])
    return (v.sum(axis=0), np.cross(x, v).sum(axis=0) + 0.1 * w.sum(axis=0), np.abs(v).max(),
            len(x))


def test_energy_and_momenta_are_conserved(build, tmp_path):
    drifts = []
    for k, (dt, steps) in enumerate(((0.004, 400), (0.002, 800))):
        thermo, snaps = nve_run(build, tmp_path / f"dt{k}", dt, steps)
        e = thermo["v_etot"]
        drifts.append(np.abs(e - e[0]).max() / thermo["PotEng"][0])
        p, ang, vscale, n = momenta(snaps[-1])
        print(f"dt {dt}: energy error / E_pot(0) {drifts[-1]:.2e}, momentum {np.abs(p).max():.1e},"
              f" angular momentum {np.abs(ang).max():.1e} (velocity scale {vscale:.2e}),"
              f" kinetic share at the end {thermo['KinEng'][-1] / thermo['PotEng'][0]:.2f}")
        assert thermo["KinEng"].max() > 0.1 * thermo["PotEng"][0]    # it does move
        assert np.abs(p).max() < 1e-12 * vscale * n
        assert np.abs(ang).max() < 1e-12 * vscale * n * 4.0
    # velocity Verlet: the energy error falls as dt^2
    print(f"error ratio dt / dt/2: {drifts[0] / drifts[1]:.2f}")
    assert drifts[0] < 1e-3
    assert 3.2 < drifts[0] / drifts[1] < 4.8


# ---------------------------------------------------------------------------
# newton_bond, ranks, restart, Kokkos


def test_forces_independent_of_newton_and_ranks(build, tmp_path):
    sites, bonds = cluster()
    data = beam_data(tmp_path / "cluster.data", sites, bonds, ((-4, 4),) * 3)
    coeff = f"bond_style beam\nbond_coeff 1 {TIMOSHENKO}\n" + DEFORM
    runs = {}
    for newton in ("on", "off"):
        for nprocs in (1, 2, 4):
            script = header(data, newton=newton) + coeff
            runs[newton, nprocs] = snapshot(build, tmp_path / f"{newton}{nprocs}", script,
                                            nprocs=nprocs)
    names = ["fx", "fy", "fz", "tqx", "tqy", "tqz"]
    ref = columns(runs["on", 1], names)
    scale = np.abs(ref).max()
    for key, snap in runs.items():
        diff = np.abs(columns(snap, names) - ref).max() / scale
        print(f"newton_bond {key[0]}, {key[1]} ranks: {diff:.1e}")
        assert diff < 1e-13


def test_ranks_and_restart_follow_one_run(build, tmp_path):
    steps = 300
    _, one = nve_run(build, tmp_path / "one", 0.004, steps)
    _, two = nve_run(build, tmp_path / "two", 0.004, steps, nprocs=2)
    _, split = nve_run(build, tmp_path / "split", 0.004, steps,
                       tail=f"run {steps // 2}\nwrite_restart half.restart\n")
    restart = f"""
read_restart    half.restart
bond_style      beam
bond_coeff      1 {TIMOSHENKO}
fix             1 all nve/mca
timestep        0.004
dump            d all custom {steps // 2} traj.dump id x y z vx vy vz omegax omegay omegaz
dump_modify     d format float %.17g
run             {steps // 2}
"""
    build.run(restart, tmp_path / "split")
    restarted = read_dump(tmp_path / "split" / "traj.dump")
    names = ["x", "y", "z", "vx", "vy", "vz", "omegax", "omegay", "omegaz"]
    ref = columns(one[-1], names)
    for label, snap in (("2 ranks", two[-1]), ("restart", restarted[-1])):
        diff = np.abs(columns(snap, names) - ref).max() / np.abs(ref).max()
        print(f"{label}: {steps} steps, largest relative difference {diff:.1e}")
        assert diff < 1e-10


@pytest.mark.parametrize("threads", [1, 2])
def test_kokkos_variant_matches_the_cpu_style(tmp_path, threads):
    kk = mcatest.kokkos_build()
    sites, bonds = cluster()
    data = beam_data(tmp_path / "cluster.data", sites, bonds, ((-4, 4),) * 3)
    script = header(data) + f"bond_style beam\nbond_coeff 1 {TIMOSHENKO}\n" + DEFORM + """
compute         pe all pe/atom bond
compute         st all stress/atom NULL bond
thermo_style    custom step pe press pxx pyy pzz pxy pxz pyz
thermo_modify   norm no format float %.17g
"""
    names = ["fx", "fy", "fz", "tqx", "tqy", "tqz", "c_pe"] + [f"c_st[{k}]" for k in range(1, 7)]
    script += ("dump d all custom 1 state.dump id " + " ".join(names) + "\n"
               "dump_modify d format float %.17g\nrun 0 post no\n")
    kk.run(script, tmp_path / "cpu")
    kk.run(script, tmp_path / "kk", extra_args=mcatest.kokkos_args(threads))
    cpu, dev = (read_dump(tmp_path / d / "state.dump")[0] for d in ("cpu", "kk"))
    worst = max(np.abs(dev[c] - cpu[c]).max() / np.abs(cpu[c]).max() for c in names)
    t_cpu, t_kk = (mcatest.read_thermo(tmp_path / d / "log.lammps") for d in ("cpu", "kk"))
    for name in ("PotEng", "Press", "Pxx", "Pyy", "Pzz", "Pxy", "Pxz", "Pyz"):
        worst = max(worst, abs(t_kk[name][-1] - t_cpu[name][-1]) / abs(t_cpu[name][-1]))
    print(f"kk {threads} thread(s): largest relative difference {worst:.1e}")
    # one thread adds in the CPU style's order; two threads in another
    assert worst < (1e-15 if threads == 1 else 1e-12)


# ---------------------------------------------------------------------------
# breaking: tension and torsion at their thresholds

SIGMA0, TAU0, FIBRE = 0.2, 0.1, 0.05


def threshold_probe(build, directory, move, below, above, extra_args=()):
    """Two particles bonded along x (a 3-D section with I_y != I_z); the
    bond must hold at `below` and break at `above`; returns the bond counts."""
    data = beam_data(directory / "pair.data", [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0)], [(0, 1)],
                     ((-2, 3), (-2, 2), (-2, 2)))
    script = header(data) + f"""
bond_style      beam
bond_coeff      1 {BEAM} break {SIGMA0} {TAU0} bending {FIBRE}
thermo_style    custom step bonds ebond
run             0 post no
"""
    for value in (below, above):
        script += move(value) + "run 0 post no\nprint \"BONDS $(bonds)\"\n"
    result = build.run(script, directory, extra_args=extra_args)
    return [int(line.split()[1]) for line in result.stdout.splitlines()
            if line.startswith("BONDS")]


def turn_first(axis):
    """Commands that turn the first particle by an angle (radians) about an axis."""
    return lambda t: (f"group first id 1\nmca_set first angle 0\n"
                      f"mca_set first turn{axis} {math.degrees(t):.17g}\ngroup first delete\n")


def bending_measure(theta, inertia):
    """The elliptic measure of the bond when its first end is turned by
    theta about the section's z (I_z) or y (I_y) axis, the other end and
    the chord unchanged: a = 2 tan(theta/2), M_i = 4 EI a / L, M_j = 2 EI a / L,
    sigma = fibre M_i / I, and the shear force |2 M_i / (1 + cos theta) + M_j| / L
    (the gradients of the two ends' measures across the chord)."""
    a = 2 * math.tan(theta / 2)
    mi, mj = 4 * E_ * inertia * a, 2 * E_ * inertia * a
    sigma = FIBRE * mi / inertia
    tau = abs(2 * mi / (1 + math.cos(theta)) + mj) / A_
    return (sigma / SIGMA0) ** 2 + (tau / TAU0) ** 2


def threshold(measure):
    lo, hi = 0.0, 1.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if measure(mid) < 1 else (lo, mid)
    return 0.5 * (lo + hi)


@pytest.mark.parametrize("axis, inertia", [("z", IZ), ("y", IY)])
def test_bending_breaks_on_the_ellipse_of_its_plane(build, tmp_path, axis, inertia):
    """Turning one end about the section's z axis bends with I_z, about y
    with I_y: each breaks at its own analytic angle (the other plane's
    would be 11 % off)."""
    theta = threshold(lambda t: bending_measure(t, inertia))
    other = threshold(lambda t: bending_measure(t, IY + IZ - inertia))
    print(f"about {axis}: breaks at {theta:.12f} rad (with the other I: {other:.12f})")
    assert abs(other / theta - 1) > 1e-3
    assert threshold_probe(build, tmp_path, turn_first(axis), theta * (1 - 1e-9),
                           theta * (1 + 1e-9)) == [1, 0]


def test_kokkos_breaks_at_the_same_thresholds(tmp_path):
    kk = mcatest.kokkos_build()
    theta = threshold(lambda t: bending_measure(t, IZ))
    p_star = 2 * math.atan(0.5 * TAU0 / (FIBRE * G_))
    for threads in mcatest.kokkos_thread_counts():
        args = mcatest.kokkos_args(threads)
        assert threshold_probe(kk, tmp_path / f"bend{threads}", turn_first("z"),
                               theta * (1 - 1e-9), theta * (1 + 1e-9), extra_args=args) == [1, 0]
        assert threshold_probe(kk, tmp_path / f"twist{threads}", turn_first("x"),
                               -p_star * (1 - 1e-9), -p_star * (1 + 1e-9),
                               extra_args=args) == [1, 0]


def test_large_turns_stiffen_up_to_a_half_turn(build, tmp_path):
    """An end turned by theta about z: energy 2 own_z tan^2(theta/2)
    (own_z = 4 E I_z / L), to 1e-12, rising without bound towards a half
    turn (a measure by the sine would fall back to 0 there)."""
    data = beam_data(tmp_path / "pair.data", [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0)], [(0, 1)],
                     ((-2, 3), (-2, 2), (-2, 2)))
    angles = [0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.1]
    script = header(data) + f"""
bond_style      beam
bond_coeff      1 {BEAM}
thermo_style    custom step ebond
thermo_modify   norm no format float %.17g
run             0 post no
"""
    for t in angles:
        script += turn_first("z")(t) + "run 0 post no\nprint \"EBOND $(ebond:%.17g)\"\n"
    out = build.run(script, tmp_path).stdout
    energies = [float(line.split()[1]) for line in out.splitlines() if line.startswith("EBOND")]
    own = 4 * E_ * IZ
    ref = [2 * own * math.tan(t / 2) ** 2 for t in angles]
    print("energies", " ".join(f"{e:.6g}" for e in energies))
    assert energies == pytest.approx(ref, rel=1e-12)
    assert all(b > a for a, b in zip(energies, energies[1:]))


def test_tension_and_torsion_break_at_their_strengths(build, tmp_path):
    u_star = SIGMA0 / E_    # N / A = E u / L0, L0 = 1
    pull = lambda u: f"set atom 2 x {1.0 + u:.17g}\n"
    assert threshold_probe(build, tmp_path / "pull", pull, u_star * (1 - 1e-9),
                           u_star * (1 + 1e-9)) == [1, 0]
    # the second particle twisted by p about x: T = GJ 2 tan(p/2) / L0,
    # tau = fibre T / J = tau0 at 2 tan(p/2) = tau0 / (fibre G)
    p_star = 2 * math.atan(0.5 * TAU0 / (FIBRE * G_))
    twist = lambda p: f"group end id 2\nmca_set end angle 0\n" \
        f"mca_set end turnx {math.degrees(p):.17g}\ngroup end delete\n"
    assert threshold_probe(build, tmp_path / "twist", twist, p_star * (1 - 1e-9),
                           p_star * (1 + 1e-9)) == [1, 0]


# ---------------------------------------------------------------------------
# coefficients: data files and bad input


def test_data_file_keeps_3d_coefficients(build, tmp_path):
    sites, bonds = cluster()
    data = beam_data(tmp_path / "cluster.data", sites, bonds, ((-4, 4),) * 3)
    data.write_text(data.read_text().replace("1 bond types", "2 bond types"))
    script = header(data) + f"""
comm_modify     vel yes
bond_style      beam
bond_coeff      1 {TIMOSHENKO} break 0.2 0.1 bending 0.05 damp 0.001
bond_coeff      2 {BEAM}
write_data      first.data
"""
    build.run(script, tmp_path)
    first = (tmp_path / "first.data").read_text()
    line = re.search(r"Bond Coeffs.*?\n\n(.*?)\n", first, re.S).group(1)
    print(line)
    assert f"section {IY:.17g} {IZ:.17g} {J_:.17g}" in line
    assert "damp 0.001" in line
    second_type = re.search(r"Bond Coeffs.*?\n\n.*?\n(.*?)\n", first, re.S).group(1)
    assert f"poisson {NU:.17g}" in second_type
    again = """
units           lj
atom_style      mca
bond_style      beam
read_data       first.data
comm_modify     vel yes
write_data      second.data
"""
    build.run(again, tmp_path)
    second = (tmp_path / "second.data").read_text()
    assert re.search(r"Bond Coeffs.*?\n\n(.*?\n.*?)\n", second, re.S).group(1) == \
        re.search(r"Bond Coeffs.*?\n\n(.*?\n.*?)\n", first, re.S).group(1)


BAD_3D = [
    ("no G", "bond_coeff 1 1.0 0.1 0.001", r"a 3-D beam needs the shear modulus"),
    ("no twist", "bond_coeff 1 shearbeam 1 1", r"a 3-D shearbeam needs its torsion spring"),
    ("section", "bond_coeff 1 1.0 0.1 0.001 poisson 0.3 section 0.1 0 0.1",
     r"section Iz = 0 must be > 0"),
    ("poisson", "bond_coeff 1 1.0 0.1 0.001 poisson 0.5", r"poisson nu = 0.5 must be in"),
    ("twice", "bond_coeff 1 1.0 0.1 0.001 poisson 0.3 shear 1 0.8",
     r"the shear modulus is given twice"),
    ("damp", "bond_coeff 1 1.0 0.1 0.001 poisson 0.3 damp -1", r"damp beta = -1 must be > 0"),
    ("twist on beam", "bond_coeff 1 1.0 0.1 0.001 poisson 0.3 twist 1",
     r"twist \(a torsion spring\) applies to shearbeam"),
]


BAD_2D = [
    ("section in 2-D", "bond_coeff 1 1.0 0.1 0.001 section 0.1 0.1 0.1",
     r"section applies to 3-D beams only"),
    ("poisson in 2-D", "bond_coeff 1 1.0 0.1 0.001 poisson 0.3",
     r"poisson \(the torsion's G\) applies to 3-D beams only"),
    ("twist in 2-D", "bond_coeff 1 shearbeam 1 1 twist 1", r"twist applies to 3-D beams only"),
    ("turnx in 2-D", "mca_set all turnx 10", r"turnx and turny need dimension 3"),
]


@pytest.mark.parametrize("case", BAD_2D, ids=[c[0] for c in BAD_2D])
def test_3d_keywords_in_2d_give_clear_errors(build, tmp_path, case):
    beam2d.expect_error(build, tmp_path, 2, case[1], case[2])


@pytest.mark.parametrize("case", BAD_3D, ids=[c[0] for c in BAD_3D])
def test_bad_3d_coefficients_give_clear_errors(build, tmp_path, case):
    beam2d.expect_error(build, tmp_path, 3, case[1], case[2])


def test_turn_and_angle_together_give_a_clear_error(build, tmp_path):
    beam2d.expect_error(build, tmp_path, 3, "mca_set all angle 10 turnx 5",
                        r"use either angle \(set\) or turnx")


# ---------------------------------------------------------------------------
# the example


def test_frame_example_settles_at_the_analytic_values(build, tmp_path):
    """examples/beam_frame_3d at 4 elements: tip deflections along y and z,
    the twist and the two turns each against its analytic value, to 1e-6
    (measured 4.5e-7: the co-rotation at turns of 4e-7 and what is left of
    the damped motion)."""
    source = mcatest.ROOT / "examples" / "beam_frame_3d" / "in.frame3d"
    result = build.run(source.read_text(), tmp_path, extra_args=("-var", "N", "4"))
    line = next(l for l in result.stdout.splitlines() if l.startswith("FRAME"))
    values = [float(v) for v in line.split()[4::2]]
    print(line)
    assert len(values) == 5
    assert max(abs(v - 1.0) for v in values) < 1e-6
