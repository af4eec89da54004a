"""MCA vs pair granular benchmark: microseconds per automaton-step and bytes
per automaton for fcc packings of edge 10a, 20a and 40a (periodic boxes of
4000, 32000, 256000 automata; MCA also as free cubes of 4631, 34461, 265721)
on 1 core and 2 MPI ranks, and MCA with plasticity and fracture on (mca+pf,
periodic boxes).  Both styles run in the same invocation, on the same
lattice, with the same neighbour count and time step.

Usage (lmp and mpirun on the PATH, e.g. eval "$(tools/mca env current)"):
    /usr/bin/python3 run.py [--sizes 10 20 40] [--ranks 1 2] [--steps N]
                            [--out results]
Writes results/bench.csv, results/breakdown.csv and results/bench.png.
"""

import argparse
import csv
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
# (label, style, geometry, variables of in.mca): the ratio is taken on the
# periodic box; the free cube (the scene of the issue, MCA only) shows the
# cost of the surface; "mca+pf" is MCA with plasticity (von Mises, yield 2
# MPa: the vibration yields the automata) and fracture (Drucker-Prager at
# strengths it never reaches: every link judged every step) on
RUNS = (("mca", "mca", "periodic", {}), ("granular", "granular", "periodic", {}),
        ("mca", "mca", "cube", {}),
        ("mca+pf", "mca", "periodic", {"plasticity": "mises", "fracture": "drucker_prager"}))
# timed steps per size: about 10 s of MCA work per run on one core
DEFAULT_STEPS = {10: 1000, 20: 200, 40: 40}


def parse_log(text):
    """Loop time, atoms, steps, memory and the timing breakdown of one run."""
    loop = re.findall(r"Loop time of ([\d.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms",
                      text)
    if not loop:
        raise RuntimeError("no 'Loop time' line in the log")
    seconds, procs, steps, atoms = loop[-1]
    mem = re.findall(r"Per MPI rank memory allocat\w+ \(min/avg/max\) = "
                     r"([\d.]+) \| ([\d.]+) \| ([\d.]+) Mbytes", text)
    neighs = re.findall(r"Ave neighs/atom = ([\d.eE+-]+)", text)
    sections = {}
    for name in ("Pair", "Bond", "Neigh", "Comm", "Output", "Modify", "Other"):
        m = re.findall(rf"^{name}\s+\|\s*[\d.]+\s*\|\s*([\d.]+)\s*\|.*\|\s*([\d.]+)\s*$", text,
                       re.M)
        if m:
            sections[name] = float(m[-1][0])
    return {"seconds": float(seconds), "procs": int(procs), "steps": int(steps),
            "atoms": int(atoms), "mem_mb_avg": float(mem[-1][1]) if mem else float("nan"),
            "neighs_per_atom": float(neighs[-1]) if neighs else float("nan"),
            "sections": sections}


def report(lines, out=None):
    """Print a results table (its lines) and write it to the file out, if given."""
    text = "\n".join(lines) + "\n"
    print(text)
    if out:
        with open(out, "w") as handle:
            handle.write(text)


def run_one(label, style, geometry, n, ranks, steps, outdir, variables=None):
    log = os.path.join(outdir, f"log.bench.{label}.{geometry}.n{n}.{ranks}")
    cmd = ["lmp", "-in", "in.bench", "-var", "style", style, "-var", "geometry", geometry,
           "-var", "n", str(n),
           "-var", "nsteps", str(steps), "-log", log, "-screen", "none"]
    for key, value in (variables or {}).items():
        cmd += ["-var", key, value]
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks)] + cmd
    # peak resident memory of the (first) process, from GNU time
    timefile = log + ".rss"
    cmd = ["/usr/bin/time", "-f", "%M", "-o", timefile] + cmd
    env = dict(os.environ, OMP_NUM_THREADS="1")
    subprocess.run(cmd, cwd=HERE, env=env, check=True)
    with open(log) as f:
        result = parse_log(f.read())
    with open(timefile) as f:
        result["peak_rss_kb"] = int(f.read().split()[-1])
    os.remove(timefile)
    return result


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sizes", type=int, nargs="+", default=[10, 20, 40])
    ap.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--steps", type=int, default=None, help="timed steps (default: by size)")
    ap.add_argument("--out", default=os.path.join(HERE, "results"))
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)

    rows, breakdown = [], []
    for n in args.sizes:
        steps = args.steps or DEFAULT_STEPS.get(n, max(10, int(4e6 / (4 * n**3))))
        for ranks in args.ranks:
            per_style = {}
            for label, style, geometry, variables in RUNS:
                r = run_one(label, style, geometry, n, ranks, steps, args.out, variables)
                us = 1e6 * r["seconds"] * r["procs"] / (r["atoms"] * r["steps"])
                bytes_per_atom = r["mem_mb_avg"] * r["procs"] * 2**20 / r["atoms"]
                if geometry == "periodic":
                    per_style[label] = us
                row = {"style": label, "geometry": geometry, "n": n, "atoms": r["atoms"], "ranks": ranks,
                       "steps": r["steps"], "seconds": r["seconds"],
                       "us_per_atom_step": us,
                       "neighs_per_atom": r["neighs_per_atom"],
                       "lammps_bytes_per_atom": bytes_per_atom,
                       "peak_rss_mb_rank0": r["peak_rss_kb"] / 1024.0}
                rows.append(row)
                for name, sec in r["sections"].items():
                    breakdown.append({"style": label, "geometry": geometry, "n": n, "ranks": ranks, "section": name,
                                      "us_per_atom_step":
                                      1e6 * sec * r["procs"] / (r["atoms"] * r["steps"]),
                                      "percent": 100.0 * sec / r["seconds"]})
                print(f"{label:9s} {geometry:8s} n={n:3d} atoms={r['atoms']:7d} ranks={ranks} "
                      f"{us:7.3f} us/atom-step (core-us) "
                      f"{bytes_per_atom:8.0f} B/atom  neighs/atom {r['neighs_per_atom']:.2f}",
                      flush=True)
            print(f"          ratio mca/granular = {per_style['mca'] / per_style['granular']:.2f},"
                  f" mca+pf/granular = {per_style['mca+pf'] / per_style['granular']:.2f}",
                  flush=True)

    with open(os.path.join(args.out, "bench.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    with open(os.path.join(args.out, "breakdown.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(breakdown[0]))
        w.writeheader()
        w.writerows(breakdown)
    print(f"wrote {args.out}/bench.csv and breakdown.csv")
    subprocess.run([sys.executable, os.path.join(HERE, "plot.py"), args.out], check=True)


if __name__ == "__main__":
    main()
