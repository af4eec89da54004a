"""Damping: the viscous link damping of pair mca ("pair_style mca damping
viscous", pair_coeff keyword eta; doc/src/pair_mca.rst, "Damping") and the
global damping of fix mca/damping (doc/src/fix_mca_damping.rst).

* dashpot: two automata pulled apart at a prescribed relative velocity v:
  the damping adds exactly area * eta * v / r to the pair force at every
  step (the positions, hence the elastic force, are those of the run
  without damping), and the energy the link dissipates is the
  trapezoidal work of that force;
* energy balance: a free, vibrating, damped cube keeps kinetic + elastic +
  dissipated energy constant to the integrator's error, while the
  dissipated energy grows to a large share of the initial energy;
* the damped cube runs the same with the kk styles, on 2 MPI ranks and
  across a restart file (the damping block travels with the links);
* an elastic-only run is unchanged by the option's existence: a model
  without the damping part and eta = 0 give the same numbers as before
  (bench/bitwise.py checks that bit for bit against the previous build);
* fix mca/damping: a lone automaton slows as exp(-gamma t), the energy it
  takes out closes the balance (in econserve) with pair mca, kk runs the
  same kernel, and the tally continues across a restart file.
"""

import pathlib
import re

import numpy as np
import pytest

from mca_inputs import lattice_data_file
from mcatest import kokkos_args, read_thermo

ROOT = pathlib.Path(__file__).resolve().parents[2]

PAIR = """
units           si
atom_style      mca
atom_modify     map array
boundary        f f f
region          box block -4 4 -4 4 -4 4 units box
create_box      1 box
create_atoms    1 single -0.254 0 0 units box
create_atoms    1 single 0.254 0 0 units box
mca_set         all packing fcc radius 0.254
comm_modify     vel yes
pair_style      mca {damping}
pair_coeff      * * E 70e9 nu 0.3 rho 2700 {eta}
group           lo id 1
group           hi id 2
fix             lo lo mca/setvelocity -0.5 0 0
fix             hi hi mca/setvelocity 0.5 0 0
fix             nve all nve/mca
compute         L all mca/link area length dissipated
compute         Lr all reduce max c_L[1] c_L[2] c_L[3]{inputs}
thermo_style    custom step f_hi[1] c_Lr[1] c_Lr[2] c_Lr[3]
thermo_modify   format float %.17g
thermo          1
timestep        1.0e-6
run             50
"""
ETA = 1.0e6      # Pa s: the damping force is of the order of the elastic one here
V_REL = 1.0      # m/s, relative velocity of the two automata
DT = 1.0e-6


def local_inputs(build):
    """compute reduce of local values: LAMMPS 2021 takes them as they come,
    later versions want 'inputs local'."""
    return "" if build.name == "kokkos" else " inputs local"


def thermo(directory):
    """The thermo columns of the last run of directory/log.lammps, one row
    per output step."""
    return np.column_stack(list(read_thermo(directory / "log.lammps").values()))


def test_dashpot_force_and_dissipation(build, tmp_path):
    inputs = local_inputs(build)
    build.run(PAIR.format(damping="damping viscous", eta=f"eta {ETA}", inputs=inputs),
              tmp_path / "damped")
    build.run(PAIR.format(damping="", eta="", inputs=inputs), tmp_path / "elastic")
    damped, elastic = thermo(tmp_path / "damped"), thermo(tmp_path / "elastic")
    assert len(damped) == 51 and len(elastic) == 51
    step, force, area, length, dissipated = damped.T
    # the positions are prescribed: the elastic force and the contact area
    # are those of the undamped run (to round-off)
    assert np.allclose(area, elastic[:, 2], rtol=1e-14, atol=0)
    # expected force of the dashpots in series on hi: -area eta v / r for
    # equal halves; the rate is dr/dt, exact but for the rounding of the
    # positions (ulp 5.6e-17 m against dr = 1e-6 m per step: 1e-10)
    expected = -area * ETA * V_REL / length
    expected[0] = 0.0    # the setup has no last step to take a rate from
    extra = force - elastic[:, 1]
    scale = np.abs(expected).max()
    error = np.abs(extra - expected).max() / scale
    print(f"\ndashpot: damping force {scale:.4e} N, elastic force "
          f"{np.abs(elastic[:, 1]).max():.4e} N, max error {error:.2e} of the damping force")
    assert error < 1e-8
    # dissipated energy: trapezoidal work of the damping force over each
    # step's dr = v dt, summed; positive
    work = np.concatenate(([0.0], np.cumsum(0.5 * (-expected[1:] - expected[:-1]) * V_REL * DT)))
    assert dissipated[-1] > 0
    assert np.abs(dissipated - work).max() < 1e-8 * work[-1]


# kinetic (translation and spin) + elastic + dissipated energy in the thermo
# output; {dissipated} is the energy taken out so far
ENERGY_OUTPUT = """
compute         L all mca/link dissipated
compute         D all reduce sum c_L{inputs}
compute         p all property/atom inertia omegax omegay omegaz
variable        erot atom 0.5*c_p[1]*(c_p[2]^2+c_p[3]^2+c_p[4]^2)
compute         erot all reduce sum v_erot
variable        etot equal ke+c_erot+pe+{dissipated}
thermo_style    custom step ke c_erot pe {dissipated} v_etot
thermo_modify   format float %.17g
"""

CUBE = """
units           si
atom_style      mca
atom_modify     map array
boundary        {boundary}
read_data       lattice.data
comm_modify     vel yes
pair_style      mca {damping}
pair_coeff      * * E 70e9 nu 0.3 rho 2700 {eta}
velocity        all ramp vx -0.5 0.5 z 0 1.5 sum yes units box
velocity        all ramp vz -0.2 0.2 x 0 1.5 sum yes units box
fix             nve all nve/mca
{fix}""" + ENERGY_OUTPUT + """thermo          {every}
timestep        {dt}
"""


def cube(build, eta=None, every=100, boundary="p p p", dt=2.0e-5, gamma=None):
    """The input of the vibrating cube: link damping of viscosity eta, or
    global damping at the rate gamma (fix mca/damping), or none."""
    return CUBE.format(
        boundary=boundary, every=every, dt=dt, inputs=local_inputs(build),
        damping="damping viscous" if eta is not None else "",
        eta=f"eta {eta}" if eta is not None else "",
        fix=f"fix             damp all mca/damping {gamma}\n" if gamma is not None else "",
        dissipated="f_damp" if gamma is not None else "c_D")


def cube_data(build, directory):
    """A free fcc block of 3x3x3 cells (108 automata) in a data file, so
    that runs on any number of ranks number the automata alike."""
    path = lattice_data_file(build, directory, "fcc", 0.7184, 3, ntypes=1)
    return path


# eta of about a tenth of the critical value for the shortest waves,
# rho c_p d / 10 (c_p = 6.2 km/s, d = 0.5 m): the vibration decays in a few
# hundred steps
ETA_CUBE = 2.0e5


def energy_balance(build, directory, eta, dt, nsteps):
    """Largest |E(t) - E(0)| / E(0) of E = kinetic + rotational + elastic +
    dissipated, and the dissipated and kinetic shares at the end."""
    cube_data(build, directory)
    script = cube(build, eta=eta, every=nsteps // 40, boundary="s s s", dt=dt)
    build.run(script + f"run {nsteps}\n", directory)
    step, ke, erot, pe, dissipated, total = thermo(directory).T
    assert np.all(np.diff(dissipated) >= 0)
    return (np.abs(total - total[0]).max() / total[0], dissipated[-1] / total[0],
            (ke[-1] + erot[-1]) / total[0])


def test_energy_balance_of_a_damped_cube(build, tmp_path):
    """The dissipated energy closes the balance to the integrator's error:
    the error is no larger than the undamped cube's at the same step, and
    falls as dt^2 (the trapezoidal work of the forces and velocity Verlet
    agree to second order)."""
    undamped, _, _ = energy_balance(build, tmp_path / "undamped", 0.0, 2.0e-5, 2000)
    error, share, kinetic = energy_balance(build, tmp_path / "dt", ETA_CUBE, 2.0e-5, 2000)
    half, _, _ = energy_balance(build, tmp_path / "dt2", ETA_CUBE, 1.0e-5, 4000)
    print(f"\ndamped cube: dissipated {share:.3f} of the initial energy, kinetic left "
          f"{kinetic:.3f}; energy balance error {error:.2e} (dt), {half:.2e} (dt/2), "
          f"undamped {undamped:.2e}")
    assert share > 0.5 and kinetic < 0.25
    assert error <= 1.2 * undamped
    assert half < error / 3.0


def dump_of(build, directory, extra_args=(), nprocs=1, split=None):
    """The damped cube, 200 steps, per-automaton fields at the end."""
    cube_data(build, directory)
    script = cube(build, eta=ETA_CUBE)
    if split == "restart":
        build.run(script + "run 100\nwrite_restart half.restart\n", directory,
                  extra_args=extra_args, nprocs=nprocs)
        script = """
read_restart    half.restart
comm_modify     vel yes
fix             nve all nve/mca
""" + ENERGY_OUTPUT.format(inputs=local_inputs(build), dissipated="c_D") + """
timestep        2.0e-5
run             100
"""
    elif split == "memory":
        script += "run 100\nrun 100\n"
    else:
        script += "run 200\n"
    script += """
write_dump      all custom final.txt id x y z vx vy vz fx fy fz tqx tqy tqz &
                modify sort id format float %.17g
"""
    build.run(script, directory, extra_args=extra_args, nprocs=nprocs, name="in.dump")
    data = np.loadtxt(directory / "final.txt", skiprows=9)
    return data, thermo(directory)[-1]


def relative_difference(a, b):
    """Largest difference of each field group over the field's scale."""
    out = {}
    for name, cols in (("x", slice(1, 4)), ("v", slice(4, 7)), ("f", slice(7, 10)),
                       ("torque", slice(10, 13))):
        scale = np.abs(a[:, cols]).max()
        out[name] = np.abs(a[:, cols] - b[:, cols]).max() / scale
    return out


def test_damped_cube_restart_is_exact(build, tmp_path):
    """A run split by a restart file continues as the run split in memory
    (the damping block of each link is in the file)."""
    memory, t_memory = dump_of(build, tmp_path / "memory", split="memory")
    restart, t_restart = dump_of(build, tmp_path / "restart", split="restart")
    assert np.array_equal(memory, restart)
    assert np.array_equal(t_memory, t_restart)


@pytest.mark.parametrize("nprocs", [2, 4])
def test_damped_cube_on_several_ranks(build, tmp_path, nprocs):
    one, t_one = dump_of(build, tmp_path / "one")
    two, t_two = dump_of(build, tmp_path / "many", nprocs=nprocs)
    diff = relative_difference(one, two)
    print(f"\n{nprocs} ranks vs 1: {diff}")
    # summation order only, grown over 200 steps of a sheared vibration (the
    # undamped box: 1.1e-10 in the forces on 2 ranks, the damped one 2.7e-10;
    # 4 ranks: 2.2e-10)
    assert max(diff.values()) < 1e-9
    assert abs(t_two[4] - t_one[4]) <= 1e-10 * t_one[4]


@pytest.mark.parametrize("threads", [1, 2])
def test_damped_cube_kk_matches_cpu(build, tmp_path, threads):
    if build.name not in ("kokkos", "kokkos5"):
        pytest.skip("the kk styles are in the kokkos builds")
    cpu, t_cpu = dump_of(build, tmp_path / "cpu")
    kk, t_kk = dump_of(build, tmp_path / "kk",
                       extra_args=kokkos_args(threads))
    diff = relative_difference(cpu, kk)
    print(f"\nkk {threads} thread(s) vs CPU: {diff}")
    if threads == 1:
        # the same kernels in the same order on one thread: bit for bit
        # today; the bound is the one of the elastic kk tests (test_kokkos.py)
        assert max(diff.values()) < 5e-13
        assert abs(t_kk[4] - t_cpu[4]) <= 5e-13 * t_cpu[4]
    else:
        # two chunks of automata sum in another order: round-off grown over
        # 200 steps, as on 2 MPI ranks (measured 2.7e-10)
        assert max(diff.values()) < 1e-9
        assert abs(t_kk[4] - t_cpu[4]) <= 1e-10 * t_cpu[4]


@pytest.mark.parametrize("style,coeff,message", [
    ("mca damping dashpot", "", r"Unknown damping part dashpot for pair_style mca "
                                r"\(allowed: viscous\)"),
    ("mca damping viscous", "eta -1", r"viscosity eta must be >= 0 and finite, got -1"),
    ("mca damping viscous", "eta 1e400",
     r"1e400 .*out of range|viscosity eta must be >= 0 and finite, got inf"),
])
def test_bad_damping_input(build, tmp_path, style, coeff, message):
    script = PAIR.format(damping="", eta=coeff, inputs=local_inputs(build))
    script = script.replace("pair_style      mca \n", f"pair_style      {style}\n")
    result = build.run(script, tmp_path, check=False, timeout=120)
    output = result.stdout + result.stderr
    assert 0 < result.returncode < 128, output[-2000:]
    assert re.search("ERROR: .*" + message, output), output[-2000:]


@pytest.mark.parametrize("damping,eta,message", [
    ("damping viscous", "", r"damping viscous with eta = 0 for every atom type damps nothing"),
    ("", "eta 1e6", r"eta is given but the link model has no damping part"),
])
def test_damping_without_viscosity_warns(build, tmp_path, damping, eta, message):
    script = PAIR.format(damping=damping, eta=eta, inputs=local_inputs(build))
    result = build.run(script.replace("run             50", "run 1"), tmp_path)
    assert re.search("WARNING: Pair mca: " + message, result.stdout + result.stderr)


def test_damping_example_at_reduced_size(build, tmp_path):
    """examples/damping/in.damping, 3 x 3 x 3 cells and 1000 steps: the
    block dissipates about half of its energy and the balance holds to the
    integrator's error at this step (the undamped block: 2e-3)."""
    if build.name == "kokkos":
        pytest.skip("the example uses 'compute reduce ... inputs local' (LAMMPS 2022 on)")
    script = (ROOT / "examples" / "damping" / "in.damping").read_text()
    build.run(script, tmp_path, variables={"eta": "2e5", "n": 3, "nsteps": 1000})
    t, ke, erot, pe, dissipated, total = np.loadtxt(tmp_path / "damping.2e5_0.dat", unpack=True)
    share = dissipated[-1] / total[0]
    error = np.abs(total - total[0]).max() / total[0]
    print(f"\nexample at n = 3: dissipated {share:.3f}, balance error {error:.2e}")
    assert share > 0.4
    assert error < 3e-3


# ---------------------------------------------------------------------------
# fix mca/damping: global damping F -= gamma m v, T -= gamma_r J omega

SINGLE = """
units           si
atom_style      mca
atom_modify     map array
boundary        f f f
region          box block -10 10 -10 10 -10 10 units box
create_box      1 box
create_atoms    1 single 0 0 0 units box
mca_set         all packing fcc radius 0.254 density 2700
velocity        all set 1.0 0.5 0 units box
set             group all omega 0 0 2.0
fix             nve all nve/mca
fix             damp all mca/damping {gamma} angular {gamma_r}
compute         p all property/atom inertia omegaz
variable        erot atom 0.5*c_p[1]*c_p[2]^2
compute         erot all reduce sum v_erot
compute         ke all ke
variable        vx equal vx[1]
thermo_style    custom step c_ke c_erot f_damp v_vx
thermo_modify   format float %.17g
thermo          100
timestep        1.0e-3
run             1000
"""


def test_global_damping_of_a_free_automaton(build, tmp_path):
    """A lone automaton slows as exp(-gamma t) (spin: exp(-gamma_r t)) to
    the integrator's first-order error in gamma dt, and its kinetic energy
    plus the dissipated energy stay constant."""
    gamma, gamma_r = 1.0, 2.0
    build.run(SINGLE.format(gamma=gamma, gamma_r=gamma_r), tmp_path)
    step, ke, erot, dissipated, vx = thermo(tmp_path).T
    t = step * 1.0e-3
    speed_error = np.abs(vx / vx[0] - np.exp(-gamma * t)).max()
    spin = np.sqrt(erot / erot[0])
    spin_error = np.abs(spin - np.exp(-gamma_r * t)).max()
    total = ke + erot + dissipated
    balance = np.abs(total - total[0]).max() / total[0]
    print(f"\nfree automaton: |v/v0 - exp(-gamma t)| {speed_error:.2e}, spin {spin_error:.2e}, "
          f"energy balance {balance:.2e}")
    # gamma dt = 1e-3 (spin 2e-3): the half-step velocity the force uses
    # lags by dt/2, an error of order gamma dt in the decay
    assert speed_error < 1e-3 and spin_error < 2e-3
    assert balance < 2e-3
    assert dissipated[-1] > 0.5 * total[0]


def test_global_damping_energy_in_econserve(build, tmp_path):
    """With pair mca: kinetic + rotational + elastic + the fix's scalar
    (ecouple) is conserved to the integrator's error, as with the links'
    damping; kk runs the same kernel (bit for bit on one thread)."""
    results = {}
    modes = [("cpu", ())]
    if build.name in ("kokkos", "kokkos5"):
        modes.append(("kk", ("-k", "on", "t", "1", "-sf", "kk")))
    for mode, args in modes:
        d = tmp_path / mode
        cube_data(build, d)
        script = cube(build, every=50, boundary="s s s", gamma=50.0)
        build.run(script + "run 2000\n", d, extra_args=args)
        results[mode] = thermo(d)
    step, ke, erot, pe, dissipated, total = results["cpu"].T
    error = np.abs(total - total[0]).max() / total[0]
    share = dissipated[-1] / total[0]
    print(f"\nglobal damping, cube: dissipated {share:.3f}, energy balance {error:.2e}")
    assert share > 0.5
    assert error < 2.5e-3    # the undamped cube: 2.1e-3 at this step
    if "kk" in results:
        assert np.abs(results["kk"] - results["cpu"]).max() <= 5e-13 * np.abs(results["cpu"]).max()


@pytest.mark.parametrize("args,message", [
    ("-1", r"Fix mca/damping: gamma must be >= 0 and finite \(1/time units\), got -1"),
    ("1 angular -2", r"angular gamma_r must be >= 0 and finite"),
    ("1 spin 2", r"Unknown fix mca/damping keyword spin \(allowed: angular\)"),
    ("", r"fix mca/damping"),
])
def test_bad_global_damping_input(build, tmp_path, args, message):
    script = SINGLE.format(gamma=1, gamma_r=1).replace(
        "fix             damp all mca/damping 1 angular 1", f"fix damp all mca/damping {args}")
    result = build.run(script, tmp_path, check=False, timeout=120)
    output = result.stdout + result.stderr
    assert 0 < result.returncode < 128, output[-2000:]
    assert re.search("ERROR: .*" + message, output), output[-2000:]


def test_global_damping_tally_continues_after_restart(build, tmp_path):
    """The energy taken out is in the restart file: a run split by
    write_restart/read_restart ends with the same tally as one split in
    memory."""
    script = SINGLE.format(gamma=1.0, gamma_r=2.0).replace("run             1000", "run 500")
    build.run(script + "run 500\n", tmp_path / "memory")
    build.run(script + "write_restart half.restart\n", tmp_path / "restart")
    # the continuation: the same fixes, output and steps after the restart
    after_setup = script[script.index("fix             nve"):]
    build.run("read_restart    half.restart\n" + after_setup, tmp_path / "restart",
              name="in.continue")
    memory, restart = thermo(tmp_path / "memory")[-1], thermo(tmp_path / "restart")[-1]
    assert memory[0] == restart[0] == 1000
    assert restart[3] > 0 and np.array_equal(memory, restart)
