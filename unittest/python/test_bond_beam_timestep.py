"""The stable time step of bond_style beam (doc/src/bond_beam.rst,
"Stable time step"; digest R12) and compute beam/timestep: Gershgorin's
bound of the fastest mode of the lattice, omega^2 <= max_r sum_c |S_rc|
for S = M^-1/2 K M^-1/2 (K: the bonds' stiffness, M: the masses and the
moments of inertia), and the step 2 (sqrt(1 + zeta^2) - zeta) / omega of
velocity Verlet (zeta = beta omega / 2 with bond damping).

* one axial bond between equal particles: its fastest mode is the
  stretch, omega^2 = 2 EA / (L m), and the bound is exact (the rows of a
  two-particle spring have the eigenvalue's sum), so the run is stable at
  0.99 of the estimate and blows up at 1.01 of it, with and without bond
  damping (zeta = 0.5); the warning appears exactly above the estimate;
* hard cases, 2-D and 3-D: a hexagonal patch and a 3-D frame whose
  masses or moments of inertia scatter over two decades (a particle 100
  times lighter than the rest): omega_max from the eigenvalues of M^-1 K,
  assembled here from the textbook frame element (independent of the
  kernel; its null space checked), is below the bound (Gershgorin's
  theorem: always), the bound within 1.6 of it (a measured slack, printed);
  and LAMMPS's runs confirm omega_max: stable at 0.98 x 2 / omega_max,
  unstable at 1.02 x;
* the same estimate on 1, 2 and 4 ranks, newton_bond on and off, and with
  the Kokkos variant (1 and 2 threads), to round-off;
* bad input: clear errors.
"""

import math
import re

import numpy as np
import pytest

import mcatest
import test_bond_beam as beam2d
import test_bond_beam_3d as beam3d

E_, A_, I_, NU = 100.0, 0.1, 0.001, 0.25
G_ = E_ / (2 * (1 + NU))
J3 = 2 * I_


def data_file(path, positions, bonds, masses, inertias, dimension):
    """An atom_style mca data file with a mass and a moment of inertia per
    particle and beams between the pairs of `bonds` (0-based)."""
    box = [(-6, 6)] * 3 if dimension == 3 else [(-6, 6), (-6, 6), (-0.5, 0.5)]
    lines = ["timestep test data", "", f"{len(positions)} atoms", "1 atom types",
             f"{len(bonds)} bonds", "1 bond types", ""]
    lines += [f"{lo} {hi} {a}lo {a}hi" for (lo, hi), a in zip(box, "xyz")]
    lines += ["", "Atoms # mca", ""]
    for k, p in enumerate(positions):
        z = p[2] if dimension == 3 else 0.0
        lines.append(f"{k + 1} 1 1 0 0.5 1.0 {masses[k]!r} {inertias[k]!r} "
                     f"{p[0]!r} {p[1]!r} {z!r}")
    lines += ["", "Bonds", ""]
    lines += [f"{k + 1} 1 {i + 1} {j + 1}" for k, (i, j) in enumerate(bonds)]
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines) + "\n")
    return path


def header(data, dimension, newton="on"):
    return f"""
units           lj
dimension       {dimension}
atom_style      mca
atom_modify     map array
boundary        f f {'f' if dimension == 3 else 'p'}
newton          on {newton}
comm_modify     cutoff 2.5 vel yes
read_data       {data}
"""


def coeff(dimension, damp=None):
    text = f"bond_style beam\nbond_coeff 1 {E_} {A_} {I_}"
    if dimension == 3:
        text += f" poisson {NU} section {I_} {I_} {J3}"
    if damp:
        text += f" damp {damp!r}"
    return text + "\n"


def estimate(build, directory, script, nprocs=1, extra_args=()):
    """The values of compute beam/timestep after `run 0`."""
    script += """
compute         dt all beam/timestep
thermo_style    custom step c_dt c_dt[2] c_dt[3] c_dt[4] c_dt[5]
thermo_modify   format float %.17g
run             0
"""
    build.run(script, directory, nprocs=nprocs, extra_args=extra_args)
    t = mcatest.read_thermo(directory / "log.lammps")
    return {name: t[key][-1] for name, key in
            (("dt", "c_dt"), ("ratio", "c_dt[2]"), ("omega", "c_dt[3]"), ("zeta", "c_dt[4]"),
             ("atom", "c_dt[5]"))}


def halted_run(build, directory, script, dt, steps, dimension):
    """`script` (the motion set up), then `steps` steps at dt with fix
    nve/mca; the run halts when the energy of the translations (kinetic and
    elastic) grows a thousand times (an unstable step).  Returns (steps run,
    largest energy ratio, log text)."""
    script += f"""
fix             1 all nve/mca
{'fix 2 all enforce2d' if dimension == 2 else ''}
timestep        {dt!r}
compute         ke all ke
compute         pe all pe
variable        e equal c_ke+c_pe
thermo_style    custom step v_e
thermo_modify   norm no format float %.17g
thermo          10
run             0
variable        e0 equal $e
fix             halt all halt 10 v_e > $(1000*v_e0) error continue
run             {steps}
"""
    build.run(script, directory)
    t = mcatest.read_thermo(directory / "log.lammps")
    energy = t["v_e"]
    return int(t["Step"][-1]), float(energy.max() / energy[0]), \
        (directory / "log.lammps").read_text()


def dynamics(build, directory, script, dt, steps, dimension, seed=4411):
    """Random small velocities and spins, then halted_run."""
    spin = "0.0 0.0 v_w3" if dimension == 2 else "v_w1 v_w2 v_w3"
    script += "".join(f"variable u{k} atom 1e-3*random(-1,1,{seed + k})\n"
                      f"variable w{k} atom 1e-3*random(-1,1,{seed + 10 + k})\n"
                      for k in (1, 2, 3))
    script += f"""
velocity        all set v_u1 v_u2 {'0.0' if dimension == 2 else 'v_u3'}
set             group all omega {spin}
"""
    return halted_run(build, directory, script, dt, steps, dimension)


# ---------------------------------------------------------------------------
# one axial bond: the bound is exact


def pair_script(directory, damp=None):
    data = data_file(directory / "pair.data", [(0.0, 0.0, 0.0), (1.3, 0.0, 0.0)], [(0, 1)],
                     [1.0, 1.0], [0.1, 0.1], 2)
    return header(data, 2) + coeff(2, damp)


def axial_run(build, directory, dt, steps, damp=None):
    """The pair (its reference state taken at rest by a first run)
    stretched by 1e-4 and let go at dt (no spin or transverse motion: only
    the stretch mode moves)."""
    script = pair_script(directory, damp) + """
thermo_style    custom step
run             0 post no
group           two id 2
displace_atoms  two move 1e-4 0.0 0.0 units box
"""
    ran, _, log = halted_run(build, directory, script, dt, steps, 2)
    return ran, log


WARNING = re.compile(r"WARNING: Time step (\S+) is above the stable time step (\S+) of "
                     r"bond_style beam \((\S+) times it")


@pytest.mark.parametrize("zeta", [0.0, 0.5])
def test_one_axial_bond_is_stable_exactly_below_the_estimate(build, tmp_path, zeta):
    k = E_ * A_ / 1.3
    omega = math.sqrt(2 * k / 1.0)
    beta = 2 * zeta / omega
    expected = 2 * (math.sqrt(1 + zeta * zeta) - zeta) / omega
    est = estimate(build, tmp_path / "est", pair_script(tmp_path / "est", beta or None))
    print(f"zeta {zeta}: estimate {est['dt']:.12g}, expected {expected:.12g}, "
          f"omega {est['omega']:.12g} ({omega:.12g}), zeta {est['zeta']:.6g}")
    assert est["dt"] == pytest.approx(expected, rel=1e-12)
    assert est["omega"] == pytest.approx(omega, rel=1e-12)
    assert est["zeta"] == pytest.approx(zeta, abs=1e-12)
    assert est["atom"] == 1
    steps = 2000
    below, log_below = axial_run(build, tmp_path / "below", 0.99 * est["dt"], steps, beta or None)
    above, log_above = axial_run(build, tmp_path / "above", 1.01 * est["dt"], steps, beta or None)
    print(f"0.99 x: ran {below} steps; 1.01 x: halted at step {above}")
    assert below == steps
    assert above < steps
    # the warning appears above the estimate only, with its value
    assert not WARNING.search(log_below)
    m = WARNING.search(log_above)
    assert m and float(m.group(2)) == pytest.approx(est["dt"], rel=1e-5)
    assert float(m.group(3)) == pytest.approx(1.01, rel=1e-3)
    assert "bond beam: stable time step" in log_below


# ---------------------------------------------------------------------------
# hard cases: scattered masses and moments of inertia, 2-D and 3-D


def frame_2d(length, angle):
    """The 6 x 6 stiffness of the 2-D Euler-Bernoulli element (E_, A_, I_)
    in global coordinates (x, y, theta of both ends)."""
    a, b, c = E_ * A_ / length, 12 * E_ * I_ / length ** 3, 6 * E_ * I_ / length ** 2
    d, e = 4 * E_ * I_ / length, 2 * E_ * I_ / length
    k = np.array([[a, 0, 0, -a, 0, 0], [0, b, c, 0, -b, c], [0, c, d, 0, -c, e],
                  [-a, 0, 0, a, 0, 0], [0, -b, -c, 0, b, -c], [0, c, e, 0, -c, d]])
    co, si = math.cos(angle), math.sin(angle)
    r = np.array([[co, si, 0], [-si, co, 0], [0, 0, 1]])
    t = np.kron(np.eye(2), r)
    return t.T @ k @ t


def frame_3d(e):
    """The 12 x 12 stiffness of the 3-D frame element (E_, A_, I_y = I_z =
    I_, J3, G_) along d = e (the textbook matrix in its local axes x = e,
    any y normal to it: the section is round), in global coordinates."""
    length = np.linalg.norm(e)
    x = e / length
    y = np.cross(x, [0.3, 0.5, 0.8])
    y /= np.linalg.norm(y)
    z = np.cross(x, y)
    r = np.array([x, y, z])
    k = np.zeros((12, 12))
    a, t = E_ * A_ / length, G_ * J3 / length
    for p, q, v in ((0, 0, a), (0, 6, -a), (6, 6, a), (3, 3, t), (3, 9, -t), (9, 9, t)):
        k[p, q] = k[q, p] = v
    b = E_ * I_ / length ** 3
    L = length
    bend = b * np.array([[12, 6 * L, -12, 6 * L], [6 * L, 4 * L * L, -6 * L, 2 * L * L],
                         [-12, -6 * L, 12, -6 * L], [6 * L, 2 * L * L, -6 * L, 4 * L * L]])
    for idx, sign in (((1, 5, 7, 11), np.ones(4)), ((2, 4, 8, 10), np.array([1, -1, 1, -1]))):
        k[np.ix_(idx, idx)] += bend * np.outer(sign, sign)
    tt = np.kron(np.eye(4), r)
    return tt.T @ k @ tt


def assembled(sites, bonds, dimension):
    nd = 3 if dimension == 2 else 6
    big = np.zeros((nd * len(sites),) * 2)
    for i, j in bonds:
        d = sites[j] - sites[i]
        ke = frame_2d(np.hypot(d[0], d[1]), math.atan2(d[1], d[0])) if dimension == 2 \
            else frame_3d(d)
        idx = list(range(nd * i, nd * i + nd)) + list(range(nd * j, nd * j + nd))
        big[np.ix_(idx, idx)] += ke
    return big


def omega_max(big, masses, inertias, dimension):
    nd = 3 if dimension == 2 else 6
    per = [[m] * dimension + [j] * (nd - dimension) for m, j in zip(masses, inertias)]
    s = 1 / np.sqrt(np.concatenate(per))
    eig = np.linalg.eigvalsh(s[:, None] * big * s[None, :])
    return math.sqrt(eig.max()), eig


def scene(dimension, case):
    if dimension == 2:
        sites, bonds = beam2d.hex_patch(radius=2.6)
        sites = np.column_stack([sites, np.zeros(len(sites))])
    else:
        sites, bonds = beam3d.cluster()
    n = len(sites)
    rng = np.random.default_rng(7)
    masses = np.ones(n) if case == "uniform" else 10 ** rng.uniform(-1, 1, n)
    inertias = 0.1 * masses * (1.0 if case == "uniform" else 10 ** rng.uniform(-0.5, 0.5, n))
    light = n // 2
    if case == "light particle":
        masses[light] = 0.01
        inertias[light] = 0.001
    if case == "light spin":
        inertias[light] = 1e-4
    return sites, bonds, masses, inertias


@pytest.mark.parametrize("dimension", [2, 3])
@pytest.mark.parametrize("case", ["uniform", "light particle", "light spin"])
def test_bound_holds_on_scattered_masses(build, tmp_path, dimension, case):
    sites, bonds, masses, inertias = scene(dimension, case)
    big = assembled(sites, bonds, dimension)
    omega, eig = omega_max(big, masses, inertias, dimension)
    # the reference's own check: the rigid motions only are free
    rigid = 3 if dimension == 2 else 6
    assert np.sum(np.abs(eig) < 1e-9 * eig.max()) == rigid
    data = data_file(tmp_path / "scene.data", sites, bonds, masses, inertias, dimension)
    script = header(data, dimension) + coeff(dimension)
    est = estimate(build, tmp_path / "est", script)
    slack = est["omega"] / omega
    critical = 2 / omega
    print(f"{dimension}-D {case}: {len(sites)} particles, {len(bonds)} bonds; omega_max "
          f"{omega:.6g}, bound {est['omega']:.6g} (x {slack:.4f}); dt {est['dt']:.6g}, "
          f"critical {critical:.6g}; stiffest row: particle {int(est['atom'])}")
    assert slack >= 1 - 1e-12
    assert slack < 1.6
    assert est["dt"] == pytest.approx(2 / est["omega"], rel=1e-14)
    if case == "uniform":
        return
    steps = 3000
    below, ratio, _ = dynamics(build, tmp_path / "below", script, 0.98 * critical, steps,
                               dimension)
    above, _, log_above = dynamics(build, tmp_path / "above", script, 1.02 * critical, steps,
                                   dimension)
    print(f"  0.98 x critical: {below} steps, energy at most {ratio:.3g} x the first; "
          f"1.02 x: halted at step {above}")
    assert below == steps and ratio < 100
    assert above < steps
    assert WARNING.search(log_above)


# ---------------------------------------------------------------------------
# ranks, newton_bond and the Kokkos variant


def frame_scene(directory):
    sites, bonds, masses, inertias = scene(3, "light particle")
    data = data_file(directory / "scene.data", sites, bonds, masses, inertias, 3)
    return header(data, 3) + coeff(3, damp=0.002) + beam3d.DEFORM


@pytest.mark.parametrize("nprocs,newton", [(2, "on"), (2, "off"), (4, "on"), (1, "off")])
def test_estimate_is_independent_of_ranks_and_newton(build, tmp_path, nprocs, newton):
    one = estimate(build, tmp_path / "one", frame_scene(tmp_path / "one"))
    script = frame_scene(tmp_path / "many").replace("newton          on on",
                                                    f"newton          on {newton}")
    many = estimate(build, tmp_path / "many", script, nprocs=nprocs)
    diff = abs(many["dt"] / one["dt"] - 1)
    print(f"{nprocs} ranks, newton_bond {newton}: dt {many['dt']:.17g} against "
          f"{one['dt']:.17g} ({diff:.1e}); zeta {many['zeta']:.6g}")
    assert one["zeta"] > 0
    assert diff < 1e-14
    assert many["atom"] == one["atom"]


@pytest.mark.parametrize("threads", [1, 2])
def test_kokkos_variant_gives_the_same_estimate(tmp_path, threads):
    kk = mcatest.kokkos_build()
    cpu = estimate(kk, tmp_path / "cpu", frame_scene(tmp_path / "cpu"))
    dev = estimate(kk, tmp_path / "kk", frame_scene(tmp_path / "kk"),
                   extra_args=mcatest.kokkos_args(threads))
    diff = abs(dev["dt"] / cpu["dt"] - 1)
    print(f"kk {threads} thread(s): dt {dev['dt']:.17g} against {cpu['dt']:.17g} ({diff:.1e})")
    assert diff < 1e-14
    assert dev["atom"] == cpu["atom"]


# ---------------------------------------------------------------------------
# bad input


def test_bad_input_gives_clear_errors(build, tmp_path):
    base = pair_script(tmp_path)
    cases = [
        (base + "compute dt all beam/timestep 1\n", "Compute beam/timestep takes no arguments"),
        (base.replace("bond_style beam", "bond_style harmonic").replace(
            f"bond_coeff 1 {E_} {A_} {I_}", "bond_coeff 1 1.0 1.0") +
         "compute dt all beam/timestep\nthermo_style custom step c_dt\nrun 0\n",
         "Compute beam/timestep requires bond_style beam (or beam/kk), not harmonic"),
    ]
    for k, (script, message) in enumerate(cases):
        result = build.run(script, tmp_path / f"bad{k}", check=False)
        out = result.stdout + result.stderr
        assert result.returncode != 0, script
        assert message in out, out[-2000:]


def test_time_step_from_the_estimate_through_python(tmp_path):
    """Asked for before the first run (no bond list yet), the compute says
    how to get the estimate; after 'run 0' a script sets its time step from
    it, and the run then reports the ratio it set."""
    lammps_module = pytest.importorskip("lammps", reason="LAMMPS Python module not on PYTHONPATH")
    if mcatest.build_named("current") is None:
        pytest.skip("the Python module belongs to the 'current' build")
    lmp = lammps_module.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    try:
        lmp.commands_string(pair_script(tmp_path) + """
compute         dt all beam/timestep
fix             1 all nve/mca
fix             2 all enforce2d
""")
        with pytest.raises(Exception, match=r"Compute beam/timestep: the estimate is made from "
                                            r"the bond list, which is built at the first run; "
                                            r"use 'run 0' before asking for it"):
            lmp.extract_compute("dt", lammps_module.LMP_STYLE_GLOBAL,
                                lammps_module.LMP_TYPE_SCALAR)
        lmp.command("run 0")
        dt = lmp.extract_compute("dt", lammps_module.LMP_STYLE_GLOBAL,
                                 lammps_module.LMP_TYPE_SCALAR)
        assert dt == pytest.approx(2 / math.sqrt(2 * E_ * A_ / 1.3), rel=1e-12)
        lmp.command(f"timestep {0.9 * dt!r}")
        lmp.command("run 10")
        ratio = lmp.extract_compute("dt", lammps_module.LMP_STYLE_GLOBAL,
                                    lammps_module.LMP_TYPE_VECTOR)[1]
        assert ratio == pytest.approx(0.9, rel=1e-12)
    finally:
        lmp.close()
