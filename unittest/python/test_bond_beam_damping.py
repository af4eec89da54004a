"""bond_style beam's bond damping (bond_coeff ... damp beta; the digest's
R5, bond-level relative-velocity damping, stiffness-proportional): the
element's loads of the deformation rates times beta, their power tallied
as the scalar of the internal fix BEAM_STATE (doc/src/bond_beam.rst).

* a pair of particles vibrating along their bond is a damped oscillator
  mu u'' + beta k u' + k u = 0 (mu = m/2): the measured damping ratio and
  period are zeta = beta omega0 / 2 and 2 pi / (omega0 sqrt(1 - zeta^2))
  to 0.5 % and 1e-3;
* energy balance: a deformed patch (2-D) and cluster (3-D) let go in NVE:
  potential + kinetic (spin included) + the tally stays at the initial
  energy, to 1 % of the energy taken out (the damping reads the half-step
  velocities: the balance error is first order in dt, halving with it);
* the damping forces conserve momentum and angular momentum (3-D, to
  round-off), and a rigid motion (translation and spin of an undeformed
  cluster) gives no damping force;
* kk equals the CPU style (forces and the tally), and a restart keeps the
  tally (the restarted run's first forces see the full-step velocities:
  it follows the uninterrupted run to O(beta dt), not to round-off); bad
  input: damp <= 0, damp without comm_modify vel yes, damp with respa;
* a minimization sees the elastic forces only and tallies nothing.
"""

import math

import numpy as np
import pytest

import mcatest
import test_bond_beam as beam2d
import test_bond_beam_3d as beam3d
from mcatest import read_dump


def oscillator(build, directory, beta, dt=0.002, steps=10000):
    """Two particles of mass 1 bonded along x (E A / L0 = 10), the second
    pulled by 0.01 and let go; the bond's stretch every step."""
    data = beam2d.beam_data(directory / "pair.data", [(0.0, 0.0), (1.0, 0.0)], [(0, 1)],
                            ((-2, 3), (-2, 2)))
    script = beam2d.header(data) + f"""
comm_modify     vel yes
bond_style      beam
bond_coeff      1 100.0 0.1 0.001 damp {beta}
run             0 post no
set             atom 2 x 1.01
fix             1 all nve/mca
fix             2 all enforce2d
variable        u equal x[2]-x[1]-1.0
timestep        {dt}
thermo_style    custom step v_u pe ke f_BEAM_STATE
thermo_modify   norm no format float %.17g
thermo          1
run             {steps}
"""
    build.run(script, directory)
    return mcatest.read_thermo(directory / "log.lammps")


def test_bonded_pair_is_a_damped_oscillator(build, tmp_path):
    k, mu, beta, dt = 10.0, 0.5, 0.03, 0.002
    omega0 = math.sqrt(k / mu)
    zeta = 0.5 * beta * omega0
    thermo = oscillator(build, tmp_path, beta, dt)
    t, u = thermo["Step"] * dt, thermo["v_u"]
    # maxima (parabola through the three samples around each)
    k_max = np.nonzero((u[1:-1] > u[:-2]) & (u[1:-1] >= u[2:]))[0] + 1
    peaks, times = [], []
    for m in k_max:
        a, b, c = u[m - 1], u[m], u[m + 1]
        shift = 0.5 * (a - c) / (a - 2 * b + c)
        peaks.append(b - 0.25 * (a - c) * shift)
        times.append(t[m] + shift * dt)
    peaks, times = np.array(peaks), np.array(times)
    delta = np.log(peaks[:-1] / peaks[1:]).mean()
    zeta_measured = delta / math.sqrt(4 * math.pi ** 2 + delta ** 2)
    period = np.diff(times).mean()
    period_ref = 2 * math.pi / (omega0 * math.sqrt(1 - zeta ** 2))
    balance = thermo["PotEng"] + thermo["KinEng"] + thermo["f_BEAM_STATE"]
    print(f"{len(peaks)} peaks: zeta {zeta_measured:.6f} (beta omega0 / 2 = {zeta:.6f}), "
          f"period {period:.6f} ({period_ref:.6f}); energy balance off by "
          f"{np.abs(balance - balance[0]).max() / thermo['f_BEAM_STATE'][-1]:.1e} of the "
          f"{thermo['f_BEAM_STATE'][-1] / balance[0]:.3f} taken out")
    assert len(peaks) > 10
    assert zeta_measured == pytest.approx(zeta, rel=5e-3)
    assert period == pytest.approx(period_ref, rel=1e-3)
    assert thermo["f_BEAM_STATE"][-1] > 0.5 * balance[0]


def balance_run(build, directory, dim, dt, steps, extra_args=(), tail="", nprocs=1, newton="on"):
    """A deformed patch (2-D) or cluster (3-D) with damped bonds in NVE:
    thermo pe, ke, rotational ke (J = 0.1) and the tally; the last state."""
    if dim == 2:
        sites, bonds = beam2d.hex_patch()
        data = beam2d.beam_data(directory / "patch.data", sites, bonds, ((-6, 6), (-6, 6)))
        script = beam2d.header(data, newton=newton) + "comm_modify vel yes\nbond_style beam\n" \
            "bond_coeff 1 100.0 0.1 0.001 shear 40.0 0.8333333333333334 damp 0.01\n" \
            + beam2d.DEFORM + "fix 2 all enforce2d\n"
    else:
        sites, bonds = beam3d.cluster()
        data = beam3d.beam_data(directory / "cluster.data", sites, bonds, ((-4, 4),) * 3)
        script = beam3d.header(data, newton=newton) + "comm_modify vel yes\nbond_style beam\n" \
            f"bond_coeff 1 {beam3d.TIMOSHENKO} damp 0.01\n" + beam3d.DEFORM
    script += f"""
fix             1 all nve/mca
compute         w all property/atom omegax omegay omegaz
variable        er atom 0.5*0.1*(c_w[1]^2+c_w[2]^2+c_w[3]^2)
compute         rke all reduce sum v_er
variable        etot equal pe+ke+c_rke+f_BEAM_STATE
timestep        {dt}
thermo_style    custom step pe ke c_rke f_BEAM_STATE v_etot
thermo_modify   norm no format float %.17g
thermo          {max(steps // 50, 1)}
dump            d all custom {steps} traj.dump id x y z vx vy vz omegax omegay omegaz fx fy fz &
                tqx tqy tqz
dump_modify     d format float %.17g
""" + (tail or f"run {steps}\n")
    build.run(script, directory, extra_args=extra_args, nprocs=nprocs)
    return mcatest.read_thermo(directory / "log.lammps"), read_dump(directory / "traj.dump")


@pytest.mark.parametrize("dim", [2, 3])
def test_energy_balance_with_the_tally(build, tmp_path, dim):
    errors = []
    for k, (dt, steps) in enumerate(((0.004, 500), (0.002, 1000))):
        thermo, _ = balance_run(build, tmp_path / f"dt{k}", dim, dt, steps)
        e, taken = thermo["v_etot"], thermo["f_BEAM_STATE"][-1]
        errors.append(np.abs(e - e[0]).max() / taken)
        print(f"{dim}-D, dt {dt}: taken out {taken / e[0]:.3f} of the energy, balance off by "
              f"{errors[-1]:.2e} of that")
        assert taken > 0.2 * e[0]    # the damping works
    print(f"error ratio dt / dt/2: {errors[0] / errors[1]:.2f}")
    assert errors[1] < 1e-2
    assert errors[0] / errors[1] > 1.6    # first order (or better) in dt


def test_damping_conserves_momenta_and_spares_rigid_motion(build, tmp_path):
    thermo, snaps = balance_run(build, tmp_path / "nve", 3, 0.004, 400)
    cols = beam3d.columns
    p, ang, vscale, n = beam3d.momenta(snaps[-1])
    print(f"momentum {np.abs(p).max():.1e}, angular momentum {np.abs(ang).max():.1e} "
          f"(velocity scale {vscale:.1e})")
    assert np.abs(p).max() < 1e-12 * vscale * n
    assert np.abs(ang).max() < 1e-12 * vscale * n * 4.0

    # an undeformed cluster in rigid motion (velocity V + W x r, spin W):
    # no force; sheared (velocity along x growing with y): damping forces
    sites, bonds = beam3d.cluster()
    data = beam3d.beam_data(tmp_path / "cluster.data", sites, bonds, ((-4, 4),) * 3)
    forces = {}
    for name, motion in (("rigid", ("0.1+0.3*z-0.2*y", "-0.2+0.2*x-0.5*z", "0.05+0.5*y-0.3*x",
                                    "0.5", "0.3", "0.2")),
                         ("shear", ("0.3*y", "0.0", "0.0", "0.0", "0.0", "0.0"))):
        script = beam3d.header(data) + f"""
comm_modify     vel yes
bond_style      beam
bond_coeff      1 {beam3d.TIMOSHENKO} damp 0.01
variable        vx atom {motion[0]}
variable        vy atom {motion[1]}
variable        vz atom {motion[2]}
velocity        all set v_vx v_vy v_vz
set             group all omega {motion[3]} {motion[4]} {motion[5]}
"""
        snap = beam3d.snapshot(build, tmp_path / name, script)
        forces[name] = np.abs(cols(snap, ["fx", "fy", "fz", "tqx", "tqy", "tqz"])).max()
    print(f"largest damping force: rigid motion {forces['rigid']:.1e}, shear "
          f"{forces['shear']:.1e}")
    assert forces["shear"] > 1e-3
    assert forces["rigid"] < 1e-13 * forces["shear"] * 100


@pytest.mark.parametrize("dim", [2, 3])
def test_kokkos_damping_matches_the_cpu_style(tmp_path, dim):
    kk = mcatest.kokkos_build()
    steps = 200
    names = ["x", "y", "vx", "vy", "omegaz", "fx", "fy", "tqz"]
    if dim == 3:
        names += ["z", "vz", "omegax", "omegay", "fz", "tqx", "tqy"]
    thermo_cpu, s = balance_run(kk, tmp_path / "cpu", dim, 0.004, steps)
    cpu = s[-1]
    for threads in mcatest.kokkos_thread_counts():
        thermo, s = balance_run(kk, tmp_path / f"kk{threads}", dim, 0.004, steps,
                                extra_args=mcatest.kokkos_args(threads))
        diff = max(np.abs(s[-1][c] - cpu[c]).max() / max(np.abs(cpu[c]).max(), 1e-300)
                   for c in names)
        tally = abs(thermo["f_BEAM_STATE"][-1] / thermo_cpu["f_BEAM_STATE"][-1] - 1)
        print(f"{dim}-D kk {threads} thread(s) (2: or the GPU), {steps} steps: largest relative "
              f"difference {diff:.1e}, tally {tally:.1e}")
        assert diff < 1e-10 and tally < 1e-12


@pytest.mark.parametrize("dim", [2, 3])
def test_damping_is_the_same_on_ranks_and_newton(build, tmp_path, dim):
    """2 MPI ranks, and newton_bond off, follow one rank with newton_bond
    on: trajectory to 1e-10, tally to 1e-12 (sums in another order)."""
    steps = 200
    ref_thermo, ref = balance_run(build, tmp_path / "one", dim, 0.004, steps)
    names = ["x", "y", "vx", "vy", "omegaz"] + (["z", "vz", "omegax", "omegay"] if dim == 3 else [])
    for label, kwargs in (("2 ranks", {"nprocs": 2}), ("4 ranks", {"nprocs": 4}),
                          ("newton_bond off", {"newton": "off"})):
        thermo, snaps = balance_run(build, tmp_path / label.replace(" ", "_"), dim, 0.004, steps,
                                    **kwargs)
        diff = max(np.abs(snaps[-1][c] - ref[-1][c]).max() / np.abs(ref[-1][c]).max()
                   for c in names)
        tally = abs(thermo["f_BEAM_STATE"][-1] / ref_thermo["f_BEAM_STATE"][-1] - 1)
        print(f"{dim}-D, {label}: largest relative difference {diff:.1e}, tally {tally:.1e}")
        assert diff < 1e-10 and tally < 1e-12


def test_restart_keeps_the_tally(build, tmp_path):
    steps = 400
    one, _ = balance_run(build, tmp_path / "one", 2, 0.004, steps)
    balance_run(build, tmp_path / "split", 2, 0.004, steps,
                tail=f"run {steps // 2}\nwrite_restart half.restart\n")
    restart = f"""
read_restart    half.restart
comm_modify     vel yes
bond_style      beam
bond_coeff      1 100.0 0.1 0.001 shear 40.0 0.8333333333333334 damp 0.01
fix             1 all nve/mca
fix             2 all enforce2d
timestep        0.004
# (the internal fix is made at the first run after read_restart)
run             0 post no
thermo_style    custom step f_BEAM_STATE
thermo_modify   norm no format float %.17g
run             {steps // 2}
"""
    build.run(restart, tmp_path / "split")
    again = mcatest.read_thermo(tmp_path / "split" / "log.lammps")
    a, b = one["f_BEAM_STATE"][-1], again["f_BEAM_STATE"][-1]
    print(f"tally after {steps} steps: one run {a:.12e}, restarted {b:.12e}")
    # the restarted run's first forces take the full-step velocities of the
    # file, the uninterrupted run had the half-step ones: an O(beta dt)
    # difference at one step (measured 1.8e-6), not round-off; the tally
    # itself is carried over (without it the difference would be 0.5)
    assert b == pytest.approx(a, rel=1e-4)


def test_minimize_neither_damps_nor_tallies(build, tmp_path):
    """Damping acts in dynamics only: a minimization of a deformed patch whose
    particles move reaches the elastic minimum (forces below 1e-8) and
    leaves the tally at 0."""
    sites, bonds = beam2d.hex_patch()
    data = beam2d.beam_data(tmp_path / "patch.data", sites, bonds, ((-6, 6), (-6, 6)))
    script = beam2d.header(data) + """
comm_modify     vel yes
bond_style      beam
bond_coeff      1 100.0 0.1 0.001 damp 0.01
""" + beam2d.DEFORM + """
velocity        all create 1.0 4321 loop geom
fix             2 all enforce2d
thermo_style    custom step pe fmax f_BEAM_STATE
thermo_modify   norm no format float %.17g
min_style       fire
minimize        0.0 1.0e-9 20000 40000
"""
    build.run(script, tmp_path)
    thermo = mcatest.read_thermo(tmp_path / "log.lammps")
    print(f"after minimize: fmax {thermo['Fmax'][-1]:.1e}, tally {thermo['f_BEAM_STATE'][-1]}")
    assert thermo["f_BEAM_STATE"][-1] == 0.0
    assert thermo["Fmax"][-1] < 1e-8


BAD = [
    ("zero", "comm_modify vel yes\nbond_coeff 1 1.0 0.1 0.001 damp 0",
     r"Bond_coeff beam: damp beta = 0 must be > 0"),
    ("no ghost velocities", "bond_coeff 1 1.0 0.1 0.001 damp 0.1",
     r"with damp requires comm_modify vel yes"),
    ("respa", "comm_modify vel yes\nbond_coeff 1 1.0 0.1 0.001 damp 0.1\nrun_style respa 2 2",
     r"with damp does not support run_style respa"),
]


@pytest.mark.parametrize("case", BAD, ids=[c[0] for c in BAD])
def test_bad_damping_gives_clear_errors(build, tmp_path, case):
    beam2d.expect_error(build, tmp_path, 2, case[1], case[2])
