"""Plot bench.csv: cost per automaton-step and memory per automaton, MCA vs granular."""

import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "results")
with open(os.path.join(out, "bench.csv")) as f:
    rows = list(csv.DictReader(f))

fig, (ax1, ax2, ax3) = plt.subplots(1, 3, figsize=(13, 4))
for style, marker in (("mca", "o"), ("granular", "s"), ("mca+pf", "D")):
    for ranks, ls in (("1", "-"), ("2", "--")):
        sel = [r for r in rows if r["style"] == style and r["ranks"] == ranks
               and r["geometry"] == "periodic"]
        if not sel:
            continue
        atoms = [int(r["atoms"]) for r in sel]
        ax1.plot(atoms, [float(r["us_per_atom_step"]) for r in sel], marker=marker, ls=ls,
                 label=f"{style}, {ranks} rank(s)")
        if style == "mca":
            cube = [r for r in rows if r["style"] == style and r["ranks"] == ranks
                    and r["geometry"] == "cube"]
            ax1.plot([int(r["atoms"]) for r in cube], [float(r["us_per_atom_step"]) for r in cube],
                     marker="^", ls=ls, label=f"mca free cube, {ranks} rank(s)")
        if ranks == "1":
            ax3.plot(atoms, [float(r["lammps_bytes_per_atom"]) / 1024 for r in sel],
                     marker=marker, label=f"{style} (LAMMPS estimate)")
for label, marker in (("mca", "o"), ("mca+pf", "D")):
    for ranks, ls in (("1", "-"), ("2", "--")):
        mca = {r["n"]: r for r in rows
               if r["style"] == label and r["ranks"] == ranks and r["geometry"] == "periodic"}
        gran = {r["n"]: r for r in rows if r["style"] == "granular" and r["ranks"] == ranks}
        keys = [n for n in mca if n in gran]
        if keys:
            ax2.plot([int(mca[n]["atoms"]) for n in keys],
                     [float(mca[n]["us_per_atom_step"]) / float(gran[n]["us_per_atom_step"])
                      for n in keys], marker=marker, ls=ls, label=f"{label}, {ranks} rank(s)")
ax2.axhline(1.5, color="k", lw=1, ls=":", label="target 1.5")
for ax in (ax1, ax2, ax3):
    ax.set_xscale("log")
    ax.set_xlabel("automata")
    ax.legend(fontsize=8)
ax1.set_ylabel("core-microseconds per automaton-step")
ax1.set_title("cost (periodic box unless marked)")
ax2.set_title("MCA / granular, periodic box (+pf: plasticity, fracture)")
ax3.set_title("memory, 1 rank")
ax2.set_ylabel("MCA / granular cost")
ax3.set_ylabel("KiB per automaton")
ax1.set_ylim(bottom=0)
ax2.set_ylim(bottom=0)
ax3.set_ylim(bottom=0)
fig.tight_layout()
fig.savefig(os.path.join(out, "bench.png"), dpi=110)
print(f"wrote {out}/bench.png")
