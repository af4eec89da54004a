#!/usr/bin/python3
"""Weak scaling of a lattice-particle scene (NUMFRAC's test, reference case
18 of the NUMFRAC/MLP notes): a fixed number of particles per MPI rank, the
time per 100 steps against the number of ranks.  The scene is in.mlp (a
periodic 2-D hexagonal lattice at T = 0.02, NVE) grown along x with the
ranks (processors R 1 1: every rank owns the same slab and has two
neighbours whatever R), pair mlp (literal) or LAMMPS's pair morse.
Reported per rank count: particles, seconds per 100 steps (best of
--repeat), the efficiency t(1)/t(R), and the share of Pair and Comm.

    eval "$(tools/mca env current)"
    /usr/bin/python3 bench/weak_scaling.py --lmp $MCA_BUILD_CURRENT/lmp
        [--per-rank 40000] [--ranks 1 2] [--steps 400] [--repeat 3]
        [--style literal] [--out bench/results/weak_scaling.md]

On a cluster, the same script runs inside one allocation (each rank count
a separate mpirun; ranks up to the allocation's cores) or, for many nodes,
one job per rank count with the same --per-rank (examples/batch shows the
Slurm scripts); keep one rank per core and the same node type throughout.
"""
import argparse
import os
import subprocess
import tempfile

from bitwise import environment
from run import parse_log, report

HERE = os.path.dirname(os.path.abspath(__file__))


def run_once(lmp, ranks, args, outdir):
    ny = args.ny
    nx = max(1, round(ranks * args.per_rank / (2 * ny)))
    log = os.path.join(outdir, f"log.weak.{args.style}.{ranks}")
    cmd = [lmp, "-in", os.path.join(HERE, "in.mlp"), "-var", "style", args.style,
           "-var", "nx", str(nx), "-var", "ny", str(ny), "-var", "nsteps", str(args.steps),
           "-var", "procs", f"{ranks} 1 1", "-log", log, "-screen", "none"]
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks)] + cmd
    subprocess.run(cmd, cwd=outdir, env=environment(lmp, 1), check=True)
    return parse_log(open(log).read())


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--lmp", default="lmp")
    ap.add_argument("--per-rank", type=int, default=40000)
    ap.add_argument("--ny", type=int, default=100, help="cells across (the slab's height)")
    ap.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--steps", type=int, default=400)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--style", default="literal", choices=("morse", "literal", "conservative",
                                                           "frame"))
    ap.add_argument("--out", default=None)
    args = ap.parse_args()
    best = {}
    with tempfile.TemporaryDirectory() as outdir:
        for _ in range(args.repeat):
            for ranks in args.ranks:
                result = run_once(args.lmp, ranks, args, outdir)
                if ranks not in best or result["seconds"] < best[ranks]["seconds"]:
                    best[ranks] = result
    base = best[args.ranks[0]]["seconds"]
    lines = [f"weak scaling, style {args.style}: {args.per_rank} particles per rank "
             f"(slabs along x, {args.ny} cells across), {args.steps} steps, best of "
             f"{args.repeat}", "",
             "| ranks | particles | s per 100 steps | efficiency t(1)/t(R) | Pair | Comm |",
             "|---|---|---|---|---|---|"]
    for ranks in args.ranks:
        r = best[ranks]
        per100 = r["seconds"] * 100.0 / r["steps"]
        share = {k: r["sections"].get(k, 0.0) / r["seconds"] for k in ("Pair", "Comm")}
        lines.append(f"| {ranks} | {r['atoms']} | {per100:.4f} | {base / r['seconds']:.3f} | "
                     f"{100 * share['Pair']:.0f} % | {100 * share['Comm']:.0f} % |")
    report(lines, args.out)


if __name__ == "__main__":
    main()
