"""Plot examples/fracture: left, |sigma_zz| against |eps_zz| of the periodic
box under the Drucker-Prager criterion in uniaxial tension and compression
(box.drucker_prager.0.dat, box.drucker_prager.180.dat) with the strengths
sigma_t and sigma_c; right, the box's failure envelope under the elliptic
criterion in the (sigma_zz, tau_xz) plane (envelope.py) with the load
path up to failure and the failure point measured at each load angle
(box.elliptic.<angle>.dat).  Prints the break stress / strength of the
Drucker-Prager runs and the measured / predicted failure load of each
angle.

    /usr/bin/python3 plot.py     (after run.sh)
"""

import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from envelope import (box_stress, drucker_prager_index, elliptic_failure_load,  # noqa: E402
                      envelope)

SIGMA_T, SIGMA_C = 2.0e6, 6.0e6
SIGMA0, TAU0 = 2.0e6, 1.5e6
ANGLES = (0, 45, 90, 135, 180)


def failure_row(path):
    """The row of the last sample before the first links break, and all rows."""
    data = np.loadtxt(path)
    broken = np.nonzero(data[:, 6] > 0)[0]
    if len(broken) == 0:
        return None, data
    return data[max(broken[0] - 1, 0)], data


fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.6))
for angle, name, strength, color in ((0, "tension", SIGMA_T, "C0"),
                                     (180, "compression", SIGMA_C, "C3")):
    path = f"box.drucker_prager.{angle}.dat"
    if not os.path.exists(path):
        continue
    row, data = failure_row(path)
    ax.plot(np.abs(data[:, 1]) * 1e3, np.abs(data[:, 3]) / 1e6, "-", color=color,
            label=f"MCA, uniaxial {name}")
    ax.axhline(strength / 1e6, color=color, ls="--", lw=1,
               label=f"sigma_{name[0]} = {strength / 1e6:g} MPa")
    if row is None:
        print(f"Drucker-Prager {name}: no link broke")
        continue
    predicted = 1.0 / drucker_prager_index(box_stress(angle), SIGMA_T, SIGMA_C)
    print(f"Drucker-Prager {name}: break stress {abs(row[3]):.4e} Pa, "
          f"break / strength = {abs(row[3]) / strength:.4f} "
          f"(criterion load {predicted:.4e} Pa)")
ax.set_xlabel("|eps_zz| (1e-3)")
ax.set_ylabel("|sigma_zz| (MPa)")
ax.set_title("Drucker-Prager: uniaxial tension and compression")
ax.legend(fontsize=8)

s, t = envelope(SIGMA0, TAU0)
bx.plot(s / 1e6, t / 1e6, "k-", lw=1, label="failure envelope (envelope.py)")
for angle in ANGLES:
    path = f"box.elliptic.{angle}.dat"
    if not os.path.exists(path):
        continue
    row, data = failure_row(path)
    intact = data[:np.argmax(data[:, 6] > 0)] if np.any(data[:, 6] > 0) else data
    bx.plot(intact[:, 3] / 1e6, intact[:, 4] / 1e6, "-", lw=0.5, color="0.6")
    if row is None:
        print(f"elliptic, angle {angle}: no link broke")
        continue
    measured = math.hypot(row[3], row[4])
    predicted = elliptic_failure_load(angle, SIGMA0, TAU0)
    print(f"elliptic, angle {angle:3d}: measured {measured:.4e} Pa, predicted "
          f"{predicted:.4e} Pa, ratio {measured / predicted:.4f}")
    bx.plot(row[3] / 1e6, row[4] / 1e6, "o", ms=6, label=f"measured, theta = {angle}")
bx.set_xlabel("sigma_zz (MPa)")
bx.set_ylabel("tau_xz (MPa)")
bx.set_title("Elliptic criterion: failure envelope of the box")
bx.set_aspect("equal", adjustable="datalim")
bx.legend(fontsize=7)

fig.tight_layout()
fig.savefig("fracture.png", dpi=120)
print("wrote fracture.png")
