#!/usr/bin/python3
"""Bonds by distance at set-up (digest R13) for the packing of in.pack:
every pair of discs whose gap is below `gap` times the sum of their radii
gets a beam (their contacts: the packing is jammed, so they overlap or
nearly touch).  The x direction becomes free: bonds across the periodic x
boundary are left out, so the lattice has two faces to pull on; y stays
periodic.  Writes bonded.data (atom_style mca, shrink-wrapped in x).

    /usr/bin/python3 bond.py pack.data bonded.data [gap]
"""

import sys

import numpy as np


def read_pack(path):
    lines = open(path).read().splitlines()
    box = {}
    for line in lines[:12]:
        words = line.split()
        if len(words) == 4 and words[2].endswith("lo"):
            box[words[2][0]] = (float(words[0]), float(words[1]))
    start = next(k for k, line in enumerate(lines) if line.startswith("Atoms")) + 2
    rows = []
    for line in lines[start:]:
        if not line.strip():
            break
        rows.append([float(w) for w in line.split()[:11]])
    atoms = np.array(rows)
    return atoms[np.argsort(atoms[:, 0])], box


def bonds_by_distance(atoms, box, gap):
    """Pairs (0-based) with d < (1 + gap)(r_i + r_j), the minimum image in y
    and none in x."""
    xy = atoms[:, 8:10]
    r = 0.5 * atoms[:, 4]
    ly = box["y"][1] - box["y"][0]
    d = xy[None, :, :] - xy[:, None, :]
    d[:, :, 1] -= ly * np.round(d[:, :, 1] / ly)
    dist = np.hypot(d[:, :, 0], d[:, :, 1])
    reach = (1.0 + gap) * (r[:, None] + r[None, :])
    i, j = np.nonzero(np.triu(dist < reach, 1))
    return list(zip(i, j))


def write_bonded(path, atoms, box, bonds):
    n = len(atoms)
    per_atom = np.bincount(np.array(bonds).ravel(), minlength=n)
    lines = ["polydisperse packing with beams by distance (bond.py)", "",
             f"{n} atoms", "1 atom types", f"{len(bonds)} bonds", "1 bond types",
             f"{per_atom.max() + 2} extra bond per atom", "24 extra special per atom", "",
             f"{box['x'][0]!r} {box['x'][1]!r} xlo xhi",
             f"{box['y'][0]!r} {box['y'][1]!r} ylo yhi", "-0.5 0.5 zlo zhi", "",
             "Atoms # mca", ""]
    for a in atoms:
        lines.append(f"{int(a[0])} 0 1 0 {a[4]!r} {a[5]!r} {a[6]!r} {a[7]!r} "
                     f"{a[8]!r} {a[9]!r} 0.0")
    lines += ["", "Bonds", ""]
    lines += [f"{k + 1} 1 {int(atoms[i, 0])} {int(atoms[j, 0])}" for k, (i, j) in enumerate(bonds)]
    open(path, "w").write("\n".join(lines) + "\n")
    return per_atom


def main():
    source = sys.argv[1] if len(sys.argv) > 1 else "pack.data"
    target = sys.argv[2] if len(sys.argv) > 2 else "bonded.data"
    gap = float(sys.argv[3]) if len(sys.argv) > 3 else 0.02
    atoms, box = read_pack(source)
    bonds = bonds_by_distance(atoms, box, gap)
    per_atom = write_bonded(target, atoms, box, bonds)
    print(f"bond.py: {len(atoms)} discs, {len(bonds)} bonds (gap < {gap} (r_i + r_j)), "
          f"mean coordination {2 * len(bonds) / len(atoms):.3f}, "
          f"{np.sum(per_atom == 0)} without bonds; radii {0.5 * atoms[:, 4].min():.4f}"
          f"-{0.5 * atoms[:, 4].max():.4f}")


if __name__ == "__main__":
    main()
