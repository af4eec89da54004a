"""The example examples/beam_packing at reduced size (11 x 11 = 121 discs): a
polydisperse random packing bonded by distance (digest R13) and the
stable time step bond_style beam bounds for it (R12).

* bonds by distance: every pair whose gap is below 2 % of the sum of the
  radii, none across the free x faces (checked against the distances of
  the data file);
* the estimate is a safe step and close to the limit: the lattice's
  fastest mode (the eigenvalues of M^-1 K of the assembled frame
  elements, the discs' own masses and moments of inertia) is below the
  bound, which is within 1.6 of it; free vibration is stable at 0.98 of
  2 / omega_max and blows up at 1.03 (both builds; the bond style warns
  there);
* tension to fracture (not where the bond style warns that the granular
  contacts act between bonded discs, as in LAMMPS 2021): the
  two grips carry the same modulus to 5 %, the energy balance (work of the
  grip against elastic, kinetic, spin and damped energy) holds to 2e-3 of
  the work until the first bond breaks, and the packing breaks brittle
  (the stress at the end below a quarter of the peak, bonds broken).
"""

import importlib.util
import subprocess
import sys

import numpy as np
import pytest

import mcatest

EXAMPLE = mcatest.ROOT / "examples" / "beam_packing"
K = 11


def load(name):
    spec = importlib.util.spec_from_file_location(f"packing_{name}", EXAMPLE / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def packing(build, directory):
    build.run((EXAMPLE / "in.pack").read_text(), directory, name="in.pack",
              variables={"k": K, "seed": 5531})
    subprocess.run([sys.executable, str(EXAMPLE / "bond.py"), "pack.data", "bonded.data", "0.02"],
                   cwd=directory, check=True)


def check(build, source, directory, factor):
    """A free-vibration run of the example at factor x the estimate."""
    directory.mkdir()
    (directory / "bonded.data").write_text((source / "bonded.data").read_text())
    build.run((EXAMPLE / "in.tension").read_text(), directory, name="in.tension",
              variables={"mode": "check", "factor": repr(factor)})
    (directory / "log.lammps").rename(directory / "log.check")
    return load("plot").checks(directory)[-1], (directory / "log.check").read_text()


def test_packing_bonds_and_its_stable_time_step(build, tmp_path):
    plot = load("plot")
    packing(build, tmp_path)
    ids, pos, radii, mass, inertia, bonds, box = plot.read_data(tmp_path / "bonded.data")
    # the bonds are the pairs within reach, minimum image in y only
    d = pos[None, :, :] - pos[:, None, :]
    ly = box["y"][1] - box["y"][0]
    d[:, :, 1] -= ly * np.round(d[:, :, 1] / ly)
    reach = np.hypot(d[:, :, 0], d[:, :, 1]) < 1.02 * (radii[:, None] + radii[None, :])
    expected = {(i, j) for i, j in zip(*np.nonzero(np.triu(reach, 1)))}
    assert set(map(tuple, bonds)) == expected
    assert np.allclose(mass, np.pi * radii ** 2, rtol=1e-12)
    assert np.allclose(inertia, 0.5 * np.pi * radii ** 4, rtol=1e-12)
    coordination = 2 * len(bonds) / len(pos)
    # the first check gives the estimate in its log
    (factor, stable, ratio), log = check(build, tmp_path, tmp_path / "c1", 1.0)
    dt, omega_bound = plot.estimate(log)
    omega, disc, nbonds = plot.fastest_mode(tmp_path)
    limit = 2 / omega / dt
    print(f"{len(pos)} discs, {nbonds} bonds (coordination {coordination:.2f}); omega_max "
          f"{omega:.6g} (disc {disc}), bound {omega_bound:.6g} ({omega_bound / omega:.4f} x); "
          f"at the estimate: {'stable' if stable else 'unstable'} ({ratio:.3g})")
    assert 3.5 < coordination < 6
    assert 1.0 <= omega_bound / omega < 1.6
    assert stable
    for factor, expect in ((0.98 * limit, True), (1.03 * limit, False)):
        (f, stable, ratio), log = check(build, tmp_path, tmp_path / f"c{factor:.4f}", factor)
        print(f"  {factor / limit:.2f} x the limit: {'stable' if stable else 'unstable'} "
              f"(energy {ratio:.3g} x the first)")
        assert stable == expect
        assert "above the stable time step" in log


def test_packing_breaks_brittle_with_its_energy_balanced(build, tmp_path):
    plot = load("plot")
    packing(build, tmp_path)
    build.run((EXAMPLE / "in.tension").read_text(), tmp_path, name="in.tension",
              variables={"strain": 0.01})
    if "keeps bonded pairs in its neighbor list" in (tmp_path / "log.lammps").read_text():
        pytest.skip("the contacts of this LAMMPS version (2021) act between bonded particles "
                    "too: another model (bond style beam's warning)")
    t = plot.thermo(tmp_path / "log.lammps")
    ml, mr, peak, at, balance, bonds_left = plot.tension(t)
    print(f"E_2D {ml:.4g} and {mr:.4g}; peak {peak:.4g} at {at:.4g}; energy balance "
          f"{balance:.2e}; bonds {int(t['Bonds'][0])} -> {bonds_left}; stress at the end "
          f"{t['v_sl'][-1]:.3g}")
    assert abs(ml / mr - 1) < 0.05
    assert balance < 2e-3    # the O(dt) error of the step and of the summed work: 7e-4 measured
    assert bonds_left < t["Bonds"][0]
    assert abs(t["v_sl"][-1]) < 0.25 * peak
