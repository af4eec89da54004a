#!/usr/bin/env python3
"""The standing waves of in.wave: the projection of the displacement against
time at each level for the three scalings of Cu Morse and the
energy-consistent scaling of Fe EAM (gp_scaling.png), and the periods from
its first zero (a quarter period) with their ratios to level 1 against the
long-wave speeds c0, sqrt(s) c0 and s c0 (periods.md)."""

import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent
# file name part, title, exponent e of the expected period ratio s^e
SERIES = [("energy", "Cu Morse, energy", 0.0), ("pmap", "Cu Morse, pmap", -0.5),
          ("pmap_invmap", "Cu Morse, pmap_invmap", -1.0),
          ("eam.energy", "Fe EAM, energy", 0.0)]


def period(data):
    t, p = data[:, 0], data[:, 1]
    for k in range(len(t) - 1):
        if p[k] > 0.0 >= p[k + 1]:
            return 4.0 * (t[k] + (t[k + 1] - t[k]) * p[k] / (p[k] - p[k + 1]))
    return float("nan")


def main():
    rows = ["| potential, scaling | level | period (ps) | ratio to level 1 | expected s^e |",
            "|---|---|---|---|---|"]
    fig, axes = plt.subplots(1, 4, figsize=(17, 4), sharey=True)
    for ax, (scaling, title, exponent) in zip(axes, SERIES):
        base = None
        for level in (1, 2, 3):
            path = HERE / f"wave.{scaling}.{level}.dat"
            if not path.exists():
                continue
            data = np.loadtxt(path)
            T = period(data)
            base = T if level == 1 else base
            s = 2.0 ** (level - 1)
            rows.append(f"| {title} | {level} | {T:.5f} | {T / base:.4f} | {s**exponent:.4f} |")
            ax.plot(data[:, 0], data[:, 1] / data[0, 1], label=f"level {level}")
        ax.set_title(title)
        ax.set_xlabel("time (ps)")
        ax.legend()
    axes[0].set_ylabel("projection / initial")
    fig.suptitle("P standing wave of the same box at GP levels 1-3 (k = 2)")
    fig.tight_layout()
    fig.savefig(HERE / "gp_scaling.png", dpi=110)
    (HERE / "periods.md").write_text("\n".join(rows) + "\n")
    print("\n".join(rows))


if __name__ == "__main__":
    main()
