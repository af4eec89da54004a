"""bond_style beam: the 2-D co-rotational Euler-Bernoulli beam of the
NUMFRAC lattice (doc/src/bond_beam.rst; digest A.3), checked against the
reference cases of ../shared/reference/numfrac_lattice_particles_digest.md:

* cantilever (case 2): the Euler-Bernoulli solution, deflection
  w = -P x^2 (3L - x) / 6EI and rotation w', placed on the nodes of 1, 4
  or 10 elements, is an equilibrium of the lattice: the transverse forces
  and the torques of the inner nodes vanish to 1e-6 P, the tip resists
  with P and the root carries -P and the moment P L (cubic Hermite
  elements are exact for a point load, so the tip deflection PL^3/3EI
  and rotation PL^2/2EI are those of the discrete beam for any N); the
  axial forces are the second-order shortening, below EA theta_max^2;
* element null space (case 1): the stiffness of one beam at rest, by
  central differences of its forces and torques, is the linear frame
  element's, with exactly three zero eigenvalues;
* objectivity (cases 1, 3): a patch of beams
  deformed, then moved rigidly (translated and turned by 90 degrees with
  its particles): the same energy, and forces and torques turned with it,
  to 1e-12 of their scale; undeformed and turned: no force at all;
* scale invariance (R14): every length times 2.5 at the same E and
  density runs the same motion with the factors of Howto_mlp;
* energy conservation (case 5): a deformed patch with spins in NVE
  (fix nve/mca) conserves energy with the error of velocity Verlet (4 times
  less when the time step halves), linear and angular momentum (spin
  included) to round-off;
* hexagonal lattice moduli (case 7): a periodic beam lattice under a
  uniaxial strain has the E_2D and nu_2D of tools/lattice_calibration.py
  (k_n = EA/L, k_s = 12 EI/L^3) for h/L = 0.1, 0.3, 0.6, to 1e-6;
* forces independent of newton_bond and of the number of MPI ranks,
  restart files keep the reference states (a restarted run follows the
  uninterrupted one), and the Kokkos variant equals the CPU style to
  round-off.
"""

import math
import re

import numpy as np
import pytest

import mcatest
from mcatest import read_dump

SQRT3 = math.sqrt(3.0)
DUMP = "id x y fx fy tqz"


def beam_data(path, positions, bonds, box, radius=0.5, mass=1.0, inertia=0.1):
    """A 2-D atom_style mca data file (z = 0) with beams between the pairs
    of `bonds` (0-based indices); `radius` is the data file's column, the
    diameter."""
    lines = ["beam test data", "", f"{len(positions)} atoms", "1 atom types",
             f"{len(bonds)} bonds", "1 bond types", "",
             f"{box[0][0]} {box[0][1]} xlo xhi", f"{box[1][0]} {box[1][1]} ylo yhi",
             "-0.5 0.5 zlo zhi", "", "Atoms # mca", ""]
    for k, (x, y) in enumerate(positions):
        lines.append(f"{k + 1} 1 1 0 {radius} 1.0 {mass} {inertia} {x:.17g} {y:.17g} 0")
    lines += ["", "Bonds", ""]
    lines += [f"{k + 1} 1 {i + 1} {j + 1}" for k, (i, j) in enumerate(bonds)]
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines) + "\n")
    return path


def header(data, boundary="f f p", newton="on", extra=""):
    return f"""
units           lj
dimension       2
atom_style      mca
atom_modify     map array
boundary        {boundary}
newton          on {newton}
read_data       {data}
comm_modify     cutoff 2.5
{extra}
"""


def hex_patch(radius=3.1, c=1.0):
    """Sites of a hexagonal lattice within `radius` of the origin, and its
    nearest-neighbour bonds."""
    sites = []
    n = int(radius / c) + 2
    for j in range(-2 * n, 2 * n + 1):
        for i in range(-2 * n, 2 * n + 1):
            x, y = (i + 0.5 * j) * c, j * SQRT3 / 2 * c
            if math.hypot(x, y) < radius:
                sites.append((x, y))
    sites = np.array(sites)
    d = np.hypot(sites[:, None, 0] - sites[None, :, 0], sites[:, None, 1] - sites[None, :, 1])
    bonds = [(i, j) for i in range(len(sites)) for j in range(i + 1, len(sites))
             if d[i, j] < 1.01 * c]
    return sites, bonds


COEFF = "bond_style beam\nbond_coeff 1 100.0 0.1 0.001\n"
COEFF_SHEAR = "bond_style beam\nbond_coeff 1 100.0 0.1 0.001 shear 40.0 0.8333333333333334\n"
COEFF_SPRINGS = "bond_style beam\nbond_coeff 1 shearbeam 10.0 0.05\n"


def snapshot(build, directory, script, name="state", extra_args=(), nprocs=1):
    script += (f"run 0 post no\nwrite_dump all custom {name}.dump {DUMP} "
               "modify format float %.17g\n")
    build.run(script, directory, extra_args=extra_args, nprocs=nprocs)
    return read_dump(directory / f"{name}.dump")[0]


def thermo_pe(directory):
    return mcatest.read_thermo(directory / "log.lammps")


# a deformed patch: every particle displaced and turned (by functions of its
# ID), with the reference taken before (run 0 on the lattice)
DEFORM = """
thermo_style    custom step pe ebond
thermo_modify   norm no format float %.17g
run             0 post no
variable        dx atom 0.03*sin(3.1*id)
variable        dy atom 0.04*cos(2.3*id)
variable        th atom 6.0*sin(1.3*id)
displace_atoms  all move v_dx v_dy 0.0
mca_set         all angle v_th
"""


# ---------------------------------------------------------------------------
# cantilever (case 2)


@pytest.mark.parametrize("elements", [1, 4, 10])
def test_cantilever_solution_is_an_equilibrium(build, tmp_path, elements):
    length, e, area, inertia = 1.0, 100.0, 1.0, 0.01
    ei, ea, load = e * inertia, e * area, 1.0e-6
    x = np.linspace(0.0, length, elements + 1)
    data = beam_data(tmp_path / "beam.data", np.stack([x, 0 * x], axis=1),
                     [(k, k + 1) for k in range(elements)], ((-0.5, 1.5), (-1, 1)))
    script = header(data) + f"bond_style beam\nbond_coeff 1 {e} {area} {inertia}\n" + f"""
run             0 post no
variable        w atom -{load}*x*x*(3*{length}-x)/(6*{ei})
variable        th atom -{load}*x*(2*{length}-x)/(2*{ei})*180/PI
set             group all y v_w
mca_set         all angle v_th
"""
    snap = snapshot(build, tmp_path, script)
    fy, tq, fx = snap["fy"], snap["tqz"], snap["fx"]
    inner = slice(1, elements)
    print(f"N={elements}: tip fy/P - 1 = {fy[-1] / load - 1:.2e}, root fy/P = {fy[0] / load:.12f},"
          f" root torque/PL = {tq[0] / (load * length):.12f}, inner |f|,|t| / P = "
          f"{np.abs(fy[inner]).max(initial=0) / load:.1e}, "
          f"{np.abs(tq[inner]).max(initial=0) / load:.1e}, |fx|max = {np.abs(fx).max():.1e}")
    # linear problem: round-off and second-order terms, far below 1e-6 P
    assert fy[-1] == pytest.approx(load, rel=1e-6)
    assert fy[0] == pytest.approx(-load, rel=1e-6)
    assert tq[0] == pytest.approx(-load * length, rel=1e-6)
    assert abs(tq[-1]) < 1e-6 * load * length
    if elements > 1:
        assert np.abs(fy[inner]).max() < 1e-6 * load
        assert np.abs(tq[inner]).max() < 1e-6 * load * length
    # the shortening of the deflected elements: N ~ EA w'^2 / 2
    theta_max = load * length ** 2 / (2 * ei)
    assert np.abs(fx).max() < ea * theta_max ** 2


def cantilever_data(path, elements, length=1.0, mass=0.01):
    """A straight beam along x of `elements` equal elements; lumped masses
    (half at the two ends), discs' moments of inertia m r^2 / 2, r = L0 / 2."""
    x = np.linspace(0.0, length, elements + 1)
    masses = np.full(elements + 1, mass)
    masses[[0, -1]] *= 0.5
    r = 0.5 * length / elements
    lines = ["cantilever", "", f"{elements + 1} atoms", "1 atom types", f"{elements} bonds",
             "1 bond types", "", f"-0.5 {length + 0.5} xlo xhi", "-1 1 ylo yhi",
             "-0.5 0.5 zlo zhi", "", "Atoms # mca", ""]
    for k in range(elements + 1):
        lines.append(f"{k + 1} 1 1 0 {r} 1.0 {masses[k]} {0.5 * masses[k] * r * r} "
                     f"{x[k]:.17g} 0 0")
    lines += ["", "Bonds", ""] + [f"{k + 1} 1 {k + 1} {k + 2}" for k in range(elements)]
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines) + "\n")
    return path


@pytest.mark.parametrize("elements", [1, 4, 10])
def test_cantilever_settles_at_the_euler_bernoulli_deflection(build, tmp_path, elements):
    """The same cantilever, the load applied and the motion damped away
    (fix nve/damped, translation and spin): tip deflection PL^3/3EI and
    rotation PL^2/2EI."""
    e, area, inertia, load = 100.0, 1.0, 0.01, 1.0e-4
    ei = e * inertia
    data = cantilever_data(tmp_path / "beam.data", elements)
    script = header(data) + f"""
bond_style      beam
bond_coeff      1 {e} {area} {inertia}
group           root id 1
group           tip id {elements + 1}
group           free subtract all root
fix             1 free nve/damped 2.0
fix             3 tip addforce 0.0 -{load} 0.0
fix             4 all enforce2d
variable        w equal y[{elements + 1}]
compute         qw all property/atom orientw
compute         qk all property/atom orientk
compute         tip tip reduce sum c_qw c_qk
variable        t equal 2*atan2(c_tip[2],c_tip[1])
timestep        0.0005
thermo_style    custom step v_w v_t ke
thermo_modify   format float %.17g
thermo          1000
run             40000
"""
    build.run(script, tmp_path)
    thermo = mcatest.read_thermo(tmp_path / "log.lammps")
    w, t = -thermo["v_w"][-1], -thermo["v_t"][-1]
    w_ref, t_ref = load / (3 * ei), load / (2 * ei)
    print(f"N={elements}: tip deflection / (PL^3/3EI) = {w / w_ref:.9f}, "
          f"rotation / (PL^2/2EI) = {t / t_ref:.9f}, kinetic energy {thermo['KinEng'][-1]:.1e}")
    # settled (exponential decay) and linear (theta^2 = 2.5e-9): 1e-6
    assert w == pytest.approx(w_ref, rel=1e-6)
    assert t == pytest.approx(t_ref, rel=1e-6)


# ---------------------------------------------------------------------------
# null space and objectivity (cases 1, 3)


def element_stiffness(build, directory, length=1.3, h=1e-5):
    """The 6 x 6 stiffness of one beam at rest (particles at (0, 0) and
    (L, 0)), by central differences of its forces and torques (fx, fy,
    tqz of both ends) in the coordinates (x, y, theta) of both ends."""
    data = beam_data(directory / "beam.data", [(0.0, 0.0), (length, 0.0)], [(0, 1)],
                     ((-3, 4), (-3, 3)))
    script = header(data) + COEFF + """
group           end1 id 1
group           end2 id 2
run             0
"""
    frame = 0
    for atom in (1, 2):
        for dof in ("x", "y", "theta"):
            for sign in (1, -1):
                if dof == "theta":
                    move = f"mca_set end{atom} angle {math.degrees(sign * h):.17g}"
                    back = f"mca_set end{atom} angle 0.0"
                else:
                    step = lambda v: f"{v:.17g} 0" if dof == "x" else f"0 {v:.17g}"
                    move = f"displace_atoms end{atom} move {step(sign * h)} 0 units box"
                    back = f"displace_atoms end{atom} move {step(-sign * h)} 0 units box"
                frame += 1
                script += (f"{move}\nrun             0\nwrite_dump      all custom probe{frame}.dump "
                           f"id fx fy tqz modify format float %.17g sort id\n{back}\n")
    build.run(script, directory)
    frames = [read_dump(directory / f"probe{k}.dump")[0] for k in range(1, frame + 1)]
    rows = [np.concatenate([[f["fx"][a], f["fy"][a], f["tqz"][a]] for a in (0, 1)])
            for f in frames]
    k = np.zeros((6, 6))
    for col in range(6):
        k[:, col] = -(rows[2 * col] - rows[2 * col + 1]) / (2 * h)
    return k


def test_element_has_three_rigid_modes_and_the_frame_stiffness(build, tmp_path):
    """Reference case 1: the stiffness of one Euler-Bernoulli beam at rest
    (central differences of its forces and torques) is the linear frame
    element's (EA/L; 12EI/L^3, 6EI/L^2, 4EI/L, 2EI/L) to 1e-6 of its
    largest entry, symmetric, and has exactly three zero eigenvalues (two
    translations and the rigid rotation: below 1e-6 of the largest, the
    other three above 1e-3 of it)."""
    L, E, A, I = 1.3, 100.0, 0.1, 0.001
    k = element_stiffness(build, tmp_path, L)
    a, b, c, d, e = E * A / L, 12 * E * I / L ** 3, 6 * E * I / L ** 2, 4 * E * I / L, 2 * E * I / L
    frame = np.array([[a, 0, 0, -a, 0, 0],
                      [0, b, c, 0, -b, c],
                      [0, c, d, 0, -c, e],
                      [-a, 0, 0, a, 0, 0],
                      [0, -b, -c, 0, b, -c],
                      [0, c, e, 0, -c, d]])
    scale = np.abs(frame).max()
    eig = np.linalg.eigvalsh(0.5 * (k + k.T))
    print(f"stiffness to {np.abs(k - frame).max() / scale:.1e} of the frame element's, asymmetry "
          f"{np.abs(k - k.T).max() / scale:.1e}; eigenvalues {', '.join(f'{v:.6g}' for v in eig)}")
    assert np.abs(k - frame).max() < 1e-6 * scale
    assert np.abs(k - k.T).max() < 1e-6 * scale
    assert np.sum(np.abs(eig) < 1e-6 * eig.max()) == 3
    assert np.sum(eig > 1e-3 * eig.max()) == 3


def scaled_patch_run(build, directory, s, steps=300):
    """The deformed patch of DEFORM in NVE with every length times s at
    the same E and areal density: A s, I s^3, masses s^2, J s^4, time
    step s (digest R14); the state after `steps` steps."""
    sites, bonds = hex_patch()
    data = beam_data(directory / "patch.data", s * sites, bonds, ((-6 * s, 6 * s),) * 2,
                     radius=0.5 * s, mass=s * s, inertia=0.1 * s ** 4)
    script = header(data).replace("comm_modify     cutoff 2.5",
                                  f"comm_modify     cutoff {2.5 * s!r}") + f"""
bond_style      beam
bond_coeff      1 100.0 {0.1 * s!r} {0.001 * s ** 3!r} shear 40.0 0.8333333333333334
run             0 post no
variable        dx atom {0.03 * s!r}*sin(3.1*id)
variable        dy atom {0.04 * s!r}*cos(2.3*id)
variable        th atom 6.0*sin(1.3*id)
displace_atoms  all move v_dx v_dy 0.0
mca_set         all angle v_th
fix             1 all nve/mca
fix             2 all enforce2d
timestep        {0.002 * s!r}
thermo_style    custom step pe ke
thermo_modify   norm no format float %.17g
thermo          {steps}
dump            d all custom {steps} state.dump id x y vx vy omegaz fx fy tqz
dump_modify     d format float %.17g sort id
run             {steps}
"""
    build.run(script, directory)
    return read_dump(directory / "state.dump")[-1], thermo_pe(directory)


def test_lengths_scale_out(build, tmp_path):
    """Scale invariance (digest R14; Howto_mlp, "Units and scale"): with
    every length times s = 2.5 at the same E and areal density (sections
    A s, I s^3, masses s^2, moments of inertia s^4) the lattice runs the
    same motion in the time step times s: after 300 steps the positions
    are s times, the velocities the same, the spins 1/s times, the forces
    s times, the torques and energies s^2 times those of the unscaled
    patch (to 1e-11: round-off of the scaled arithmetic; measured 1.1e-13)."""
    s = 2.5
    ref, t_ref = scaled_patch_run(build, tmp_path / "one", 1.0)
    big, t_big = scaled_patch_run(build, tmp_path / "scaled", s)
    factors = {"x": s, "y": s, "vx": 1.0, "vy": 1.0, "omegaz": 1.0 / s, "fx": s, "fy": s,
               "tqz": s * s}
    worst = 0.0
    for name, factor in factors.items():
        diff = np.abs(big[name] - factor * ref[name]).max() / np.abs(factor * ref[name]).max()
        worst = max(worst, diff)
    energy = abs(t_big["PotEng"][-1] - s * s * t_ref["PotEng"][-1]) / abs(t_ref["PotEng"][-1] * s * s)
    print(f"scaled by {s}: largest relative difference {worst:.1e}, energy {energy:.1e}")
    assert np.abs(ref["vx"]).max() > 1e-3    # it moves
    assert worst < 1e-11 and energy < 1e-11


@pytest.mark.parametrize("coeff", [COEFF, COEFF_SHEAR, COEFF_SPRINGS],
                         ids=["euler", "timoshenko", "shearbeam"])
def test_rigid_motion_keeps_energy_and_turns_forces(build, tmp_path, coeff):
    sites, bonds = hex_patch()
    data = beam_data(tmp_path / "patch.data", sites, bonds, ((-6, 6), (-6, 6)))
    base = header(data) + coeff + DEFORM
    ref = snapshot(build, tmp_path / "a", base)
    e_ref = thermo_pe(tmp_path / "a")["PotEng"][-1]

    # the deformed patch moved rigidly: turned by 90 degrees about (0.3, -0.2)
    # with its particles, then translated
    turned = base + """
fix             xy all store/state 0 x y
variable        ux atom 0.3-(f_xy[2]+0.2)+1.1-f_xy[1]
variable        uy atom -0.2+(f_xy[1]-0.3)-0.7-f_xy[2]
variable        tr atom v_th+90.0
displace_atoms  all move v_ux v_uy 0.0
mca_set         all angle v_tr
"""
    # (the coordinates before the move: displace_atoms moves along x first)
    rot = snapshot(build, tmp_path / "b", turned)
    e_rot = thermo_pe(tmp_path / "b")["PotEng"][-1]
    scale = np.abs(np.stack([ref["fx"], ref["fy"]])).max()
    assert scale > 1e-2    # the patch is deformed
    df = max(np.abs(rot["fx"] + ref["fy"]).max(), np.abs(rot["fy"] - ref["fx"]).max()) / scale
    dt = np.abs(rot["tqz"] - ref["tqz"]).max() / np.abs(ref["tqz"]).max()
    print(f"energy {e_ref:.6e} / {e_rot:.6e}; turned force, torque differences {df:.1e}, {dt:.1e}")
    assert e_rot == pytest.approx(e_ref, rel=1e-12)
    assert df < 1e-12 and dt < 1e-12

    # undeformed, turned by 90 degrees and moved: no force (case 1 and 3)
    still = header(data) + coeff + """
run             0 post no
fix             xy all store/state 0 x y
variable        ux atom -f_xy[2]+1.1-f_xy[1]
variable        uy atom f_xy[1]-0.7-f_xy[2]
displace_atoms  all move v_ux v_uy 0.0
mca_set         all angle 90.0
"""
    snap = snapshot(build, tmp_path / "c", still)
    print(f"undeformed, turned: largest force {np.abs(np.stack([snap['fx'], snap['fy']])).max():.1e},"
          f" torque {np.abs(snap['tqz']).max():.1e}")
    assert np.abs(np.stack([snap["fx"], snap["fy"]])).max() < 1e-12 * scale
    assert np.abs(snap["tqz"]).max() < 1e-12 * np.abs(ref["tqz"]).max()


# ---------------------------------------------------------------------------
# energy conservation (case 5)


def nve_run(build, directory, dt, steps, extra_args=(), nprocs=1, newton="on", tail=""):
    """The deformed patch let go in NVE; thermo pe, ke, rotational ke (J = 0.1)."""
    sites, bonds = hex_patch()
    data = beam_data(directory / "patch.data", sites, bonds, ((-6, 6), (-6, 6)))
    script = header(data, newton=newton) + COEFF + DEFORM + f"""
fix             1 all nve/mca
fix             2 all enforce2d
compute         w all property/atom omegaz
variable        er atom 0.5*0.1*c_w*c_w
compute         rke all reduce sum v_er
variable        etot equal pe+ke+c_rke
timestep        {dt}
thermo_style    custom step pe ke c_rke v_etot
thermo_modify   norm no format float %.17g
thermo          {max(steps // 40, 1)}
dump            d all custom {steps} traj.dump id x y vx vy omegaz
dump_modify     d format float %.17g
""" + (tail or f"run {steps}\n")
    build.run(script, directory, extra_args=extra_args, nprocs=nprocs)
    return mcatest.read_thermo(directory / "log.lammps"), read_dump(directory / "traj.dump")


def test_energy_and_momenta_are_conserved(build, tmp_path):
    drifts = []
    for k, (dt, steps) in enumerate(((0.004, 500), (0.002, 1000))):
        thermo, snaps = nve_run(build, tmp_path / f"dt{k}", dt, steps)
        e = thermo["v_etot"]
        drifts.append(np.abs(e - e[0]).max() / thermo["PotEng"][0])
        end = snaps[-1]
        p = np.array([end["vx"].sum(), end["vy"].sum()])
        lz = (end["x"] * end["vy"] - end["y"] * end["vx"]).sum() + 0.1 * end["omegaz"].sum()
        vscale = np.abs(np.stack([end["vx"], end["vy"]])).max()
        print(f"dt {dt}: energy error / E_pot(0) {drifts[-1]:.2e}, momentum {np.abs(p).max():.1e},"
              f" angular momentum {lz:.1e} (velocity scale {vscale:.2e}),"
              f" kinetic share at the end {thermo['KinEng'][-1] / thermo['PotEng'][0]:.2f}")
        assert thermo["KinEng"].max() > 0.1 * thermo["PotEng"][0]    # it does move
        assert np.abs(p).max() < 1e-12 * vscale * len(end["vx"])
        assert abs(lz) < 1e-12 * vscale * len(end["vx"]) * 4.0
    # velocity Verlet: the energy error falls as dt^2
    print(f"error ratio dt / dt/2: {drifts[0] / drifts[1]:.2f}")
    assert drifts[0] < 1e-3
    assert 3.2 < drifts[0] / drifts[1] < 4.8


# ---------------------------------------------------------------------------
# hexagonal lattice moduli (case 7)


def lattice_moduli(build, directory, coeff_words, strain=1.0e-6, length=1.0, diameter=0.5):
    """E_2D and nu_2D of a periodic hexagonal lattice of bonds from its stress
    under a uniaxial strain (the nodes of a Bravais lattice do not turn)."""
    nx, ny = 6, 4
    sites = []
    for j in range(ny):
        for i in range(nx):
            sites.append((i * length, j * SQRT3 * length))
            sites.append(((i + 0.5) * length, (j + 0.5) * SQRT3 * length))
    sites = np.array(sites) + 0.25
    lx, ly = nx * length, ny * SQRT3 * length
    bonds = set()
    for a in range(len(sites)):
        for b in range(a + 1, len(sites)):
            d = sites[b] - sites[a]
            d -= np.array([lx, ly]) * np.round(d / np.array([lx, ly]))
            if np.hypot(*d) < 1.01 * length:
                bonds.add((a, b))
    data = beam_data(directory / "lattice.data", sites, sorted(bonds), ((0, lx), (0, ly)),
                     radius=diameter)
    script = header(data, "p p p") + f"""
bond_style      beam
bond_coeff      1 {coeff_words}
thermo_style    custom step pxx pyy pxy
thermo_modify   norm no format float %.17g
run             0 post no
change_box      all x scale {1.0 + strain} remap
run             0 post no
"""
    build.run(script, directory)
    thermo = mcatest.read_thermo(directory / "log.lammps")
    # 2-D pressure = -stress (force per length); C11 = sxx / exx, C12 = syy / exx
    c11, c12 = -thermo["Pxx"][-1] / strain, -thermo["Pyy"][-1] / strain
    return (c11 * c11 - c12 * c12) / c11, c12 / c11


def calibration_tool():
    import sys
    sys.path.insert(0, str(mcatest.ROOT / "tools"))
    import lattice_calibration
    return lattice_calibration


@pytest.mark.parametrize("h_over_l", [0.1, 0.3, 0.6])
def test_hexagonal_beam_lattice_moduli(build, tmp_path, h_over_l):
    lc = calibration_tool()
    e, length = 50.0, 1.0
    area, inertia = h_over_l * length, (h_over_l * length) ** 3 / 12.0
    e2, nu2 = lattice_moduli(build, tmp_path, f"{e} {area} {inertia}")
    kn, ks = lc.beam_stiffness(e, area, inertia, length)
    ref = lc.beam_moduli(kn, ks)
    e2_ref, nu2_ref = ref["E2"], ref["nu2"]
    print(f"h/L {h_over_l}: E_2D {e2:.8f} (tool {e2_ref:.8f}), nu_2D {nu2:.8f} (tool {nu2_ref:.8f},"
          f" rectangular section {lc.rectangular_beam_nu2(h_over_l):.8f})")
    # (strain 1e-6: the geometric nonlinearity is of that order)
    assert e2 == pytest.approx(e2_ref, rel=1e-5)
    assert nu2 == pytest.approx(nu2_ref, rel=1e-5, abs=1e-7)
    assert nu2 == pytest.approx(lc.rectangular_beam_nu2(h_over_l), rel=1e-5, abs=1e-7)


@pytest.mark.parametrize("target", [(5.0, 0.25), (2.0, 0.0), (1.0, -0.5)])
def test_shear_beam_lattice_has_the_calibrated_moduli(build, tmp_path, target):
    """The shear beam (digest A.4): k_n and k_r from the tool's mapping for
    a target E_2D, nu_2D (k_s = 2 k_r / L0^2) give that lattice."""
    lc = calibration_tool()
    e2_target, nu2_target = target
    kn, ks = lc.beam_springs(e2_target, nu2_target)
    kr = lc.shear_beam_kr(ks, 1.0)
    e2, nu2 = lattice_moduli(build, tmp_path, f"shearbeam {kn:.17g} {kr:.17g}")
    print(f"target E_2D {e2_target}, nu_2D {nu2_target}: k_n {kn:.6f}, k_r {kr:.6f}; "
          f"lattice E_2D {e2:.8f}, nu_2D {nu2:.8f}")
    assert e2 == pytest.approx(e2_target, rel=1e-5)
    assert nu2 == pytest.approx(nu2_target, rel=1e-5, abs=1e-6)


# ---------------------------------------------------------------------------
# newton_bond, MPI ranks, restart


def test_forces_independent_of_newton_and_ranks(build, tmp_path):
    sites, bonds = hex_patch()
    data = beam_data(tmp_path / "patch.data", sites, bonds, ((-6, 6), (-6, 6)))
    runs = {}
    for newton in ("on", "off"):
        for nprocs in (1, 2, 4):
            d = tmp_path / f"{newton}{nprocs}"
            runs[newton, nprocs] = snapshot(build, d, header(data, newton=newton)
                                            + COEFF_SHEAR + DEFORM, nprocs=nprocs)
    ref = runs["on", 1]
    scale = np.abs(np.stack([ref["fx"], ref["fy"], ref["tqz"]])).max()
    for key, snap in runs.items():
        diff = np.abs(np.stack([snap["fx"] - ref["fx"], snap["fy"] - ref["fy"],
                                snap["tqz"] - ref["tqz"]])).max() / scale
        print(f"newton_bond {key[0]}, {key[1]} ranks: {diff:.1e}")
        assert diff < 1e-13


def test_ranks_and_restart_follow_one_run(build, tmp_path):
    steps = 400
    _, one = nve_run(build, tmp_path / "one", 0.004, steps)
    _, two = nve_run(build, tmp_path / "two", 0.004, steps, nprocs=2)
    _, four = nve_run(build, tmp_path / "four", 0.004, steps, nprocs=4)
    _, split = nve_run(build, tmp_path / "split", 0.004, steps,
                       tail=f"run {steps // 2}\nwrite_restart half.restart\n")
    restart = f"""
units           lj
dimension       2
read_restart    half.restart
comm_modify     cutoff 2.5
fix             1 all nve/mca
fix             2 all enforce2d
timestep        0.004
reset_timestep  {steps // 2}
dump            d all custom {steps} traj.dump id x y vx vy omegaz
dump_modify     d format float %.17g
run             {steps // 2}
"""
    build.run(restart, tmp_path / "split")
    resumed = read_dump(tmp_path / "split" / "traj.dump")[-1]
    ref = one[-1]
    for name, snap in (("2 ranks", two[-1]), ("4 ranks", four[-1]), ("restart", resumed)):
        diff = max(np.abs(snap[c] - ref[c]).max() / np.abs(ref[c]).max()
                   for c in ("x", "y", "vx", "vy", "omegaz"))
        print(f"{name}: largest relative difference after {steps} steps {diff:.1e}")
        assert diff < 1e-10


# ---------------------------------------------------------------------------
# Kokkos


PER_ATOM = """
compute         pe all pe/atom bond
compute         st all stress/atom NULL bond
thermo_style    custom step pe press pxx pyy pxy
"""


@pytest.mark.parametrize("threads", [1, 2])
@pytest.mark.parametrize("newton", ["on", "off"])
def test_kokkos_variant_matches_the_cpu_style(tmp_path, threads, newton):
    kk = mcatest.kokkos_build()
    sites, bonds = hex_patch()
    data = beam_data(tmp_path / "patch.data", sites, bonds, ((-6, 6), (-6, 6)))
    script = header(data, newton=newton) + COEFF_SHEAR + DEFORM + PER_ATOM
    script += ("thermo_modify   norm no format float %.17g\n"
               f"dump d all custom 1 state.dump {DUMP} c_pe c_st[1] c_st[2] c_st[4]\n"
               "dump_modify d format float %.17g\nrun 0 post no\n")
    kk.run(script, tmp_path / "cpu")
    kk.run(script, tmp_path / "kk", extra_args=mcatest.kokkos_args(threads))
    cpu, gpu = (read_dump(tmp_path / d / "state.dump")[0] for d in ("cpu", "kk"))
    worst = 0.0
    for column in ("fx", "fy", "tqz", "c_pe", "c_st[1]", "c_st[2]", "c_st[4]"):
        diff = np.abs(gpu[column] - cpu[column]).max() / np.abs(cpu[column]).max()
        worst = max(worst, diff)
    t_cpu, t_kk = (mcatest.read_thermo(tmp_path / d / "log.lammps") for d in ("cpu", "kk"))
    for name in ("PotEng", "Press", "Pxx", "Pyy", "Pxy"):
        worst = max(worst, abs(t_kk[name][-1] - t_cpu[name][-1]) / abs(t_cpu[name][-1]))
    print(f"kk {threads} thread(s), newton_bond {newton}: largest relative difference {worst:.1e}")
    # one thread adds in the CPU style's order; two threads in another
    assert worst < (1e-15 if threads == 1 else 1e-12)


def test_kokkos_trajectory_follows_the_cpu_style(tmp_path):
    kk = mcatest.kokkos_build()
    steps = 400
    _, cpu = nve_run(kk, tmp_path / "cpu", 0.004, steps)
    _, dev = nve_run(kk, tmp_path / "kk", 0.004, steps, extra_args=mcatest.kokkos_args(2))
    diff = max(np.abs(dev[-1][c] - cpu[-1][c]).max() / np.abs(cpu[-1][c]).max()
               for c in ("x", "y", "vx", "vy", "omegaz"))
    print(f"kk 2 threads, {steps} NVE steps: largest relative difference {diff:.1e}")
    assert diff < 1e-10


# ---------------------------------------------------------------------------
# bad input


BAD = [
    ("E", "bond_coeff 1 0.0 0.1 0.001", r"Bond_coeff beam: E = 0 must be > 0"),
    ("A", "bond_coeff 1 1.0 -0.1 0.001", r"Bond_coeff beam: A = -0.1 must be > 0"),
    ("I", "bond_coeff 1 1.0 0.1 0", r"Bond_coeff beam: I = 0 must be > 0"),
    ("G", "bond_coeff 1 1.0 0.1 0.001 shear 0 0.8", r"shear G = 0 must be > 0"),
    ("ks", "bond_coeff 1 1.0 0.1 0.001 shear 1 1.5", r"shear ks = 1.5 must be in \(0, 1\]"),
    ("keyword", "bond_coeff 1 1.0 0.1 0.001 timoshenko", r"unknown keyword 'timoshenko'"),
    ("kn", "bond_coeff 1 shearbeam 0 1", r"Bond_coeff beam: shearbeam kn = 0 must be > 0"),
    ("kr", "bond_coeff 1 shearbeam 1 -1", r"Bond_coeff beam: shearbeam kr = -1 must be > 0"),
    ("shearbeam shear", "bond_coeff 1 shearbeam 1 1 shear 1 0.8",
     r"shear \(Timoshenko\) applies to beams"),
    ("shearbeam bending", "bond_coeff 1 shearbeam 1 1 break 1 1 bending 0.1",
     r"bending \(a fibre stress\) needs a beam section"),
    ("bending alone", "bond_coeff 1 1.0 0.1 0.001 bending 0.1",
     r"bending, mohr, scatter and criterion need the break keyword"),
    ("mohr angle", "bond_coeff 1 1.0 0.1 0.001 break 1 1 mohr 90",
     r"mohr friction angle = 90 must be in \[0, 90\) degrees"),
    ("scatter kind", "bond_coeff 1 1.0 0.1 0.001 break 1 1 scatter normal 0.1 5",
     r"scatter normal is unknown \(allowed: uniform, weibull\)"),
    ("scatter width", "bond_coeff 1 1.0 0.1 0.001 break 1 1 scatter uniform 1.0 5",
     r"scatter uniform width = 1 must be in \[0, 1\)"),
    ("scatter seed", "bond_coeff 1 1.0 0.1 0.001 break 1 1 scatter weibull 5 0",
     r"scatter seed = 0 must be > 0"),
    ("missing", "bond_coeff 1 1.0 0.1", r"[Mm]issing argument|Illegal"),
    ("type", "bond_coeff 3 1.0 0.1 0.001", r"[Nn]umeric index 3 is out of bounds"),
]


def expect_error(build, directory, dim, lines, message):
    """Two bonded particles (2-D or 3-D), bond_style beam, then `lines` and
    a run: LAMMPS must stop with an ERROR matching `message` (the bad-input
    tests of all beam test files)."""
    if dim == 2:
        data = beam_data(directory / "pair.data", [(0.0, 0.0), (1.0, 0.0)], [(0, 1)],
                         ((-2, 3), (-2, 2)))
        script = header(data)
    else:
        import test_bond_beam_3d as beam3d
        data = beam3d.beam_data(directory / "pair.data", [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0)],
                                [(0, 1)], ((-2, 3), (-2, 2), (-2, 2)))
        script = beam3d.header(data)
    result = build.run(script + "bond_style beam\n" + lines + "\nrun 0\n", directory,
                       check=False)
    out = result.stdout + result.stderr
    assert result.returncode != 0
    assert "ERROR" in out and re.search(message, out), out[-800:]


@pytest.mark.parametrize("case", BAD, ids=[c[0] for c in BAD])
def test_bad_coefficients_give_clear_errors(build, tmp_path, case):
    expect_error(build, tmp_path, 2, case[1], case[2])


def test_wrong_atom_style_gives_a_clear_error(build, tmp_path):
    cases = [
        ("""units lj
dimension 2
atom_style bond
region box block 0 4 0 4 -0.5 0.5
create_box 1 box bond/types 1 extra/bond/per/atom 1
create_atoms 1 single 1 1 0
create_atoms 1 single 2 1 0
mass 1 1.0
create_bonds single/bond 1 1 2
bond_style beam
bond_coeff 1 1.0 0.1 0.001
run 0
""", r"Bond style beam requires atom_style mca \(its quaternions"),
    ]
    for k, (script, message) in enumerate(cases):
        result = build.run(script, tmp_path / str(k), check=False)
        out = result.stdout + result.stderr
        assert result.returncode != 0 and re.search(message, out), out[-800:]


# ---------------------------------------------------------------------------
# breaking (digest A.5): the elliptic criterion at its threshold


E_, A_, I_, L_ = 100.0, 0.1, 0.001, 1.0
SIGMA0, TAU0, FIBRE, PHI = 0.2, 0.1, 0.05, 30.0


def threshold_probe(build, directory, coeff_words, move, below, above, reverse=False):
    """Two particles (the first one at the origin), bonded along x; `move`
    takes a value and gives the commands that deform the bond to it.  The
    bond must hold at `below` and break at `above`; returns the bond counts."""
    data = beam_data(directory / "pair.data", [(0.0, 0.0), (L_, 0.0)],
                     [(1, 0) if reverse else (0, 1)], ((-2, 3), (-2, 2)))
    script = header(data) + f"""
bond_style      beam
bond_coeff      1 {E_} {A_} {I_} {coeff_words}
thermo_style    custom step bonds ebond
run             0 post no
"""
    for value in (below, above):
        script += move(value) + "run 0 post no\nprint \"BONDS $(bonds)\"\n"
    result = build.run(script, directory)
    return [int(line.split()[1]) for line in result.stdout.splitlines()
            if line.startswith("BONDS")]


def pull(u):
    return f"group end id 2\ndisplace_atoms end move {u:.17g} 0 0\ngroup end delete\n"


def turn(theta):
    # the first particle turned by theta (radians), in pure bending
    return f"group first id 1\nmca_set first angle {math.degrees(theta):.17g}\ngroup first delete\n"


def squeeze_and_turn(u, theta):
    return lambda t: f"set atom 2 x {L_ - u:.17g}\n" + turn(t)


@pytest.mark.parametrize("stored_by", ["lower", "higher"])
def test_tension_breaks_at_sigma0(build, tmp_path, stored_by):
    u_star = SIGMA0 * L_ / E_    # N / A = E u / L0
    # (pull moves the end by its argument: the second step adds 2e-9 u*)
    counts = threshold_probe(build, tmp_path, f"break {SIGMA0} {TAU0}", pull,
                             u_star * (1 - 1e-9), u_star * 2e-9, reverse=stored_by == "higher")
    assert counts == [1, 0]


@pytest.mark.parametrize("bending", [False, True])
def test_bending_and_shear_break_on_the_ellipse(build, tmp_path, bending):
    # one end turned by theta: q_i = theta, M_i = 4 EI theta / L,
    # V = 6 EI theta / L^2, N = 0; sigma = fibre M_i / I, tau = V / A
    shear = 6 * E_ * I_ / (A_ * L_ ** 2 * TAU0)
    normal = 4 * E_ * FIBRE / (L_ * SIGMA0) if bending else 0.0
    theta_star = 1.0 / math.hypot(normal, shear)
    words = f"break {SIGMA0} {TAU0}" + (f" bending {FIBRE}" if bending else "")
    counts = threshold_probe(build, tmp_path, words, turn, theta_star * (1 - 1e-9),
                             theta_star * (1 + 1e-9))
    print(f"bending {bending}: theta* = {math.degrees(theta_star):.6f} deg, bonds {counts}")
    assert counts == [1, 0]


@pytest.mark.parametrize("mohr", [False, True])
def test_compression_strengthens_shear_with_mohr_coulomb(build, tmp_path, mohr):
    # squeezed by u (sigma = -E u / L0 < 0), then turned: only tau counts
    # (tension only), against tau0 or tau0 - sigma tan(phi)
    u = 0.5 * SIGMA0 * L_ / E_
    sigma = -E_ * u / L_
    tau_limit = TAU0 - sigma * math.tan(math.radians(PHI)) if mohr else TAU0
    theta_star = tau_limit * A_ * (L_ - u) ** 2 / (6 * E_ * I_) * (L_ / (L_ - u))
    # (V = (M_i + M_j) / L with the current length and k = EI / L0)
    words = f"break {SIGMA0} {TAU0}" + (f" mohr {PHI}" if mohr else "")
    counts = threshold_probe(build, tmp_path, words, squeeze_and_turn(u, 0.0),
                             theta_star * (1 - 1e-9), theta_star * (1 + 1e-9))
    print(f"mohr {mohr}: theta* = {math.degrees(theta_star):.6f} deg, bonds {counts}")
    assert counts == [1, 0]


@pytest.mark.parametrize("scatter", ["uniform 0.4", "weibull 6.0"])
def test_strength_scatter_has_its_distribution(build, tmp_path, scatter):
    """400 separate beams pulled together: the share broken at u = s u*
    is the distribution function of the strength factor."""
    pairs = 400
    sites = [(x, 3.0 * k) for k in range(pairs) for x in (0.0, L_)]
    data = beam_data(tmp_path / "pairs.data", sites, [(2 * k, 2 * k + 1) for k in range(pairs)],
                     ((-2, 3), (-2, 3.0 * pairs)))
    u_star = SIGMA0 * L_ / E_
    levels = np.linspace(0.5, 1.5, 21)
    script = header(data) + f"""
bond_style      beam
bond_coeff      1 {E_} {A_} {I_} break {SIGMA0} {TAU0} scatter {scatter} 4321
run             0 post no
variable        right atom x>0.5
group           right variable right
"""
    previous = 0.0
    for s in levels:
        script += (f"displace_atoms right move {(s - previous) * u_star:.17g} 0 0\n"
                   "run 0 post no\nprint \"BONDS $(bonds)\"\n")
        previous = s
    result = build.run(script, tmp_path)
    intact = np.array([int(line.split()[1]) for line in result.stdout.splitlines()
                       if line.startswith("BONDS")])
    broken = 1.0 - intact / pairs
    kind, value = scatter.split()
    value = float(value)
    if kind == "uniform":
        expected = np.clip((levels - (1 - value)) / (2 * value), 0.0, 1.0)
    else:
        expected = 1.0 - np.exp(-(levels * math.gamma(1 + 1 / value)) ** value)
    bound = 4.0 * np.sqrt(expected * (1 - expected) / pairs) + 1.0 / pairs
    print(f"{scatter}: largest |broken - F(s)| {np.abs(broken - expected).max():.3f} "
          f"(4 sigma {bound.max():.3f}); broken at s = 1: {broken[10]:.3f} (F {expected[10]:.3f})")
    assert np.all(np.abs(broken - expected) <= bound)
    assert np.all(np.diff(intact) <= 0)    # a broken bond stays broken


# ---------------------------------------------------------------------------
# a strip torn apart: the same broken bonds on any number of ranks, with
# newton_bond on or off, after a restart, and with the Kokkos variant


# the free particles integrated, the right edge pulled at 0.003 (the left
# one held): the run after the groups are made, or after a restart
STRIP_DYNAMICS = """
group           free subtract all left right
fix             1 free nve/mca
fix             2 right move linear 0.003 0.0 0.0
fix             3 all enforce2d
timestep        0.02
thermo_style    custom step bonds ebond ke
thermo_modify   norm no format float %.17g
thermo          20
dump            d all custom {every} strip.dump id x y vx vy omegaz
dump_modify     d format float %.17g
"""


WRITE_FINAL = "write_data final.data\n"


def bonds_in_data(path):
    """The bond count of a data file's header and the lines of its Bonds section."""
    text = path.read_text()
    header = int(re.search(r"^(\d+) bonds$", text, re.M).group(1))
    section = text[text.index("\nBonds") + 1:].split("\n\n")[1]
    return header, len([line for line in section.splitlines() if line.strip()])


STRIP_COEFF = f"{E_} {A_} {I_} break {SIGMA0} {TAU0} bending {FIBRE} scatter uniform 0.3 77"


def strip_run(build, directory, nprocs=1, newton="on", extra_args=(), tail="", extra="",
              coeff=STRIP_COEFF):
    nx, ny = 14, 4
    sites = []
    for j in range(2 * ny):
        for i in range(nx):
            sites.append((i + 0.5 * (j % 2), j * SQRT3 / 2))
    sites = np.array(sites)
    d = np.hypot(sites[:, None, 0] - sites[None, :, 0], sites[:, None, 1] - sites[None, :, 1])
    # each bond stored by its higher-ID atom (the count of broken bonds must
    # not depend on which atom holds a bond)
    bonds = [(b, a) for a in range(len(sites)) for b in range(a + 1, len(sites)) if d[a, b] < 1.01]
    data = beam_data(directory / "strip.data", sites, bonds, ((-1, 16), (-1, 8)))
    script = header(data, newton=newton, extra=extra) + f"""
bond_style      beam
bond_coeff      1 {coeff}
variable        left atom x<0.4
variable        right atom x>{nx - 1.1}
group           left variable left
group           right variable right
""" + STRIP_DYNAMICS.format(every=2000) + (tail or "run 2000\n" + WRITE_FINAL)
    build.run(script, directory, nprocs=nprocs, extra_args=extra_args)
    thermo = mcatest.read_thermo(directory / "log.lammps")
    if (directory / "final.data").exists():
        # thermo's count (atom->nbonds, lowered when bonds break) is the bonds left
        header_count, listed = bonds_in_data(directory / "final.data")
        assert header_count == listed == int(thermo["Bonds"][-1])
    return thermo, read_dump(directory / "strip.dump")


def compare_strips(ref, other, name):
    (t_ref, d_ref), (t_other, d_other) = ref, other
    steps = np.intersect1d(t_ref["Step"], t_other["Step"])
    a = t_ref["Bonds"][np.isin(t_ref["Step"], steps)]
    b = t_other["Bonds"][np.isin(t_other["Step"], steps)]
    end_ref, end = d_ref[-1], d_other[-1]
    diff = max(np.abs(end[c] - end_ref[c]).max() / np.abs(end_ref[c]).max()
               for c in ("x", "y", "vx", "vy", "omegaz"))
    print(f"{name}: bonds {int(a[0])} -> {int(a[-1])} (same history: {np.array_equal(a, b)}),"
          f" largest relative difference at the end {diff:.1e}")
    assert np.array_equal(a, b)
    assert diff < 1e-9


def strip_on_ranks_newton_and_restart(build, directory, coeff=STRIP_COEFF, split=1000):
    """The strip on 1 rank, then on 2 ranks and with newton_bond off, and
    continued from a restart file written at step `split`: the same
    bond counts at every thermo step and the same end state (1e-9)."""
    ref = strip_run(build, directory / "ref", coeff=coeff)
    assert ref[0]["Bonds"][-1] < ref[0]["Bonds"][0] - 5    # it does tear
    for nprocs, newton in ((2, "on"), (1, "off"), (2, "off")):
        compare_strips(ref, strip_run(build, directory / f"{nprocs}{newton}", nprocs, newton,
                                      coeff=coeff),
                       f"{nprocs} ranks, newton_bond {newton}")
    strip_run(build, directory / "split", tail=f"run {split}\nwrite_restart half.restart\n",
              coeff=coeff)
    restart = """
units           lj
dimension       2
read_restart    half.restart
comm_modify     cutoff 2.5
""" + STRIP_DYNAMICS.format(every=2000) + f"run {2000 - split}\n" + WRITE_FINAL
    build.run(restart, directory / "split")
    header_count, listed = bonds_in_data(directory / "split" / "final.data")
    resumed = (mcatest.read_thermo(directory / "split" / "log.lammps"),
               read_dump(directory / "split" / "strip.dump"))
    assert header_count == listed == int(resumed[0]["Bonds"][-1])
    compare_strips(ref, resumed, f"restart at step {split}")
    return ref


def test_torn_strip_is_the_same_on_ranks_newton_and_restart(build, tmp_path):
    strip_on_ranks_newton_and_restart(build, tmp_path)


def test_kokkos_strip_tears_as_the_cpu_style(tmp_path):
    kk = mcatest.kokkos_build()
    ref = strip_run(kk, tmp_path / "cpu")
    compare_strips(ref, strip_run(kk, tmp_path / "kk", extra_args=mcatest.kokkos_args(2)),
                   "kk 2 threads")


# ---------------------------------------------------------------------------
# fix nve/damped on beam particles (automata: their J, the orientation
# turned as fix nve/mca does)


def damped_patch(build, directory, integrator, steps=400, extra_args=()):
    sites, bonds = hex_patch()
    data = beam_data(directory / "patch.data", sites, bonds, ((-6, 6), (-6, 6)))
    script = header(data) + COEFF + DEFORM + f"""
fix             1 all {integrator}
fix             2 all enforce2d
compute         w all property/atom omegaz
variable        er atom 0.5*0.1*c_w*c_w
compute         rke all reduce sum v_er
variable        etot equal pe+ke+c_rke
timestep        0.004
thermo_style    custom step pe ke c_rke v_etot ecouple
thermo_modify   norm no format float %.17g
thermo          10
dump            d all custom {steps} traj.dump id x y vx vy omegaz
dump_modify     d format float %.17g
run             {steps}
"""
    build.run(script, directory, extra_args=extra_args)
    return mcatest.read_thermo(directory / "log.lammps"), read_dump(directory / "traj.dump")


def test_damped_integrator_without_damping_is_nve_mca(build, tmp_path):
    _, ref = damped_patch(build, tmp_path / "mca", "nve/mca")
    _, damped = damped_patch(build, tmp_path / "damped", "nve/damped 0.0")
    diff = max(np.abs(damped[-1][c] - ref[-1][c]).max() / np.abs(ref[-1][c]).max()
               for c in ("x", "y", "vx", "vy", "omegaz"))
    print(f"nve/damped 0 against nve/mca after 400 steps: {diff:.1e}")
    # the same steps; (dt/m) f against dt (f/m): round-off
    assert diff < 1e-11


def test_damped_integrator_balances_the_energy_of_beams(build, tmp_path):
    free, _ = damped_patch(build, tmp_path / "free", "nve/damped 0.0", steps=1000)
    thermo, _ = damped_patch(build, tmp_path / "damped", "nve/damped 0.5 angular 2.0", steps=1000)
    e = thermo["v_etot"]
    balance = e + thermo["Ecouple"] - e[0]
    verlet = np.abs(free["v_etot"] - free["v_etot"][0]).max()
    print(f"energy {e[0]:.6f} -> {e[-1]:.6f}, dissipated {thermo['Ecouple'][-1]:.6f}, "
          f"balance error {np.abs(balance).max() / e[0]:.1e} (undamped energy error "
          f"{verlet / e[0]:.1e})")
    assert e[-1] < 0.2 * e[0]    # damped
    # the tally is exact to O((gamma dt)^2) per step: what remains is the
    # energy error of velocity Verlet, as without damping
    assert np.abs(balance).max() < 1.5 * verlet


def test_damped_integrator_kokkos_matches_the_cpu_fix(tmp_path):
    kk = mcatest.kokkos_build()
    t_cpu, cpu = damped_patch(kk, tmp_path / "cpu", "nve/damped 0.5 angular 2.0")
    t_kk, dev = damped_patch(kk, tmp_path / "kk", "nve/damped 0.5 angular 2.0",
                             extra_args=mcatest.kokkos_args(2))
    diff = max(np.abs(dev[-1][c] - cpu[-1][c]).max() / np.abs(cpu[-1][c]).max()
               for c in ("x", "y", "vx", "vy", "omegaz"))
    de = abs(t_kk["Ecouple"][-1] - t_cpu["Ecouple"][-1]) / t_cpu["Ecouple"][-1]
    print(f"nve/damped/kk 2 threads: trajectory {diff:.1e}, dissipated energy {de:.1e}")
    assert diff < 1e-10 and de < 1e-10


def test_data_file_keeps_every_coefficient(build, tmp_path):
    sites, bonds = hex_patch()
    data = beam_data(tmp_path / "patch.data", sites, bonds, ((-6, 6), (-6, 6)))
    data.write_text(data.read_text().replace("1 bond types", "3 bond types"))
    coeffs = ("bond_coeff 1 100.0 0.1 0.001 shear 40.0 0.8 break 0.2 0.1 bending 0.05 mohr 30 "
              "scatter weibull 6 4321\n"
              "bond_coeff 2 shearbeam 10.0 0.05 break 0.02 0.01 scatter uniform 0.3 7\n"
              "bond_coeff 3 50.0 0.2 0.002\n")
    first = header(data) + "bond_style beam\n" + coeffs + DEFORM + "write_data written.data\n"
    build.run(first, tmp_path / "a")
    text = (tmp_path / "a" / "written.data").read_text()
    section = text[text.index("Bond Coeffs"):].split("\n\n")[1]
    second = header(tmp_path / "a" / "written.data").replace("read_data", "bond_style beam\nread_data")
    second += "write_data again.data\n"
    build.run(second, tmp_path / "b")
    again = (tmp_path / "b" / "again.data").read_text()
    print(section)
    assert section == again[again.index("Bond Coeffs"):].split("\n\n")[1]
    for words in ("1 100 0.10000000000000001 0.001 shear 40 0.80000000000000004 break "
                  "0.20000000000000001 0.10000000000000001 bending 0.050000000000000003 mohr 30 "
                  "scatter weibull 6 4321",
                  "2 shearbeam 10 0.050000000000000003 break 0.02 0.01 scatter uniform "
                  "0.29999999999999999 7", "3 50 0.20000000000000001 0.002"):
        assert words in section


# ---------------------------------------------------------------------------
# the example examples/beam_calving: tidal flexure at a grounding line


def test_tidal_flexure_calves_at_the_analytic_tide(build, tmp_path):
    """A beam shelf on a Winkler foundation, clamped at the grounding line:
    the moment there is 2 EI beta^2 w0 and the root bond breaks at the
    elliptic criterion's w0*, both to 0.5 % once the rate's (linear)
    effect is extrapolated away from two tide rates."""
    script = (mcatest.ROOT / "examples" / "beam_calving" / "in.tide").read_text()
    results = {}
    for rate in (0.001, 0.0005):
        out = build.run(script, tmp_path / str(rate), variables={"rate": rate}).stdout
        calved = re.search(r"^CALVED at tide \S+, shelf at (\S+): w0/w0\* = (\S+), "
                           r"bonds left (\d+)", out, re.M)
        # the first run's rows end at the tide of 0.04 (before fix halt): the last one
        log = (tmp_path / str(rate) / "log.lammps").read_text()
        first = log[log.index("Step"):log.index("Loop time")].splitlines()
        names, last = first[0].split(), first[-1].split()
        row = dict(zip(names, map(float, last)))
        results[rate] = (float(calved.group(2)), -row["c_root"] / row["v_M0"])
        assert int(calved.group(3)) == 119    # of 120: the root bond alone
    slow, fast = results[0.0005], results[0.001]
    calve = 2 * slow[0] - fast[0]
    moment = 2 * slow[1] - fast[1]
    print(f"w0/w0* at the break: {fast[0]:.5f} (rate 0.001), {slow[0]:.5f} (0.0005), "
          f"extrapolated {calve:.5f}; root moment / M0 at w0 = 0.04: {fast[1]:.5f}, "
          f"{slow[1]:.5f}, extrapolated {moment:.5f}")
    assert calve == pytest.approx(1.0, abs=5e-3)
    assert moment == pytest.approx(1.0, abs=5e-3)


def test_reference_states_survive_delete_bonds(build, tmp_path):
    """delete_bonds compresses the bond arrays: a bond that moves to
    another slot keeps its reference (found by the partner's ID), so the
    energy left is the energy before less that of the deleted bonds."""
    sites, bonds = hex_patch()
    data = beam_data(tmp_path / "patch.data", sites, bonds, ((-6, 6), (-6, 6)))
    data.write_text(data.read_text().replace("1 atom types", "2 atom types"))
    # the bonds of the particle at the centre are deleted; the other
    # bonds of its neighbours move in their arrays
    centre = int(np.argmin(np.hypot(sites[:, 0], sites[:, 1]))) + 1
    script = header(data) + COEFF_SHEAR + DEFORM + f"""
compute         b all bond/local engpot
compute         p all property/local batom1 batom2
dump            b all local 1 bonds.dump c_b c_p[1] c_p[2]
dump_modify     b format float %.17g
thermo_style    custom step ebond
thermo_modify   norm no format float %.17g
run             0 post no
undump          b
set             atom {centre} type 2
delete_bonds    all atom 2 remove special
run             0 post no
"""
    build.run(script, tmp_path)
    log = (tmp_path / "log.lammps").read_text()
    energies = [float(m) for m in re.findall(r"^\s+0\s+(\S+)\s*$", log, re.M)]
    rows = np.loadtxt(tmp_path / "bonds.dump", skiprows=9, ndmin=2)
    deleted = rows[(rows[:, 1] == centre) | (rows[:, 2] == centre)]
    before, after = energies[-2], energies[-1]
    print(f"energy {before:.12f} -> {after:.12f}; the {len(deleted)} bonds deleted had "
          f"{deleted[:, 0].sum():.12f}; difference {before - after - deleted[:, 0].sum():.1e}")
    assert len(deleted) == 6
    assert before - after == pytest.approx(deleted[:, 0].sum(), rel=1e-10)
