#!/usr/bin/python3
"""Cost of pair_style mlp: microseconds per particle-step on a periodic
2-D hexagonal lattice (in.mlp: 2 nx ny particles at T = 0.02, NVE) for
LAMMPS's pair morse (a half list: each pair once) and pair mlp with the
same Morse potential and the return force (literal and conservative; a
full list: each pair twice; frame: literal with the axes of fix
mlp/frame, the whole lattice one body measured every step), with the CPU styles and the kk styles on 1
and 2 threads (the build with KOKKOS).  Reported: the whole step and the
Pair section per particle-step, best of --repeat runs (the runs of each
repeat one after the other).

    eval "$(tools/mca env kokkos)"
    /usr/bin/python3 bench/mlp.py [--nx 200 --ny 100] [--steps 200] [--repeat 3]
        [--out bench/results/mlp.md]
"""
import argparse
import os
import subprocess
import tempfile

from run import parse_log, report

HERE = os.path.dirname(os.path.abspath(__file__))
MODES = {"cpu": (), "kk1": ("-k", "on", "t", "1", "-sf", "kk"),
         "kk2": ("-k", "on", "t", "2", "-sf", "kk")}
STYLES = ("morse", "literal", "conservative", "frame")


def run_once(lmp, style, mode, args, outdir):
    log = os.path.join(outdir, f"log.mlp.{style}.{mode}")
    cmd = [lmp, "-in", os.path.join(HERE, "in.mlp"), "-var", "style", style, "-var", "nx",
           str(args.nx), "-var", "ny", str(args.ny), "-var", "nsteps", str(args.steps),
           "-log", log, "-screen", "none"] + list(MODES[mode])
    threads = "2" if mode == "kk2" else "1"
    env = dict(os.environ, OMP_NUM_THREADS=threads, OMP_PROC_BIND="false")
    subprocess.run(cmd, cwd=outdir, env=env, check=True)
    result = parse_log(open(log).read())
    per = 1e6 / (result["atoms"] * result["steps"])
    return {"step": result["seconds"] * per, "pair": result["sections"].get("Pair", 0.0) * per}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--lmp", default="lmp")
    ap.add_argument("--nx", type=int, default=200)
    ap.add_argument("--ny", type=int, default=100)
    ap.add_argument("--steps", type=int, default=200)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--modes", nargs="+", default=list(MODES), choices=list(MODES))
    ap.add_argument("--out", default=None)
    args = ap.parse_args()
    runs = {}
    with tempfile.TemporaryDirectory() as outdir:
        for _ in range(args.repeat):
            for mode in args.modes:
                for style in STYLES:
                    runs.setdefault((mode, style), []).append(
                        run_once(args.lmp, style, mode, args, outdir))
    lines = [f"hexagonal lattice of {2 * args.nx * args.ny} particles, {args.steps} steps, "
             f"best of {args.repeat}; us per particle-step", "",
             "| mode | style | step | Pair | Pair / morse cpu |", "|---|---|---|---|---|"]
    base = min(r["pair"] for r in runs[(args.modes[0], "morse")])
    for mode in args.modes:
        for style in STYLES:
            if mode != "cpu" and style == "morse":
                continue    # (pair morse/kk is not in every KOKKOS build)
            best = min(runs[(mode, style)], key=lambda r: r["step"])
            lines.append(f"| {mode} | {style} | {best['step']:.3f} | {best['pair']:.3f} | "
                         f"{best['pair'] / base:.2f} |")
    report(lines, args.out)


if __name__ == "__main__":
    main()
