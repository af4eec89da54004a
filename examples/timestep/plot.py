#!/usr/bin/env python3
"""Total energy of the free block at 0.5, 0.7 and 0.9 of the stable time
step (energy.<model>.<f>.dat of in.timestep; for the plastic and fracture
models it includes the plastic work and the released energy), relative
to its value at step 0:
its offset (the integrator's energy error for this motion, which excites
the fastest modes fully: the mean after the first SETTLE steps), its
drift per 1000 steps after them (slope of a straight line fitted to it)
and its spread (standard deviation); written to drift.md, drawn in
timestep.png."""

import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent
FRACTIONS = ("0.5", "0.7", "0.9")
MODELS = ("elastic", "plastic", "fracture")
SETTLE = 2000


def drift(path):
    data = np.loadtxt(path)
    step, energy = data[:, 0], data[:, 1]
    e0 = energy[0]
    late = step >= SETTLE
    slope = np.polyfit(step[late], energy[late], 1)[0]
    return (step, energy, energy[late].mean() / e0 - 1.0, 1000.0 * slope / e0,
            energy[late].std() / e0)


def main():
    rows = [f"| model | fraction of the stable time step | offset | drift per 1000 steps after "
            f"step {SETTLE} | spread |", "|---|---|---|---|---|"]
    fig, axes = plt.subplots(1, len(MODELS), figsize=(13, 4), sharey=True)
    for ax, model in zip(axes, MODELS):
        for f in FRACTIONS:
            path = HERE / f"energy.{model}.{f}.dat"
            if not path.exists():
                continue
            step, energy, offset, per_1000, spread = drift(path)
            rows.append(f"| {model} | {f} | {offset:.3g} | {per_1000:.2e} | {spread:.2e} |")
            ax.plot(step, energy / energy[0] - 1.0, label=f"{f} of the stable time step")
        ax.set_xlabel("step")
        ax.set_title(f"{model}")
        ax.legend()
    axes[0].set_ylabel("(E - E(0)) / E(0)")
    fig.suptitle("free fcc block, nu = 0.3, random motion: total energy")
    fig.tight_layout()
    fig.savefig(HERE / "timestep.png", dpi=110)
    (HERE / "drift.md").write_text("\n".join(rows) + "\n")
    print("\n".join(rows))


if __name__ == "__main__":
    main()
