"""The models of the GP speed-against-error benchmark (bench/gp_pareto.py).

The benchmark's cost comparison is fair only if every model is the same
block of Fe, uniform along the crack front: these tests check what its
figures rest on, without the timed runs.

* thickness: each model's periodic length along [001] is the least
  multiple of its coarsest level's period that exceeds twice that level's
  cutoff (what the builder and fix gp/link require; MD 4 a0, k2 m2 8 a0,
  k3 m2 12 a0, k2 m3 16 a0, k2 m4 32 a0);
* same material: at L = 2 units (96.9 A) every model's real particles
  stand for exactly the atoms of the fully atomistic block of its
  thickness (atoms per a0 of front equal to MD's, to the atom);
* crack faces atomic all along (the measured advice of examples/gp_crack):
  every real level-n particle (n > 1) is farther from the slit than its
  imaginary depth (2 r_c of level n), so no coarse particle sees the
  crack as a coarse surface, and the builder's warning for that case
  (Model.check_cuts) is silent for these models and speaks for a strip
  too narrow (level 2 at 5.8 A from a face);
* the shared frame is at least 2 r_c of the coarsest level of any model
  (the EAM density of a held particle next to the interior is that of
  the bulk) and a multiple of the levels' common period;
* a trailing q (fix gp/link fit quadratic) changes the fit and nothing
  else; a trailing c (the builder's sites centroid) moves each coarse
  level as a whole and changes no count;
* bad model names and sizes stop with a message naming the argument.
"""

import math
import re
import subprocess
import sys

import numpy as np
import pytest

import mcatest

sys.path.insert(0, str(mcatest.ROOT / "bench"))
import gp_pareto  # noqa: E402
import gp_build  # noqa: E402  (tools/, put on the path by gp_pareto)

MODELS = ["md", "md16", "k2m2h32", "k2m2h32s24", "k3m2h36s36", "k2m3h32s24", "k2m3h32s24w97", "k2m4h32s24"]


@pytest.fixture(autouse=True)
def potentials(monkeypatch):
    tree = mcatest.build_named("current") or mcatest.builds()[0]
    monkeypatch.setenv("LAMMPS_POTENTIALS", tree.environment()["LAMMPS_POTENTIALS"])


@pytest.mark.parametrize("k, levels, expected", [(1, 1, 4), (2, 2, 8), (3, 2, 12), (2, 3, 16), (2, 4, 32)])
def test_least_thickness(k, levels, expected):
    n = gp_pareto.thickness(k, levels)
    s = k ** (levels - 1)
    assert n == expected
    assert n % s == 0 and n * gp_pareto.A0 > 2 * gp_pareto.RC * s
    assert (n - s) * gp_pareto.A0 <= 2 * gp_pareto.RC * s       # the least such


def slit_distance(x):
    """Distance of points x from the benchmark's slit, |y| < 2.25 A from
    the xlo face to the tip at x = 1 A."""
    return np.hypot(np.maximum(x[:, 0] - 1.0, 0), np.maximum(np.abs(x[:, 1]) - 2.25, 0))


def test_models_are_the_same_block():
    L = 2 * gp_pareto.UNIT
    per_a0 = {}
    for name in MODELS:
        model = gp_build.build(gp_pareto.spec(name, L))
        k, levels, _, _ = gp_pareto.parse(name)
        per_a0[name] = model.atoms() / gp_pareto.model_thickness(name)
        # the slit |y| < 2.25 A from the xlo face to the tip at x = 1 A
        for n in range(1, model.nlevels):
            x = model.real[n]
            if len(x) == 0:       # k2m4 at this size: level 4 lies beyond the block
                continue
            gap = slit_distance(x)
            depth = 2 * gp_pareto.RC * k ** n
            assert gap.min() > depth, f"{name}: level {n + 1} at {gap.min():.3g} A of the crack"
        assert model.warnings == []
    md = per_a0["md"]
    print({m: round(v) for m, v in per_a0.items()})
    for name, v in per_a0.items():
        assert v == md, f"{name} stands for {v} atoms per a0 of front, full MD has {md}"


def test_builder_warns_of_coarse_crack_faces():
    model = gp_build.build(gp_pareto.spec("k2m2h32s12", 2 * gp_pareto.UNIT))
    gap = slit_distance(model.real[1])
    near = int(np.sum(gap <= 2 * gp_pareto.RC * 2 + 1e-6))
    assert near > 0
    assert len(model.warnings) == 1
    m = re.search(r"(\d+) real level-2 particles lie within the imaginary depth 21.2 A of a cut",
                  model.warnings[0])
    # the removed atoms lie inside the slit: none nearer than its faces
    assert m and 0 < int(m[1]) <= near, (model.warnings, near)
    assert any("WARNING" in line for line in model.summary())


def test_quadratic_models():
    """A trailing q asks fix gp/link for the quadratic fit, nothing else
    changes: the same particles as the linear model."""
    L = 2 * gp_pareto.UNIT
    linear, quadratic = (gp_pareto.spec(name, L) for name in ("k2m3h32s24", "k2m3h32s24q"))
    assert quadratic.pop("fit") == "quadratic" and linear.pop("fit") == "linear"
    assert quadratic == linear
    assert gp_pareto.parse("k2m3h32s24q") == gp_pareto.parse("k2m3h32s24")
    fragment = gp_build.build(gp_pareto.spec("k2m3h32s24q", L)).commands("k2m3h32s24q.data")
    assert any(line.endswith("gp/link real coupling force fit quadratic") for line in fragment)


def test_centroid_models():
    """A trailing c asks the builder for sites centroid, nothing else
    changes: the same regions and particle counts, each coarse level moved
    as a whole (a quarter period per level step along X, Y, Z)."""
    L = 2 * gp_pareto.UNIT
    origin, centroid = (gp_pareto.spec(name, L) for name in ("k2m3h32s24q", "k2m3h32s24qc"))
    assert centroid.pop("sites") == "centroid" and origin.pop("sites") == "origin"
    assert centroid == origin
    a, b = (gp_build.build(gp_pareto.spec(name, L)) for name in ("k2m3h32s24q", "k2m3h32s24qc"))
    assert [len(x) for x in a.real] == [len(x) for x in b.real]
    assert [len(x) for x in a.imaginary] == [len(x) for x in b.imaginary]
    quarter = np.array([math.sqrt(2), math.sqrt(2), 1.0]) * gp_pareto.A0 / 4
    assert np.allclose(b.shift[1], quarter) and np.allclose(b.shift[2], 3 * quarter)


def test_frame():
    for models in (["md", "k2m2h32"], ["md", "k3m2h36s36"], ["md", "k2m3h32"], ["md", "k2m4h32s24"]):
        frame = gp_pareto.frame_depth(models)
        deepest = max(2 * gp_pareto.RC * k ** (m - 1) for k, m, _, _ in map(gp_pareto.parse, models))
        assert frame >= deepest and frame - gp_pareto.UNIT < deepest
        assert math.isclose(frame / gp_pareto.UNIT, round(frame / gp_pareto.UNIT), abs_tol=1e-12)


@pytest.mark.parametrize("argv, message", [
    (["--models", "k2m2h32"], "needs md"),
    (["--models", "md,k4m2h32"], "k 2 or 3"),
    (["--models", "md,k2m5h32"], "2 to 4 levels"),
    (["--models", "md,gp32"], "is not md[<N>] or k<k>m<m>h<H>[s<S>][w<W>][q][c]"),
    (["--models", "md,k2m2h32s24p"], "is not md[<N>] or k<k>m<m>h<H>[s<S>][w<W>][q][c]"),
    (["--models", "md,k2m2h32s24cq"], "is not md[<N>] or k<k>m<m>h<H>[s<S>][w<W>][q][c]"),
    (["--units", "0"], "--units 0: at least 1"),
    (["--models", "md,md3"], "'md3': at least 4 a0"),
    (["--units", "1", "--models", "md,k2m3h32"], "the frame"),
])
def test_bad_arguments(argv, message, tmp_path):
    r = subprocess.run([sys.executable, str(mcatest.ROOT / "bench" / "gp_pareto.py"), *argv,
                        "--work", str(tmp_path), "--out", str(tmp_path / "out")],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode != 0
    assert message in r.stderr, r.stderr
