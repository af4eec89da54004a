"""The 3-D beam cantilever: tip deflections along y and z and the tip's
twist while the motion is damped away, each over its analytic value
(PL^3/3EI_z, PL^3/3EI_y, TL/GJ), for 4 and 10 elements; the final figures
printed (also the tip's turns against PL^2/2EI)."""

import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# in.frame3d
E, IY, IZ, J, NU, L = 100.0, 0.0008, 0.0012, 0.0016, 0.25, 1.0
G = E / (2 * (1 + NU))
PY, PZ, T = 1.0e-7, 1.0e-7, 1.0e-8
REF = {"v_wy": -PY * L ** 3 / (3 * E * IZ), "v_wz": -PZ * L ** 3 / (3 * E * IY),
       "v_tx": -T * L / (G * J)}
LABEL = {"v_wy": "deflection y / (P L^3 / 3 E I_z)", "v_wz": "deflection z / (P L^3 / 3 E I_y)",
         "v_tx": "twist / (T L / G J)"}


def thermo(path):
    names, rows = None, []
    for line in open(path):
        words = line.split()
        if words[:2] == ["Step", "Time"]:
            names, rows = words, []
        elif names and words and words[0] == "Loop":
            break
        elif names:
            rows.append([float(w) for w in words])
    return dict(zip(names, np.array(rows).T))


fig, axes = plt.subplots(1, 3, figsize=(14, 4.2))
for n in (4, 10):
    text = open(f"log.frame{n}").read()
    match = re.search(r"^FRAME N \d+: y (\S+) z (\S+) twist (\S+) turn_z (\S+) turn_y (\S+)",
                      text, re.M)
    y, z, twist, tz, ty = (float(v) for v in match.groups())
    print(f"{n:2d} elements: tip deflection y / (PL^3/3EI_z) = {y:.10f}, z / (PL^3/3EI_y) = "
          f"{z:.10f}, twist / (TL/GJ) = {twist:.10f}; turns / (PL^2/2EI): about z {tz:.10f},"
          f" about y {ty:.10f}")
    run = thermo(f"log.frame{n}")
    for ax, key in zip(axes, ("v_wy", "v_wz", "v_tx")):
        ax.plot(run["Time"], run[key] / REF[key], label=f"{n} elements")
for ax, key in zip(axes, ("v_wy", "v_wz", "v_tx")):
    ax.axhline(1.0, color="k", lw=0.5)
    ax.set_xlabel("time")
    ax.set_ylabel(LABEL[key])
    ax.legend()
axes[1].set_title("3-D cantilever, loads on, damped (fix nve/damped 4.0)")
fig.tight_layout()
fig.savefig("frame3d.png", dpi=110)
