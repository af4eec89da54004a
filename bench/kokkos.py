"""KOKKOS_MCA benchmark: microseconds per automaton-step of pair mca on the
free fcc cubes of 34461 (n = 20) and 265721 (n = 40) automata, all with the
LAMMPS build that has the KOKKOS package (OpenMP backend), five ways:

    cpu       the CPU styles, 1 rank
    cpu_mpi2  the CPU styles, 2 MPI ranks
    kk1       -k on t 1 -sf kk, 1 rank
    kk2       -k on t 2 -sf kk, 1 rank (2 OpenMP threads)
    kk_mpi2   -k on t 1 -sf kk, 2 MPI ranks

Reported: wall-clock microseconds per automaton-step (us_wall) and the cost
in core-microseconds (us_wall x cores), the kk/CPU cost on one core
(kk1 / cpu, target <= 1.1) and the parallel efficiency on two threads
(kk1 / (2 kk2), target >= 0.9) and two ranks.

Usage (the kokkos build's lmp and mpirun on the PATH, e.g.
eval "$(tools/mca env kokkos)"; export PATH=$MCA_BUILD_KOKKOS:$PATH):
    /usr/bin/python3 kokkos.py [--sizes 20 40] [--repeat 3] [--out results] [--name kokkos]
Writes results/NAME.csv and results/NAME.png (NAME: kokkos, or kokkos5 for the
LAMMPS 4 Jul 2026 + Kokkos 5 build of 'tools/mca build kokkos5').
"""

import argparse
import csv
import os
import subprocess
import sys

from run import parse_log

HERE = os.path.dirname(os.path.abspath(__file__))
KK = ["-k", "on", "t", "{threads}", "-sf", "kk"]
MODES = {  # name: (ranks, threads, kokkos)
    "cpu": (1, 1, False),
    "cpu_mpi2": (2, 1, False),
    "kk1": (1, 1, True),
    "kk2": (1, 2, True),
    "kk_mpi2": (2, 1, True),
}
# timed steps per cube size: about 10 s of work per run on one core
STEPS = {10: 1000, 20: 200, 40: 40}


def run_mode(mode, n, steps, outdir, repeat=1, name="kokkos"):
    """Best of `repeat` runs (the noise of a shared machine only adds time)."""
    results = [run_once(mode, n, steps, outdir, name) for _ in range(repeat)]
    return min(results, key=lambda r: r["us_wall"])


def run_mode_command(mode, lmp, args, cwd):
    """Run lmp with its arguments args in a mode of MODES (the kk switches,
    mpirun for several ranks, the threads in the environment)."""
    ranks, threads, kokkos = MODES[mode]
    cmd = [lmp] + list(args)
    if kokkos:
        cmd += [a.format(threads=threads) for a in KK]
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks)] + cmd
    env = dict(os.environ, OMP_NUM_THREADS=str(threads), OMP_PROC_BIND="false")
    # a copied shared-library build loads the library next to it
    env["LD_LIBRARY_PATH"] = os.path.dirname(os.path.abspath(lmp)) + ":" + env.get(
        "LD_LIBRARY_PATH", "") if os.sep in lmp else env.get("LD_LIBRARY_PATH", "")
    subprocess.run(cmd, cwd=cwd, env=env, check=True)


def run_once(mode, n, steps, outdir, name="kokkos", lmp="lmp", variables=None):
    ranks, threads, _ = MODES[mode]
    log = os.path.join(outdir, f"log.{name}.{mode}.n{n}")
    args = ["-in", "in.bench", "-var", "style", "mca", "-var", "geometry", "cube",
            "-var", "n", str(n), "-var", "nsteps", str(steps), "-log", log, "-screen", "none"]
    for key, value in (variables or {}).items():
        args += ["-var", key, str(value)]
    run_mode_command(mode, lmp, args, HERE)
    with open(log) as f:
        result = parse_log(f.read())
    cores = ranks * threads
    us_wall = 1e6 * result["seconds"] / (result["atoms"] * result["steps"])
    return {"mode": mode, "n": n, "atoms": result["atoms"], "ranks": ranks, "threads": threads,
            "steps": result["steps"], "seconds": result["seconds"], "us_wall": us_wall,
            "core_us": us_wall * cores,
            "pair_percent": 100.0 * result["sections"].get("Pair", 0.0) / result["seconds"]}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sizes", type=int, nargs="+", default=[20, 40])
    ap.add_argument("--repeat", type=int, default=3, help="runs per mode (the best counts)")
    ap.add_argument("--out", default=os.path.join(HERE, "results"))
    ap.add_argument("--name", default="kokkos", help="name of the CSV, plot and logs")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)

    rows = []
    for n in args.sizes:
        steps = STEPS.get(n, max(10, int(2e6 / (4 * n**3))))
        by_mode = {}
        for mode in MODES:
            row = run_mode(mode, n, steps, args.out, args.repeat, args.name)
            by_mode[mode] = row
            rows.append(row)
            print(f"n={n:3d} atoms={row['atoms']:7d} {mode:9s} {row['us_wall']:7.3f} us/atom-step"
                  f" (wall), {row['core_us']:7.3f} core-us", flush=True)
        kk_cost = by_mode["kk1"]["us_wall"] / by_mode["cpu"]["us_wall"]
        eff_threads = by_mode["kk1"]["us_wall"] / (2 * by_mode["kk2"]["us_wall"])
        eff_mpi_kk = by_mode["kk1"]["us_wall"] / (2 * by_mode["kk_mpi2"]["us_wall"])
        eff_mpi_cpu = by_mode["cpu"]["us_wall"] / (2 * by_mode["cpu_mpi2"]["us_wall"])
        for row in rows[-len(MODES):]:
            row.update({"kk1_over_cpu": kk_cost, "efficiency_kk_2threads": eff_threads,
                        "efficiency_kk_2ranks": eff_mpi_kk, "efficiency_cpu_2ranks": eff_mpi_cpu})
        print(f"        kk/CPU on 1 core {kk_cost:.3f}; efficiency kk 2 threads {eff_threads:.3f},"
              f" kk 2 ranks {eff_mpi_kk:.3f}, CPU 2 ranks {eff_mpi_cpu:.3f}", flush=True)

    path = os.path.join(args.out, f"{args.name}.csv")
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    print(f"wrote {path}")
    subprocess.run([sys.executable, os.path.join(HERE, "plot_kokkos.py"), args.out, args.name],
                   check=True)


if __name__ == "__main__":
    main()
