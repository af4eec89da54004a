"""tools/lattice_calibration.py: the elastic constants of hexagonal
particle lattices and the parameters that give them (doc/src/Howto_mlp.rst;
NUMFRAC/MLP notes A.4, B.2, reference cases 6-8):

* each map and its inverse give the moduli back to round-off (1e-12) over
  the reachable range of nu_2D (-0.9 to 1/3) for both lattices;
* the notes' figures: case 6 (central springs: mu = lambda = sqrt3 k / 4,
  nu_2D 1/3, E_2D 2k / sqrt3), case 7 (rectangular beams, h/L 0.1, 0.3,
  0.6: nu_2D 0.3289, 0.2945, 0.1905), case 8 (k1 0.3, k2 1.7: mu 1.2557,
  lambda 0.2165, nu_2D 0.0794), to the printed digits;
* a lattice of pair_style mlp built from the tool's parameters for a
  target E_2D and nu_2D has them: its long-wave stiffness (two wavelengths,
  extrapolated to q -> 0, independent of the corrected Eq. 11) gives E_2D
  and nu_2D to 1e-5;
* the static moduli (--moduli static): the stress of a homogeneous strain
  (a periodic lattice stretched along x: C11 and C12 from its pressure)
  has the target E_2D and nu_2D to 1e-5, and the lattice calibrated by
  its waves has the static moduli the tool gives for its springs (the two
  differ: the null Lagrangian sqrt3 k1 det grad u of the return force
  acts on the stress of a homogeneous strain, not on the field
  equations);
* nu_2D above 1/3 (unreachable with a restoring transverse stiffness) is
  refused with the reason, on the command line too.
"""

import math
import subprocess
import sys

import numpy as np
import pytest

import mcatest
from test_pair_mlp import wave_stiffness

sys.path.insert(0, str(mcatest.ROOT / "tools"))
import lattice_calibration as lc  # noqa: E402

SQRT3 = math.sqrt(3.0)
TOOL = mcatest.ROOT / "tools" / "lattice_calibration.py"


def static_springs(e2, nu2):
    return lc.mlp_springs(e2, nu2, "static")


@pytest.mark.parametrize("nu2", np.linspace(-0.9, 1.0 / 3.0, 9))
def test_maps_and_inverses_agree(nu2):
    for springs, moduli in ((lc.mlp_springs, lc.mlp_moduli), (lc.beam_springs, lc.beam_moduli),
                            (static_springs, lc.mlp_static_moduli)):
        a, b = springs(2.7, nu2)
        back = moduli(a, b)
        assert back["E2"] == pytest.approx(2.7, rel=1e-12)
        assert back["nu2"] == pytest.approx(nu2, abs=1e-12)
        mu, lam = lc.lame(2.7, nu2)
        assert back["mu"] == pytest.approx(mu, rel=1e-12)
        assert back["lambda"] == pytest.approx(lam, rel=1e-12, abs=1e-12)
    e2, nu = lc.in_plane(70.0, 0.25, 2.0, "strain")
    assert (e2, nu) == (pytest.approx(2.0 * 70.0 / (1.0 - 0.0625)), pytest.approx(1.0 / 3.0))


def test_reference_cases():
    k = 1.7
    central = lc.mlp_moduli(0.0, k)
    assert central["mu"] == pytest.approx(SQRT3 * k / 4.0, rel=1e-14)
    assert central["lambda"] == pytest.approx(SQRT3 * k / 4.0, rel=1e-14)
    assert central["nu2"] == pytest.approx(1.0 / 3.0, rel=1e-14)
    assert central["E2"] == pytest.approx(2.0 * k / SQRT3, rel=1e-14)
    assert lc.beam_moduli(k, 0.0) == pytest.approx(central, rel=1e-14)
    case8 = lc.mlp_moduli(0.3, 1.7)
    assert [round(case8[q], 4) for q in ("mu", "lambda", "nu2")] == [1.2557, 0.2165, 0.0794]
    for h, nu_ref in ((0.1, 0.3289), (0.3, 0.2945), (0.6, 0.1905)):
        kn, ks = lc.beam_stiffness(200.0, h, h ** 3 / 12.0, 1.0)    # per unit thickness
        assert round(lc.beam_moduli(kn, ks)["nu2"], 4) == nu_ref
        assert round(lc.rectangular_beam_nu2(h), 4) == nu_ref
    # a shear beam acts as k_s = 2 k_r / L0^2
    assert lc.shear_beam_kr(0.4, 1.5) == pytest.approx(0.4 * 1.5 ** 2 / 2.0)



def test_periodic_affine_moduli_of_case_9():
    """Reference case 9 (k1 = 0.3, k2 = 1.7, box deformations): pure-shear
    mu 0.9959 and lambda + 2 mu 2.7280 are the static moduli, the
    simple-shear mu 1.2557 the waves' (the null Lagrangian sqrt3 k1 det H
    tells them apart), the rotation energy per omega^2 sqrt3 k1 = 0.5196."""
    static, waves = lc.mlp_static_moduli(0.3, 1.7), lc.mlp_moduli(0.3, 1.7)
    assert round(static["mu"], 4) == 0.9959
    assert round(static["lambda"] + 2.0 * static["mu"], 4) == 2.7280
    assert round(waves["mu"], 4) == 1.2557
    assert round(SQRT3 * 0.3, 4) == 0.5196
    assert waves["mu"] - static["mu"] == pytest.approx(SQRT3 * 0.3 / 2.0, rel=1e-14)


def test_long_wave_stability_bound_of_case_15():
    """Reference case 15 (the linear hexagonal model, k2 = 1, k1 < 0): the
    lowest eigenvalue of the dynamical matrix over the Brillouin zone is 0
    (at q = 0) for k1 = -0.20 and -0.24 and -0.080 for k1 = -0.26 (at the
    zone boundary M); the bound is k1 = -k2/4, where mu = sqrt3 (k1 + k2/4)
    vanishes (bisection to 1e-9, for k2 = 1 and 2.5).  The same dynamical
    matrix gives the long waves of the simulated lattices: its long-wave
    limit D / q^2 has the eigenvalues (sqrt3/2)(mu, lambda + 2 mu)."""
    for k1 in (-0.20, -0.24):
        lowest, _ = lc.mlp_lowest_mode(k1, 1.0)
        assert abs(lowest) < 1e-12
    lowest, q = lc.mlp_lowest_mode(-0.26, 1.0)
    assert lowest == pytest.approx(-0.080, abs=1e-12)
    assert q == pytest.approx([math.pi, math.pi / SQRT3], abs=1e-12)    # M
    for k2 in (1.0, 2.5):
        lo, hi = -k2, 0.0
        while hi - lo > 1e-10:
            mid = 0.5 * (lo + hi)
            unstable = lc.mlp_lowest_mode(mid, k2, n=21)[0] < -1e-13
            lo, hi = (mid, hi) if unstable else (lo, mid)
        print(f"k2 = {k2}: stable down to k1 = {hi:.10f} (-k2/4 = {-k2 / 4:.10f})")
        assert hi == pytest.approx(-k2 / 4.0, abs=1e-9)
    m = lc.mlp_moduli(0.3, 1.7)
    q = 1e-4
    d = np.linalg.eigvalsh(lc.mlp_dynamical_matrix(0.3, 1.7, np.array([q, 0.0]))) / q ** 2
    assert d == pytest.approx([SQRT3 / 2 * m["mu"], SQRT3 / 2 * (m["lambda"] + 2 * m["mu"])],
                              rel=1e-7)

def test_unreachable_moduli_are_refused():
    for springs in (lc.mlp_springs, lc.beam_springs, static_springs):
        with pytest.raises(lc.CalibrationError, match=r"nu_2D = 0.4 > 1/3.*at most 1/3"):
            springs(1.0, 0.4)
        with pytest.raises(lc.CalibrationError, match=r"nu_2D = -1 must be in \(-1, 1\)"):
            springs(1.0, -1.0)
    with pytest.raises(lc.CalibrationError, match=r"E_2D = -2 must be > 0"):
        lc.beam_springs(-2.0, 0.2)
    result = subprocess.run([sys.executable, str(TOOL), "mlp", "--E", "1", "--nu", "0.3"],
                            capture_output=True, text=True)
    # plane strain: nu_2D = 0.3 / 0.7 > 1/3
    assert result.returncode == 2
    assert "nu_2D = 0.428571 > 1/3" in result.stderr
    result = subprocess.run([sys.executable, str(TOOL), "beam", "--E2", "1", "--nu2", "0.2",
                             "--moduli", "static"], capture_output=True, text=True)
    assert result.returncode == 2
    assert "--moduli applies to mlp lattices" in result.stderr



def test_glen_prefactor_of_the_beam_lattice():
    """glen_creep_prefactor: the initial shear creep rate k tau^3 of a
    melting beam lattice (Levin's theorem; simulated in
    test_bond_beam_melt.py).  Checked here against the sum of the squared
    bond energies written out for the three bond directions of a uniform
    shear (0, 60, 120 degrees; area per particle sqrt3 / 2, three bonds
    per particle), against the exponent (k tau^3 is the rate: the prefactor
    does not depend on tau, and it is linear in A), and on the command
    line; bad input is refused."""
    kn, ks, e, a = 30.0, 2.7, 100.0, 3.0e-4
    k = lc.glen_creep_prefactor(kn, ks, e, a)
    mu = lc.beam_moduli(kn, ks)["mu"]
    for tau in (0.05, 0.2):
        strain = tau / (2.0 * mu)
        energies = [0.5 * strain ** 2 * (kn * math.sin(2 * t) ** 2 + ks * math.cos(2 * t) ** 2)
                    for t in (0.0, math.pi / 3.0, 2.0 * math.pi / 3.0)]
        rate = 4.0 * a * e * e * sum(u * u for u in energies) / (SQRT3 / 2.0) / tau
        assert rate == pytest.approx(k * tau ** 3, rel=1e-12)
    assert lc.glen_creep_prefactor(kn, ks, e, 2 * a) == pytest.approx(2 * k, rel=1e-15)
    assert k / a == pytest.approx(19.4161, abs=1e-4)
    result = subprocess.run([sys.executable, str(TOOL), "beam", "--E2", "36.658939422331585",
                             "--nu2", "0.29449838187702265", "--E-bond", "100", "--glen",
                             "3e-4"], capture_output=True, text=True)
    assert result.returncode == 0 and "(19.4161 A)" in result.stdout, result.stdout
    result = subprocess.run([sys.executable, str(TOOL), "beam", "--E2", "36.6", "--nu2", "0.29",
                             "--glen", "3e-4"], capture_output=True, text=True)
    assert result.returncode == 2 and "--glen needs --E-bond" in result.stderr
    with pytest.raises(lc.CalibrationError, match=r"A = 0 must be > 0"):
        lc.glen_creep_prefactor(kn, ks, e, 0.0)
    with pytest.raises(lc.CalibrationError, match=r"k_s = -1 must be >= 0"):
        lc.glen_creep_prefactor(kn, -1.0, e, a)

def long_wave_moduli(build, directory, coeff):
    """mu and lambda + 2 mu from D / q^2 of transverse and longitudinal waves
    of two wavelengths (D/q^2 = M (sqrt3/2) c^2 + O(q^2), extrapolated)."""
    out = {}
    for pol in ("L", "T"):
        values = []
        for nx in (24, 48):
            d, q = wave_stiffness(build, directory / f"{pol}{nx}", None, None, "literal", pol,
                                  nx=nx, coeff=coeff)
            values.append((d / q ** 2 / (SQRT3 / 2.0), q))
        (m1, q1), (m2, q2) = values
        out[pol] = (m2 * q1 ** 2 - m1 * q2 ** 2) / (q1 ** 2 - q2 ** 2)
    mu, p = out["T"], out["L"]
    return mu, p - 2.0 * mu


@pytest.mark.parametrize("potential,e2,nu2", [("harmonic", 1.0, 0.2), ("morse", 3.0, -0.25)])
def test_lattice_built_from_the_tool_has_the_moduli(build, tmp_path, potential, e2, nu2):
    upp, f0 = lc.mlp_pair(e2, nu2)
    coeff = f"{lc.central_potential(potential, upp, 1.0, 2.0)} {f0:.17g} 6 0.0"
    result = subprocess.run([sys.executable, str(TOOL), "mlp", "--E2", str(e2), "--nu2", str(nu2),
                             "--potential", potential, "--D0", "2"], capture_output=True,
                            text=True, check=True)
    assert f"pair_coeff * * {lc.central_potential(potential, upp, 1.0, 2.0)}" in result.stdout
    mu, lam = long_wave_moduli(build, tmp_path, coeff)
    e2_wave, nu2_wave = lc.young(mu, lam)
    print(f"{potential}: target E_2D {e2}, nu_2D {nu2}; pair_coeff {coeff}; long waves: "
          f"E_2D {e2_wave:.8f}, nu_2D {nu2_wave:.8f}")
    assert e2_wave == pytest.approx(e2, rel=1e-5)
    assert nu2_wave == pytest.approx(nu2, abs=1e-5)


def homogeneous_moduli(build, directory, coeff, strain=1e-6):
    """E_2D and nu_2D of the stress of a homogeneous strain: a periodic
    hexagonal lattice (spacing 1) stretched along x, C11 and C12 from its
    pressure (2-D: minus the stress, force per length)."""
    from test_pair_mlp import data_file, header, hex_sites
    sites = hex_sites(12, 7)
    data = data_file(directory / "lattice.data", sites, ((-0.25, 11.75), (-0.25, 7 * SQRT3 - 0.25)))
    script = header(data.name) + f"""pair_style mlp 1.3 taper 0.2
pair_coeff 1 1 {coeff}
thermo_style custom step pxx pyy
thermo_modify norm no format float %.17g
run 0 post no
change_box all x scale {1.0 + strain!r} remap
run 0 post no
"""
    build.run(script, directory)
    thermo = mcatest.read_thermo(directory / "log.lammps")
    c11, c12 = -thermo["Pxx"][-1] / strain, -thermo["Pyy"][-1] / strain
    return (c11 * c11 - c12 * c12) / c11, c12 / c11


@pytest.mark.parametrize("potential,e2,nu2", [("harmonic", 1.0, 0.2), ("morse", 3.0, -0.25)])
def test_static_moduli_are_those_of_a_homogeneous_strain(build, tmp_path, potential, e2, nu2):
    upp, f0 = lc.mlp_pair(e2, nu2, kind="static")
    coeff = f"{lc.central_potential(potential, upp, 1.0, 2.0)} {f0:.17g} 6 0.0"
    result = subprocess.run([sys.executable, str(TOOL), "mlp", "--E2", str(e2), "--nu2", str(nu2),
                             "--potential", potential, "--D0", "2", "--moduli", "static"],
                            capture_output=True, text=True, check=True)
    assert f"pair_coeff * * {lc.central_potential(potential, upp, 1.0, 2.0)}" in result.stdout
    e2_static, nu2_static = homogeneous_moduli(build, tmp_path / "static", coeff)
    # the lattice calibrated by its waves for the same targets: other static moduli
    upp_w, f0_w = lc.mlp_pair(e2, nu2)
    coeff_w = f"{lc.central_potential(potential, upp_w, 1.0, 2.0)} {f0_w:.17g} 6 0.0"
    e2_w, nu2_w = homogeneous_moduli(build, tmp_path / "waves", coeff_w)
    expected = lc.mlp_static_moduli(*lc.mlp_springs(e2, nu2))
    print(f"{potential}: target E_2D {e2}, nu_2D {nu2}; static calibration: E_2D "
          f"{e2_static:.8f}, nu_2D {nu2_static:.8f}; wave calibration: E_2D {e2_w:.8f}, "
          f"nu_2D {nu2_w:.8f} (tool: {expected['E2']:.8f}, {expected['nu2']:.8f})")
    # a strain of 1e-6: the geometric nonlinearity is of that order
    assert e2_static == pytest.approx(e2, rel=1e-5)
    assert nu2_static == pytest.approx(nu2, abs=1e-5)
    assert e2_w == pytest.approx(expected["E2"], rel=1e-5)
    assert nu2_w == pytest.approx(expected["nu2"], abs=1e-5)
    assert abs(nu2_w - nu2) > 0.05    # the two kinds differ
