"""Memory per automaton of one or more LAMMPS executables: LAMMPS's own
estimate ("Per MPI rank memory allocated", avg), the heap in use after the
run (glibc's allocated bytes, "Current reserved memory pool size" of "info
memory", which in.bench prints at its end: what a run holds between its
set-ups, whether LAMMPS's estimate counts it or not) and the peak resident
set of the process (GNU time; and its excess over the peak of a box of 32
automata, n = 2: what the executable with MPI and its libraries holds
anyway), per automaton, for the periodic fcc boxes of in.bench (4 n^3
automata) with pair mca (elastic, and with plasticity and fracture on, as
run.py) and pair granular for reference.  1 rank, a few
steps (the set-up's stable time step estimate is in the peak).

    /usr/bin/python3 bench/memory.py --lmp base=/tmp/base/lmp new=~/.cache/mca/build/current/lmp
        [--sizes 20 40] [--steps 5] [--out results/memory]

An entry label=path,KEY=VALUE,... gives the pair mca runs of that
executable in.bench variables too (mixed=PATH,precision=mixed: the link
rows in precision mixed).

An executable's directory goes first on LD_LIBRARY_PATH (a copied build
with its liblammps.so*).  Writes OUT.md and OUT.csv.
"""

import argparse
import csv
import os
import re
import subprocess
import tempfile

from run import HERE, RUNS, parse_log, report


def measure(lmp, label, variables, n, steps, logdir):
    log = os.path.join(logdir, f"log.{label}.n{n}")
    rss = log + ".rss"
    style = "granular" if label == "granular" else "mca"
    cmd = ["/usr/bin/time", "-f", "%M", "-o", rss, lmp, "-in", "in.bench", "-var", "style", style,
           "-var", "geometry", "periodic", "-var", "n", str(n), "-var", "nsteps", str(steps),
           "-log", log, "-screen", "none"]
    for key, value in variables.items():
        cmd += ["-var", key, value]
    env = dict(os.environ, OMP_NUM_THREADS="1",
               LD_LIBRARY_PATH=os.path.dirname(lmp) + ":" + os.environ.get("LD_LIBRARY_PATH", ""))
    subprocess.run(cmd, cwd=HERE, env=env, check=True)
    with open(log) as f:
        r = parse_log(f.read())
    with open(rss) as f:
        peak_kb = int(f.read().split()[-1])
    with open(log) as f:
        heap = re.findall(r"Current reserved memory pool size: ([\d.eE+-]+) Mbyte", f.read())
    return {"atoms": r["atoms"], "estimate_kib": r["mem_mb_avg"] * 1024.0 / r["atoms"],
            "heap_after_kib": float(heap[-1]) * 1024.0 / r["atoms"] if heap else float("nan"),
            "peak_rss_kib": peak_kb / r["atoms"], "peak_rss_total_kib": peak_kb}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--lmp", nargs="+", required=True,
                    help="label=path[,KEY=VALUE...] of each executable")
    ap.add_argument("--sizes", type=int, nargs="+", default=[20, 40])
    ap.add_argument("--steps", type=int, default=5)
    ap.add_argument("--out", default=os.path.join(HERE, "results", "memory"))
    args = ap.parse_args()
    builds, build_vars = [], {}
    for entry in args.lmp:
        label, rest = entry.split("=", 1)
        path, *pairs = rest.split(",")
        builds.append((label, os.path.abspath(os.path.expanduser(path))))
        build_vars[label] = dict(kv.split("=", 1) for kv in pairs)
    runs = [(label, variables) for label, _, geometry, variables in RUNS if geometry == "periodic"]

    rows, rest = [], {}
    with tempfile.TemporaryDirectory() as logs:
        for n in args.sizes:
            for label, variables in runs:
                for build, lmp in builds:
                    if label == "granular" and build != builds[0][0]:
                        continue    # (the same code in every build)
                    extra = {} if label == "granular" else build_vars[build]
                    # the executable's own peak (MPI, the libraries): a box of 32 automata
                    if (build, label) not in rest:
                        rest[build, label] = measure(lmp, label, dict(variables, **extra), 2,
                                                     args.steps, logs)["peak_rss_total_kib"]
                    r = measure(lmp, label, dict(variables, **extra), n, args.steps, logs)
                    r["peak_rss_above_rest_kib"] = ((r["peak_rss_total_kib"] - rest[build, label]) /
                                                    r["atoms"])
                    rows.append({"build": build, "style": label, "n": n, **r,
                                 "rest_kib": rest[build, label]})
                    print(f"{build:8s} {label:9s} {r['atoms']:7d} automata: estimate "
                          f"{r['estimate_kib']:.2f} KiB, heap after the run "
                          f"{r['heap_after_kib']:.2f} KiB, peak RSS {r['peak_rss_kib']:.2f} KiB "
                          f"({r['peak_rss_above_rest_kib']:.2f} above the "
                          f"{rest[build, label] / 1024.0:.1f} MiB of a run of 32)", flush=True)

    with open(args.out + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    lines = ["| build | style | automata | LAMMPS estimate KiB per automaton | "
             "heap after the run | peak RSS | peak RSS above a run of 32 automata |",
             "|---|---|---|---|---|---|---|"]
    lines += [f"| {r['build']} | {r['style']} | {r['atoms']} | {r['estimate_kib']:.2f} | "
              f"{r['heap_after_kib']:.2f} | {r['peak_rss_kib']:.2f} | "
              f"{r['peak_rss_above_rest_kib']:.2f} |" for r in rows]
    report(lines, args.out + ".md")


if __name__ == "__main__":
    main()
