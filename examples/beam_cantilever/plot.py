"""The beam cantilever: the static tip deflection and rotation against the
Euler-Bernoulli values for 1, 4 and 10 elements, and the ringing tip after
the load is taken off for 5, 10 and 20 elements, its period against the
first bending mode of the continuous beam; the figures printed."""

import math
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

E, I, L, MU = 100.0, 0.01, 1.0, 0.1    # in.cantilever: mass 0.1 per unit length
# first bending mode of a clamped-free Euler-Bernoulli beam
OMEGA1 = 1.8751040687119611 ** 2 * math.sqrt(E * I / (MU * L ** 4))


def thermo_runs(path):
    """The thermo tables of a log, each a dict of columns."""
    runs, names, rows = [], None, []
    for line in open(path):
        words = line.split()
        if words[:2] == ["Step", "Time"]:
            names, rows = words, []
        elif names and words and words[0] == "Loop":
            runs.append(dict(zip(names, np.array(rows).T)))
            names = None
        elif names:
            rows.append([float(w) for w in words])
    return runs


def static_line(path):
    text = open(path).read()
    match = re.search(r"^STATIC N (\d+): tip deflection / \(PL\^3/3EI\) = (\S+), "
                      r"rotation / \(PL\^2/2EI\) = (\S+)", text, re.M)
    return int(match.group(1)), float(match.group(2)), float(match.group(3))


fig, axes = plt.subplots(1, 3, figsize=(17, 4.4))
for n in (1, 4, 10):
    _, w, t = static_line(f"log.static{n}")
    print(f"static, {n:2d} elements: tip deflection / (PL^3/3EI) = {w:.10f}, "
          f"rotation / (PL^2/2EI) = {t:.10f}")
    run = thermo_runs(f"log.static{n}")[0]
    axes[0].plot(run["Time"], run["v_w"] / (-1.0e-4 / (3 * E * I)), label=f"{n} elements")
axes[0].axhline(1.0, color="k", lw=0.5)
axes[0].set_xlabel("time")
axes[0].set_ylabel("tip deflection / (P L^3 / 3 EI)")
axes[0].set_title("load on, damped (fix nve/damped)")
axes[0].legend()

for n in (5, 10, 20):
    ring = thermo_runs(f"log.ring{n}")[-1]
    time, w = ring["Time"], ring["v_w"]
    # period from the upward zero crossings (linear interpolation)
    k = np.nonzero((w[:-1] < 0) & (w[1:] >= 0))[0]
    crossings = time[k] - w[k] * (time[k + 1] - time[k]) / (w[k + 1] - w[k])
    period = (crossings[-1] - crossings[0]) / (len(crossings) - 1)
    ratio = (2 * math.pi / period) / OMEGA1
    print(f"ringing, {n:2d} elements: period {period:.5f}, omega / omega1(Euler-Bernoulli) "
          f"= {ratio:.5f} ({len(crossings) - 1} periods)")
    axes[1].plot(time - time[0], w / 1.0e-4 * 3 * E * I, label=f"{n} elements: "
                 f"omega/omega1 = {ratio:.4f}")
axes[1].set_xlabel("time after the load is taken off")
axes[1].set_ylabel("tip deflection / (P L^3 / 3 EI)")
axes[1].set_title("free vibration (fix nve/mca)")
axes[1].set_xlim(0, 2.5)
axes[1].legend(loc="lower left", fontsize=8)

# ringdown: the log decrement of the tip's swings against beta omega / 2
for beta in (0.001, 0.002):
    ring = thermo_runs(f"log.ringdown{beta}")[-1]
    time, w = ring["Time"] - ring["Time"][0], ring["v_w"]
    k = np.nonzero((w[1:-1] > w[:-2]) & (w[1:-1] >= w[2:]) & (w[1:-1] > 0))[0] + 1
    peaks, times = [], []
    for m in k:
        a, b, c = w[m - 1], w[m], w[m + 1]
        shift = 0.5 * (a - c) / (a - 2 * b + c)
        peaks.append(b - 0.25 * (a - c) * shift)
        times.append(time[m] + shift * (time[1] - time[0]))
    peaks, times = np.array(peaks), np.array(times)
    slope = np.polyfit(times, np.log(peaks), 1)[0]
    period = np.diff(times).mean()
    omega = 2 * math.pi / period
    zeta = -slope / omega
    print(f"ringdown, 5 elements, beta {beta}: period {period:.5f}, damping ratio "
          f"{zeta:.6f}, beta omega / 2 = {beta * omega / 2:.6f} "
          f"(ratio {zeta / (beta * omega / 2):.4f}; {len(peaks)} swings)")
    axes[2].plot(time, w / 1.0e-4 * 3 * E * I, label=f"beta = {beta}: zeta = {zeta:.5f}")
    axes[2].plot(time, peaks[0] * np.exp(-beta * omega / 2 * omega * (time - times[0]))
                 / 1.0e-4 * 3 * E * I, "k--", lw=0.6)
axes[2].set_xlabel("time after the load is taken off")
axes[2].set_ylabel("tip deflection / (P L^3 / 3 EI)")
axes[2].set_title("bond damping, 5 elements: zeta = beta omega / 2")
axes[2].legend(loc="lower left", fontsize=8)
fig.tight_layout()
fig.savefig("cantilever.png", dpi=110)
