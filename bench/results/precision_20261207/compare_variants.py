#!/usr/bin/python3
"""The errors of pareto.py's scenes with emulated single-precision rows
against double (bench/README.md, "Single-precision rows").

    ./compare_variants.py all mixed n p rel > differences.txt

reads pareto.base.csv and pareto.VARIANT.csv here and prints, for every
case and error, the value of double and of each variant with the change;
then, per variant, the largest change of each error over its cases (the
README's table) and the range of the errors of double.
"""

import csv
import pathlib
import sys

HERE = pathlib.Path(__file__).resolve().parent
ERRORS = {  # scene: the errors pareto.py writes for it
    "cube": ["E_error", "nu_error"],
    "wave": ["speed_error", "energy_error", "amplitude_loss"],
    "plastic": ["yield_error", "tangent_error"],
}


def load(variant):
    with open(HERE / f"pareto.{variant}.csv") as f:
        return {(r["scene"], r["resolution"], r["fraction"]): r for r in csv.DictReader(f)}


def main(variants):
    base = load("base")
    runs = {v: load(v) for v in variants}
    for case, b in base.items():
        for col in ERRORS[case[0]]:
            line = f"{case[0]:8s} {case[1]:>3s} {case[2]:4s} {col:15s} base {float(b[col]):+.6e}"
            for v in variants:
                if case in runs[v]:
                    x = float(runs[v][case][col])
                    line += f" | {v} {x:+.6e} (d {x - float(b[col]):+.2e})"
            print(line)

    print("\nlargest change against double over the cases (- where the variant ran no case)")
    print("variant | " + " | ".join(f"{s} {c}" for s, cols in ERRORS.items() for c in cols))
    for v in variants:
        changes = []
        for scene, cols in ERRORS.items():
            for col in cols:
                d = [abs(float(r[col]) - float(base[k][col])) for k, r in runs[v].items() if k[0] == scene]
                changes.append(f"{max(d):.1e}" if d else "-")
        print(f"{v} | " + " | ".join(changes))
    ranges = []
    for scene, cols in ERRORS.items():
        for col in cols:
            e = [abs(float(r[col])) for k, r in base.items() if k[0] == scene]
            ranges.append(f"{min(e):.1e} - {max(e):.1e}")
    print("double (the errors themselves) | " + " | ".join(ranges))


if __name__ == "__main__":
    main(sys.argv[1:])
