"""Plastic compression of a slab of movable lattice particles (reference
case 21): the width ratio dh(t) (Eq. 23) under the load and after it for
each pressure (the paper's Fig. 5), and the elastic interior strains
against the lattice's static moduli (and against Eq. 11's moduli of its
waves, which do not govern a body loaded by forces); the figures printed."""

import os
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# (tools/mca run copies the example elsewhere and sets MCA_ROOT)
ROOT = pathlib.Path(os.environ.get("MCA_ROOT", pathlib.Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(ROOT / "tools"))
import lattice_calibration as lc  # noqa: E402

PRESSURES = ("0.05", "0.5", "0.92", "0.94", "1.5")
# Morse D0 = 1, alpha = 2 (U'' = 8), f0 = 0.2, n = 6, c = 1
K1 = 6 * 0.2
K2 = 8.0 - K1


def read(path):
    """Thermo rows of all runs of a log, and its LOADED and RELAXED lines."""
    names, rows = None, []
    marks = {}
    for line in open(path):
        words = line.split()
        if words[:1] == ["Step"]:
            names = words
        elif words[:1] in (["LOADED"], ["RELAXED"]):
            marks[words[0]] = dict(zip(words[2::2], map(float, words[3::2])))
        elif names and len(words) == len(names):
            try:
                rows.append([float(w) for w in words])
            except ValueError:
                pass
    return dict(zip(names, np.array(rows).T)), marks


static = lc.mlp_static_moduli(K1, K2)
waves = lc.mlp_moduli(K1, K2)
print(f"k1 {K1}, k2 {K2}: static E_2D {static['E2']:.5f}, nu_2D {static['nu2']:.5f}; "
      f"waves (Eq. 11) E_2D {waves['E2']:.5f}, nu_2D {waves['nu2']:.5f}")

fig, ax = plt.subplots(figsize=(8, 4.8))
for p in PRESSURES:
    t, marks = read(f"log.p{p}")
    load, relax = marks["LOADED"], marks["RELAXED"]
    line = f"P {p}: loaded dh {load['dh']:.6f}, relaxed dh {relax['dh']:.6f}"
    if float(p) <= 0.5:
        # elastic: the interior strains (rows and columns of the middle)
        line += f"; interior eyy {load['eyy']:.6f}, exx {load['exx']:.6f}"
        pressure = float(p)
        for name, m in (("static", static), ("waves", waves)):
            line += (f"; {name}: eyy {m['nu2'] * pressure / m['E2']:.6f}, "
                     f"exx {-pressure / m['E2']:.6f}")
    print(line)
    ax.plot(t["Time"], t["v_dh"], label=f"P = {p}: relaxed dh {relax['dh']:.4f}")
ax.axvline(300.0, color="k", lw=0.6, ls=":")
ax.set_xlabel("time (load taken off at the dotted line)")
ax.set_ylabel("dh = height / height at t = 0 (Eq. 23)")

ax.set_title("MLP slab pressed on its left and right faces (force P per outer particle)")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig("slab.png", dpi=110)
