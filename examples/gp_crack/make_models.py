#!/usr/bin/python3
"""The models of the K-test (in.ktest), made with the package's GP model
builder (tools/gp_build.py) through its Python interface.

Bcc Fe (Fe_mm.eam.fs), X = [110], Y = [-110], Z = [001] (8 a0 = 22.8 A,
periodic: more than twice the level-2 cutoff), a block [-L, L)^2, L = n
level-2 periods 2 sqrt(2) a0 along X and Y (both levels end on the same
planes), with an edge crack from the xlo face to the tip at x = 1 A (a slit 4.5 A high:
three (110) planes removed, faces 8.1 A apart, beyond the cutoff).

  md.n      all atoms
  gpH.n     atoms in x < H, |y| < H (the crack faces are atomic all along),
            level-2 particles (k = 2) elsewhere, fix gp/link fit quadratic

  make_models.py n H [H ...]   (H in A; writes md.n.data, in.md.n, ...;
                                prints L)
"""
import math
import os
import pathlib
import sys

root = pathlib.Path(os.environ.get("MCA_ROOT", pathlib.Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(root / "tools"))
import gp_build  # noqa: E402


A0 = 2.855324
PERIOD = 2 * math.sqrt(2) * A0          # level 2 along X and Y


def cracked_plate(xlo, xhi, ylo, yhi, tip, atoms, fit="quadratic"):
    """The Fe plate of this example's models, [xlo, xhi) x [ylo, yhi) x 8 a0,
    an edge crack from xlo to tip; all atoms (atoms None) or atoms in x < X,
    |y| < Y (atoms = (X, Y)) and level 2 elsewhere.  The box is shifted down by 1e-4 A: the
    planes at the lower faces are in, those at the upper ones out (as the
    builder's half-open regions), the same for all levels.  fit: fix
    gp/link's fit of the interface particles (quadratic, exact for the
    curved crack-tip field, is the advice for crack tips; the K-test
    measured both)."""
    return {"lattice": "bcc", "a0": A0, "element": "Fe",
            "orient": [[1, 1, 0], [-1, 1, 0], [0, 0, 1]],
            "potential": {"style": "eam/fs", "file": "Fe_mm.eam.fs"}, "ratio": 2,
            "box": [xlo - 1e-4, xhi - 1e-4, ylo - 1e-4, yhi - 1e-4, 0, 8 * A0], "periodic": "z",
            "cuts": [{"crack": {"tip": tip, "y": 0, "height": 4.5}}], "fit": fit,
            "levels": [None] if atoms is None else
            [{"block": [None, atoms[0], -atoms[1], atoms[1], None, None]}, None]}


def main(n, heights):
    L = n * PERIOD
    print(f"L {L:.6f}")
    models = [(f"md.{n}", None)] + [(f"gp{h:g}.{n}", h) for h in heights]
    for name, H in models:
        model = gp_build.build(cracked_plate(-L, L, -L, L, 1.0, None if H is None else (H, H)))
        model.write(name)
        print(f"{name}: " + "; ".join(line.strip() for line in model.summary()[1:]))


if __name__ == "__main__":
    main(int(sys.argv[1]), [float(h) for h in sys.argv[2:]])
