#!/usr/bin/python3
"""The polydisperse packing (examples/beam_packing): the stable time step
against the lattice's exact fastest mode, the stability check, the tension
test and its energy balance; draws packing.png.

    /usr/bin/python3 plot.py [directory]

It reads bonded.data, tension.end.data, log.tension and log.check* of the
directory (default: here).  The exact fastest mode: the 2-D frame elements
(E = 100, sections from the radii as the input sets them, R = 0.6 min(r_i,
r_j), A = 2R, I = (2R)^3 / 12, reference lengths of the set-up) assembled
with the discs' masses and moments of inertia, the largest eigenvalue of
M^-1 K by numpy.
"""

import math
import pathlib
import re
import sys

import numpy as np

E_BEAM, LAMBDA = 100.0, 0.6
CHECK = re.compile(r"^check: factor (\S+), ran to step (\d+) of (\d+), energy (\S+) x the first",
                   re.M)
ESTIMATE = re.compile(r"bond beam: stable time step (\S+) \(Gershgorin bound of the fastest "
                      r"mode: omega <= (\S+?)[;,]")


def read_data(path):
    """(ids, positions, radii, masses, inertias, bonds as index pairs, box)"""
    lines = pathlib.Path(path).read_text().splitlines()
    box = {}
    for line in lines[:20]:
        words = line.split()
        if len(words) == 4 and words[2].endswith("lo"):
            box[words[2][0]] = (float(words[0]), float(words[1]))

    def section(name):
        start = next((k for k, line in enumerate(lines) if line.startswith(name)), None)
        if start is None:
            return []
        rows = []
        for line in lines[start + 2:]:
            if not line.strip():
                break
            rows.append(line.split())
        return rows

    atoms = np.array([[float(w) for w in row[:11]] for row in section("Atoms")])
    atoms = atoms[np.argsort(atoms[:, 0])]
    index = {int(a): k for k, a in enumerate(atoms[:, 0])}
    bonds = [(index[int(r[2])], index[int(r[3])]) for r in section("Bonds") if int(r[1]) > 0]
    return (atoms[:, 0].astype(int), atoms[:, 8:10], 0.5 * atoms[:, 4], atoms[:, 6],
            atoms[:, 7], bonds, box)


def bond_vectors(pos, bonds, box):
    ly = box["y"][1] - box["y"][0]
    i, j = np.array(bonds).T
    d = pos[j] - pos[i]
    d[:, 1] -= ly * np.round(d[:, 1] / ly)
    return d


def stiffness(pos, radii, bonds, box):
    """The assembled 2-D frame stiffness (x, y, theta per disc)."""
    n = len(pos)
    big = np.zeros((3 * n, 3 * n))
    for (i, j), d in zip(bonds, bond_vectors(pos, bonds, box)):
        L = math.hypot(d[0], d[1])
        R = LAMBDA * min(radii[i], radii[j])
        A, I = 2 * R, (2 * R) ** 3 / 12
        a, b, c = E_BEAM * A / L, 12 * E_BEAM * I / L ** 3, 6 * E_BEAM * I / L ** 2
        p, q = 4 * E_BEAM * I / L, 2 * E_BEAM * I / L
        k = np.array([[a, 0, 0, -a, 0, 0], [0, b, c, 0, -b, c], [0, c, p, 0, -c, q],
                      [-a, 0, 0, a, 0, 0], [0, -b, -c, 0, b, -c], [0, c, q, 0, -c, p]])
        co, si = d[0] / L, d[1] / L
        t = np.kron(np.eye(2), np.array([[co, si, 0], [-si, co, 0], [0, 0, 1]]))
        idx = [3 * i, 3 * i + 1, 3 * i + 2, 3 * j, 3 * j + 1, 3 * j + 2]
        big[np.ix_(idx, idx)] += t.T @ k @ t
    return big


def fastest_mode(directory):
    """omega_max of the set-up lattice and the disc whose motion dominates it."""
    ids, pos, radii, mass, inertia, bonds, box = read_data(directory / "bonded.data")
    big = stiffness(pos, radii, bonds, box)
    s = 1 / np.sqrt(np.column_stack([mass, mass, inertia]).ravel())
    w, v = np.linalg.eigh(s[:, None] * big * s[None, :])
    share = (v[:, -1] ** 2).reshape(-1, 3).sum(axis=1)
    return math.sqrt(w[-1]), ids[np.argmax(share)], len(bonds)


def estimate(log_text):
    m = ESTIMATE.search(log_text)
    return float(m.group(1)), float(m.group(2))


def checks(directory):
    """(factor, stable) of the check runs: stable if it ran all its steps
    and its energy ended within twice the first."""
    out = []
    for path in sorted(directory.glob("log.check*")):
        for m in CHECK.finditer(path.read_text()):
            out.append((float(m.group(1)), int(m.group(2)) == int(m.group(3))
                        and float(m.group(4)) < 2.0, float(m.group(4))))
    return sorted(out)


def thermo(path):
    """The tension run's thermo rows as a dict of arrays."""
    lines = pathlib.Path(path).read_text().splitlines()
    start = max(k for k, line in enumerate(lines) if line.split()[:2] == ["Step", "Time"])
    names = lines[start].split()
    rows = []
    for line in lines[start + 1:]:
        words = line.split()
        if line.startswith("WARNING"):
            continue
        if len(words) != len(names):
            break
        try:
            rows.append([float(w) for w in words])
        except ValueError:
            break
    data = np.array(rows)
    return {name: data[:, k] for k, name in enumerate(names)}


def tension(t):
    """Modulus (both grips, fitted below half the peak), peak stress and
    its strain, the energy balance while every bond is intact (relative to
    the work done until then), the bonds left."""
    e, right, left = t["v_e"], t["v_s"], t["v_sl"]
    peak = int(np.argmax(left))
    fit = (e > 0) & (left < 0.5 * left[peak]) & (np.arange(len(e)) < peak)
    modulus_left = np.polyfit(e[fit], left[fit], 1)[0]
    modulus_right = np.polyfit(e[fit], right[fit], 1)[0]
    # work of the right grip (summed by the input at every step) + the
    # kinetic energy of the start = elastic + kinetic + dissipated energy
    work = t["v_work"]
    stored = t["E_bond"] + t["E_pair"] + t["KinEng"] + t["c_erot"] + t["f_1"]
    balance = stored - stored[0] - work
    # until the first bond breaks (a broken bond's energy leaves with it)
    intact = np.nonzero(t["Bonds"] == t["Bonds"][0])[0]
    upto = slice(1, intact[-1] + 1)
    relative = np.abs(balance[upto]).max() / work[intact[-1]]
    return modulus_left, modulus_right, left[peak], e[peak], relative, int(t["Bonds"][-1])


def main():
    directory = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
    log = (directory / "log.tension").read_text()
    dt_bound, omega_bound = estimate(log)
    omega, disc, nbonds = fastest_mode(directory)
    critical = 2 / omega
    print(f"packing: {nbonds} bonds; fastest mode omega {omega:.6g} (disc {disc}); the estimate's "
          f"bound {omega_bound:.6g} = {omega_bound / omega:.4f} x it; stable time step "
          f"{dt_bound:.6g} against the limit {critical:.6g}")
    runs = checks(directory)
    limit = critical / dt_bound
    agree = all(stable == (factor < limit) for factor, stable, _ in runs)
    for factor, stable, ratio in runs:
        print(f"  check at {factor:.2f} x the estimate ({factor / limit:.3f} x the limit): "
              f"{'stable' if stable else 'unstable'} (energy {ratio:.3g} x the first)")
    print(f"  the runs {'agree' if agree else 'DISAGREE'} with the limit at {limit:.4f} x the "
          "estimate")
    t = thermo(directory / "log.tension")
    ml, mr, peak, at, balance, left_bonds = tension(t)
    print(f"tension: E_2D {ml:.4g} (left grip), {mr:.4g} (right); peak stress {peak:.4g} at "
          f"strain {at:.4g}; energy balance until the first break within {100 * balance:.3g} % of "
          f"the work; "
          f"bonds {int(t['Bonds'][0])} -> {left_bonds}")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from matplotlib.collections import LineCollection
    except ImportError:
        return
    ids, pos, radii, mass, inertia, bonds, box = read_data(directory / "bonded.data")
    end = read_data(directory / "tension.end.data")
    kept = set(end[5])
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.8))
    d = bond_vectors(pos, bonds, box)
    segs, colors = [], []
    for (i, j), dv in zip(bonds, d):
        segs.append([pos[i], pos[i] + dv])
        colors.append("0.6" if (i, j) in kept or (j, i) in kept else "red")
    for p, r in zip(pos, radii):
        ax[0].add_patch(plt.Circle(p, r, fill=False, lw=0.3, color="0.3"))
    ax[0].add_collection(LineCollection(segs, colors=colors, linewidths=0.8))
    ax[0].set_aspect("equal")
    ax[0].autoscale()
    ax[0].set_title(f"{len(pos)} discs, radii 0.25-0.5; broken bonds red")
    ax[1].plot(t["v_e"], t["v_sl"], label="left grip")
    ax[1].plot(t["v_e"], t["v_s"], "--", label="right grip")
    ax[1].set_xlabel("strain")
    ax[1].set_ylabel("stress (force / height)")
    ax[1].legend()
    ax[1].set_title(f"tension: E_2D {ml:.3g}, peak {peak:.3g}")
    fac = [r[0] for r in runs]
    ax[2].semilogy(fac, [r[2] for r in runs], "o-")
    ax[2].axvline(limit, color="red", label="2 / omega_max (numpy)")
    ax[2].set_xlabel("time step / estimate")
    ax[2].set_ylabel("energy after 3000 steps / first")
    ax[2].legend()
    ax[2].set_title("free vibration")
    fig.tight_layout()
    fig.savefig(directory / "packing.png", dpi=110)


if __name__ == "__main__":
    main()
