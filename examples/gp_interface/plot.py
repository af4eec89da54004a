#!/usr/bin/env python3
"""The runs of run.sh: the energy of the two-level model in NVE for the two
couplings (nve.*.dat), and the energy a wave packet carries into the
level-2 region and back into the atoms' region for each wavelength and
coupling (wave.*.dat): transmission T and reflection R from twice the
kinetic energy of each level's real particles, averaged over the last
0.5 ps, over the packet's energy at the start (gp_interface.png,
waves.md)."""

import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent
COUPLINGS = ("force", "energy")


def coefficients(path):
    data = np.loadtxt(path)
    t, e_atoms, k_atoms, k_level2 = data[:, 0], data[:, 1], data[:, 3], data[:, 4]
    window = t > t[-1] - 0.5
    packet = e_atoms[0]
    return 2 * k_level2[window].mean() / packet, 2 * k_atoms[window].mean() / packet


def main():
    fig, (ax_nve, ax_wave) = plt.subplots(1, 2, figsize=(12, 4.5))
    for coupling in COUPLINGS:
        path = HERE / f"nve.{coupling}.dat"
        if path.exists():
            data = np.loadtxt(path)
            ax_nve.plot(data[:, 0], data[:, 1] - data[0, 1], label=f"coupling {coupling}")
    ax_nve.set_xlabel("time (ps)")
    ax_nve.set_ylabel("pe + ke of the real particles - start (eV)")
    ax_nve.set_title("NVE from 100 K (Fe EAM, 2880 real particles)")
    ax_nve.legend()

    rows = ["| coupling | wavelength (atomic cells) | T | R | T + R |", "|---|---|---|---|---|"]
    for coupling in COUPLINGS:
        points = []
        for path in sorted(HERE.glob(f"wave.{coupling}.*.dat"),
                           key=lambda p: float(p.name.split(".")[2])):
            lam = float(path.name.split(".")[2])
            trans, refl = coefficients(path)
            points.append((lam, trans, refl))
            rows.append(f"| {coupling} | {lam:g} | {trans:.3f} | {refl:.3f} | {trans + refl:.3f} |")
        if points:
            lam, trans, refl = np.array(points).T
            ax_wave.plot(lam, trans, "o-", label=f"T, coupling {coupling}")
            ax_wave.plot(lam, refl, "s--", label=f"R, coupling {coupling}")
    ax_wave.set_xlabel("wavelength (cells of the atomic lattice)")
    ax_wave.set_ylabel("energy fraction")
    ax_wave.set_title("P-wave packet crossing the atoms / level-2 interface")
    ax_wave.legend()
    fig.tight_layout()
    fig.savefig(HERE / "gp_interface.png", dpi=110)
    (HERE / "waves.md").write_text("\n".join(rows) + "\n")
    print("\n".join(rows))


if __name__ == "__main__":
    main()
