"""Before/after benchmark of two LAMMPS executables (e.g. a copy of the
build before a change and the build after it): microseconds per
automaton-step of pair mca on the free fcc cubes of bench/kokkos.py, in
the modes asked for (cpu, kk1, kk2, ...; kk modes need a Kokkos build).

The runs alternate base, new, base, new, ... and the best of each counts,
so that the drift of a shared machine's speed hits both alike.  Prints a
markdown table with new/base and writes it to --out.

    /usr/bin/python3 bench/compare.py --base /tmp/base/kokkos/lmp \\
        --new ~/.cache/mca/build/kokkos/lmp [--modes cpu kk1 kk2] \\
        [--sizes 20 40] [--repeat 5] [--out results/compare.md] \\
        [--base-var KEY=VALUE ...] [--new-var KEY=VALUE ...]

--base-var and --new-var give in.bench variables to one side (e.g. one
executable as both sides, --new-var precision=mixed: the cost of an
option).
"""

import argparse
import os
import tempfile

from kokkos import MODES, STEPS, run_once


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--base", required=True, help="lmp executable before the change")
    ap.add_argument("--new", required=True, help="lmp executable after the change")
    ap.add_argument("--modes", nargs="+", default=["cpu", "kk1", "kk2"], choices=list(MODES))
    ap.add_argument("--sizes", type=int, nargs="+", default=[20, 40])
    ap.add_argument("--repeat", type=int, default=5, help="runs of each (the best counts)")
    ap.add_argument("--out", default=None, help="markdown file for the table")
    ap.add_argument("--base-var", nargs="+", default=[], metavar="KEY=VALUE",
                    help="in.bench variables of the base runs")
    ap.add_argument("--new-var", nargs="+", default=[], metavar="KEY=VALUE",
                    help="in.bench variables of the new runs")
    args = ap.parse_args()
    variables = {side: dict(kv.split("=", 1) for kv in getattr(args, f"{side}_var"))
                 for side in ("base", "new")}

    lines = ["| automata | mode | base us/automaton-step | new | new/base |",
             "|---|---|---|---|---|"]
    with tempfile.TemporaryDirectory() as logs:
        for n in args.sizes:
            for mode in args.modes:
                best = {}
                for _ in range(args.repeat):
                    for side in ("base", "new"):
                        lmp = os.path.abspath(os.path.expanduser(getattr(args, side)))
                        row = run_once(mode, n, STEPS[n], logs, side, lmp,
                                       variables=variables[side])
                        if side not in best or row["us_wall"] < best[side]["us_wall"]:
                            best[side] = row
                ratio = best["new"]["us_wall"] / best["base"]["us_wall"]
                line = (f"| {best['new']['atoms']} | {mode} | {best['base']['us_wall']:.4f} | "
                        f"{best['new']['us_wall']:.4f} | {ratio:.3f} |")
                lines.append(line)
                print(line, flush=True)
    if args.out:
        with open(args.out, "w") as f:
            f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
