#!/usr/bin/python3
"""Crack-tip displacements of the K-test (in.ktest): the GP and the
full-MD model against each other and against the two-term LEFM field
that holds their frame (the GP digest, sec. 4.7: u_y on the Y axis above
the tip, u_x on the X axis ahead of it, u_r on the circle R = 15 A).

Averaging volumes through the whole thickness: on the Y axis rectangles
8 A wide (x) and 2 A high, on the X axis 2 A wide and 8 A high, on the
circle cylinders of radius 3.615 A (the digest's).  u_y on the Y axis is
the mean of +r and (minus) -r (mode I symmetry), u_x on the X axis is
taken as it is.  Writes ktest.txt and ktest.png.

  crack_fields.py md.12 gp32.12 ...   (the logs log.ktest.<model> and
  the dumps ktest.<model>.dump of run.sh)
"""
import math
import sys

import numpy as np

XT = 1.0                    # the tip (in.ktest)
K, T = 0.399, -1.34         # MPa m^0.5, GPa
E, NU = 224.0, 0.3          # GPa
R_AXIS = [2, 3, 5, 8, 10, 12, 15, 20, 25, 30, 40]
THETA = [0, 15, 30, 45, 60, 75, 90]


def read(path):
    with open(path) as f:
        lines = f.read().splitlines()
    n = int(lines[3])
    d = np.array([l.split() for l in lines[9:9 + n]], dtype=float)
    # reference positions: current less displacement
    return {"x": d[:, 1] - d[:, 4], "y": d[:, 2] - d[:, 5], "ux": d[:, 4], "uy": d[:, 5]}


def mean_box(d, key, cx, cy, wx, wy):
    sel = (np.abs(d["x"] - cx) < wx / 2) & (np.abs(d["y"] - cy) < wy / 2)
    return d[key][sel].mean() if sel.any() else math.nan    # (outside the atoms)


def mean_disc(d, cx, cy, radius):
    sel = np.hypot(d["x"] - cx, d["y"] - cy) < radius
    return d["ux"][sel].mean(), d["uy"][sel].mean()


def lefm(r, theta):
    mu, kappa = E / (2 * (1 + NU)), 3 - 4 * NU
    c = K / (2 * mu) * 1e2 * math.sqrt(r / (2 * math.pi))
    ux = c * math.cos(theta / 2) * (kappa - 1 + 2 * math.sin(theta / 2) ** 2) \
        + (1 - NU ** 2) * T * r * math.cos(theta) / E
    uy = c * math.sin(theta / 2) * (kappa + 1 - 2 * math.cos(theta / 2) ** 2) \
        - NU * (1 + NU) * T * r * math.sin(theta) / E
    return ux, uy


def fields(d):
    uy = [0.5 * (mean_box(d, "uy", XT, r, 8, 2) - mean_box(d, "uy", XT, -r, 8, 2)) for r in R_AXIS]
    ux = [mean_box(d, "ux", XT + r, 0, 2, 8) for r in R_AXIS]
    ur = []
    for t in THETA:
        th = math.radians(t)
        a, b = mean_disc(d, XT + 15 * math.cos(th), 15 * math.sin(th), 3.615)
        ur.append(a * math.cos(th) + b * math.sin(th))
    return np.array(uy), np.array(ux), np.array(ur)


def cost(model):
    """Particles (real and imaginary) and seconds of the two relaxations."""
    text = open(f"log.ktest.{model}").read()
    import re
    loops = re.findall(r"Loop time of ([0-9.]+) on \d+ procs for (\d+) steps with (\d+) atoms", text)
    return int(loops[-1][2]), sum(float(l[0]) for l in loops), sum(int(l[1]) for l in loops)


def main(models):
    data = {m: fields(read(f"ktest.{m}.dump")) for m in models}
    ref_uy = np.array([lefm(r, math.pi / 2)[1] for r in R_AXIS])
    ref_ux = np.array([lefm(r, 0)[0] for r in R_AXIS])
    ref_ur = np.array([lefm(15, math.radians(t))[0] * math.cos(math.radians(t)) +
                       lefm(15, math.radians(t))[1] * math.sin(math.radians(t)) for t in THETA])
    out = []
    for name, idx, ref, xs in (("u_y on the Y axis (A)", 0, ref_uy, R_AXIS),
                               ("u_x on the X axis (A)", 1, ref_ux, R_AXIS),
                               ("u_r on R = 15 A (A)", 2, ref_ur, THETA)):
        out.append(f"# {name}: r (A) or theta (deg), LEFM two-term, " + ", ".join(models))
        for i, x in enumerate(xs):
            out.append(f"{x} {ref[i]:.4f} " + " ".join(f"{data[m][idx][i]:.4f}" for m in models))
    far = [i for i, r in enumerate(R_AXIS) if r >= 5 and all(np.isfinite(data[m][0][i]) for m in models)]
    for m in models:
        size = m.split(".", 1)[1]
        md = data["md." + size]
        n, seconds, steps = cost(m)
        n_md, seconds_md, _ = cost("md." + size)
        line = f"{m}: {n} particles, {seconds:.1f} s, {steps} steps"
        if not m.startswith("md"):
            e_uy = max(abs(data[m][0][i] / md[0][i] - 1) for i in far)
            e_ux = max(abs(data[m][1][i] - md[1][i]) for i in far) / max(abs(md[1][i]) for i in far)
            e_ur = max(abs(data[m][2] - md[2])) / max(abs(md[2]))
            line += (f" ({n_md / n:.2f}x fewer, {seconds_md / seconds:.2f}x faster than md.{size}); "
                     f"error against md (r >= 5 A): u_y {e_uy:.4f}, u_x {e_ux:.4f}, u_r(15 A) {e_ur:.4f}")
        else:
            e = max(abs(data[m][0][i] / ref_uy[i] - 1) for i in far)
            line += f"; u_y against two-term LEFM (r >= 5 A): {e:.4f}"
        out.append("RESULT " + line)
    open("ktest.txt", "w").write("\n".join(out) + "\n")
    print("\n".join(out))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.2))
    rr = np.linspace(1, 40, 100)
    axes[0].plot(rr, [lefm(r, math.pi / 2)[1] for r in rr], "k-", label="two-term LEFM")
    axes[1].plot(rr, [lefm(r, 0)[0] for r in rr], "k-", label="two-term LEFM")
    axes[2].plot(THETA, ref_ur, "k-", label="two-term LEFM")
    for m in models:
        style = "o" if m.startswith("md") else "x"
        axes[0].plot(R_AXIS, data[m][0], style + "-", ms=4, lw=0.8, label=m)
        axes[1].plot(R_AXIS, data[m][1], style + "-", ms=4, lw=0.8, label=m)
        axes[2].plot(THETA, data[m][2], style + "-", ms=4, lw=0.8, label=m)
    for ax, title, xl in zip(axes, ["u_y on the Y axis", "u_x on the X axis", "u_r on R = 15 A"],
                             ["r (A)", "r (A)", "theta (deg)"]):
        ax.set_title(title)
        ax.set_xlabel(xl)
        ax.set_ylabel("displacement (A)")
    axes[0].legend(fontsize=7)
    fig.suptitle("Fe edge crack, K-test, K = 0.399 MPa m^0.5, T = -1.34 GPa")
    fig.tight_layout()
    fig.savefig("ktest.png", dpi=110)


if __name__ == "__main__":
    main(sys.argv[1:])
