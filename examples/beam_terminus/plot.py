#!/usr/bin/python3
"""The grounded terminus (examples/beam_terminus): the depth-integrated
stresses of the static runs against the force balance, the flotation, the
calving depth against the static tension; draws terminus.png.

    /usr/bin/python3 plot.py [directory]

Reads log.static<w> with bonds.static<w>.dump, log.float and log.calve of
the directory (default: here).  The calving depth is predicted from the static runs: the largest
tensile bond stress N/A as a function of the water depth, interpolated
linearly to the strength sigma0 of the calving run.
"""

import pathlib
import re
import sys

import numpy as np

LINE = re.compile(r"^terminus: (.*)$", re.M)
SIGMA0 = re.compile(r"^bond_coeff\s+1 100\.0 0\.3 0\.00225 break ([0-9.eE+-]+)", re.M)


def terminus(path):
    """The key-value pairs of a run's 'terminus:' line."""
    words = LINE.search(pathlib.Path(path).read_text()).group(1).split()
    return {words[k]: float(words[k + 1]) for k in range(0, len(words) - 1, 2)}


def largest_tension(path, area=0.3):
    """The largest N / A of the bonds in the last frame of a local dump of
    bond/local force (-N)."""
    lines = pathlib.Path(path).read_text().splitlines()
    k = max(i for i, line in enumerate(lines) if line.startswith("ITEM: ENTRIES"))
    force = np.array([float(line.split()[1]) for line in lines[k + 1:] if line.strip()])
    return -force.min() / area


def statics(directory):
    """The 'terminus:' values of each log.static<w>, with the largest
    tension of its bonds.static<w>.dump."""
    runs = []
    for path in directory.glob("log.static*"):
        r = terminus(path)
        r["tension"] = largest_tension(directory / f"bonds.{path.name[4:]}.dump")
        runs.append(r)
    return sorted(runs, key=lambda r: r["D/H"])


def calving(directory):
    """sigma0, the water depth at the first break, the rows (depth, bonds)."""
    text = (directory / "log.calve").read_text()
    sigma0 = float(SIGMA0.search(text).group(1))
    lines = text.splitlines()
    start = [k for k, line in enumerate(lines) if line.split()[:3] == ["Step", "Time", "v_depth"]][-1]
    names = lines[start].split()
    rows = []
    for line in lines[start + 1:]:
        words = line.split()
        if len(words) != len(names):
            break
        try:
            rows.append([float(w) for w in words])
        except ValueError:
            break
    t = {name: np.array(rows)[:, k] for k, name in enumerate(names)}
    broke = np.nonzero(t["Bonds"] < t["Bonds"][0])[0]
    first = t["v_depth"][broke[0]] if len(broke) else None
    return sigma0, first, t


def read_data(path):
    """(positions by atom index, set of bonds as sorted index pairs) of a
    data file written by the input (atom_style mca)."""
    lines = pathlib.Path(path).read_text().splitlines()

    def section(name):
        k = next(i for i, line in enumerate(lines) if line.startswith(name)) + 2
        rows = []
        while k < len(lines) and lines[k].strip():
            rows.append(lines[k].split())
            k += 1
        return rows

    atoms = sorted((int(r[0]), float(r[8]), float(r[9])) for r in section("Atoms"))
    index = {a[0]: k for k, a in enumerate(atoms)}
    pos = np.array([a[1:] for a in atoms])
    bonds = {tuple(sorted((index[int(r[2])], index[int(r[3])]))) for r in section("Bonds")}
    return pos, bonds


def predicted_depth(runs, sigma0, height):
    """Where the static tension curve crosses sigma0 (it falls with depth)."""
    depth = np.array([r["D/H"] for r in runs]) * height
    tension = np.array([r["tension"] for r in runs])
    k = np.nonzero((tension[:-1] >= sigma0) & (tension[1:] < sigma0))[0]
    if not len(k):
        return None
    k = k[0]
    return depth[k] + (depth[k + 1] - depth[k]) * (tension[k] - sigma0) / (tension[k] - tension[k + 1])


def main():
    directory = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
    runs = statics(directory)
    print("D/H     int sxx dz (balance)    int syy dz (lattice)    back stress (formula)   "
          "bed / (weight - uplift)   max tension")
    worst = 0.0
    for r in runs:
        uplift = r["weight"] - r["bed"]
        print(f"{r['D/H']:.3f}  {r['sxx']:.6f} ({-r['front']:.6f})  {r['syy']:.6f} "
              f"({r['syy_lattice']:.6f})  {r['back_stress']:.6f} ({r['back_pred']:.6f})  "
              f"{r['bed']:.6f}  {r['tension']:.5f}")
        worst = max(worst, abs(r["back_stress"] - r["back_pred"]) / abs(r["syy_lattice"]))
    print(f"back stress against rho_i g h^2 n (n - 1) / 2 - rho_w g D^2 / 2: within "
          f"{100 * worst:.2f} % of rho_i g H^2 / 2")
    if (directory / "log.float").exists():
        f = terminus(directory / "log.float")
        print(f"flotation (D = H): bed {f['bed']:.3g}, mean draft {f['draft']:.8g} against "
              f"rho_i H / rho_w = {f['draft_float']:.8g} ({f['draft'] / f['draft_float'] - 1:.1e})")
    height = 12 * np.sqrt(3.0) / 2.0
    sigma0, first, t = calving(directory)
    pred = predicted_depth(runs, sigma0, height)
    if first is not None and pred is not None:
        print(f"calving: sigma0 {sigma0}; the first bond breaks at the water depth {first:.4f} "
              f"(D/H {first / height:.4f}); the static tension reaches sigma0 at {pred:.4f} "
              f"({first / pred - 1:+.1%}); bonds {int(t['Bonds'][0])} -> {int(t['Bonds'][-1])}")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    dh = np.array([r["D/H"] for r in runs])
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.6))
    fine = np.linspace(0, dh.max(), 100)
    n, h, g, ri, rw = 12, np.sqrt(3.0) / 2.0, 0.004, 0.9, 1.0
    ax[0].plot(fine, ri * g * h * h * n * (n - 1) / 2 - rw * g * (fine * n * h) ** 2 / 2,
               label="rho_i g h^2 n(n-1)/2 - rho_w g D^2/2")
    ax[0].plot(fine, ri * g * (n * h) ** 2 / 2 - rw * g * (fine * n * h) ** 2 / 2, ":",
               label="continuum rho_i g H^2/2 - rho_w g D^2/2")
    ax[0].plot(dh, [r["back_stress"] for r in runs], "o", label="lattice (slab of 10 columns)")
    ax[0].set_xlabel("water depth D / H")
    ax[0].set_ylabel("int (sigma_xx - sigma_yy) dz")
    ax[0].legend(fontsize=8)
    ax[0].set_title("back stress")
    ax[1].plot(dh, [r["tension"] for r in runs], "o-", label="static: largest N / A")
    ax[1].axhline(sigma0, color="red", ls="--", label=f"sigma0 = {sigma0}")
    if first is not None:
        ax[1].axvline(first / height, color="black", label="first break (draw-down)")
    ax[1].set_xlabel("water depth D / H")
    ax[1].set_ylabel("tensile stress")
    ax[1].legend(fontsize=8)
    ax[1].set_title("calving as the water falls")
    if (directory / "calve.end.data").exists():
        start = read_data(directory / "calve.start.data")
        end = read_data(directory / "calve.end.data")
        pos = end[0]
        ax[2].plot(pos[:, 0], pos[:, 1], ".", ms=2, color="0.6")
        for a, b in sorted(start[1] - end[1]):
            p, q = start[0][a], start[0][b]
            ax[2].plot([p[0], q[0]], [p[1], q[1]], "r-", lw=1.5)
        ax[2].set_aspect("equal")
        ax[2].set_title(f"after the draw-down: {len(start[1] - end[1])} broken bonds (red)")
    fig.tight_layout()
    fig.savefig(directory / "terminus.png", dpi=110)


if __name__ == "__main__":
    main()
