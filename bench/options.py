"""Cost of the optional parts of the link law against the elastic law:
microseconds per automaton-step of pair mca on the free fcc cubes of
in.bench with and without an option (damping viscous, plasticity mises,
fracture links with the Drucker-Prager or the elliptic criterion, strengths
that nothing reaches), the runs
alternating, the best of N each.  One executable: what the option costs
when a scene asks for it.  (What its existence costs an elastic-only run
is a before/after comparison of two builds: compare.py.)

    /usr/bin/python3 bench/options.py [--lmp LMP] [--modes cpu kk1 kk2]
        [--sizes 20] [--repeat 3] [--out results/options.md]
"""

import argparse
import tempfile

from kokkos import MODES, STEPS, run_once

OPTIONS = {"elastic": {}, "damping viscous": {"damping": "viscous"},
           "plasticity mises": {"plasticity": "mises"},
           "fracture drucker_prager": {"fracture": "drucker_prager"},
           "fracture elliptic": {"fracture": "elliptic"}}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--lmp", default="lmp")
    ap.add_argument("--modes", nargs="+", default=["cpu", "kk1", "kk2"], choices=list(MODES))
    ap.add_argument("--sizes", type=int, nargs="+", default=[20])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--out", default=None)
    args = ap.parse_args()

    options = [o for o in OPTIONS if o != "elastic"]
    lines = ["| automata | mode | " + " | ".join(f"{o} us" for o in OPTIONS) + " | " +
             " | ".join(f"{o}/elastic" for o in options) + " |",
             "|---|---|" + "---|" * (len(OPTIONS) + len(options))]
    with tempfile.TemporaryDirectory() as tmp:
        for n in args.sizes:
            for mode in args.modes:
                best = {}
                for _ in range(args.repeat):
                    for label, variables in OPTIONS.items():
                        row = run_once(mode, n, STEPS.get(n, 20), tmp, name=label.split()[0],
                                       lmp=args.lmp, variables=variables)
                        if label not in best or row["us_wall"] < best[label]["us_wall"]:
                            best[label] = row
                base = best["elastic"]["us_wall"]
                lines.append(f"| {best['elastic']['atoms']} | {mode} | " +
                             " | ".join(f"{best[o]['us_wall']:.4f}" for o in OPTIONS) + " | " +
                             " | ".join(f"{best[o]['us_wall'] / base:.3f}" for o in options) +
                             " |")
                print(lines[-1], flush=True)
    table = "\n".join(lines) + "\n"
    print(table)
    if args.out:
        with open(args.out, "w") as f:
            f.write(table)


if __name__ == "__main__":
    main()
