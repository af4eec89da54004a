#!/usr/bin/python3
"""Cost of the contact part of pair mca: microseconds per automaton-step on
one periodic sc packing (in.contacts: n^3 automata, random velocities of
~ 0.1 m/s, a skin of 0.01 R so that the lists are rebuilt every few tens
of steps) in four cases:
    links     every neighbour pair linked, no contact part (the elastic
              baseline)
    idle      the same with 'contacts coulomb' (contact list, rows kept at
              each reneighboring, the contact pass; no pair touches)
    contacts  no pair linked, 'contacts coulomb': every neighbour pair is a
              contact
    healing   the same with 'healing weld' and a healing pressure no contact
              reaches (the cost of the heal pass)
each with the CPU styles and the kk styles on 1 and 2 threads (the build
with KOKKOS).  Reported: the whole step, the Pair section (the passes and,
at reneighboring, the update of the contact rows) and the Neigh section
(the list builds; with contacts the full contact list), each per
automaton-step, and the number of builds.  Best of --repeat runs, the
runs of each repeat one after the other.

    eval "$(tools/mca env kokkos)"
    /usr/bin/python3 bench/contacts.py [--n 20] [--steps 200] [--repeat 3]
        [--out bench/results/contacts.md]
"""
import argparse
import os
import re
import subprocess
import tempfile

from run import parse_log

HERE = os.path.dirname(os.path.abspath(__file__))
MODES = {"cpu": (), "kk1": ("-k", "on", "t", "1", "-sf", "kk"),
         "kk2": ("-k", "on", "t", "2", "-sf", "kk")}
CASES = ("links", "idle", "contacts", "healing")


def run_once(lmp, case, mode, n, steps, outdir):
    log = os.path.join(outdir, f"log.contacts.{case}.{mode}")
    cmd = [lmp, "-in", os.path.join(HERE, "in.contacts"), "-var", "case", case, "-var", "n",
           str(n), "-var", "nsteps", str(steps), "-log", log, "-screen", "none"]
    cmd += list(MODES[mode])
    threads = "2" if mode == "kk2" else "1"
    env = dict(os.environ, OMP_NUM_THREADS=threads, OMP_PROC_BIND="false")
    subprocess.run(cmd, cwd=outdir, env=env, check=True)
    text = open(log).read()
    result = parse_log(text)
    builds = re.findall(r"Neighbor list builds = (\d+)", text)[-1]
    per = 1e6 / (result["atoms"] * result["steps"])
    return {"step": result["seconds"] * per, "pair": result["sections"].get("Pair", 0.0) * per,
            "neigh": result["sections"].get("Neigh", 0.0) * per, "builds": int(builds)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--lmp", default="lmp")
    ap.add_argument("--n", type=int, default=20)
    ap.add_argument("--steps", type=int, default=200)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--modes", nargs="+", default=list(MODES), choices=list(MODES))
    ap.add_argument("--out", default=None)
    args = ap.parse_args()
    lines = [f"sc packing of {args.n ** 3} automata, {args.steps} steps, best of {args.repeat}; "
             "us per automaton-step", "",
             "| mode | case | step | Pair | Neigh | list builds | step / links |",
             "|---|---|---|---|---|---|---|"]
    # the runs of a repeat one after the other (cases and modes), so that a
    # slow spell of the machine does not fall on one case alone
    runs = {}
    with tempfile.TemporaryDirectory() as outdir:
        for _ in range(args.repeat):
            for mode in args.modes:
                for case in CASES:
                    runs.setdefault((mode, case), []).append(
                        run_once(args.lmp, case, mode, args.n, args.steps, outdir))
    for mode in args.modes:
        base = None
        for case in CASES:
            best = min(runs[(mode, case)], key=lambda r: r["step"])
            base = best["step"] if case == "links" else base
            lines.append(f"| {mode} | {case} | {best['step']:.3f} | {best['pair']:.3f} | "
                         f"{best['neigh']:.3f} | {best['builds']} | {best['step'] / base:.2f} |")
    text = "\n".join(lines) + "\n"
    if args.out:
        with open(args.out, "w") as f:
            f.write(text)
    print(text)


if __name__ == "__main__":
    main()
