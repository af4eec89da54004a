"""fix nve/damped: NUMFRAC's damped integrator (Eq. 4 of the NUMFRAC notes,
digest A.6 and reference case 4), checked against the recurrence itself:

* 16 one-dimensional oscillators (omega dt = 1, 1.5, 1.99, 2.01; damping
  ratios xi = 0, 0.5, 1, 3) follow Eq. 4, x(n+1) = [(2 - h^2) x(n)
  - (1 - a) x(n-1)] / (1 + a), h = omega dt, a = xi h, to 1e-12: the
  fix is that scheme; below omega dt = 2 every one stays bounded, above
  it every one grows, whatever xi;
* the explicit, lagged damping of fix viscous with fix nve, at xi = 0.5
  and omega dt = 1.5 (its limit: 2 (sqrt(1 + xi^2) - xi) = 1.236), grows
  where fix nve/damped decays;
* gamma = 0 is fix nve, bit for bit;
* kinetic + potential energy + the energy the fix took out (its scalar,
  ecouple: econserve) is conserved to the integrator's O(dt^2) on a
  damped MLP lattice (pair mlp, return conservative);
* the spin of finite-size spheres: a free spin decays by ((1 - a)/(1 + a))
  per step exactly, and the energy the fix takes out is the rotational
  energy lost with J = 0.4 m r^2 (sphere) or 0.5 m r^2 (disc), to the
  tally's (1 + a^2);
* MPI ranks, restart (the tally continues), the Kokkos variant equal to
  the CPU fix (translation and spin);
* the example examples/numfrac_damping: its measured growth factors
  follow the characteristic polynomials, and the first unstable omega dt
  is 2.1 for the centred damping, 1.3 (xi 0.5) and 0.9 (xi 1) for the
  lagged one.
"""

import importlib.util
import math
import re

import numpy as np
import pytest

import mcatest
from mcatest import read_dump, read_thermo

H_VALUES = (1.0, 1.5, 1.99, 2.01)
XI_VALUES = (0.0, 0.5, 1.0, 3.0)


def oscillators_script(nsteps, lagged=False):
    """One particle per (h, xi) in a 1-D spring k = h^2 (m = 1, dt = 1),
    starting at x = 1 at rest; the spring is an atom-style force from the
    charge q = k.  lagged: fix viscous + fix nve instead."""
    lines = ["units lj", "atom_style charge", "atom_modify map array", "boundary f f f",
             "region box block -1e280 1e280 -1 40 -1 1", "create_box 1 box", "mass 1 1.0",
             "timestep 1.0"]
    k = 0
    for h in H_VALUES:
        for xi in XI_VALUES:
            k += 1
            lines.append(f"create_atoms 1 single 1.0 {2 * k} 0.0")
            lines.append(f"set atom {k} charge {h * h:.17g}")
            lines.append(f"group g{k} id {k}")
            gamma = 2.0 * xi * h    # c = 2 xi m omega, m = 1, dt = 1
            if lagged:
                lines.append(f"fix v{k} g{k} viscous {gamma:.17g}")
                lines.append(f"fix i{k} g{k} nve")
            else:
                lines.append(f"fix i{k} g{k} nve/damped {gamma:.17g}")
    lines += ["variable fx atom -q*x", "fix spring all addforce v_fx 0.0 0.0",
              "dump d all custom 1 osc.dump id x", "dump_modify d format float %.17g sort id",
              f"run {nsteps}"]
    return "\n".join(lines) + "\n"


def trajectories(build, directory, nsteps, lagged=False):
    build.run(oscillators_script(nsteps, lagged), directory)
    snaps = read_dump(directory / "osc.dump")
    return np.array([s["x"] for s in snaps])    # [step, particle]


def test_oscillators_follow_eq4_and_are_stable_below_two(build, tmp_path):
    nsteps = 200
    x = trajectories(build, tmp_path, nsteps)
    k = 0
    for h in H_VALUES:
        for xi in XI_VALUES:
            a = xi * h
            # Eq. 4 from the first two positions of the run
            ref = [x[0, k], x[1, k]]
            for _ in range(nsteps - 1):
                ref.append(((2.0 - h * h) * ref[-1] - (1.0 - a) * ref[-2]) / (1.0 + a))
            ref = np.array(ref)
            err = np.abs(x[:, k] - ref).max() / max(1.0, np.abs(ref).max())
            print(f"omega dt {h}, xi {xi}: |x| max {np.abs(x[:, k]).max():.3e}, "
                  f"final {abs(x[-1, k]):.3e}; Eq. 4: {err:.1e}")
            assert err < 1e-12
            if h < 2.0:
                assert np.abs(x[:, k]).max() <= 1.0 + 1e-12
            else:
                # the root of modulus > 1 (1.22 at xi 0 ... 1.0036 at xi 3)
                assert abs(x[-1, k]) > 1.5
            k += 1


def test_lagged_damping_is_unstable_where_the_centred_one_is_not(build, tmp_path):
    nsteps = 200
    centred = trajectories(build, tmp_path / "centred", nsteps)
    lagged = trajectories(build, tmp_path / "lagged", nsteps, lagged=True)
    k = H_VALUES.index(1.5) * len(XI_VALUES) + XI_VALUES.index(0.5)
    print(f"omega dt 1.5, xi 0.5: centred |x(200)| {abs(centred[-1, k]):.2e}, "
          f"lagged {abs(lagged[-1, k]):.2e} (limit of the lagged scheme "
          f"{2 * (math.sqrt(1.25) - 0.5):.3f})")
    assert abs(centred[-1, k]) < 1e-10
    assert abs(lagged[-1, k]) > 1e3


# --------------------------------------------------------------------------
# lattices


SQRT3 = math.sqrt(3.0)


def lattice(nx=10, ny=6):
    sites = []
    for j in range(ny):
        for i in range(nx):
            sites.append((i, j * SQRT3))
            sites.append((i + 0.5, (j + 0.5) * SQRT3))
    return sites


def lattice_script(directory, fix, dt, nsteps, extra=""):
    sites = lattice()
    lines = ["MLP lattice", "", f"{len(sites)} atoms", "1 atom types", "",
             "-0.25 9.75 xlo xhi", f"-0.25 {6 * SQRT3 - 0.25:.17g} ylo yhi", "-0.5 0.5 zlo zhi",
             "", "Masses", "", "1 1.0", "", "Atoms # atomic", ""]
    lines += [f"{k + 1} 1 {x:.17g} {y:.17g} 0.0" for k, (x, y) in enumerate(sites)]
    (directory / "lattice.data").parent.mkdir(parents=True, exist_ok=True)
    (directory / "lattice.data").write_text("\n".join(lines) + "\n")
    return f"""
units           lj
dimension       2
atom_style      atomic
atom_modify     map array
read_data       lattice.data
pair_style      mlp 1.3 return conservative taper 0.2
pair_coeff      1 1 morse 1.0 1.0 1.0 0.05 6 0.0
velocity        all create 0.05 4928 dist gaussian mom yes rot no
{fix}
timestep        {dt}
{extra}
run             {nsteps}
"""


def test_gamma_zero_is_fix_nve(build, tmp_path):
    out = {}
    for name, fix in (("nve", "fix 1 all nve"), ("damped", "fix 1 all nve/damped 0.0")):
        extra = ("dump d all custom 50 run.dump id x y vx vy\n"
                 "dump_modify d format float %.17g sort id")
        build.run(lattice_script(tmp_path / name, fix, 0.01, 200, extra), tmp_path / name)
        out[name] = (tmp_path / name / "run.dump").read_text()
    assert out["nve"] == out["damped"]


def energy_balance(build, directory, dt, gamma=0.5, time=10.0):
    nsteps = int(round(time / dt))
    extra = ("thermo_style custom step ke pe f_1 econserve\n"
             f"thermo_modify norm no format float %.17g\nthermo {max(1, nsteps // 100)}")
    build.run(lattice_script(directory, f"fix 1 all nve/damped {gamma}", dt, nsteps, extra),
              directory)
    thermo = read_thermo(directory / "log.lammps")
    total = thermo["KinEng"] + thermo["PotEng"] + thermo["f_1"]
    assert np.allclose(total, thermo["Econserve"], rtol=1e-12, atol=1e-12)
    return (float(np.abs(total - total[0]).max()), float(thermo["KinEng"][0]),
            float(thermo["f_1"][-1]))


def test_damped_lattice_balances_its_energy(build, tmp_path):
    err1, ke0, taken = energy_balance(build, tmp_path / "a", 0.02)
    err2, _, _ = energy_balance(build, tmp_path / "b", 0.01)
    print(f"energy taken out {taken:.4f} (initial kinetic {ke0:.4f}); largest |E + W - E0|: "
          f"{err1:.3e} (dt 0.02), {err2:.3e} (dt 0.01), ratio {err1 / err2:.2f}")
    assert taken > 0.5 * ke0    # (the motion decays: most of it is taken out)
    assert err1 < 2e-3 * taken
    assert 3.0 < err1 / err2 < 5.0


# --------------------------------------------------------------------------
# spin of finite-size spheres


def spheres_script(disc, gamma_r, nsteps):
    """Two spheres (discs in 2-D) of radius 0.6, density 2 spinning freely
    at omega_z = 3 and 1.5."""
    box = ("dimension       2\nregion          box block -5 5 -5 5 -0.5 0.5" if disc else
           "region          box block -5 5 -5 5 -5 5")
    return f"""
units           lj
atom_style      sphere
atom_modify     map array
{box}
create_box      1 box
create_atoms    1 single -2 0 0
create_atoms    1 single 2 0 0
set             atom * diameter 1.2
set             atom * density{'/disc' if disc else ''} 2.0
set             atom 1 omega 0 0 3.0
set             atom 2 omega 0 0 1.5
fix             1 all nve/damped 0.0 angular {gamma_r} {'disc' if disc else ''}
dump            d all custom 1 spin.dump id omegaz
dump_modify     d format float %.17g sort id
thermo_style    custom step f_1
thermo_modify   norm no format float %.17g
thermo          {nsteps}
timestep        0.01
run             {nsteps}
"""


@pytest.mark.parametrize("disc", [False, True])
def test_spin_decays_and_the_tally_takes_its_energy(build, tmp_path, disc):
    """A free spin decays by (1 - a)/(1 + a) per step exactly; the energy
    taken out, gamma_r dt J (w(n)^2 + w(n+1)^2)/2 per step, equals the lost
    rotational energy (1/2) J (w0^2 - wN^2) times 1 + a^2 (the tally's
    second-order error): J = 0.4 m r^2 (sphere), 0.5 m r^2 (disc)."""
    radius, density, gamma_r, dt, nsteps = 0.6, 2.0, 0.8, 0.01, 3000
    # (a disc: set density/disc, mass per area)
    mass = density * (math.pi * radius ** 2 if disc else 4.0 / 3.0 * math.pi * radius ** 3)
    inertia = (0.5 if disc else 0.4) * mass * radius ** 2
    build.run(spheres_script(disc, gamma_r, nsteps), tmp_path)
    snaps = read_dump(tmp_path / "spin.dump")
    w = np.array([s["omegaz"] for s in snaps])
    a = 0.5 * gamma_r * dt
    decay = (1.0 - a) / (1.0 + a)
    expected = np.outer(decay ** np.arange(len(w)), [3.0, 1.5])
    taken = read_thermo(tmp_path / "log.lammps")["f_1"][-1]
    lost = 0.5 * inertia * float(np.sum(w[0] ** 2 - w[-1] ** 2))
    print(f"{'disc' if disc else 'sphere'}: spin error {np.abs(w - expected).max():.1e}; "
          f"energy taken {taken:.12f}, rotational energy lost {lost:.12f}, ratio - 1 "
          f"{taken / lost - 1:.3e} (a^2 = {a * a:.3e})")
    assert np.abs(w - expected).max() < 1e-12 * 3.0
    assert taken / lost == pytest.approx(1.0 + a * a, rel=1e-10)


# --------------------------------------------------------------------------
# ranks, restart, Kokkos


def damped_run(build, directory, nprocs=1, extra_args=(), restart=False):
    extra = "dump d all custom 100 run.dump id x y vx vy\ndump_modify d format float %.17g sort id"
    thermo = "thermo_style custom step pe f_1\nthermo_modify norm no format float %.17g\n"
    script = lattice_script(directory, "fix 1 all nve/damped 0.3", 0.01, 100, thermo + extra)
    if restart:
        script = script.replace("run             100", "run 50\nwrite_restart half.restart\n"
                                "clear\nread_restart half.restart\n"
                                "fix 1 all nve/damped 0.3\n" + thermo + extra.replace("run.dump",
                                                                             "run2.dump") +
                                "\nrun 50")
    build.run(script + "info fixes out log\n", directory, nprocs=nprocs, extra_args=extra_args)
    dump = "run2.dump" if restart else "run.dump"
    snap = read_dump(directory / dump)[-1]
    state = np.stack([snap[c] for c in ("x", "y", "vx", "vy")], axis=1)
    taken = float(re.findall(r"^\s*100\s+\S+\s+(\S+)\s*$",
                             (directory / "log.lammps").read_text(), re.M)[-1])
    return state, taken


@pytest.mark.mpi
def test_ranks_and_restart(build, tmp_path):
    ref, taken = damped_run(build, tmp_path / "one")
    two, taken2 = damped_run(build, tmp_path / "two", nprocs=2)
    rst, taken3 = damped_run(build, tmp_path / "restart", restart=True)
    print(f"2 ranks {np.abs(two - ref).max():.1e}, restart {np.abs(rst - ref).max():.1e}; "
          f"energy taken {taken:.15g} {taken2:.15g} {taken3:.15g}")
    assert np.abs(two - ref).max() < 1e-12
    assert np.abs(rst - ref).max() < 1e-12
    assert taken2 == pytest.approx(taken, rel=1e-12)
    # the tally continues across the restart file
    assert taken3 == pytest.approx(taken, rel=1e-12)


def test_kokkos_variant_matches_the_cpu_fix(tmp_path):
    build = mcatest.kokkos_build()
    ref, taken = damped_run(build, tmp_path / "cpu")
    for threads in mcatest.kokkos_thread_counts():
        kk, taken_kk = damped_run(build, tmp_path / f"kk{threads}",
                                  extra_args=mcatest.kokkos_args(threads))
        log = (tmp_path / f"kk{threads}" / "log.lammps").read_text()
        assert re.search(r"style = nve/damped/kk", log), "the kk fix did not run"
        print(f"kk {threads}: {np.abs(kk - ref).max():.1e}, energy taken {taken_kk:.15g} "
              f"(cpu {taken:.15g})")
        assert np.abs(kk - ref).max() < 1e-12
        assert taken_kk == pytest.approx(taken, rel=1e-12)



@pytest.mark.parametrize("disc", [False, True])
def test_kokkos_variant_spins_as_the_cpu_fix(tmp_path, disc):
    build = mcatest.kokkos_build()
    results = {}
    for name, args in (("cpu", ()), ("kk", mcatest.kokkos_args(2))):
        directory = tmp_path / name
        build.run(spheres_script(disc, 0.8, 500) + "info fixes out log\n", directory,
                  extra_args=args)
        snaps = read_dump(directory / "spin.dump")
        results[name] = (np.array([s["omegaz"] for s in snaps]),
                         read_thermo(directory / "log.lammps")["f_1"][-1])
    assert re.search(r"style = nve/damped/kk", (tmp_path / "kk" / "log.lammps").read_text())
    err = float(np.abs(results["kk"][0] - results["cpu"][0]).max())
    print(f"{'disc' if disc else 'sphere'}: kk spin vs cpu {err:.1e}, energy taken "
          f"{results['kk'][1]:.15g} (cpu {results['cpu'][1]:.15g})")
    assert err < 1e-14
    assert results["kk"][1] == pytest.approx(results["cpu"][1], rel=1e-13)

# --------------------------------------------------------------------------
# the example: growth factors of damped oscillators


EXAMPLE = mcatest.ROOT / "examples" / "numfrac_damping"


def example_plot():
    spec = importlib.util.spec_from_file_location("numfrac_plot", EXAMPLE / "plot.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.mark.parametrize("xi", ["0.5", "1"])
def test_example_growth_factors(build, tmp_path, xi):
    """examples/numfrac_damping at xi = 0.5 and 1: the growth factors the
    example measures from its runs follow the spectral radius of each
    scheme's characteristic polynomial (to 0.03, the envelope fit's
    error where two roots beat), and the first unstable omega dt on its
    grid is 2.1 for the centred damping and 1.3 or 0.9 for the lagged one
    (limits 1.236 and 0.828)."""
    plot = example_plot()
    first = {}
    for scheme in ("centred", "lagged"):
        build.run((EXAMPLE / "in.oscillators").read_text(), tmp_path,
                  variables={"xi": xi, "scheme": scheme})
        rho = plot.measured(scheme, xi, tmp_path)
        exact = np.array([plot.spectral_radius(h, float(xi), scheme) for h in plot.H])
        ok = np.isfinite(rho) & (exact > 0.2)
        err = float(np.abs(rho[ok] - exact[ok]).max())
        first[scheme] = plot.critical(plot.H, rho)
        print(f"xi {xi} {scheme}: growth factor error {err:.1e}, first unstable omega dt "
              f"{first[scheme]:.1f}")
        assert err < 0.03
    assert first["centred"] == pytest.approx(2.1)
    assert first["lagged"] == pytest.approx({"0.5": 1.3, "1": 0.9}[xi])
