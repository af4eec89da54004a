"""Before/after count of the instructions per automaton-step of pair mca
(two LAMMPS executables, e.g. a build before a change and after it), by
valgrind's cachegrind: a free fcc cube of in.bench (n = 8, 2457 automata)
runs 10 and 30 steps, and the difference over 20 steps x automata removes
the set-up.  Instruction counts do not depend on the clock or on other
work on the machine: where the times of compare.py scatter by more than
the effect (a shared virtual machine), this still resolves 0.1 %.  (What
it does not see: cache misses and the cost of each instruction.)

    /usr/bin/python3 bench/ir_compare.py --base /tmp/base/kokkos/lmp \\
        --new ~/.cache/mca/build/kokkos/lmp [--modes cpu kk1 kk2] [--out FILE.md]

With --options, one executable (--new) runs the elastic law and each
optional part of in.bench (damping viscous, plasticity mises, fracture links
with each criterion, at strengths the scene never reaches): what an
option costs a scene that asks for it, in instructions (results/ir_options.md).
"""

import argparse
import os
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
SHORT, LONG, N, ATOMS = 10, 30, 8, 2457


def instructions(lmp, steps, mode, variables=None):
    cmd = ["valgrind", "--tool=cachegrind", "--cache-sim=no", "--cachegrind-out-file=/dev/null",
           lmp, "-in", "in.bench", "-var", "style", "mca", "-var", "geometry", "cube",
           "-var", "n", str(N), "-var", "nsteps", str(steps), "-log", "none", "-screen", "none"]
    for key, value in (variables or {}).items():
        cmd += ["-var", key, str(value)]
    if mode == "kk1":
        cmd += ["-k", "on", "t", "1", "-sf", "kk"]
    env = dict(os.environ, OMP_NUM_THREADS="1")
    if mode == "kk2":
        # (valgrind runs the two threads one after the other: the count is
        # the work of both, the chunk copies included; threads that wait at
        # a barrier sleep instead of spinning, which would count the wait)
        cmd += ["-k", "on", "t", "2", "-sf", "kk"]
        env.update(OMP_NUM_THREADS="2", OMP_WAIT_POLICY="PASSIVE", GOMP_SPINCOUNT="0")
    if os.sep in lmp:
        env["LD_LIBRARY_PATH"] = os.path.dirname(os.path.abspath(lmp)) + ":" + \
            env.get("LD_LIBRARY_PATH", "")
    out = subprocess.run(cmd, cwd=HERE, capture_output=True, text=True, env=env, check=True)
    refs = [line for line in out.stderr.splitlines() if "I" in line and "refs:" in line]
    return int(refs[0].split()[-1].replace(",", ""))


def per_step(lmp, mode, variables=None):
    """Instructions per automaton-step."""
    return (instructions(lmp, LONG, mode, variables) -
            instructions(lmp, SHORT, mode, variables)) / ((LONG - SHORT) * ATOMS)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--base", help="lmp executable before the change")
    ap.add_argument("--new", required=True, help="lmp executable after the change")
    ap.add_argument("--modes", nargs="+", default=["cpu", "kk1"], choices=["cpu", "kk1", "kk2"])
    ap.add_argument("--out", default=None, help="markdown file for the table")
    ap.add_argument("--options", action="store_true",
                    help="the optional parts of the link law against the elastic law (--new)")
    args = ap.parse_args()
    if args.options:
        return options(args)
    if not args.base:
        ap.error("--base is needed (or --options)")
    lines = ["| automata | mode | base instr/step | new instr/step | new/base |",
             "|---|---|---|---|---|"]
    for mode in args.modes:
        base, new = per_step(args.base, mode), per_step(args.new, mode)
        lines.append(f"| {ATOMS} | {mode} | {base:.1f} | {new:.1f} | {new / base:.4f} |")
        print(lines[-1], flush=True)
    if args.out:
        with open(args.out, "w") as f:
            f.write("\n".join(lines) + "\n")


OPTIONS = {"damping viscous": {"damping": "viscous"}, "plasticity mises": {"plasticity": "mises"},
           **{f"fracture {c}": {"fracture": c}
              for c in ("strain", "stress", "drucker_prager", "elliptic")}}


def options(args):
    lines = ["| automata | mode | elastic instr/step | " + " | ".join(OPTIONS) + " | " +
             " | ".join(f"{o.split()[-1]}/elastic" for o in OPTIONS) + " |",
             "|---|---|---|" + "---|" * (2 * len(OPTIONS))]
    for mode in args.modes:
        elastic = per_step(args.new, mode)
        counts = [per_step(args.new, mode, variables) for variables in OPTIONS.values()]
        lines.append(f"| {ATOMS} | {mode} | {elastic:.1f} | " +
                     " | ".join(f"{c:.1f}" for c in counts) + " | " +
                     " | ".join(f"{c / elastic:.3f}" for c in counts) + " |")
        print(lines[-1], flush=True)
    if args.out:
        with open(args.out, "w") as f:
            f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
