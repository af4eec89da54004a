#!/usr/bin/python3
"""GP against full MD on a crack tip: cost against displacement error.

The K-test of examples/gp_crack (bcc Fe, Fe_mm.eam.fs, edge crack along
X = [110], load along Y = [-110], Z = [001] periodic, plane strain; a
frame at the faces of a block [-L, L)^2 held at the two-term LEFM field,
the interior relaxed with FIRE to a largest force component of 1e-4
eV/A), made by the model builder (tools/gp_build.py) as full MD and as GP
models with 2, 3 or 4 levels, ratio k = 2 or 3:

  md[<N>]               all atoms (N a0 thick; default the least, 4 a0)
  k<k>m<m>h<H>[s<S>][w<W>]
                        level 1 in the tip block |x|, |y| < H and along
                        the crack faces (x < -H, |y| < S; without s: the
                        whole strip x < H, |y| < H), level n (1 < n < m)
                        out to H + W (n - 1) A (default W 48.45: the
                        level-(n+1) imaginary shell, 2 r_c of level
                        n+1, fits in it),
                        level m beyond; q: fix gp/link fit quadratic
                        (the interface particles exact for curved
                        fields; without q the linear fit, exact for
                        uniform strains only); c: the builder's sites
                        centroid (each coarse particle at the centroid of
                        its atoms: the levels' material tiles at every
                        interface; without c the thesis's common
                        origin); the builder snaps H and S onto
                        the level-2 planes (k 2: multiples of 8.08 A,
                        k 3: 12.11 A).  S must keep level 2 more than its
                        imaginary depth (2 r_c of level 2: 21.2 A for k 2,
                        31.8 A for k 3) from the crack faces, else level 2
                        sees the crack as a coarse surface (the builder
                        warns): s24 for k 2, s36 for k 3

Each model has the least thickness its coarsest level allows (a multiple
of that level's period along [001], more than twice its cutoff: MD and
k2m2 8 a0, k3m2 12 a0, k2m3 16 a0, k2m4 32 a0).  The problem is uniform
along z (a straight crack front at 0 K), the relaxed fields do not
depend on the thickness, and the cost is given per nm of crack front as
well as per model.  All models of one run share the block and the frame
(2 r_c of the coarsest level of any of them, rounded up to 12 sqrt(2) a0
= 48.45 A, the common period of the levels).

Per model: particles (real + imaginary), core-seconds of the two
relaxations (LAMMPS's loop times x ranks), FIRE iterations, the error of
u_y on the Y axis above the tip (relative, r >= 5 A where the model has
atoms), of u_x on the X axis ahead of it and u_r on the R = 15 A circle
(as fractions of the largest MD value on the path), all against full MD
of the same block, and the largest of the three (the model's
displacement error); u_y also against the two-term LEFM field.  The fields
are averaged as the thesis did (examples/gp_crack/crack_fields.py).

  bench/gp_pareto.py [--units 6] [--models md,k2m2h32s24,...] [--np 1]
                     [--work DIR] [--out bench/results/gp_pareto] [--reuse]

--reuse takes the log and dump of a model already run in the work
directory (same units) instead of running it again.

L = units x 48.45 A.  Writes OUT.md (the table), OUT.csv and OUT.png
(core-seconds per nm of front against the largest of the three errors;
open marks: fit quadratic), the LAMMPS logs to
OUT/ and prints the table.  Needs lmp with the MCA and MANYBODY packages
on PATH and LAMMPS_POTENTIALS set (eval "$(tools/mca env current)").
"""

import argparse
import csv
import math
import os
import pathlib
import re
import shutil
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
sys.path.insert(0, str(ROOT / "examples" / "gp_crack"))
import gp_build  # noqa: E402
import crack_fields  # noqa: E402

A0 = 2.855324
RC = 5.3                                   # Fe_mm.eam.fs
UNIT = 12 * math.sqrt(2) * A0              # common period along X, Y of k2 m<=4 and k3 m2
SHELL = 48.45                              # width of an intermediate level (> 2 r_c of k2 level 3)
DEFAULT = "md,k2m2h32s24,k2m2h48s24,k3m2h36s36,k2m3h32s24,k2m3h48s24"


def parse(name):
    """(k, m, H, S) of a model name; md is (1, 1, None, None)."""
    return parse_all(name)[:4]


def shell_width(name):
    """Width of each intermediate level (A): w<W>, default SHELL."""
    w = parse_all(name)[4]
    return SHELL if w is None else w


def parse_all(name):
    """(k, m, H, S, W, fit, sites) of a model name."""
    if re.fullmatch(r"md(\d*)", name):
        return 1, 1, None, None, None, "linear", "origin"
    m = re.fullmatch(r"k(\d)m(\d)h(\d+)(?:s(\d+))?(?:w(\d+))?(q?)(c?)", name)
    if not m:
        raise SystemExit(f"--models: '{name}' is not md[<N>] or k<k>m<m>h<H>[s<S>][w<W>][q][c]")
    k, levels, H = int(m[1]), int(m[2]), float(m[3])
    if k not in (2, 3) or not 2 <= levels <= 4:
        raise SystemExit(f"--models: '{name}': k 2 or 3, 2 to 4 levels")
    return (k, levels, H, (float(m[4]) if m[4] else None), (float(m[5]) if m[5] else None),
            "quadratic" if m[6] else "linear", "centroid" if m[7] else "origin")


def model_thickness(name):
    """a0 along [001]: md<N> N, else the least the levels allow."""
    m = re.fullmatch(r"md(\d+)", name)
    if m:
        if int(m[1]) < thickness(1, 1):
            raise SystemExit(f"--models: '{name}': at least {thickness(1, 1)} a0")
        return int(m[1])
    k, levels, _, _ = parse(name)
    return thickness(k, levels)


def thickness(k, levels):
    """Least number of a0 along [001]: a multiple of the coarsest level's
    period, more than twice its cutoff."""
    s = k ** (levels - 1)
    n = s
    while n * A0 <= 2 * RC * s:
        n += s
    return n


def frame_depth(models):
    deepest = max(2 * RC * k ** (levels - 1) for k, levels, _, _ in map(parse, models))
    return UNIT * math.ceil(deepest / UNIT)


def spec(name, L):
    k, levels, H, S, _, fit, sites = parse_all(name)
    nz = model_thickness(name)
    if levels == 1:
        regions = [None]
    else:
        first = [{"block": [None, H, -H, H, None, None]}]
        if S is not None:
            first = [{"block": [None, -H, -S, S, None, None]}, {"block": [-H, H, -H, H, None, None]}]
        regions = [first]
        for n in range(2, levels):
            X = H + shell_width(name) * (n - 1)
            regions.append({"block": [None, X, -X, X, None, None]})
        regions.append(None)
    return {"lattice": "bcc", "a0": A0, "element": "Fe",
            "orient": [[1, 1, 0], [-1, 1, 0], [0, 0, 1]],
            "potential": {"style": "eam/fs", "file": "Fe_mm.eam.fs"}, "ratio": max(k, 2),
            "box": [-L - 1e-4, L - 1e-4, -L - 1e-4, L - 1e-4, 0, nz * A0], "periodic": "z",
            "cuts": [{"crack": {"tip": 1.0, "y": 0, "height": 4.5}}], "levels": regions,
            "fit": fit, "sites": sites}


def run_model(name, L, frame, args, work):
    t0 = time.time()
    model = gp_build.build(spec(name, L))
    model.write(work / name)
    built = time.time() - t0
    cmd = ["lmp", "-in", "in.ktest", "-var", "model", name, "-var", "L", f"{L:.6f}",
           "-var", "frame", f"{frame:.6f}", "-var", "ftol", f"{args.ftol:g}", "-log", f"log.ktest.{name}", "-screen", "none"]
    if args.np > 1:
        cmd = ["mpirun", "--oversubscribe", "-np", str(args.np)] + cmd
    log = work / f"log.ktest.{name}"
    if not (args.reuse and log.exists() and (work / f"ktest.{name}.dump").exists()
            and "Total wall time" in log.read_text()):
        subprocess.run(cmd, cwd=work, check=True)
    text = (work / f"log.ktest.{name}").read_text()
    loops = re.findall(r"Loop time of ([0-9.]+) on (\d+) procs for (\d+) steps with (\d+) atoms", text)
    k, levels, _, _ = parse(name)
    real = sum(len(r) for r in model.real)
    return {"model": name, "k": k, "levels": levels, "nz": model_thickness(name),
            "front_nm": model_thickness(name) * A0 / 10,
            "real": real, "particles": int(loops[-1][3]),
            "atoms": model.atoms(),
            "core_s": sum(float(t) * int(p) for t, p, _, _ in loops),
            "steps": sum(int(s) for _, _, s, _ in loops), "build_s": built,
            "warnings": len(model.warnings)}


def errors(rows, work):
    import numpy as np
    data = {r["model"]: crack_fields.fields(crack_fields.read(work / f"ktest.{r['model']}.dump"))
            for r in rows}
    md = data["md"]
    lefm = np.array([crack_fields.lefm(r, math.pi / 2)[1] for r in crack_fields.R_AXIS])
    for r in rows:
        uy, ux, ur = data[r["model"]]
        far = [i for i, x in enumerate(crack_fields.R_AXIS)
               if x >= 5 and np.isfinite(uy[i]) and np.isfinite(ux[i]) and np.isfinite(md[0][i])]
        r["r_max"] = max(crack_fields.R_AXIS[i] for i in far)
        r["err_uy"] = max(abs(uy[i] / md[0][i] - 1) for i in far)
        r["err_ux"] = max(abs(ux[i] - md[1][i]) for i in far) / max(abs(md[1][i]) for i in far)
        r["err_ur"] = float(max(abs(ur - md[2])) / max(abs(md[2])))
        r["err_uy_lefm"] = max(abs(uy[i] / lefm[i] - 1) for i in far)
        r["uy10"] = float(uy[crack_fields.R_AXIS.index(10)])


def largest(row):
    """The displacement error of a model: the largest of its three."""
    return max(row["err_uy"], row["err_ux"], row["err_ur"])


def table(rows, L, frame, ranks, ftol):
    md = next(r for r in rows if r["model"] == "md")
    per_nm_md = md["core_s"] / md["front_nm"]
    lines = [f"Fe edge crack K-test, block [-L, L)^2, L = {L:.2f} A, frame {frame:.2f} A, "
             f"K 0.399 MPa m^0.5, T -1.34 GPa; FIRE to a largest force of {ftol:g} eV/A; errors at r >= 5 A against full MD; "
             f"{ranks} MPI rank(s) a run, core-s = LAMMPS's loop seconds x ranks (both relaxations)",
             "",
             "| model | k | levels | thickness (a0) | particles (real + imaginary) | per nm of front "
             "| atoms per particle | FIRE iterations | core-s | core-s per nm | speed-up per nm "
             "| u_y error | u_x error | u_r(15 A) error | largest error | u_y vs LEFM | u_y(10 A) (A) |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        per_nm = r["core_s"] / r["front_nm"]
        vs = "" if r is md else f"{r['err_uy'] * 100:.2f} %"
        lines.append(
            f"| {r['model']}{' (*)' if r['warnings'] else ''} | {r['k']} | {r['levels']} | {r['nz']} | {r['particles']} "
            f"| {r['particles'] / r['front_nm']:.0f} | {r['atoms'] / r['particles']:.2f} | {r['steps']} "
            f"| {r['core_s']:.1f} | {per_nm:.1f} | {per_nm_md / per_nm:.2f} "
            f"| {vs} | {'' if r is md else format(r['err_ux'] * 100, '.2f') + ' %'} "
            f"| {'' if r is md else format(r['err_ur'] * 100, '.2f') + ' %'} "
            f"| {'' if r is md else format(largest(r) * 100, '.2f') + ' %'} "
            f"| {r['err_uy_lefm'] * 100:.1f} % | {r['uy10']:.4f} |")
    if any(r["warnings"] for r in rows):
        lines += ["", "(*) level 2 within its imaginary depth of the crack faces (the builder's "
                  "warning): it sees them as a coarse surface"]
    return lines


def plot(rows, path, L):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(figsize=(7, 4.8))
    md = next(r for r in rows if r["model"] == "md")
    marks = {(2, 2): "o", (3, 2): "s", (2, 3): "^", (2, 4): "D"}
    for r in rows:
        if r is md:
            continue
        quadratic = parse_all(r["model"])[5] == "quadratic"
        ax.plot(largest(r) * 100, r["core_s"] / r["front_nm"], marks.get((r["k"], r["levels"]), "x"),
                label=r["model"], mfc="none" if quadratic else None)
        ax.annotate(r["model"], (largest(r) * 100, r["core_s"] / r["front_nm"]), fontsize=7,
                    xytext=(3, 3), textcoords="offset points")
    per_nm_md = md["core_s"] / md["front_nm"]
    ax.axhline(per_nm_md, color="k", lw=1, label="full MD")
    ax.axhline(per_nm_md / 10, color="k", ls=":", lw=1, label="full MD / 10")
    ax.axvline(5, color="r", ls=":", lw=1, label="5 % error")
    ax.set_yscale("log")
    ax.set_xscale("log")
    ax.set_xlabel("largest displacement error against full MD (u_y, u_x, u_r; r >= 5 A) (%)")
    ax.set_ylabel("core-seconds per nm of crack front")
    ax.set_title(f"Fe crack K-test, L = {L:.1f} A: cost against error")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--units", type=int, default=6, help="L in units of 48.45 A")
    ap.add_argument("--models", default=DEFAULT)
    ap.add_argument("--np", type=int, default=1, help="MPI ranks of each run")
    ap.add_argument("--work", default=os.path.expanduser("~/.cache/mca/output/gp_pareto"))
    ap.add_argument("--out", default=str(ROOT / "bench" / "results" / "gp_pareto"))
    ap.add_argument("--ftol", type=float, default=1e-4,
                    help="the relaxations' largest force component (eV/A)")
    ap.add_argument("--reuse", action="store_true", help="keep models already run in --work")
    args = ap.parse_args()
    models = args.models.split(",")
    if "md" not in models:
        raise SystemExit("--models: the list needs md (the reference)")
    if args.units < 1:
        raise SystemExit(f"--units {args.units}: at least 1")
    L = args.units * UNIT
    for name in models:
        model_thickness(name)
    frame = frame_depth(models)
    if frame > L / 2:
        raise SystemExit(f"--units {args.units}: the frame ({frame:.2f} A) takes more than half the "
                         f"block (L = {L:.2f} A); use more units")
    tag = f"u{args.units}" + ("" if args.ftol == 1e-4 else f".f{args.ftol:g}")
    work = pathlib.Path(args.work) / tag
    work.mkdir(parents=True, exist_ok=True)
    shutil.copy(ROOT / "examples" / "gp_crack" / "in.ktest", work)
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    for name in models:
        print(f"{name}: building and relaxing ...", flush=True)
        rows.append(run_model(name, L, frame, args, work))
        shutil.copy(work / f"log.ktest.{name}", out / f"log.ktest.{tag}.{name}")
        print(f"  {rows[-1]['particles']} particles, {rows[-1]['core_s']:.1f} core-s, "
              f"{rows[-1]['steps']} iterations", flush=True)
    errors(rows, work)
    lines = table(rows, L, frame, args.np, args.ftol)
    stem = str(out.parent / f"{out.name}.{tag}")
    pathlib.Path(stem + ".md").write_text("\n".join(lines) + "\n")
    with open(stem + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    plot(rows, stem + ".png", L)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
