#!/usr/bin/python3
"""Cost of bond_style beam: microseconds per bond-step on a periodic 2-D
hexagonal lattice (in.beam: 2 nx ny particles, 3 bonds each, NVE at a small
temperature), or with --dim 3 an fcc lattice (4 n^3 particles, 6 bonds
each; --nx is n), against LAMMPS's bond_style bpm/rotational on the same
lattice (the build with the BPM package: LAMMPS 2026, "current"), and the
kk variant on 1 and 2 threads (the build with KOKKOS), and beams with their
sections from the particles' radii (bond_coeff ... radii).  Reported: the
Bond section and the whole step per bond-step, best of --repeat runs.

    eval "$(tools/mca env current)"; eval "$(tools/mca env kokkos)"
    /usr/bin/python3 bench/beam.py [--nx 200 --ny 100] [--steps 200] [--repeat 3]
        [--out bench/results/beam.md]
    /usr/bin/python3 bench/beam.py --dim 3 --nx 20 --steps 100 [--out bench/results/beam3d.md]
"""
import argparse
import os
import subprocess
import tempfile

from run import parse_log, report

HERE = os.path.dirname(os.path.abspath(__file__))
# (label, build variable, style, switches)
CASES = (("current cpu", "MCA_BUILD_CURRENT", "beam", ()),
         ("current cpu", "MCA_BUILD_CURRENT", "bpm", ()),
         ("current cpu", "MCA_BUILD_CURRENT", "beam", ("-var", "sections", "radii")),
         ("kokkos cpu", "MCA_BUILD_KOKKOS", "beam", ()),
         ("kokkos kk 1 thread", "MCA_BUILD_KOKKOS", "beam", ("-k", "on", "t", "1", "-sf", "kk")),
         ("kokkos kk 2 threads", "MCA_BUILD_KOKKOS", "beam", ("-k", "on", "t", "2", "-sf", "kk")),
         ("kokkos kk 1 thread", "MCA_BUILD_KOKKOS", "beam",
          ("-k", "on", "t", "1", "-sf", "kk", "-var", "sections", "radii")))


def bonds_per_atom(args):
    return 3 if args.dim == 2 else 6


def run_once(case, args, outdir):
    label, build, style, switches = case
    lmp = os.path.join(os.environ[build], "lmp")
    kind = style + ("_radii" if "radii" in switches else "")
    log = os.path.join(outdir, f"log.{kind}.{label.replace(' ', '_')}")
    ny, nz = (args.ny, 1) if args.dim == 2 else (args.nx, args.nx)
    cmd = [lmp, "-in", os.path.join(HERE, "in.beam"), "-var", "style", style, "-var", "dim",
           str(args.dim), "-var", "nx", str(args.nx), "-var", "ny", str(ny), "-var", "nz",
           str(nz), "-var", "nsteps", str(args.steps), "-log", log, "-screen", "none"]
    cmd += list(switches)
    threads = "2" if "2 threads" in label else "1"
    env = dict(os.environ, OMP_NUM_THREADS=threads, OMP_PROC_BIND="false")
    subprocess.run(cmd, cwd=outdir, env=env, check=True)
    result = parse_log(open(log).read())
    per = 1e6 / (bonds_per_atom(args) * result["atoms"] * result["steps"])
    return {"step": result["seconds"] * per, "bond": result["sections"].get("Bond", 0.0) * per}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--dim", type=int, choices=(2, 3), default=2)
    ap.add_argument("--nx", type=int, default=200)
    ap.add_argument("--ny", type=int, default=100)
    ap.add_argument("--steps", type=int, default=200)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--out", default=None)
    args = ap.parse_args()
    runs = {}
    with tempfile.TemporaryDirectory() as outdir:
        for _ in range(args.repeat):
            for case in CASES:
                runs.setdefault(case, []).append(run_once(case, args, outdir))
    natoms = 2 * args.nx * args.ny if args.dim == 2 else 4 * args.nx ** 3
    nbonds = bonds_per_atom(args) * natoms
    kind = "hexagonal" if args.dim == 2 else "fcc"
    lines = [f"{kind} lattice of {natoms} particles and {nbonds} bonds, "
             f"{args.steps} steps, best of {args.repeat}; us per bond-step", "",
             "| build, mode | bond style | Bond | whole step | Bond / beam current cpu |",
             "|---|---|---|---|---|"]
    base = min(r["bond"] for r in runs[CASES[0]])
    for case in CASES:
        best = min(runs[case], key=lambda r: r["bond"])
        name = "beam" if case[2] == "beam" else "bpm/rotational"
        if "radii" in case[3]:
            name += " (radii)"
        lines.append(f"| {case[0]} | {name} | {best['bond']:.4f} | {best['step']:.4f} | "
                     f"{best['bond'] / base:.2f} |")
    report(lines, args.out)


if __name__ == "__main__":
    main()
