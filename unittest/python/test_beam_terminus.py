"""The example examples/beam_terminus at reduced size (30 x 8 particles):
a grounded glacier terminus, a beam lattice under gravity and water
(digest R10: gravity, buoyancy and hydrostatic pressure below a water
line, pressure on boundary groups).  Facts of statics, with the
tolerances of the relaxed lattice (measured, same input, both builds):

* the back wall holds the water's push: -(front force) to 1e-6 of it;
* the slab in the middle carries it: int sigma_xx dz = -(front force) to
  1e-3 (measured 2e-5 at full size);
* and the weight: int sigma_yy dz = -rho_i g h^2 n (n - 1) / 2 (the
  lattice's interface forces) to 2 % (1.5 % at D/H = 3/4 in this short
  block, whose front reaches the slab; 0.2 % at full size), and their
  difference is the
  back stress rho_i g H^2/2 - rho_w g D^2/2 (lattice form) to 2 % of
  rho_i g H^2 / 2, dry and at D/H = 1/2 and 3/4;
* the bed carries the weight less the buoyancy: bed force = weight -
  ncols rho_w g c (mean draft) to 1e-6 of the weight;
* water as deep as the ice: the block floats off (bed force 0) at the mean
  draft rho_i H / rho_w to 1e-4;
* drawing the water down: the first bond breaks where the static tension
  (largest N/A, every half row of water, interpolated) reaches sigma0, to
  5 % of the depth (measured 0.6 % at full size; sigma0 where the static
  curve is steep: where the water line passes a row of the lumped load).
"""

import importlib.util

import numpy as np
import pytest

import mcatest

EXAMPLE = mcatest.ROOT / "examples" / "beam_terminus"
SIZE = {"ncols": 30, "nrows": 8}
H = 8 * np.sqrt(3.0) / 2.0
RHO_I, RHO_W, G = 0.9, 1.0, 0.004


def load_plot():
    spec = importlib.util.spec_from_file_location("terminus_plot", EXAMPLE / "plot.py")
    plot = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(plot)
    return plot


def run(build, directory, **variables):
    build.run((EXAMPLE / "in.terminus").read_text(), directory, name="in.terminus",
              variables={**SIZE, **variables})
    return load_plot().terminus(directory / "log.lammps")


@pytest.mark.parametrize("wrows", [0, 4, 6])
def test_terminus_carries_the_water_and_the_weight(build, tmp_path, wrows):
    r = run(build, tmp_path, wrows=wrows, steps=12000)
    h = np.sqrt(3.0) / 2.0
    n = SIZE["nrows"]
    # (dry, the bottom row pressed into the bed lies below the water line y_b)
    uplift = SIZE["ncols"] * RHO_W * G * max(r["draft"], 0.0)
    print(f"D/H {r['D/H']:.3f}: sxx {r['sxx']:.6g} (front {r['front']:.6g}), syy {r['syy']:.6g} "
          f"({r['syy_lattice']:.6g}), back stress {r['back_stress']:.6g} ({r['back_pred']:.6g}), "
          f"bed {r['bed']:.6g} (weight - uplift {r['weight'] - uplift:.6g}), ke {r['ke']:.1e}")
    assert r["ke"] < 1e-12
    assert abs(r["back_wall"] + r["front"]) <= 1e-6 * max(r["front"], 1e-3)
    assert abs(r["sxx"] + r["front"]) <= 1e-3 * max(r["front"], 1e-3)
    assert r["syy_lattice"] == pytest.approx(-RHO_I * G * h * h * n * (n - 1) / 2, rel=1e-12)
    assert abs(r["syy"] / r["syy_lattice"] - 1) < 0.02
    scale = RHO_I * G * H * H / 2
    assert abs(r["back_stress"] - r["back_pred"]) < 0.02 * scale
    assert abs(r["bed"] - (r["weight"] - uplift)) < 1e-6 * r["weight"]


def test_terminus_in_deep_water_floats_at_archimedes_draft(build, tmp_path):
    r = run(build, tmp_path, wrows=SIZE["nrows"], steps=40000)
    print(f"bed {r['bed']:.3g}, mean draft {r['draft']:.8g} against {r['draft_float']:.8g}, "
          f"ke {r['ke']:.1e}")
    assert r["bed"] == 0.0
    assert r["draft_float"] == pytest.approx(RHO_I * H / RHO_W, rel=1e-9)
    assert abs(r["draft"] / r["draft_float"] - 1) < 1e-4


CALVE = {**SIZE, "wrows": 6, "steps": 12000, "mode": "calve", "sigma0": 0.0195, "drawdown": 300.0}


def test_drawing_the_water_down_breaks_the_front_at_the_static_strength(build, tmp_path):
    # a probe first (the calving run's setup, no step): where the contacts
    # act between bonded particles too, this is another model
    build.run((EXAMPLE / "in.terminus").read_text(), tmp_path / "probe", name="in.terminus",
              variables={**CALVE, "steps": 40, "drawdown": 1e-9})
    if "keeps bonded pairs in its neighbor list" in (tmp_path / "probe" / "log.lammps").read_text():
        pytest.skip("the contacts of this LAMMPS version (2021) act between bonded particles "
                    "too: another model (bond style beam's warning)")
    plot = load_plot()
    for k, w in enumerate(np.arange(0.0, 6.01, 0.5)):
        run(build, tmp_path / f"s{k}", wrows=w, steps=12000)
        (tmp_path / f"s{k}" / "log.lammps").rename(tmp_path / f"log.static{w}")
        (tmp_path / f"s{k}" / "bonds.dump").rename(tmp_path / f"bonds.static{w}.dump")
    build.run((EXAMPLE / "in.terminus").read_text(), tmp_path / "calve", name="in.terminus",
              variables=CALVE)
    (tmp_path / "calve" / "log.lammps").rename(tmp_path / "log.calve")
    sigma0, first, t = plot.calving(tmp_path)
    pred = plot.predicted_depth(plot.statics(tmp_path), sigma0, H)
    print(f"sigma0 {sigma0}: first break at the depth {first}, static prediction {pred}; bonds "
          f"{int(t['Bonds'][0])} -> {int(t['Bonds'][-1])}")
    assert first is not None and pred is not None
    assert abs(first / pred - 1) < 0.05
