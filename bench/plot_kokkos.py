"""Plot results/NAME.csv (written by kokkos.py; NAME kokkos by default):
microseconds per automaton-step (wall clock) of each mode for each cube size.

Usage: /usr/bin/python3 plot_kokkos.py [results [NAME]]
"""

import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "results")
    name = sys.argv[2] if len(sys.argv) > 2 else "kokkos"
    with open(os.path.join(out, f"{name}.csv")) as f:
        rows = list(csv.DictReader(f))
    modes = list(dict.fromkeys(r["mode"] for r in rows))
    sizes = sorted({int(r["atoms"]) for r in rows})
    fig, ax = plt.subplots(figsize=(7, 4))
    width = 0.8 / len(sizes)
    for k, atoms in enumerate(sizes):
        values = [next(float(r["us_wall"]) for r in rows
                       if r["mode"] == m and int(r["atoms"]) == atoms) for m in modes]
        xs = [i + (k - (len(sizes) - 1) / 2) * width for i in range(len(modes))]
        bars = ax.bar(xs, values, width, label=f"{atoms} automata")
        ax.bar_label(bars, fmt="%.2f", fontsize=7)
    ax.set_xticks(range(len(modes)))
    ax.set_xticklabels(modes)
    ax.set_ylabel("wall-clock us per automaton-step")
    version = {"kokkos": "LAMMPS 29 Sep 2021 + Kokkos 3.4",
               "kokkos5": "LAMMPS 4 Jul 2026 + Kokkos 5"}.get(name, name)
    ax.set_title(f"pair mca, CPU styles and Kokkos (OpenMP) variants ({version})", fontsize=9)
    ax.legend()
    fig.tight_layout()
    path = os.path.join(out, f"{name}.png")
    fig.savefig(path, dpi=120)
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
