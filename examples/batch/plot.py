#!/usr/bin/env python3
"""Energies of the batch scene (energies.dat of in.batch, appended by every
job of a chain) against time: kinetic, elastic and total, and the total
relative to its start.  Lines that a killed job wrote after its last restart
file are written again by its successor; the later ones are kept.  The
steps where a chain's jobs began (log.chain.*) are marked.  Draws
batch.png in the working directory (default: this directory)."""

import pathlib
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

WORK = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent)


def energies():
    rows = {}
    for line in (WORK / "energies.dat").read_text().splitlines():
        if line.startswith("#") or not line.strip():
            continue
        values = [float(w) for w in line.split()]
        rows[values[0]] = values    # a repeated time: the later line
    data = np.array([rows[t] for t in sorted(rows)])
    return data[:, 0], data[:, 1], data[:, 2], data[:, 3], data[:, 4]


def segment_starts():
    starts = []
    for log in sorted(WORK.glob("log.chain.*"), key=lambda p: int(p.suffix[1:])):
        # the first thermo line of the segment's run (the header with Time)
        m = re.search(r"^\s*Step\s+Time\b.*\n\s*(\d+)\s", log.read_text(), re.M)
        if m:
            starts.append(int(m.group(1)))
    return starts


def main():
    time, ke, erot, pe, etot = energies()
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    top.plot(time * 1e3, ke, lw=0.6, label="kinetic")
    top.plot(time * 1e3, pe, lw=0.6, label="elastic")
    top.plot(time * 1e3, etot, lw=1.2, color="k", label="total (with rotational)")
    top.set_ylabel("energy (J)")
    top.legend(loc="center right", fontsize=8)
    top.set_title(f"standing P wave, {len(time)} samples")
    bottom.plot(time * 1e3, etot / etot[0] - 1.0, lw=0.6, color="k")
    bottom.set_ylabel("total / total(0) - 1")
    bottom.set_xlabel("time (ms)")
    dt = np.diff(time).min() / 5 if len(time) > 1 else 0.0
    for step in segment_starts():
        for ax in (top, bottom):
            ax.axvline(step * dt * 1e3, color="r", lw=0.8, ls="--")
    fig.tight_layout()
    fig.savefig(WORK / "batch.png", dpi=120)
    drift = np.polyfit(time, etot / etot[0] - 1.0, 1)[0] * (time[-1] - time[0])
    print(f"BATCH plot: {len(time)} samples to t = {time[-1]:.6g} s; total energy "
          f"{etot[0]:.6e} -> {etot[-1]:.6e} J, spread {np.std(etot / etot[0]):.2e}, "
          f"fitted drift over the run {drift:.2e}")


if __name__ == "__main__":
    main()
