"""Bit-for-bit check of a refactoring: two LAMMPS builds ("base" and "new")
run the examples' scenes, and everything they write must be byte-identical.

A refactoring meant to change no arithmetic must leave every bit unchanged;
the unit tests' tolerances would hide a reordered sum or another rounding.
Each scene (an example's own input, copied and cut to --nsteps steps) runs
with both executables in each mode:

    cpu   CPU styles, 1 rank                kk1  -k on t 1 -sf kk, 1 rank
    cpu2  CPU styles, mpirun -np 2          kk2  -k on t 2 -sf kk, 1 rank

(kk modes only if both builds list mca/kk in lmp -h).  Before the run a dump
of id, type, x, image, v, f, omega, torque and the compute mca/atom values
(scenes with pair mca) every nsteps/4 steps and thermo every nsteps/10, both
%.17g, are added, and after the run the estimate of the stable time step
(compute mca/timestep: dt_c, omega, zeta, %.17g).  Compared byte for byte:
the thermo lines of the log, that estimate and every file the run writes
(the dump, the examples' .dat files).  A change meant to move only the
round-off of the estimate (its own arithmetic) is checked with
--estimate-rtol R: an estimate within R relative is reported, not counted.
Where they differ, each numeric column's max absolute difference and that
over the column's largest |value| (relative) are reported.  A scene that
fails in both builds (rolling on LAMMPS 2021: fix wall/gran needs atom_style
sphere) is listed as n/a, not counted as a difference.

    /usr/bin/python3 bitwise.py --base DIR --new DIR [--nsteps 200]
        [--modes cpu,cpu2,kk1,kk2] [--scenes a,b] [--out FILE.md] [--keep DIR]
        [--estimate-rtol R]

DIR holds an lmp (and, for a shared build, liblammps.so*).  Exit status 0
if all is identical, 1 otherwise.
"""

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

EXAMPLES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "examples")
CUBE = "tension_cube/in.tension_cube"
SCENES = {  # name: (input under examples/, variables)
    "cube_free_tension": (CUBE, {"grips": "free", "load": "tension"}),
    "cube_clamped_tension": (CUBE, {"grips": "clamped", "load": "tension"}),
    "cube_clamped_shear": (CUBE, {"grips": "clamped", "load": "shear"}),
    "shear_layer": ("tension_cube/in.shear_layer", {}),
    "shear_box": ("tension_cube/in.shear_box", {"erate": 2.5}),  # 1 % in 200 steps
    "wave_p": ("waves/in.wave", {"pol": "p", "m": 10}),
    "wave_s": ("waves/in.wave", {"pol": "s", "m": 10}),
    "energy": ("energy/in.energy", {"factor": 1}),
    "rigid": ("energy/in.rigid", {}),
    "rolling": ("rolling/in.rolling", {"packing": "fcc"}),
    # the parts of the link law (plasticity, fracture, damping)
    "plastic_box": ("plasticity/in.plastic_box", {}),
    "load_unload": ("plasticity/in.load_unload", {"n": 4}),
    "fracture_box": ("fracture/in.box", {"srate": 7.0e9}),  # breaks from step ~30 on
    "damping": ("damping/in.damping", {"n": 4}),
    "notched_plate": ("hard_cases/in.notched_plate", {"nx": 12, "ny": 12}),
    # contacts that heal into links under pressure during the press (its
    # 1500 steps whole), then the pull (cut to nsteps)
    "weld": ("healing/in.weld", {"heal": 3.5e6}),
}
MODES = {  # name: (MPI ranks, OpenMP threads, Kokkos)
    "cpu": (1, 1, False), "cpu2": (2, 1, False), "kk1": (1, 1, True), "kk2": (1, 2, True)}
MCA_ATOM = "sxx syy szz sxy sxz syz smean seq eeq links"
NAMES = {f"c_bitwise_mca[{k + 1}]": name for k, name in enumerate(MCA_ATOM.split())}
DUMP = """compute         bitwise_mca all mca/atom {mca_atom}
dump            bitwise all custom {every} bitwise.dump id type x y z ix iy iz vx vy vz &
                fx fy fz omegax omegay omegaz tqx tqy tqz {columns}
dump_modify     bitwise sort id format float %.17g
thermo          {thermo}
thermo_modify   format float %.17g
"""


def scene_input(path, nsteps, extra=""):
    """The example's input with the dump before its last run, run for nsteps."""
    lines = open(os.path.join(EXAMPLES, path)).read().splitlines()
    # the last run of the scene (not the run 0 of the examples' final state)
    last = max(i for i, line in enumerate(lines)
               if re.match(r"\s*run\s", line) and not re.match(r"\s*run\s+0\s+post\s+no", line))
    mca = re.search(r"^\s*pair_style\s+mca(\s|$)", "\n".join(lines), re.M)
    dump = DUMP.format(every=max(1, nsteps // 4), thermo=max(1, nsteps // 10),
                       mca_atom=MCA_ATOM, columns="c_bitwise_mca[*]" if mca else "")
    if not mca:
        dump = dump.split("\n", 1)[1]
    # the estimate of the stable time step to the last bit, as at the last
    # step of the run (a fix keeps it: LAMMPS 2021 reads no compute between
    # runs); invoked there only (Nfreq: that step), not at every step
    if mca:
        dump += ("compute         bitwise_dt all mca/timestep\n"
                 f"fix             bitwise_dt all ave/time 1 1 $(step+{nsteps}) c_bitwise_dt[*]\n")
    estimate = ['print "BITWISE stable time step $(f_bitwise_dt[1]:%.17g) omega '
                '$(f_bitwise_dt[4]:%.17g) zeta $(f_bitwise_dt[5]:%.17g)"'] if mca else []
    return "\n".join(lines[:last] + [dump + extra, f"run {nsteps}"] + estimate +
                     lines[last + 1:]) + "\n"


def environment(lmp, threads):
    """mpirun as root and oversubscribed (unittest/mcatest.py); the build's own
    liblammps.so first (a copied shared build's RUNPATH names the original)."""
    env = dict(os.environ, OMP_NUM_THREADS=str(threads), OMP_PROC_BIND="false",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    if os.geteuid() == 0:
        env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    env["LD_LIBRARY_PATH"] = ":".join(filter(None, [os.path.dirname(lmp),
                                                    env.get("LD_LIBRARY_PATH")]))
    return env


def has_kokkos(lmp):
    out = subprocess.run([lmp, "-h"], capture_output=True, text=True, env=environment(lmp, 1))
    return "mca/kk" in out.stdout.split()


def read_output(path):
    """A file the run wrote: its text, or its bytes if it is not text (the
    examples' pictures)."""
    data = open(path, "rb").read()
    try:
        return data.decode()
    except UnicodeDecodeError:
        return data


def run(lmp, scene, mode, nsteps, cwd, extra=""):
    """Run one scene in cwd; return {output name: text} or an error message."""
    path, variables = SCENES[scene]
    ranks, threads, kokkos = MODES[mode]
    shutil.rmtree(cwd, ignore_errors=True)
    os.makedirs(cwd)
    with open(os.path.join(cwd, "in.scene"), "w") as f:
        f.write(scene_input(path, nsteps, extra))
    # without the examples' snapshots, final state and picture
    cmd = [lmp, "-in", "in.scene", "-log", "log.lammps", "-nocite", "-var", "visevery", "0"]
    for key, value in variables.items():
        cmd += ["-var", key, str(value)]
    if kokkos:
        cmd += ["-k", "on", "t", str(threads), "-sf", "kk"]
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks)] + cmd
    try:
        proc = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True,
                              env=environment(lmp, threads), timeout=600)
    except (OSError, subprocess.TimeoutExpired) as e:
        return str(e)
    if proc.returncode != 0:
        text = [l.strip() for l in (proc.stdout + proc.stderr).splitlines()
                if re.search("[a-z]", l)]
        return ([l for l in text if "ERROR" in l] + text + ["failed"])[0]
    outputs = {name: read_output(os.path.join(cwd, name)) for name in os.listdir(cwd)
               if name not in ("in.scene", "log.lammps")}
    thermo, inside = [], False
    for line in open(os.path.join(cwd, "log.lammps")).read().splitlines():
        inside = (inside or line.split()[:1] == ["Step"]) and not line.startswith("Loop time")
        # pair mca's estimate of the stable time step, printed after it: an
        # output of its own (its three numbers under a header)
        if line.startswith("BITWISE stable time step"):
            t = line.split()
            outputs["estimate"] = f"dt omega zeta\n{t[4]} {t[6]} {t[8]}"
        elif inside:
            thermo.append(line)
    outputs["thermo"] = "\n".join(thermo)
    return outputs


def numbers(line):
    try:
        return [float(t) for t in line.split()]
    except ValueError:
        return None


def column_diffs(a, b):
    """'column abs (rel), ...' of two texts of the same layout (the column
    named by the last header line), or where their layouts differ.  Relative
    to the column's largest |value|: per value, the residual forces near zero
    would read 2 for any perturbation."""
    la, lb = a.splitlines(), b.splitlines()
    if len(la) != len(lb):
        return f"{len(la)} vs {len(lb)} lines", float("inf")
    diff, size, header = {}, {}, []
    for x, y in zip(la, lb):
        va, vb = numbers(x), numbers(y)
        if va is None or vb is None or len(va) != len(vb):
            if x.split() != y.split():
                return f"line differs: {x.strip()[:60]!r} vs {y.strip()[:60]!r}", float("inf")
            header = [NAMES.get(t, t) for t in x.split() if t not in ("ITEM:", "ATOMS", "#")]
            continue
        for k, (p, q) in enumerate(zip(va, vb)):
            name = header[k] if len(header) == len(va) else f"{(header or ['col'])[0]}[{k + 1}]"
            diff[name] = max(diff.get(name, 0.0), abs(p - q))
            size[name] = max(size.get(name, 0.0), abs(p), abs(q))
    rel = {k: d / size[k] for k, d in diff.items() if d > 0}
    text = ", ".join(f"{k} {diff[k]:.3g} ({r:.3g})" for k, r in rel.items())
    return text or "same numbers, other text", max(rel.values(), default=0.0)


def compare(base, new, estimate_rtol=0.0):
    """(identical: True/False/None if both failed, max rel difference, details).
    An estimate of the stable time step within estimate_rtol (relative, of
    each of its numbers) is listed in the details but is no difference."""
    if isinstance(base, str) or isinstance(new, str):
        if isinstance(base, str) and isinstance(new, str):
            return None, float("nan"), [f"both fail: {base}"]
        return False, float("nan"), [f"{side}: {out if isinstance(out, str) else 'ran'}"
                                     for side, out in (("base", base), ("new", new))]
    details, tolerated, worst = [], [], 0.0
    for name in sorted(set(base) | set(new)):
        if base.get(name) == new.get(name):
            continue
        if name not in base or name not in new:
            text, rel = "written by one build only", float("inf")
        elif isinstance(base[name], bytes) or isinstance(new[name], bytes):
            text, rel = "binary files differ", float("inf")
        else:
            text, rel = column_diffs(base[name], new[name])
        if name == "estimate" and rel <= estimate_rtol:
            tolerated.append(f"{name}: {text} (within --estimate-rtol {estimate_rtol:g})")
            continue
        details.append(f"{name}: {text}")
        worst = max(worst, rel)
    return not details, worst, details + tolerated


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--base", required=True, help="directory with the base lmp")
    ap.add_argument("--new", required=True, help="directory with the new lmp")
    ap.add_argument("--nsteps", type=int, default=200)
    ap.add_argument("--modes", default=",".join(MODES))
    ap.add_argument("--scenes", default=",".join(SCENES))
    ap.add_argument("--out", help="markdown file for the table")
    ap.add_argument("--keep", help="keep the run directories here (default: a temporary one)")
    ap.add_argument("--estimate-rtol", type=float, default=0.0,
                    help="a change of the stable time step estimate (dt, omega, zeta) up to "
                    "this relative size is reported but not counted as a difference (a "
                    "change meant to move only the estimate's round-off; default 0)")
    ap.add_argument("--new-cmd", default="", help="debug: LAMMPS command(s) added before the "
                    "run of the new build only, to see that differences are found")
    args = ap.parse_args()
    lmp = {side: os.path.abspath(os.path.join(os.path.expanduser(d), "lmp"))
           for side, d in (("base", args.base), ("new", args.new))}
    for x in lmp.values():
        if not os.access(x, os.X_OK):
            sys.exit(f"no executable {x}")
    modes = args.modes.split(",")
    if any(MODES[m][2] for m in modes) and not all(has_kokkos(x) for x in lmp.values()):
        print("pair_style mca/kk not in both builds: kk modes skipped")
        modes = [m for m in modes if not MODES[m][2]]
    work = args.keep or tempfile.mkdtemp(prefix="bitwise.")
    rows, failed, start = [], False, time.time()
    for scene in args.scenes.split(","):
        for mode in modes:
            t0 = time.time()
            out = {side: run(lmp[side], scene, mode, args.nsteps,
                             os.path.join(work, scene, mode, side),
                             args.new_cmd if side == "new" else "") for side in lmp}
            same, rel, details = compare(out["base"], out["new"], args.estimate_rtol)
            failed |= same is False
            cell = {True: "yes", False: "**no**", None: "n/a"}[same]
            rows.append(f"| {scene} | {mode} | {cell} | {rel:.3g} | {'<br>'.join(details)} |")
            print(f"{scene:20s} {mode:4s} identical: {cell:6s} max rel diff {rel:.3g}"
                  f"  ({time.time() - t0:.1f} s)", flush=True)
            for line in details:
                print("    " + line)
    summary = (f"{'DIFFERENCES' if failed else 'all identical'}: base {lmp['base']}, new "
               f"{lmp['new']}, {args.nsteps} steps, {time.time() - start:.0f} s")
    if args.estimate_rtol > 0.0:
        summary += f" (the estimate of the stable time step to {args.estimate_rtol:g} relative)"
    print(summary)
    if args.out:
        with open(args.out, "w") as f:
            f.write("\n".join([summary, "", "| scene | mode | identical | max rel diff | details |",
                               "|---|---|---|---|---|"] + rows) + "\n")
    if not args.keep:
        shutil.rmtree(work)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
