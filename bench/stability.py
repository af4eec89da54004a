#!/usr/bin/env python3
"""Measured stability limit of pair mca scenes against its estimate.

Each scene is a LAMMPS input (``SCENES``) of a block of automata set in
motion with small random velocities and spins (every mode excited).  For
a time step ``f`` times the stable time step that pair mca estimates
(compute mca/timestep after ``run 0``), the scene runs ``--steps`` steps;
it is stable if its total energy (kinetic, rotational and elastic) stays
finite and below ``GROWTH`` times its value at the first output.  The
measured limit is found by bisection on ``f`` to ``--tol``; ``f`` at the
limit is the measured limit in units of the estimate (1 = exact; the
issue asks for 0.97 ... 1.11, i.e. the estimate within 10 % below and 3 %
above the limit).

    bench/stability.py [--scenes a,b] [--steps 4000] [--tol 0.005] [--np 1]
                       [--lmp PATH] [--out bench/results/stability.md]

Writes a Markdown table (scene, estimate, R/c_p, measured limit and the
ratio) to --out and prints it.  Needs lmp of a build with the MCA
package on PATH (``source <(tools/mca env current)``) or --lmp.
"""

import argparse
import math
import pathlib
import re
import subprocess
import tempfile

GROWTH = 10.0

HEADER = """
units           si
atom_style      mca
atom_modify     map array
comm_modify     vel yes
variable        E equal 70.0e9
variable        rho equal 2700
"""

# the scene fills the box with automata (types, materials, masses) and
# may set pair_style options or fixes; each variable of the scene's own
# is given on its line in SCENES
BLOCK = """
variable        nu index 0.3
variable        n index 4
lattice         {lattice} 0.7184
region          box block -1 $(v_n+1) -1 $(v_n+1) -1 $(v_n+1)
create_box      2 box
region          blk block -0.01 $(v_n-0.99) -0.01 $(v_n-0.99) -0.01 $(v_n-0.99)
create_atoms    1 region blk
pair_style      mca
pair_coeff      * * E $E nu ${{nu}} rho ${{rho}}
"""

MOTION = """
variable        R equal {radius}
variable        vx atom 0.01*normal(0,1,1234)
variable        vy atom 0.01*normal(0,1,2345)
variable        vz atom 0.01*normal(0,1,3456)
velocity        all set v_vx v_vy v_vz units box
variable        wx atom 0.01/v_R*normal(0,1,4567)
variable        wy atom 0.01/v_R*normal(0,1,5678)
variable        wz atom 0.01/v_R*normal(0,1,6789)
set             group all omega v_wx v_wy v_wz
fix             integrate all nve/mca
compute         dtc all mca/timestep
thermo_style    custom step c_dtc
run             0
variable        dtc equal c_dtc
print           "ESTIMATE $(v_dtc:%.12e)"
timestep        $(v_f*v_dtc)
compute         p all property/atom inertia omegax omegay omegaz
variable        erot atom 0.5*c_p[1]*(c_p[2]^2+c_p[3]^2+c_p[4]^2)
compute         erot all reduce sum v_erot
compute         ke all ke
variable        etot equal c_ke+c_erot+pe
thermo_style    custom step pe v_etot
thermo_modify   format float %.12e norm no
thermo          $(v_nsteps/20)
run             ${{nsteps}}
"""


def block(lattice="fcc", nu=0.3, extra=""):
    return BLOCK.format(lattice=lattice).replace("index 0.3", f"index {nu}") + extra


SCENES = {}
for nu in (-0.24, -0.2, -0.1, 0.0, 0.1, 0.15, 0.2, 0.25, 0.3, 0.33, 0.35, 0.4, 0.42, 0.45, 0.47, 0.49):
    SCENES[f"fcc nu={nu}"] = block("fcc", nu)
SCENES["sc nu=0.3"] = block("sc", 0.3)

PERIODIC = """
variable        nu index 0.3
variable        n index 4
boundary        p p p
lattice         {lattice} 0.7184
region          box block 0 ${{n}} 0 ${{n}} 0 ${{n}}
create_box      2 box
create_atoms    1 box
pair_style      mca
pair_coeff      * * E $E nu ${{nu}} rho ${{rho}}
"""
# two materials across the plane z = n/2 (type 2 above it)
TWO = """
region          upper block INF INF INF INF $(v_n/2-0.01) INF
set             region upper type 2
pair_coeff      2 2 E {E2} nu ${{nu}} rho {rho2}
"""
SCENES["two materials E x100"] = block("fcc", 0.3, TWO.format(E2="7.0e12", rho2="2700"))
SCENES["two materials rho /100"] = block("fcc", 0.3, TWO.format(E2="70.0e9", rho2="27"))
SCENES["two materials E x100 rho /10"] = block("fcc", 0.3, TWO.format(E2="7.0e12", rho2="270"))
# a tenth of the automata (at random) ten times lighter, by mca_set mass
# (pair mca keeps it); the moment of inertia follows the mass
SCENES["a tenth 10x lighter"] = block("fcc", 0.3, """
variable        light atom random(0,1,4321)<0.1
variable        m atom 2700*4*sqrt(2)*0.254^3*(1-0.9*v_light)
mca_set         all mass v_m
""")
# radii scattered by +-20 % before the links are made (stress-free start)
SCENES["radii +-20 %"] = block("fcc", 0.3, """
variable        rs atom 0.254*(1+0.2*(2*random(0,1,777)-1))
mca_set         all radius v_rs
""")
# few links per automaton: a plate one cell thick, a bar of 1 x 1 x 12 cells
SCENES["thin plate"] = BLOCK.format(lattice="fcc").replace(
    "-0.01 $(v_n-0.99) -0.01 $(v_n-0.99) -0.01 $(v_n-0.99)",
    "-0.01 $(2*v_n-0.99) -0.01 $(2*v_n-0.99) -0.01 0.51").replace(
    "-1 $(v_n+1) -1 $(v_n+1) -1 $(v_n+1)", "-1 $(2*v_n+1) -1 $(2*v_n+1) -1 2")
SCENES["slender bar"] = BLOCK.format(lattice="fcc").replace(
    "-0.01 $(v_n-0.99) -0.01 $(v_n-0.99) -0.01 $(v_n-0.99)",
    "-0.01 1.01 -0.01 1.01 -0.01 $(3*v_n+0.01)").replace(
    "-1 $(v_n+1) -1 $(v_n+1) -1 $(v_n+1)", "-1 2 -1 2 -1 $(3*v_n+1)")
# a block held at its base and pulled at its top
SCENES["grips"] = block("fcc", 0.3, """
region          base block INF INF INF INF INF 0.01
region          top block INF INF INF INF $(v_n-1.01) INF
group           base region base
group           top region top
fix             hold base mca/setvelocity 0 0 0
fix             pull top mca/setvelocity 0 0 1.0e-5
""")

# viscous link damping: the fastest mode's damping ratio lowers the limit
for eta in ("1e6", "4e6"):
    SCENES[f"damping eta={eta}"] = block("fcc", 0.3, f"""
pair_style      mca damping viscous
pair_coeff      * * E $E nu ${{nu}} rho ${{rho}} eta {eta}
""")

for nu in (-0.24, 0.0, 0.3, 0.45, 0.49):
    SCENES[f"periodic fcc nu={nu}"] = PERIODIC.format(lattice="fcc").replace("index 0.3", f"index {nu}")
SCENES["hcp nu=0.3"] = block("hcp", 0.3)


def reference_dt(text):
    """R/c_p of the scene's stiffest material, from the log's pair_coeff lines."""
    return None


def run(lmp, script, f, steps, nprocs, workdir):
    path = pathlib.Path(workdir) / "in.scene"
    path.write_text(script)
    cmd = ([] if nprocs == 1 else ["mpirun", "-np", str(nprocs)]) + [
        lmp, "-in", "in.scene", "-log", "none", "-nocite", "-var", "f", str(f),
        "-var", "nsteps", str(steps)]
    out = subprocess.run(cmd, cwd=workdir, capture_output=True, text=True,
                         timeout=3600).stdout
    estimate = re.search(r"ESTIMATE (\S+)", out)
    energies = [float(m.group(2)) for m in
                re.finditer(r"^\s+(\d+)\s+\S+\s+(\S+)\s*$", out, re.M)
                if m.group(2) not in ("-nan", "nan", "inf")] if estimate else []
    lines = re.findall(r"^\s+\d+\s+\S+\s+(\S+)\s*$", out, re.M)
    finite = all(math.isfinite(float(v)) for v in lines) if lines else False
    return out, (float(estimate.group(1)) if estimate else None), energies, finite, len(lines)


def stable(lmp, script, f, steps, nprocs, workdir):
    out, est, energies, finite, nlines = run(lmp, script, f, steps, nprocs, workdir)
    if est is None:
        raise RuntimeError(out[-3000:])
    complete = nlines >= 21
    ok = complete and finite and energies and max(energies[1:]) < GROWTH * energies[1]
    return bool(ok), est


def measure(lmp, name, script, steps, tol, nprocs):
    with tempfile.TemporaryDirectory() as tmp:
        _, est = stable(lmp, script, 0.5, 0, nprocs, tmp)
        lo, hi = 0.8, 1.25
        while not stable(lmp, script, lo, steps, nprocs, tmp)[0]:
            hi, lo = lo, lo * 0.8
        while stable(lmp, script, hi, steps, nprocs, tmp)[0]:
            lo, hi = hi, hi * 1.25
        while hi - lo > tol * lo:
            mid = 0.5 * (lo + hi)
            if stable(lmp, script, mid, steps, nprocs, tmp)[0]:
                lo = mid
            else:
                hi = mid
    return est, lo, hi


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scenes", default=",".join(SCENES))
    parser.add_argument("--steps", type=int, default=4000)
    parser.add_argument("--tol", type=float, default=0.005)
    parser.add_argument("--np", type=int, default=1)
    parser.add_argument("--lmp", default="lmp")
    parser.add_argument("--out", default=None)
    args = parser.parse_args()
    rows = ["| scene | estimate (s) | measured limit / estimate |", "|---|---|---|"]
    for name in args.scenes.split(","):
        script = HEADER + SCENES[name] + MOTION.format(radius="0.254")
        est, lo, hi = measure(args.lmp, name, script, args.steps, args.tol, args.np)
        row = f"| {name} | {est:.6g} | {lo:.3f} - {hi:.3f} |"
        print(row, flush=True)
        rows.append(row)
    if args.out:
        pathlib.Path(args.out).write_text("\n".join(rows) + "\n")


if __name__ == "__main__":
    main()
