"""Instructions and cycles per automaton-step of pair mca and pair granular
(the periodic fcc boxes of run.py, 1 core), counted by `perf stat` in user
space.  Each case runs twice, with 50 and 250 steps, and the difference
divided by 200 steps x automata removes the set-up (lattice, links, first
neighbour lists).  Instructions do not depend on the clock or on other work
on the machine, unlike the times of run.py; cycles show the instructions
per cycle.

Usage (lmp and perf on the PATH, e.g. eval "$(tools/mca env current)"):
    /usr/bin/python3 instructions.py [--sizes 10 20] [--out results]
Writes results/instructions.csv.
"""

import argparse
import csv
import os
import subprocess
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SHORT, LONG = 50, 250


def counters(style, n, steps):
    """User-space instructions and cycles of one run."""
    with tempfile.NamedTemporaryFile(suffix=".perf") as out:
        cmd = ["perf", "stat", "-x,", "-e", "instructions:u,cycles:u", "-o", out.name,
               "lmp", "-in", "in.bench", "-var", "style", style, "-var", "n", str(n),
               "-var", "nsteps", str(steps), "-log", "none", "-screen", "none"]
        subprocess.run(cmd, cwd=HERE, env=dict(os.environ, OMP_NUM_THREADS="1"), check=True)
        values = {}
        for line in open(out.name):
            fields = line.strip().split(",")
            if len(fields) > 2 and fields[0].isdigit():
                values[fields[2].split(":")[0]] = int(fields[0])
    if set(values) != {"instructions", "cycles"}:
        raise RuntimeError(f"perf stat counted {values}: are hardware counters available?")
    return values


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sizes", type=int, nargs="+", default=[10, 20])
    ap.add_argument("--out", default=os.path.join(HERE, "results"))
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rows = []
    for n in args.sizes:
        atoms = 4 * n ** 3
        per_step = {}
        for style in ("mca", "granular"):
            short, long = counters(style, n, SHORT), counters(style, n, LONG)
            per = {k: (long[k] - short[k]) / ((LONG - SHORT) * atoms) for k in long}
            per_step[style] = per
            rows.append({"style": style, "automata": atoms,
                         "instructions_per_automaton_step": round(per["instructions"]),
                         "cycles_per_automaton_step": round(per["cycles"]),
                         "instructions_per_cycle": round(per["instructions"] / per["cycles"], 2)})
            print(rows[-1])
        ratio = per_step["mca"]["instructions"] / per_step["granular"]["instructions"]
        print(f"{atoms} automata: mca / granular = {ratio:.2f} in instructions, "
              f"{per_step['mca']['cycles'] / per_step['granular']['cycles']:.2f} in cycles")
    with open(os.path.join(args.out, "instructions.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


if __name__ == "__main__":
    main()
