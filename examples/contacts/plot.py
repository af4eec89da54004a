#!/usr/bin/python3
"""Plots of the contacts example (after run.sh): the friction force over
the normal force of the sliding block against its slide (mu = 0.3 and 0)
with the Coulomb value corrected for the tilt of the contact normals; the
energies of the oblique impact; the pieces of the perforated plate (size
histogram); the stress and energy balance of the packing compressed by
50 %.  Prints the figures the README quotes."""
import glob
import os
import pathlib
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent
# plate_analysis.py of examples/hard_cases (tools/mca run copies this
# example elsewhere and names the checkout in MCA_ROOT)
sys.path.insert(0, str(HERE.parent / "hard_cases"))
sys.path.insert(0, str(pathlib.Path(os.environ.get("MCA_ROOT", HERE.parents[1])) / "examples"
                       / "hard_cases"))
from plate_analysis import pieces, read_snapshots, read_thermo  # noqa: E402

R = 1.0e-3


def newest(pattern):
    return sorted(glob.glob(str(HERE / pattern)))[-1]


fig, axes = plt.subplots(2, 2, figsize=(11, 8.4))
(slide_ax, impact_ax), (plate_ax, pack_ax) = axes

for mu, colour in ((0.3, "C0"), (0.0, "C1")):
    t, slide, fx, fz, ratio, friction = np.loadtxt(HERE / f"sliding.{mu}.dat", unpack=True)
    slide_ax.plot(slide * 1e6, ratio, colour, label=f"MCA, mu = {mu}")
    s = np.linspace(0, slide.max(), 50)
    slide_ax.plot(s * 1e6, mu - s / (2 * R) * (1 + mu * mu), "k--", lw=0.8)
    second = slide > slide.max() / 2
    pred = mu - slide / (2 * R) * (1 + mu * mu)
    print(f"sliding block mu {mu}: N {-fz[second].mean():.2f} N, F_x/N mean over the second "
          f"half {ratio[second].mean():.5f} (mu - tilt: {pred[second].mean():.5f}), largest "
          f"deviation {np.abs(ratio[second] - pred[second]).max():.4f}, friction energy "
          f"{friction[-1]:.4e} J")
slide_ax.set_xlabel("slide of the block (um)")
slide_ax.set_ylabel("F_x / N on the plane")
slide_ax.set_title("block dragged on a plane (dashed: mu - (slide/2R)(1 + mu^2))")
slide_ax.legend(fontsize=8)

d = np.loadtxt(HERE / "impact.0.3.dat")
for k, name in ((1, "kinetic"), (2, "spin"), (3, "elastic"), (4, "friction"), (6, "total")):
    impact_ax.plot(d[:, 0] * 1e6, d[:, k] / d[0, 6], label=name)
impact_ax.set_xlabel("time (us)")
impact_ax.set_ylabel("energy / initial")
impact_ax.set_title("oblique impact, mu = 0.3")
impact_ax.legend(fontsize=8)
print(f"oblique impact: friction {d[-1, 4] / d[0, 6]:.4f}, dropped contacts left "
      f"{d[-1, 5] / d[0, 6]:.2e}, balance {np.abs(d[:, 6] - d[0, 6]).max() / d[0, 6]:.2e}, "
      f"contacts at most {d[:, 7].max():.0f}")

t = read_thermo(newest("log.impact_plate*"))
atoms = read_snapshots(HERE / "dump.impact.atoms")[-1][2]
links = read_snapshots(HERE / "dump.impact.links")[-1][2]
labels = pieces(atoms[:, 0], links)
sizes = np.sort(np.bincount(np.array(list(labels.values()))))[::-1]
plate_ax.hist(sizes, bins=np.unique(np.round(np.logspace(0, np.log10(sizes.max() + 1), 20))),
              color="C2")
plate_ax.set_xscale("log")
plate_ax.set_xlabel("automata in a piece")
plate_ax.set_ylabel("pieces")
plate_ax.set_title(f"perforated plate: {len(sizes)} pieces")
print(f"impact on a plate: {t['c_f[1]'][-1]:.0f} links broken, {len(sizes)} pieces, largest "
      f"{list(sizes[:5])}, {np.sum(sizes == 1)} single automata, friction "
      f"{t['c_A[1]'][-1] / t['KinEng'][0]:.4f} of the energy, balance "
      f"{np.abs(t['v_balance']).max():.2e}")

for path, colour in ((newest("log.packing.0.15*"), "C0"), (newest("log.packing.1.36*"), "C3")):
    t = read_thermo(path)
    factor = re.search(r"packing\.(\d+\.\d+)", path).group(1)
    balance = (t["v_etot"] - t["v_work"]) / t["v_work"][-1]
    pack_ax.plot(t["v_strain"], t["v_stress"] / 1e6, colour, label=f"stress, dt {factor} R/c_p")
    print(f"packing at {path.split('/')[-1]}: strain {t['v_strain'][-1]:.3f}, contacts pushing "
          f"{t['c_A[3]'][-1] / 2:.0f}, friction {t['c_A[1]'][-1] / t['v_work'][-1]:.3f} of the "
          f"work, balance {np.abs(balance).max():.2e}")
pack_ax.set_xlabel("strain of the packing")
pack_ax.set_ylabel("stress on the top plate (MPa)")
pack_ax.set_title("packing compressed by 50 %")
pack_ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(HERE / "contacts.png", dpi=100)
