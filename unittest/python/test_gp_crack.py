"""The crack-tip K-test of examples/gp_crack at reduced size (doc/src/Howto_gp.rst;
the GP digest, sec. 4.7): an edge crack in bcc Fe (Fe_mm.eam.fs, X = [110],
Y = [-110], Z = [001], plane strain), a block of half width 64.6 A (8
level-2 periods; the example: 96.9 and 145.4 A) whose frame is held at the
two-term LEFM field of K = 0.399 MPa m^0.5, T = -1.34 GPa, the interior
relaxed; the full-MD model and GP models (made by tools/gp_build.py) with
atoms within 16 and 32 A of the crack, level-2 particles elsewhere (fix
gp/link fit quadratic, as the example).

* GP against full MD of the same block (the coarse-graining error, r >= 5
  A from the tip): the 32 A model within 5 % in u_y on the Y axis (the
  issue's bound; measured 0.67 %, with the linear fit 2.0 %) and on the R
  = 15 A circle (0.30 % of the largest u_r; linear 1.8 %); the error
  falls as the atomic region grows (16 A: 2.0 %, 3.9 %);
* full MD against the isotropic two-term LEFM field (E = 224 GPa, nu =
  0.3, the thesis's constants; Fe is anisotropic and its crack faces are
  a slit of three removed planes): u_y on the Y axis within 25 % (measured
  16 %) and increasing with r: the load is the one meant.
"""

import shutil
import subprocess
import sys

import numpy as np
import pytest

import mcatest

EXAMPLE = mcatest.ROOT / "examples" / "gp_crack"
sys.path.insert(0, str(EXAMPLE))
import crack_fields as analysis  # noqa: E402


@pytest.fixture(scope="module")
def fields(tmp_path_factory):
    build = mcatest.build_named("current") or mcatest.builds()[0]
    directory = tmp_path_factory.mktemp("gp_crack")
    for name in ("in.ktest", "make_models.py"):
        shutil.copy(EXAMPLE / name, directory)
    env = build.environment()
    made = subprocess.run([sys.executable, "make_models.py", "8", "16", "32"], cwd=directory,
                          capture_output=True, text=True, env=dict(env, MCA_ROOT=str(mcatest.ROOT)))
    assert made.returncode == 0, made.stderr
    L = float(made.stdout.split("\n")[0].split()[1])
    result = {}
    for model in ("md.8", "gp16.8", "gp32.8"):
        build.run(open(directory / "in.ktest").read(), directory,
                  variables={"model": model, "L": L}, name=f"in.run.{model}")
        shutil.copy(directory / "log.lammps", directory / f"log.ktest.{model}")
        result[model] = analysis.fields(analysis.read(directory / f"ktest.{model}.dump"))
    return result


def errors(gp, md):
    far = [i for i, r in enumerate(analysis.R_AXIS) if r >= 5 and np.isfinite(gp[0][i])]
    e_uy = max(abs(gp[0][i] / md[0][i] - 1) for i in far)
    e_ur = max(abs(gp[2] - md[2])) / max(abs(md[2]))
    return e_uy, e_ur


def test_gp_against_full_md(fields):
    md = fields["md.8"]
    e16 = errors(fields["gp16.8"], md)
    e32 = errors(fields["gp32.8"], md)
    print(f"\nGP against MD (r >= 5 A): atoms within 16 A: u_y {e16[0]:.4f}, u_r(15 A) {e16[1]:.4f}; "
          f"within 32 A: u_y {e32[0]:.4f}, u_r(15 A) {e32[1]:.4f}")
    assert e32[0] < 0.05 and e32[1] < 0.05
    assert e32[0] < e16[0] and e32[1] < e16[1]


def test_full_md_against_lefm(fields):
    md = fields["md.8"]
    ref = np.array([analysis.lefm(r, np.pi / 2)[1] for r in analysis.R_AXIS])
    far = [i for i, r in enumerate(analysis.R_AXIS) if r >= 5 and np.isfinite(md[0][i])]
    deviation = max(abs(md[0][i] / ref[i] - 1) for i in far)
    print(f"\nfull MD against two-term LEFM, u_y on the Y axis (r >= 5 A): {deviation:.4f}")
    assert deviation < 0.25
    assert np.all(np.diff(md[0][far]) > 0)


def test_size_effect(tmp_path):
    """The trend of the GP digest sec. 4.8 (smaller plates too stiff): GP
    plates of width 193.8 A with an edge crack to x = 41 A, half heights 6
    and 12 level-2 periods (48.5, 96.9 A), pulled by grips to 1 %: u_y
    above the tip grows with the plate (the example: 64.6 to 258 A)."""
    import crack_size as size
    build = mcatest.build_named("current") or mcatest.builds()[0]
    for name in ("in.tension", "make_tension.py", "make_models.py"):
        shutil.copy(EXAMPLE / name, tmp_path)
    env = dict(build.environment(), MCA_ROOT=str(mcatest.ROOT))
    u10 = []
    for n in (6, 12):
        made = subprocess.run([sys.executable, "make_tension.py", str(n), "--width", "24", "--tip",
                               "41"], cwd=tmp_path, capture_output=True, text=True, env=env)
        assert made.returncode == 0, made.stderr
        W, H = (float(line.split()[1]) for line in made.stdout.split("\n")[:2])
        build.run(open(tmp_path / "in.tension").read(), tmp_path,
                  variables={"model": f"tgp.{n}", "W": W, "H": H}, name=f"in.run.{n}")
        d = analysis.read(tmp_path / f"tension.tgp.{n}.dump")
        size.TIP = 41.0
        u10.append([size.opening(d, r) for r in (5, 10, 15)])
    print(f"\nu_y at 5, 10, 15 A above the tip: H 48.5 A {np.round(u10[0], 4)}, "
          f"96.9 A {np.round(u10[1], 4)}")
    assert np.all(np.array(u10[1]) > 1.05 * np.array(u10[0]))
