"""Viscous flow to large strains: the shear strain and the bond count of
the sheared layer against time (logs log.flow<tau> with fix beam/freeze,
log.nofreeze<tau> without), the shear strain rate early (strain 0.05 to
0.35, where melted bonds still freeze again as the same pairs) and late
(strain 0.5 to 2.5, where the rows have exchanged neighbours), and the
power law of the late rates, rate = k tau^n; flow.png and the figures
printed."""

import math
import re
import sys

import numpy as np

EARLY, LATE = (0.05, 0.35), (0.5, 2.5)


def read(path):
    """tau, whether new bonds were made (freeze), and the thermo rows of the
    flow run: time, strain, bonds, bonds made."""
    text = open(path).read()
    match = re.search(r"^flow: tau (\S+) freeze (\d)", text, re.M)
    blocks = re.findall(r"^\s*Step\s+Time\s+v_strain\s+Bonds\s+v_made.*?\n(.*?)^Loop", text,
                        re.M | re.S)
    rows = np.array([[float(w) for w in line.split()[:5]] for line in blocks[-1].splitlines()
                     if re.match(r"^\s*\d", line)])
    return float(match.group(1)), match.group(2) == "1", rows[:, 1:]


def rate_between(time, strain, window):
    """The slope of the strain over the rows whose strain is in the window
    (None if the run does not cover it)."""
    inside = (strain >= window[0]) & (strain <= window[1])
    if inside.sum() < 5 or strain.max() < window[1]:
        return None
    return np.polyfit(time[inside], strain[inside], 1)[0]


def summary(path):
    tau, freeze, rows = read(path)
    time, strain, bonds, made = rows.T
    return {"path": path, "tau": tau, "freeze": freeze, "time": time - time[0],
            "strain": strain, "bonds": bonds, "made": made,
            "early": rate_between(time, strain, EARLY),
            "late": rate_between(time, strain, LATE)}


def main(logs):
    runs = sorted((summary(p) for p in logs), key=lambda r: (not r["freeze"], r["tau"]))
    for r in runs:
        bonds0 = r["bonds"][0]
        fmt = lambda v: "-" if v is None else f"{v:.4e}"
        print(f"tau {r['tau']:.4g} {'with' if r['freeze'] else 'without'} beam/freeze: strain "
              f"{r['strain'][-1]:.3f} at t = {r['time'][-1]:.0f}, bonds {r['bonds'].min():.0f} to "
              f"{r['bonds'].max():.0f} of {bonds0:.0f} (end {r['bonds'][-1] / bonds0:.1%}), "
              f"{r['made'][-1]:.0f} made; rate early {fmt(r['early'])}, late {fmt(r['late'])}")
    flowing = [r for r in runs if r["freeze"] and r["late"] is not None and r["early"] is not None]
    if len(flowing) >= 2:
        tau = np.array([r["tau"] for r in flowing])
        late = np.array([r["late"] for r in flowing])
        early = np.array([r["early"] for r in flowing])
        n_late, logk = np.polyfit(np.log(tau), np.log(late), 1)
        n_early = np.polyfit(np.log(tau), np.log(early), 1)[0]
        print(f"late rate = {math.exp(logk):.4g} tau^{n_late:.3f}; early rate ~ tau^{n_early:.3f} "
              f"(Glen: n = 3); late / early {', '.join(f'{v:.2f}' for v in late / early)}")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.2))
    for r in runs:
        label = f"tau {r['tau']:.3g}" + ("" if r["freeze"] else ", no new bonds")
        style = "-" if r["freeze"] else "--"
        left.plot(r["time"], r["strain"], style, label=label)
        right.plot(r["strain"], r["bonds"] / r["bonds"][0], style, label=label)
    left.set_xlabel("time (melting on)")
    left.set_ylabel("shear strain")
    left.set_ylim(0.0, 4.0)
    left.legend()
    right.set_xlabel("shear strain")
    right.set_ylabel("bonds / bonds of the lattice")
    right.set_xlim(0.0, 4.0)
    right.axvspan(*LATE, color="0.9")
    right.legend()
    fig.tight_layout()
    fig.savefig("flow.png", dpi=120)
    print("wrote flow.png")


if __name__ == "__main__":
    main(sys.argv[1:])
