"""KOKKOS_MCA on a GPU: automaton-steps per second of pair mca/kk on the
free fcc cubes of bench/in.bench (n = 20: 34461, 40: 265721, 60: 885781
automata) with -k on g 1 -sf kk, against the CPU styles on one core of the
same machine, and against LAMMPS's pair gran/hooke/history/kk on the same
lattice in a periodic box (n = 20: 32000, 40: 256000, 60: 864000 spheres,
12 contacts each, shear history; in.gran_hooke), with one LAMMPS
executable built with Kokkos for the GPU (tools/mca-gpu).

Reported per run: wall-clock microseconds per automaton-step, automaton-
steps per second, the share of the pair style and of the communication in
the loop time, and the memory LAMMPS reports per rank (host memory only:
the device views are not counted there).

Usage (the GPU build's lmp on the PATH):
    python3 gpu.py [--sizes 20 40 60] [--repeat 3] [--modes cpu kk_gpu gran_kk_gpu]
                   [--out results]
Writes <out>/gpu.csv (or --csv) and the logs log.gpu.<mode>.n<n>.
"""

import argparse
import csv
import os
import subprocess

from run import parse_log

HERE = os.path.dirname(os.path.abspath(__file__))
GPU = ["-k", "on", "g", "1", "-sf", "kk"]
# gran/hooke/history/kk computes on a half list (newton on: each contact once)
GRAN_PACKAGE = "neigh half newton on"


def gran_mode(package=GRAN_PACKAGE):
    """in.bench's style and geometry and the arguments of gran/hooke/history/kk
    with the '-pk kokkos' keywords `package` (also bench/gpu_profile.py's)."""
    return ("gran_hooke", "periodic", GPU + ["-pk", "kokkos"] + package.split())


MODES = {  # name: (style and geometry of in.bench, extra command-line arguments)
    "cpu": ("mca", "cube", []),
    "kk_gpu": ("mca", "cube", GPU),
    "gran_kk_gpu": gran_mode(),
}
# timed steps: some seconds per run; the CPU runs are shorter (one core)
STEPS = {"cpu": {20: 100, 40: 20, 60: 10}, "kk_gpu": {20: 2000, 40: 1000, 60: 400},
         "gran_kk_gpu": {20: 2000, 40: 1000, 60: 400}}


def run_once(mode, n, steps, outdir, lmp="lmp", name=None):
    """One run of the cube of edge n; the log is <outdir>/log.gpu.<name>.n<n>
    (name: the mode unless given)."""
    log = os.path.join(outdir, f"log.gpu.{name or mode}.n{n}")
    style, geometry, extra = MODES[mode]
    cmd = [lmp, "-in", "in.bench", "-var", "style", style, "-var", "geometry", geometry,
           "-var", "n", str(n), "-var", "nsteps", str(steps), "-log", log,
           "-screen", "none"] + extra
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
    ap.add_argument("--modes", nargs="+", choices=list(MODES), default=list(MODES))
    ap.add_argument("--out", default=os.path.join(HERE, "results"))
    ap.add_argument("--csv", default="gpu.csv", help="name of the table in --out")
    ap.add_argument("--gran-package", default=GRAN_PACKAGE,
                    help="the '-pk kokkos' keywords of gran/hooke/history/kk")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    MODES["gran_kk_gpu"] = gran_mode(args.gran_package)

    rows = []
    for n in args.sizes:
        by_mode = {}
        for mode in args.modes:
            steps = STEPS[mode].get(n, 10)
            try:
                runs = [run_once(mode, n, steps, args.out) for _ in range(args.repeat)]
            except subprocess.CalledProcessError as err:
                # (gran/hooke/history/kk of LAMMPS 2021 stopped on an H200)
                print(f"n={n:3d} {mode}: failed ({err.returncode}), see its log", flush=True)
                continue
            row = min(runs, key=lambda r: r["us_wall"])
            by_mode[mode] = row
            rows.append(row)
            print(f"n={n:3d} atoms={row['atoms']:7d} {mode:7s} {row['us_wall']:8.4f} us/atom-step"
                  f" {row['atom_steps_per_s']:.3e} atom-steps/s, pair {row['pair_percent']:.0f} %,"
                  f" comm {row['comm_percent']:.0f} %", flush=True)
        for row in by_mode.values():
            row["gpu_over_one_core"] = float("nan")
            row["mca_over_gran"] = float("nan")
        if "cpu" in by_mode and "kk_gpu" in by_mode:
            speedup = by_mode["cpu"]["us_wall"] / by_mode["kk_gpu"]["us_wall"]
            by_mode["kk_gpu"]["gpu_over_one_core"] = speedup
            print(f"        GPU / one core of the same machine: {speedup:.1f}x", flush=True)
        if "gran_kk_gpu" in by_mode and "kk_gpu" in by_mode:
            ratio = by_mode["kk_gpu"]["us_wall"] / by_mode["gran_kk_gpu"]["us_wall"]
            by_mode["kk_gpu"]["mca_over_gran"] = ratio
            print(f"        mca/kk / gran/hooke/history/kk per automaton-step: {ratio:.2f}",
                  flush=True)
        # the table so far (a run cut by a time limit keeps the sizes done)
        if rows:
            path = os.path.join(args.out, args.csv)
            with open(path, "w", newline="") as f:
                writer = csv.DictWriter(f, fieldnames=list(rows[0]))
                writer.writeheader()
                writer.writerows(rows)
            print(f"wrote {path}", flush=True)
    if not rows:
        raise SystemExit("no run succeeded")


if __name__ == "__main__":
    main()
