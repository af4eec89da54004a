"""Tidal flexure at a grounding line: the shelf's profile at a tide of
0.04 against the beam on an elastic foundation, the moment at the
grounding line against M0 = 2 EI beta^2 w0 as the tide falls, and the tide
at which the root bond breaks against the elliptic criterion's w0*; the
figures printed."""

import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

RUNS = (("r0.002", "rate 0.002, L0 0.5"), ("r0.001", "rate 0.001, L0 0.5"),
        ("r0.0005", "rate 0.0005, L0 0.5"), ("fine", "rate 0.0005, L0 0.25"))


def thermo(path):
    """All thermo rows of a log (its runs joined), by column name."""
    names, rows, inside = None, [], False
    for line in open(path):
        words = line.split()
        if words[:2] == ["Step", "Time"]:
            names, inside = words, True
        elif inside and words and words[0] == "Loop":
            inside = False
        elif inside:
            try:
                rows.append([float(w) for w in words])
            except ValueError:    # a warning or the halt message
                pass
    return dict(zip(names, np.array(rows).T))


def setup(path):
    text = open(path).read()
    beta = float(re.search(r"^SETUP beta (\S+)", text, re.M).group(1))
    w0star = float(re.search(r"^SETUP .* w0\* (\S+)$", text, re.M).group(1))
    calved = re.search(r"^CALVED at tide (\S+), shelf at (\S+): w0/w0\* = (\S+),", text, re.M)
    return beta, w0star, float(calved.group(2)), float(calved.group(3))


fig, axes = plt.subplots(1, 2, figsize=(13, 4.6))
for name, label in RUNS:
    beta, w0star, tide, ratio = setup(f"log.{name}")
    t = thermo(f"log.{name}")
    w0 = -t["v_yfar"]
    elastic = (w0 > 0.01) & (t["Bonds"] == t["Bonds"][0])
    m_ratio = -t["c_root"][elastic] / t["v_M0"][elastic]
    lag = np.abs(t["v_yfar"] - t["v_yw"])[elastic].mean()
    print(f"{label}: root moment / (2 EI beta^2 w0) = {m_ratio.mean():.5f} (from "
          f"{m_ratio.min():.5f} to {m_ratio.max():.5f}); calved at w0 = {-tide:.5f}, "
          f"w0/w0* = {ratio:.5f}; the shelf lags the tide by {lag:.2e}")
    axes[1].plot(w0[elastic], m_ratio, label=f"{label}: calved at w0/w0* = {ratio:.4f}")
    snap = np.loadtxt(f"profile.{name}.dump", skiprows=9)
    x, y = snap[:, 1], snap[:, 2]
    y = y * 0.04 / -y[np.argmin(np.abs(x - 40.0))]    # scaled to a fall of 0.04
    if name in ("r0.0005", "fine"):
        axes[0].plot(x, y, "o" if name == "fine" else "s", ms=2.5, label=label)

xs = np.linspace(0.0, 20.0, 400)
w0 = 0.04
beta = setup("log.r0.001")[0]
analytic = -w0 + w0 * np.exp(-beta * xs) * (np.cos(beta * xs) + np.sin(beta * xs))
axes[0].plot(xs, analytic, "k-", lw=1, label="beam on an elastic foundation")
axes[0].set_xlim(0, 20)
axes[0].set_xlabel("x (grounding line at 0)")
axes[0].set_ylabel("y")
axes[0].set_title("profile at a tide of -0.04 (scaled to w0 = 0.04)")
axes[0].legend(fontsize=8)
axes[1].axhline(1.0, color="k", lw=0.5)
axes[1].set_xlabel("fall of the shelf w0 (40 from the grounding line)")
axes[1].set_ylabel("moment at the grounding line / (2 EI beta^2 w0)")
axes[1].set_title(f"until the root breaks (w0* = {setup('log.r0.001')[1]:.4f})")
axes[1].legend(fontsize=8)
fig.tight_layout()
fig.savefig("tide.png", dpi=110)

for name, _ in RUNS[2:]:
    snap = np.loadtxt(f"profile.{name}.dump", skiprows=9)
    x, y = snap[:, 1], snap[:, 2]
    y = y * w0 / -y[np.argmin(np.abs(x - 40.0))]
    ref = -w0 + w0 * np.exp(-beta * x) * (np.cos(beta * x) + np.sin(beta * x))
    print(f"profile {name}: largest |y - y_analytic| / w0 = {np.abs(y - ref).max() / w0:.5f}")
