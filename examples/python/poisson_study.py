#!/usr/bin/env python3
"""A parameter study driven through the LAMMPS Python module: the tension
cube with frictionless grips (examples/tension_cube, uniaxial stress) for a
list of Poisson's ratios.  For each one the script builds the cube, takes
its time step from compute mca/timestep, loads it in chunks of steps and
reads, after every chunk, the reaction force of the top grip (fix
mca/setvelocity's global vector) and the gauge strains as numpy arrays;
at the end it reads the per-automaton stress tensor of compute mca/atom.
It fits the apparent E and nu (slopes of the loading, strain > 30 % of its
largest) and compares the mean stress of the interior automata with the
grip's stress, writes one CSV row per run and draws the study.

    python3 poisson_study.py [--nu 0.0 0.1 0.2 0.3 0.4] [--n 6] [--fraction 0.7] [--out DIR]

Needs the LAMMPS Python module of a build with the MCA package on the
PYTHONPATH and its shared library on LD_LIBRARY_PATH
(eval "$(tools/mca env current)" sets both).  Output: DIR/poisson_study.csv,
DIR/poisson_study.png, DIR/cube.nu<nu>.dump (DIR default: the working directory).
"""

import argparse
import csv
import pathlib
import sys

import numpy as np

E = 70.0e9
RHO = 2700.0
SIDE = 7.184          # m, the cube of examples/tension_cube at n = 10
SPEED = 0.01          # m/s, the top grip's final speed
RAMP = 0.005          # s, its smooth start
LOAD_TIME = 0.06      # s of loading
CHUNKS = 60


def build(lmp, nu, n, fraction):
    """The cube of n cells across, its grips, and the time step."""
    a = SIDE / n
    lmp.commands_string(f"""
units           si
atom_style      mca
atom_modify     map array
boundary        f f f
lattice         fcc {a}
region          box block -1 {n + 1} -1 {n + 1} -1 {n + 1}
create_box      1 box
region          cube block -0.01 {n + 0.01} -0.01 {n + 0.01} -0.01 {n + 0.01}
create_atoms    1 region cube
comm_modify     vel yes
pair_style      mca
pair_coeff      * * E {E} nu {nu} rho {RHO}
region          top block INF INF INF INF {n - 0.1} INF
region          bot block INF INF INF INF INF 0.1
group           top region top
group           bot region bot
region          pin block {n / 2 - 0.1} {n / 2 + 0.1} {n / 2 - 0.1} {n / 2 + 0.1} INF 0.1
group           pin region pin
region          xlo block INF 0.1 INF INF {n / 2 - 0.1} {n / 2 + 0.1}
region          xhi block {n - 0.1} INF INF INF {n / 2 - 0.1} {n / 2 + 0.1}
group           xlo region xlo
group           xhi region xhi
variable        v equal {SPEED}*(1.0-exp(-((time/{RAMP})^2)))
fix             top top mca/setvelocity NULL NULL v_v
fix             bot bot mca/setvelocity NULL NULL 0
fix             pin pin mca/setvelocity 0 0 NULL
fix             integrate all nve/mca
compute         dt all mca/timestep
compute         stress all mca/atom sxx syy szz sxy sxz syz
thermo_style    custom step c_dt
run             0
""")
    dt = fraction * lmp.extract_compute("dt", 0, 0)     # global scalar
    lmp.command(f"timestep {dt!r}")
    lmp.commands_string("""
variable        L0 equal xcm(top,z)-xcm(bot,z)
variable        L0 equal $(v_L0)
variable        W0 equal xcm(xhi,x)-xcm(xlo,x)
variable        W0 equal $(v_W0)
variable        strain equal (xcm(top,z)-xcm(bot,z))/v_L0-1.0
variable        lateral equal (xcm(xhi,x)-xcm(xlo,x))/v_W0-1.0
""")
    return a, dt


def run_case(lammps_module, nu, n, fraction, out):
    """One run; the histories and the final per-automaton stress as numpy arrays."""
    lmp = lammps_module.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    try:
        a, dt = build(lmp, nu, n, fraction)
        area = n * (n + 0.5) * a * a     # load-bearing area of a (001) plane (examples/tension_cube)
        steps = max(1, round(LOAD_TIME / dt / CHUNKS))
        time, strain, lateral, reaction = [], [], [], []
        for chunk in range(CHUNKS):
            # one run in chunks: the set-up once, then straight on
            lmp.command(f"run {steps} pre {'yes' if chunk == 0 else 'no'} post no")
            time.append(lmp.get_thermo("time"))
            strain.append(lmp.extract_variable("strain"))
            lateral.append(lmp.extract_variable("lateral"))
            # fix mca/setvelocity: the force the grip applies, a global 3-vector
            reaction.append([lmp.extract_fix("top", 0, 1, k) for k in range(3)])
        # the final state for OVITO or ParaView (the examples' snapshot columns)
        lmp.command(f"write_dump all custom {out}/cube.nu{nu:g}.dump id type x y z vx vy vz "
                    "radius c_stress[*] modify sort id")
        nlocal = lmp.extract_global("nlocal")
        x, y, z = lmp.numpy.extract_atom("x")[:nlocal].T.copy()
        stress = lmp.numpy.extract_compute("stress", 1, 2)[:nlocal].copy()    # per atom, array
        natoms = lmp.get_natoms()
    finally:
        lmp.close()
    reaction = np.array(reaction)
    # the automata of the middle third, away from grips and free faces
    low, high = n * a / 3, 2 * n * a / 3
    inner = (x > low) & (x < high) & (y > low) & (y < high) & (z > low) & (z < high)
    return {"nu": nu, "n": n, "natoms": natoms, "dt": dt, "time": np.array(time),
            "strain": np.array(strain), "lateral": np.array(lateral),
            "stress": -reaction[:, 2] / area, "reaction": reaction,
            "szz_inner": stress[inner, 2], "ninner": int(inner.sum())}


def fit(case):
    """Apparent E and nu: slopes over the loading with strain > 30 % of its largest."""
    strain = case["strain"]
    use = strain > 0.3 * strain.max()
    e_app = np.polyfit(strain[use], case["stress"][use], 1)[0]
    nu_app = -np.polyfit(strain[use], case["lateral"][use], 1)[0]
    szz = case["szz_inner"].mean()
    return {"nu": case["nu"], "n": case["n"], "automata": case["natoms"], "dt": case["dt"],
            "E_app": e_app, "E_error": e_app / E - 1.0, "nu_app": nu_app,
            "nu_error": nu_app - case["nu"], "grip_stress": case["stress"][-1],
            "inner_szz_mean": szz, "inner_szz_spread": case["szz_inner"].std() / abs(szz),
            "inner_vs_grip": szz / case["stress"][-1] - 1.0, "inner_automata": case["ninner"]}


def plot(rows, cases, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    for case in cases:
        left.plot(case["strain"] * 1e6, case["stress"] / 1e6, label=f"nu = {case['nu']:g}")
    left.set_xlabel("axial strain (1e-6)")
    left.set_ylabel("grip stress (MPa)")
    left.legend(fontsize=8)
    nu = np.array([r["nu"] for r in rows])
    right.plot(nu, nu, "k--", lw=0.8, label="input")
    right.plot(nu, [r["nu_app"] for r in rows], "o", label="apparent nu")
    right.plot(nu, [r["E_app"] / E for r in rows], "s", label="apparent E / E")
    right.set_xlabel("Poisson's ratio of the material")
    right.legend(fontsize=8)
    fig.suptitle(f"tension cube, {rows[0]['automata']} automata: the law gives the continuum's "
                 "E and nu for every nu")
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--nu", type=float, nargs="+", default=[0.0, 0.1, 0.2, 0.3, 0.4])
    parser.add_argument("--n", type=int, default=6, help="cells across the cube (default 6)")
    parser.add_argument("--fraction", type=float, default=0.7,
                        help="fraction of the stable time step (default 0.7)")
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("."))
    args = parser.parse_args(argv)
    for nu in args.nu:
        if not -1.0 < nu < 0.5:
            parser.error(f"--nu {nu}: Poisson's ratio must lie in (-1, 0.5)")
    if args.n < 2:
        parser.error(f"--n {args.n}: the cube needs at least 2 cells across")
    if not 0.0 < args.fraction <= 1.0:
        parser.error(f"--fraction {args.fraction}: must lie in (0, 1]")
    try:
        import lammps as lammps_module
    except ImportError:
        sys.exit("poisson_study: the LAMMPS Python module is not on PYTHONPATH "
                 "(eval \"$(tools/mca env current)\" sets it)")
    args.out.mkdir(parents=True, exist_ok=True)
    cases = []
    for nu in args.nu:
        cases.append(run_case(lammps_module, nu, args.n, args.fraction, args.out))
        print(f"STUDY nu {nu:g}: {cases[-1]['natoms']} automata, {len(cases[-1]['time'])} chunks",
              flush=True)
    rows = [fit(c) for c in cases]
    with open(args.out / "poisson_study.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    for r in rows:
        print(f"STUDY nu {r['nu']:g}: E_app {r['E_app']:.6e} ({r['E_error']:+.3%}), nu_app "
              f"{r['nu_app']:.5f} ({r['nu_error']:+.5f}), interior szz / grip stress - 1 = "
              f"{r['inner_vs_grip']:+.3%} (spread {r['inner_szz_spread']:.2%}, "
              f"{r['inner_automata']} automata)")
    plot(rows, cases, args.out / "poisson_study.png")
    return rows


if __name__ == "__main__":
    main()
