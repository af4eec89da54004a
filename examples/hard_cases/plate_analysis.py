"""Analysis of the notched plate (in.notched_plate): the pieces the intact
links hold together, the crack path, the stable time step; and the log
reader of the examples' plots.  Used by plot.py, ../contacts/plot.py and
unittest/python/test_hard_cases.py (numpy only)."""

import numpy as np


def read_thermo(path):
    """The thermo output of the last run of a log file as a dict of numpy
    arrays, warnings between its lines skipped (the examples' plots)."""
    with open(path) as handle:
        lines = handle.read().splitlines()
    start = [k for k, line in enumerate(lines) if line.split()[:1] == ["Step"]][-1]
    names = lines[start].split()
    rows = []
    for line in lines[start + 1:]:
        if line.startswith("WARNING"):
            continue
        words = line.split()
        if len(words) != len(names):
            break
        try:
            rows.append([float(w) for w in words])
        except ValueError:
            break
    data = np.array(rows)
    return {name: data[:, k] for k, name in enumerate(names)}


def read_snapshots(path):
    """The snapshots of a LAMMPS text dump (custom or local): a list of
    (step, column names, array)."""
    snapshots = []
    with open(path) as handle:
        lines = handle.read().splitlines()
    i = 0
    while i < len(lines):
        if not lines[i].startswith("ITEM: TIMESTEP"):
            i += 1
            continue
        step = int(lines[i + 1])
        count = int(lines[i + 3])
        columns = lines[i + 8].split()[2:]
        rows = [lines[i + 9 + k].split() for k in range(count)]
        data = np.array(rows, dtype=float).reshape(count, len(columns))
        snapshots.append((step, columns, data))
        i += 9 + count
    return snapshots


def pieces(ids, links):
    """Label of the piece of each automaton: connected components of the
    graph of intact links (state 1).  ids: atom IDs; links: rows of id1,
    id2, state.  Returns {id: label}, labels 0.. by decreasing size."""
    index = {int(i): k for k, i in enumerate(ids)}
    parent = list(range(len(ids)))

    def root(k):
        while parent[k] != k:
            parent[k] = parent[parent[k]]
            k = parent[k]
        return k

    for id1, id2, state in links[:, :3]:
        if int(state) != 1:
            continue
        a, b = root(index[int(id1)]), root(index[int(id2)])
        if a != b:
            parent[a] = b
    roots = np.array([root(k) for k in range(len(ids))])
    unique, counts = np.unique(roots, return_counts=True)
    order = unique[np.argsort(-counts, kind="stable")]
    label = {r: n for n, r in enumerate(order)}
    return {int(i): label[roots[k]] for k, i in enumerate(ids)}


def broken_midpoints(ids, positions, links):
    """Midpoints of the broken links (state 2) in the given positions."""
    index = {int(i): k for k, i in enumerate(ids)}
    broken = links[links[:, 2] == 2]
    lo = np.array([index[int(i)] for i in broken[:, 0]], dtype=int)
    hi = np.array([index[int(i)] for i in broken[:, 1]], dtype=int)
    if len(lo) == 0:
        return np.zeros((0, 3))
    return 0.5 * (positions[lo] + positions[hi])


def plate_result(directory, name="plate"):
    """What the last dumps of a run of in.notched_plate (-var name) show:
    the pieces, and which hold the bottom and the top grip; the broken
    links' midpoints in the reference (first) positions."""
    atoms = read_snapshots(directory / f"dump.{name}.atoms")
    links = read_snapshots(directory / f"dump.{name}.links")
    step0, columns, first = atoms[0]
    stepN, _, last = atoms[-1]
    col = {name: k for k, name in enumerate(columns)}
    ids = last[:, col["id"]]
    final_links = links[-1][2]
    label = pieces(ids, final_links)
    order0 = np.argsort(first[:, col["id"]])
    ref = first[order0][:, [col["x"], col["y"], col["z"]]]
    ref_ids = first[order0][:, col["id"]]
    y0 = ref[:, 1]
    labels = np.array([label[int(i)] for i in ref_ids])
    return {
        "step": stepN,
        "labels": labels,
        "reference": ref,
        "ids": ref_ids,
        "bottom_label": labels[np.argmin(y0)],
        "top_label": labels[np.argmax(y0)],
        "npieces": len(set(labels.tolist())),
        "midpoints": broken_midpoints(ref_ids, ref, final_links),
    }


def stable_factor(run, lo, hi, tolerance):
    """Bisection for the largest stable time step factor: run(factor) is
    True where the run stays stable; lo stable, hi not; stops when
    hi - lo <= tolerance.  Returns (lo, hi)."""
    assert run(lo), f"factor {lo} is not stable"
    assert not run(hi), f"factor {hi} is stable"
    while hi - lo > tolerance:
        mid = 0.5 * (lo + hi)
        if run(mid):
            lo = mid
        else:
            hi = mid
    return lo, hi
