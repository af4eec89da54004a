"""Fretting of a brittle beam lattice: the bonds broken under the pad
(fretting.start.data, fretting.end.data: the bonds at the start and at the
end), drawn where they were at the start, and the history of the run
(log: the drive, the pad's force on its driven row, the bonds left); the
depth profile of the broken bonds printed.  fretting.png."""

import re
import sys

import numpy as np


def read_data(path):
    """(positions by atom ID, set of bonds (lo, hi) by type) of a data file
    of atom_style mca (x, y in the 9th and 10th columns)."""
    text = open(path).read()
    atoms = text.split("\nAtoms")[1].split("\n\n")[1]
    pos = {}
    for line in atoms.strip().splitlines():
        w = line.split()
        pos[int(w[0])] = (float(w[8]), float(w[9]))
    bonds = {}
    if "\nBonds" in text:
        for line in text.split("\nBonds")[1].split("\n\n")[1].strip().splitlines():
            _, btype, a, b = map(int, line.split()[:4])
            bonds.setdefault(btype, set()).add((min(a, b), max(a, b)))
    box = re.search(r"(\S+) (\S+) xlo xhi", text)
    return pos, bonds, (float(box.group(1)), float(box.group(2)))


def broken_bonds(start, end, btype=1):
    """The substrate's bonds (type 1) present at the start and gone at the end."""
    return sorted(start[1].get(btype, set()) - end[1].get(btype, set()))


def depth_profile(start, broken, surface):
    """Broken bonds per row below the substrate's surface (depth of the bond's
    middle in rows of sqrt(3)/2)."""
    pos = start[0]
    depth = [(surface - 0.5 * (pos[a][1] + pos[b][1])) / (np.sqrt(3.0) / 2.0) for a, b in broken]
    return np.bincount(np.floor(np.array(depth) + 0.5).astype(int).clip(0)) if depth else []


def clusters(data):
    """The fragments of a data file's particles, clusters joined by its
    bonds (union-find): {atom ID: lowest atom ID of its cluster}."""
    parent = {a: a for a in data[0]}

    def root(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a
    for bonds in data[1].values():
        for a, b in bonds:
            ra, rb = root(a), root(b)
            if ra != rb:
                parent[max(ra, rb)] = min(ra, rb)
    return {a: root(a) for a in data[0]}


def read_fragments(path):
    """{atom ID: fragment ID} of the dump of compute fragment/atom."""
    lines = open(path).read().split("ITEM: ATOMS id c_frag")[-1].strip().splitlines()
    return {int(w[0]): int(float(w[1])) for w in (line.split() for line in lines)}


def fragment_sizes(fragment_of):
    """Fragment sizes (particles), largest first."""
    return sorted(np.bincount(np.unique(list(fragment_of.values()), return_inverse=True)[1]),
                  reverse=True)


def thermo(path):
    rows = []
    for block in re.findall(r"^\s*Step\s+Time.*?\n(.*?)^Loop", open(path).read(), re.M | re.S):
        rows += [[float(w) for w in line.split()] for line in block.strip().splitlines()
                 if re.match(r"^\s*\d", line)]
    return np.array(rows)


def main(log="log.fretting", start_file="fretting.start.data", end_file="fretting.end.data"):
    start, end = read_data(start_file), read_data(end_file)
    broken = broken_bonds(start, end)
    ys = [p[1] for a, p in start[0].items()
          if any(a in bond for bond in start[1].get(1, ()))]
    surface = max(ys)
    profile = depth_profile(start, broken, surface)
    total = len(start[1].get(1, ()))
    print(f"substrate bonds {total}, broken {len(broken)} ({100.0 * len(broken) / total:.1f} %)")
    print("broken bonds by row below the surface: "
          + ", ".join(f"{k}: {n}" for k, n in enumerate(profile)))
    sizes = fragment_sizes(clusters(end))
    debris = [n for n in sizes[2:]]
    print(f"fragments {len(sizes)}: the two bodies of {sizes[0]} and {sizes[1]} particles, "
          f"debris {len(debris)} (sizes {', '.join(map(str, debris)) or 'none'})")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(11, 7.5),
                                      gridspec_kw={"height_ratios": [2.2, 1]})
    lx = start[2][1] - start[2][0]

    def segments(bonds, pos):
        out = []
        for a, b in bonds:
            (xa, ya), (xb, yb) = pos[a], pos[b]
            if abs(xb - xa) < 0.5 * lx:    # (not across the periodic boundary)
                out.append([(xa, ya), (xb, yb)])
        return out
    intact = set().union(*end[1].values()) if end[1] else set()
    top.add_collection(LineCollection(segments(intact, end[0]), colors="0.6", linewidths=0.6))
    top.add_collection(LineCollection(segments(broken, start[0]), colors="red", linewidths=1.6))
    xy = np.array(list(end[0].values()))
    top.plot(xy[:, 0], xy[:, 1], ".", color="0.3", ms=2)
    top.set_aspect("equal")
    top.set_xlim(start[2])
    top.set_title(f"bonds broken by fretting (red, {len(broken)} of {total}); intact bonds at "
                  "the end (grey)")
    data = thermo(log)
    time, dx, bonds, fx = data[:, 1], data[:, 2], data[:, 4], data[:, 5]
    bottom.plot(time, dx, label="drive x")
    bottom.plot(time, fx / max(1e-300, np.abs(fx).max()) * np.abs(dx).max(),
                label="force on the driven row (scaled)")
    bottom.set_xlabel("time")
    twin = bottom.twinx()
    twin.plot(time, bonds, "k-", label="bonds")
    twin.set_ylabel("bonds")
    bottom.legend(loc="lower left")
    fig.tight_layout()
    fig.savefig("fretting.png", dpi=110)


if __name__ == "__main__":
    main(*sys.argv[1:])
