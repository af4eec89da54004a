"""pair mca/kk on a GPU: two or more executables on the free fcc cubes of
in.bench, alternating (base, new, base, new, ...), best of N per size.

A GPU run's time is stable to a few per mille between runs of the same
executable, so one series tells a change of 1 %; the executables alternate
all the same, to take a drifting clock out.

Usage (on the GPU machine, from bench/ or with --bench):
    python3 gpu_compare.py NAME=LMP NAME=LMP ... [--sizes 20 60] [--repeat 2]
        [--out gpu_compare.csv]
The first executable is the reference of the ratios printed.  Reported per
run: microseconds per automaton-step of the whole loop and of the pair
style (Pair in LAMMPS's timing breakdown).
"""

import argparse
import csv

from gpu import STEPS, run_once


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("exes", nargs="+", help="NAME=path of an lmp built for the GPU")
    ap.add_argument("--sizes", type=int, nargs="+", default=[20, 60])
    ap.add_argument("--repeat", type=int, default=2)
    ap.add_argument("--out", default="gpu_compare.csv")
    ap.add_argument("--logs", default="/tmp", help="where the LAMMPS logs go")
    args = ap.parse_args()
    exes = dict(e.split("=", 1) for e in args.exes)
    names = list(exes)

    rows, best = [], {}
    for n in args.sizes:
        for rep in range(args.repeat):
            for name in names:
                row = run_once("kk_gpu", n, STEPS["kk_gpu"].get(n, 200), args.logs, lmp=exes[name],
                               name=f"{name}.{rep}")
                row["us_pair"] = row["us_wall"] * row["pair_percent"] / 100.0
                row.update(name=name, n=n, rep=rep)
                rows.append(row)
                if (name, n) not in best or row["us_pair"] < best[(name, n)]["us_pair"]:
                    best[(name, n)] = row
                print(f"{name:10s} n={n} rep={rep} wall {row['us_wall']:.5f} pair "
                      f"{row['us_pair']:.5f} us/automaton-step", flush=True)
    for n in args.sizes:
        ref = best[(names[0], n)]
        for name in names[1:]:
            b = best[(name, n)]
            print(f"n={n} ({ref['atoms']} automata): pair {names[0]} {ref['us_pair']:.5f}, "
                  f"{name} {b['us_pair']:.5f}, ratio {b['us_pair'] / ref['us_pair']:.3f}; "
                  f"wall ratio {b['us_wall'] / ref['us_wall']:.3f}")
    with open(args.out, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=["name", "n", "rep", "atoms", "steps", "us_wall",
                                               "us_pair"], extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
