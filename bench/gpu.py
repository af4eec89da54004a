"""KOKKOS_MCA on a GPU: automaton-steps per second of pair mca/kk on the
free fcc cubes of bench/in.bench (n = 20: 34461, 40: 265721, 60: 886981
automata) with -k on g 1 -sf kk, against the CPU styles on one core of the
same machine, with one LAMMPS executable built with Kokkos for the GPU.

Reported per run: wall-clock microseconds per automaton-step, automaton-
steps per second, the share of the pair style and of the communication in
the loop time, and the memory LAMMPS reports per rank (host memory only:
the device views are not counted there).

Usage (the GPU build's lmp on the PATH):
    python3 gpu.py [--sizes 20 40 60] [--repeat 3] [--out results]
Writes <out>/gpu.csv and the logs log.gpu.<mode>.n<n>.
"""

import argparse
import csv
import os
import subprocess

from run import parse_log

HERE = os.path.dirname(os.path.abspath(__file__))
MODES = {  # name: extra command-line arguments
    "cpu": [],
    "kk_gpu": ["-k", "on", "g", "1", "-sf", "kk"],
}
# timed steps: some seconds per run; the CPU runs are shorter (one core)
STEPS = {"cpu": {20: 100, 40: 20, 60: 10}, "kk_gpu": {20: 2000, 40: 1000, 60: 400}}


def run_once(mode, n, steps, outdir, lmp="lmp", name=None):
    """One run of the cube of edge n; the log is <outdir>/log.gpu.<name>.n<n>
    (name: the mode unless given)."""
    log = os.path.join(outdir, f"log.gpu.{name or mode}.n{n}")
    cmd = [lmp, "-in", "in.bench", "-var", "style", "mca", "-var", "geometry", "cube",
           "-var", "n", str(n), "-var", "nsteps", str(steps), "-log", log,
           "-screen", "none"] + MODES[mode]
    env = dict(os.environ, OMP_NUM_THREADS="1", OMP_PROC_BIND="false")
    subprocess.run(cmd, cwd=HERE, env=env, check=True)
    with open(log) as f:
        result = parse_log(f.read())
    us_wall = 1e6 * result["seconds"] / (result["atoms"] * result["steps"])
    sections = result["sections"]
    return {"mode": mode, "n": n, "atoms": result["atoms"], "steps": result["steps"],
            "seconds": result["seconds"], "us_wall": us_wall,
            "atom_steps_per_s": 1e6 / us_wall,
            "pair_percent": 100.0 * sections.get("Pair", 0.0) / result["seconds"],
            "comm_percent": 100.0 * sections.get("Comm", 0.0) / result["seconds"],
            "host_mem_mb": result["mem_mb_avg"]}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sizes", type=int, nargs="+", default=[20, 40, 60])
    ap.add_argument("--repeat", type=int, default=3, help="runs per mode (the best counts)")
    ap.add_argument("--out", default=os.path.join(HERE, "results"))
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)

    rows = []
    for n in args.sizes:
        by_mode = {}
        for mode in MODES:
            steps = STEPS[mode].get(n, 10)
            runs = [run_once(mode, n, steps, args.out) for _ in range(args.repeat)]
            row = min(runs, key=lambda r: r["us_wall"])
            by_mode[mode] = row
            rows.append(row)
            print(f"n={n:3d} atoms={row['atoms']:7d} {mode:7s} {row['us_wall']:8.4f} us/atom-step"
                  f" {row['atom_steps_per_s']:.3e} atom-steps/s, pair {row['pair_percent']:.0f} %,"
                  f" comm {row['comm_percent']:.0f} %", flush=True)
        speedup = by_mode["cpu"]["us_wall"] / by_mode["kk_gpu"]["us_wall"]
        for row in rows[-len(MODES):]:
            row["gpu_over_one_core"] = speedup
        print(f"        GPU / one core of the same machine: {speedup:.1f}x", flush=True)

    path = os.path.join(args.out, "gpu.csv")
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
