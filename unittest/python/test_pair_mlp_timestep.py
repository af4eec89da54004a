"""The stable time step of pair_style mlp (doc/src/pair_mlp.rst, "Stable
time step"; digest R12) and compute mlp/timestep: Gershgorin's bound of
the fastest mode, omega^2 <= max_r sum_c |S_rc| for S = M^-1/2 K M^-1/2,
K = -dF/dx the pairs' stiffness at the present positions, and the step
2 / omega of velocity Verlet.

* the bound is the Gershgorin row sum of the stiffness itself: K
  assembled here by central differences of LAMMPS's forces (h = 1e-6) on
  a disordered periodic hexagonal lattice with masses over two decades,
  for the literal (non-symmetric K) and the conservative return force,
  harmonic, Morse and LJ central parts, the taper (second neighbours in
  it) and special-bond factors; its row sums give the style's omega^2 to
  1e-6 (the differences' error), and the largest |eigenvalue| of M^-1 K
  is below it (Gershgorin's theorem holds for any matrix), the slack
  printed;
* on a lattice at rest in its equilibrium (linear motion) the runs are
  stable at 0.98 of 2 / omega_max (from the eigenvalues) and blow up at
  1.02; the warning appears when the step is above the estimate;
* with fix mlp/frame the estimate is taken at the turned axes: a patch
  turned by 90 degrees in its frame has the estimate of the unturned one
  (the physics rotated by a right angle: the row sums permuted), which it
  has not without the frame;
* the same estimate on 1, 2 and 4 ranks, newton_pair on and off, and with
  pair mlp/kk (1 and 2 threads; with a frame too), to round-off;
* bad input: clear errors.
"""

import math
import re

import numpy as np
import pytest

import mcatest
from test_pair_mlp import SQRT3, hex_sites, rotated_patch

MASSES = (1.0, 0.1, 10.0)    # of types 1-3


def data_file(path, positions, box, types):
    lines = ["MLP time step data", "", f"{len(positions)} atoms", f"{len(MASSES)} atom types", "",
             f"{box[0][0]!r} {box[0][1]!r} xlo xhi", f"{box[1][0]!r} {box[1][1]!r} ylo yhi",
             "-0.5 0.5 zlo zhi", "", "Masses", ""]
    lines += [f"{t + 1} {m!r}" for t, m in enumerate(MASSES)]
    lines += ["", "Atoms # atomic", ""]
    lines += [f"{k + 1} {types[k]} {x!r} {y!r} 0.0" for k, (x, y) in enumerate(positions)]
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines) + "\n")
    return path


def lattice(directory, disorder=0.08, nx=8, ny=5, seed=5):
    """A periodic hexagonal lattice (nx x ny cells, spacing 1), its sites
    moved by up to `disorder`, types (masses) drawn at random."""
    rng = np.random.default_rng(seed)
    sites = hex_sites(nx, ny) + rng.uniform(-disorder, disorder, (2 * nx * ny, 2))
    types = rng.integers(1, len(MASSES) + 1, len(sites))
    data = data_file(directory / "lattice.data", sites, ((-0.25, nx - 0.25),
                                                         (-0.25, ny * SQRT3 - 0.25)), types)
    return data, types


def header(data, boundary="p p p", newton="on"):
    return f"""
units           lj
dimension       2
atom_style      atomic
atom_modify     map array sort 0 0.0
boundary        {boundary}
newton          {newton}
read_data       {data}
neighbor        0.3 bin
"""


CASES = {
    # name: (pair_style, pair_coeff words after "* *", a bonded pair's factor)
    "harmonic literal taper": ("mlp 1.9 return literal taper 0.5", "harmonic 2.0 1.0 0.1 6 7.0",
                               None),
    "lj conservative taper": ("mlp 1.9 return conservative taper 0.5",
                              f"lj {2.0 / 72.0!r} {2.0 ** (-1.0 / 6.0)!r} 0.1 6 -5.0", None),
    "morse literal n4 special": ("mlp 1.6 return literal taper 0.2", "morse 1.0 2.0 1.0 0.2 4 3.0",
                                 0.5),
}


def pair_lines(case):
    style, words, _ = CASES[case]
    return f"pair_style      {style}\npair_coeff      * * {words}\n"


def estimate(build, directory, script, nprocs=1, extra_args=()):
    """The values of compute mlp/timestep after `run 0`, and the log."""
    script += """
compute         dt all mlp/timestep
thermo_style    custom step c_dt c_dt[2] c_dt[3] c_dt[4]
thermo_modify   format float %.17g
run             0
"""
    build.run(script, directory, nprocs=nprocs, extra_args=extra_args)
    t = mcatest.read_thermo(directory / "log.lammps")
    return {name: t[key][-1] for name, key in
            (("dt", "c_dt"), ("ratio", "c_dt[2]"), ("omega", "c_dt[3]"), ("atom", "c_dt[4]"))}


def stiffness_by_differences(lammps_module, script, n, h=1e-6):
    """K = -dF/dx (2n x 2n, x then y of atoms 1..n) by central differences
    of the forces of LAMMPS's run 0."""
    lmp = lammps_module.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    try:
        lmp.commands_string(script + "thermo_style custom step\nrun 0 post no\n")

        def forces():
            lmp.command("run 0 post no")
            ids = lmp.numpy.extract_atom("id")[:n]
            f = np.array(lmp.numpy.extract_atom("f")[:n, :2])
            out = np.zeros((n, 2))
            out[ids - 1] = f
            return out.reshape(-1)

        ids = np.array(lmp.numpy.extract_atom("id")[:n])
        row = {int(t) - 1: k for k, t in enumerate(ids)}
        k = np.zeros((2 * n, 2 * n))
        for atom in range(n):
            for c in range(2):
                moved = []
                for sign in (1.0, -1.0):
                    x = lmp.numpy.extract_atom("x")
                    x[row[atom], c] += sign * h
                    moved.append(forces())
                    x = lmp.numpy.extract_atom("x")
                    x[row[atom], c] -= sign * h
                k[:, 2 * atom + c] = -(moved[0] - moved[1]) / (2 * h)
        return k
    finally:
        lmp.close()


@pytest.mark.parametrize("case", list(CASES))
def test_bound_is_the_row_sums_of_the_stiffness(build, tmp_path, case):
    lammps_module = pytest.importorskip("lammps", reason="LAMMPS Python module not on PYTHONPATH")
    if mcatest.build_named("current") is None or build.name != "current":
        pytest.skip("the Python module belongs to the 'current' build")
    data, types = lattice(tmp_path)
    n = len(types)
    script = header(data) + pair_lines(case)
    factor = CASES[case][2]
    if factor is not None:
        # a chain of bonds 1-2, 2-3, ... through the lattice: their pairs
        # at the special factor
        script = script.replace("atom_style      atomic", "atom_style      bond")
        text = data.read_text().replace("Atoms # atomic", "Atoms # bond")
        text = re.sub(r"^(\d+) (\d+) ", r"\1 1 \2 ", text, flags=re.M)
        text = text.replace(f"{len(MASSES)} atom types",
                            f"{len(MASSES)} atom types\n{n // 2} bonds\n1 bond types")
        text += "\nBonds\n\n" + "".join(f"{b + 1} 1 {2 * b + 1} {2 * b + 2}\n"
                                        for b in range(n // 2))
        data.write_text(text)
        script = script.replace("neighbor        0.3 bin",
                                "neighbor        0.3 bin\nbond_style zero\nbond_coeff 1\n"
                                f"special_bonds   lj {factor} 1.0 1.0")
    est = estimate(build, tmp_path / "est", script)
    k = stiffness_by_differences(lammps_module, script, n)
    m = np.repeat([MASSES[t - 1] for t in types], 2)
    s = k / np.sqrt(m)[:, None] / np.sqrt(m)[None, :]
    rows = np.abs(s).sum(axis=1)
    bound = rows.max()
    eig = np.linalg.eigvals(k / m[:, None])
    largest = np.abs(eig).max()
    asym = np.abs(k - k.T).max() / np.abs(k).max()
    print(f"{case}: {n} atoms; omega^2 bound {est['omega'] ** 2:.12g}, row sums of the "
          f"differenced K {bound:.12g} ({est['omega'] ** 2 / bound - 1:.1e}); largest "
          f"|eigenvalue| {largest:.6g} (bound / it {est['omega'] ** 2 / largest:.4f}); "
          f"asymmetry of K {asym:.1e}; stiffest row: atom {int(est['atom'])} "
          f"({np.argmax(rows) // 2 + 1})")
    # the differences' error: h^2 f''' ~ 1e-12, round-off 1e-16 / h ~ 1e-10
    assert est["omega"] ** 2 == pytest.approx(bound, rel=1e-8)
    assert int(est["atom"]) == np.argmax(rows) // 2 + 1
    assert largest <= est["omega"] ** 2 * (1 + 1e-9)
    assert est["dt"] == pytest.approx(2 / est["omega"], rel=1e-14)
    if "literal" in case:
        assert asym > 1e-3    # the return force is not conservative: K is not symmetric
    else:
        assert asym < 1e-6


# --------------------------------------------------------------------------
# a lattice in its equilibrium: stable below 2 / omega_max, unstable above


def equilibrium_script(directory):
    data, types = lattice(directory, disorder=0.0)
    return header(data) + ("pair_style      mlp 1.5 return conservative\n"
                                "pair_coeff      * * harmonic 2.0 1.0 0.1 6 0.0\n"), types


def halted_run(build, directory, script, dt, steps):
    script += f"""
variable        u atom 1e-4*random(-1,1,4411)
variable        v atom 1e-4*random(-1,1,4412)
velocity        all set v_u v_v 0.0
fix             1 all nve
fix             2 all enforce2d
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
    return int(t["Step"][-1]), (directory / "log.lammps").read_text()


WARNING = re.compile(r"WARNING: Time step (\S+) is above the stable time step (\S+) of "
                     r"pair_style mlp \((\S+) times it")


def test_equilibrium_lattice_is_stable_below_the_critical_step(build, tmp_path):
    script, types = equilibrium_script(tmp_path)
    est = estimate(build, tmp_path / "est", script)
    # the lattice's own K: nearest neighbours at 1 (the conservative
    # return force adds n f0 / c transverse stiffness, U'' = 2 along)
    sites = hex_sites(8, 5)
    n = len(sites)
    box = np.array([8.0, 5 * SQRT3])
    k = np.zeros((2 * n, 2 * n))
    for i in range(n):
        for j in range(n):
            d = sites[i] - sites[j]
            d -= box * np.round(d / box)
            r = math.hypot(*d)
            if i == j or r > 1.2:
                continue
            u = d / r
            e = np.array([-u[1], u[0]])
            block = 2.0 * np.outer(u, u) + 6 * 0.1 / 1.0 * np.outer(e, e)
            k[2 * i:2 * i + 2, 2 * j:2 * j + 2] -= block
            k[2 * i:2 * i + 2, 2 * i:2 * i + 2] += block
    m = np.repeat([MASSES[t - 1] for t in types], 2)
    eig = np.linalg.eigvalsh(k / np.sqrt(m)[:, None] / np.sqrt(m)[None, :])
    omega = math.sqrt(eig.max())
    critical = 2 / omega
    print(f"omega_max {omega:.6g}, bound {est['omega']:.6g} (x {est['omega'] / omega:.4f}); "
          f"dt {est['dt']:.6g}, critical {critical:.6g}")
    assert est["omega"] >= omega * (1 - 1e-12)
    assert est["omega"] < 1.6 * omega
    steps = 3000
    below, log_below = halted_run(build, tmp_path / "below", script, 0.98 * critical, steps)
    above, _ = halted_run(build, tmp_path / "above", script, 1.02 * critical, steps)
    print(f"0.98 x critical: {below} steps; 1.02 x: halted at step {above}")
    assert below == steps
    assert above < steps
    # the warning: above the estimate only (the critical step is above it)
    assert bool(WARNING.search(log_below)) == (0.98 * critical > est["dt"])
    quiet, log_quiet = halted_run(build, tmp_path / "quiet", script, 0.999 * est["dt"], 100)
    assert quiet == 100 and not WARNING.search(log_quiet)
    assert "pair mlp: stable time step" in log_quiet
    loud, log_loud = halted_run(build, tmp_path / "loud", script, 1.001 * est["dt"], 10)
    m = WARNING.search(log_loud)
    assert m and float(m.group(2)) == pytest.approx(est["dt"], rel=1e-5)
    assert float(m.group(3)) == pytest.approx(1.001, rel=1e-4)


# --------------------------------------------------------------------------
# the frame


def patch_script(directory, beta_degrees, frame):
    """The hexagonal disc of test_pair_mlp (types 1-3 in turn) turned by
    beta after the frame (if any) is defined: its measured angle is beta."""
    sites = rotated_patch(0.0)
    types = 1 + (np.arange(len(sites)) % 3)
    data_file(directory / "patch.data", sites, ((-12, 12), (-12, 12)), types)
    script = header("patch.data", "f f p")
    script += ("pair_style      mlp 1.3 return literal" + (" frame fr" if frame else "") +
               "\npair_coeff      * * harmonic 2.0 1.0 0.3 6 0.0\n")
    if frame:
        script += "fix             fr all mlp/frame 1\n"
    return script + f"displace_atoms  all rotate 0 0 0 0 0 1 {beta_degrees!r}\n"


def test_frame_turns_the_estimate_with_the_lattice(build, tmp_path):
    plain = estimate(build, tmp_path / "plain", patch_script(tmp_path / "plain", 0.0, False))
    framed = estimate(build, tmp_path / "framed", patch_script(tmp_path / "framed", 90.0, True))
    fixed = estimate(build, tmp_path / "fixed", patch_script(tmp_path / "fixed", 90.0, False))
    print(f"omega: unturned {plain['omega']:.15g}, turned 90 in its frame "
          f"{framed['omega']:.15g}, turned without the frame {fixed['omega']:.15g}")
    assert framed["omega"] == pytest.approx(plain["omega"], rel=1e-12)
    assert abs(fixed["omega"] / plain["omega"] - 1) > 1e-3


# --------------------------------------------------------------------------
# ranks, newton and the Kokkos variant


def disordered_script(directory):
    data, _ = lattice(directory, nx=12, ny=7)
    return header(data) + pair_lines("harmonic literal taper")


@pytest.mark.parametrize("nprocs,newton", [(2, "on"), (2, "off"), (4, "on"), (1, "off")])
def test_estimate_is_independent_of_ranks_and_newton(build, tmp_path, nprocs, newton):
    one = estimate(build, tmp_path / "one", disordered_script(tmp_path / "one"))
    script = disordered_script(tmp_path / "many").replace("newton          on",
                                                          f"newton          {newton}")
    many = estimate(build, tmp_path / "many", script, nprocs=nprocs)
    diff = abs(many["dt"] / one["dt"] - 1)
    print(f"{nprocs} ranks, newton {newton}: dt {many['dt']:.17g} against {one['dt']:.17g} "
          f"({diff:.1e})")
    assert diff < 1e-14
    assert many["atom"] == one["atom"]


@pytest.mark.parametrize("threads", [1, 2])
@pytest.mark.parametrize("scene", ["lattice", "frame"])
def test_kokkos_variant_gives_the_same_estimate(tmp_path, threads, scene):
    kk = mcatest.kokkos_build()

    def script(directory):
        if scene == "lattice":
            return disordered_script(directory)
        return patch_script(directory, 30.0, True)

    cpu = estimate(kk, tmp_path / "cpu", script(tmp_path / "cpu"))
    dev = estimate(kk, tmp_path / "kk", script(tmp_path / "kk"),
                   extra_args=mcatest.kokkos_args(threads))
    diff = abs(dev["dt"] / cpu["dt"] - 1)
    print(f"kk {threads} thread(s), {scene}: dt {dev['dt']:.17g} against {cpu['dt']:.17g} "
          f"({diff:.1e})")
    assert diff < 1e-14
    assert dev["atom"] == cpu["atom"]
    assert "pair mlp: stable time step" in (tmp_path / "kk" / "log.lammps").read_text()


# --------------------------------------------------------------------------
# bad input


def test_bad_input_gives_clear_errors(build, tmp_path):
    base = disordered_script(tmp_path)
    cases = [
        (base + "compute dt all mlp/timestep 1\n", "Compute mlp/timestep takes no arguments"),
        (base.replace(pair_lines("harmonic literal taper"),
                      "pair_style lj/cut 1.5\npair_coeff * * 1.0 1.0\n") +
         "compute dt all mlp/timestep\nthermo_style custom step c_dt\nrun 0\n",
         "Compute mlp/timestep requires pair_style mlp (or mlp/kk), not lj/cut"),
    ]
    for k, (script, message) in enumerate(cases):
        result = build.run(script, tmp_path / f"bad{k}", check=False)
        out = result.stdout + result.stderr
        assert result.returncode != 0, script
        assert message in out, out[-2000:]


def test_time_step_from_the_estimate_through_python(tmp_path):
    """Asked for before the first run (no neighbour list yet), the compute
    says how to get the estimate; after 'run 0' a script sets its time
    step from it, and the run then reports the ratio it set."""
    lammps_module = pytest.importorskip("lammps", reason="LAMMPS Python module not on PYTHONPATH")
    if mcatest.build_named("current") is None:
        pytest.skip("the Python module belongs to the 'current' build")
    lmp = lammps_module.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    try:
        lmp.commands_string(equilibrium_script(tmp_path)[0] +
                            "compute dt all mlp/timestep\nfix 1 all nve\nfix 2 all enforce2d\n")
        with pytest.raises(Exception, match=r"Compute mlp/timestep: the estimate is made from "
                                            r"the neighbour list, which is built at the first "
                                            r"run; use 'run 0' before asking for it"):
            lmp.extract_compute("dt", lammps_module.LMP_STYLE_GLOBAL,
                                lammps_module.LMP_TYPE_SCALAR)
        lmp.command("run 0")
        dt = lmp.extract_compute("dt", lammps_module.LMP_STYLE_GLOBAL,
                                 lammps_module.LMP_TYPE_SCALAR)
        assert 0 < dt < 1
        lmp.command(f"timestep {0.5 * dt!r}")
        lmp.command("run 10")
        ratio = lmp.extract_compute("dt", lammps_module.LMP_STYLE_GLOBAL,
                                    lammps_module.LMP_TYPE_VECTOR)[1]
        # (the lattice at rest in its equilibrium stays: the same estimate)
        assert ratio == pytest.approx(0.5, rel=1e-12)
    finally:
        lmp.close()
