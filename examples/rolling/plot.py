"""Plot translational and rolling velocity against time for three packings."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

CASES = {"none": (0.4, "sphere"), "sc": (2.0 / 3.0, "sc cube"),
         "fcc": (0.5, "fcc rhombic dodecahedron")}

fig, ax = plt.subplots(figsize=(7, 4.5))
for (packing, (ratio, label)), color in zip(CASES.items(), ("C0", "C1", "C2")):
    t, v, rw = np.loadtxt(f"rolling.{packing}.dat", unpack=True)
    ax.plot(t, v, color=color, label=f"{label}: $v_x$")
    ax.plot(t, rw, color=color, ls="--", label=f"{label}: $R\\omega_y$")
    ax.axhline(1.0 / (1.0 + ratio), color=color, ls=":", lw=1)
ax.set_xlabel("time (LJ units)")
ax.set_ylabel("velocity")
ax.set_title("sliding to rolling: dotted lines $v_0/(1+J/mR^2)$")
ax.legend(fontsize=8, loc="lower right")
fig.tight_layout()
fig.savefig("rolling.png", dpi=120)
print("wrote rolling.png")
