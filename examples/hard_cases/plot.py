"""Plot examples/hard_cases (after run.sh): the crack path of the notched
plate (reference positions of the automata coloured by the piece they end
in, midpoints of the broken links), the energies of the plate against the
grip's displacement with the balance error, and the stress, mean plastic
strain and balance error of the cube compressed by 30 %.  Prints the
figures the README quotes.

    /usr/bin/python3 plot.py
"""

import glob
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from plate_analysis import plate_result, read_thermo  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent


def thermo(pattern):
    """The thermo output of the (last) run of the newest log matching
    pattern."""
    return read_thermo(sorted(glob.glob(str(HERE / pattern)))[-1])


def balance(t):
    """|etot - work| / largest work, before and after the first break."""
    error = np.abs(t["v_etot"] - t["v_work"]) / t["v_work"].max()
    if "c_frac[1]" not in t:
        return error, error.max(), None
    loaded = t["v_work"] > 1e-6 * t["v_work"].max()
    broken = t["c_frac[1]"] > 0
    return error, error[loaded & ~broken].max(), error[broken].max()


def main():
    fig, axes = plt.subplots(1, 3, figsize=(16, 5))

    # crack path
    ax = axes[0]
    plate = plate_result(HERE)
    ref = plate["reference"]
    front = ref[:, 2] < ref[:, 2].min() + 0.1
    for label, colour in ((plate["bottom_label"], "tab:blue"), (plate["top_label"], "tab:orange")):
        mask = front & (plate["labels"] == label)
        ax.scatter(ref[mask, 0], ref[mask, 1], s=6, color=colour,
                   label=f"piece {label} ({np.sum(plate['labels'] == label)} automata)")
    mid = plate["midpoints"]
    ax.scatter(mid[:, 0], mid[:, 1], s=4, color="k", marker="x",
               label=f"broken links ({len(mid)})")
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title(f"notched plate: {plate['npieces']} pieces at step {plate['step']}")
    ax.legend(loc="upper right", fontsize=8)

    # plate energies
    ax = axes[1]
    t = thermo("log.*.notched_plate.0.5.*")
    d = t["v_disp"] * 1e3
    ax.plot(d, t["v_work"], "k-", label="work of the grip")
    ax.plot(d, t["PotEng"], label="elastic (pe)")
    ax.plot(d, t["c_keplate"] + t["c_erot"], label="kinetic")
    ax.plot(d, t["c_frac[6]"], label="released")
    ax.plot(d, t["v_etot"], "r--", label="sum")
    ax.set_xlabel("grip displacement (mm)")
    ax.set_ylabel("energy (J)")
    error, before, after = balance(t)
    fast = thermo("log.*.notched_plate.1.19.*")
    _, fast_before, fast_after = balance(fast)
    ax.set_title(f"plate energy; balance {before:.1e} / {after:.1e} before / after the breaks")
    twin = ax.twinx()
    twin.semilogy(d, np.maximum(error, 1e-12), "g:", label="|sum - work| / max work")
    twin.set_ylabel("balance error", color="g")
    ax.legend(loc="upper left", fontsize=8)
    print(f"plate (dt = 0.5 R/c_p): {int(t['c_frac[1]'][-1])} links broken, pieces "
          f"{np.bincount(plate['labels'])}, balance {before:.2e} before the first break, "
          f"{after:.2e} after; released {t['c_frac[6]'][-1] / t['v_work'][-1]:.3f} of the work")
    print(f"plate (dt = 1.19 R/c_p): {int(fast['c_frac[1]'][-1])} links broken, balance "
          f"{fast_before:.2e} before, {fast_after:.2e} after")
    fast_plate = plate_result(HERE, name="plate_fast")
    print(f"plate (dt = 1.19 R/c_p): {fast_plate['npieces']} pieces, grips apart: "
          f"{fast_plate['bottom_label'] != fast_plate['top_label']}")

    # compression
    ax = axes[2]
    c = thermo("log.*.compression.*")
    ax.plot(c["v_strain"], c["v_stress"] / 1e6, label="engineering stress (MPa)")
    ax.plot(c["v_strain"], 100 + 1000 * c["c_epmean"], "--",
            label="sigma_y + H mean eps_p (MPa)")
    ax.set_xlabel("engineering strain")
    ax.set_ylabel("stress (MPa)")
    error, worst, _ = balance(c)
    ax.set_title(f"cube compressed by 30 %: balance {worst:.1e}")
    twin = ax.twinx()
    twin.plot(c["v_strain"], c["c_epmean"], "g:", label="mean eps_p")
    twin.plot(c["v_strain"], np.log(1.0 / (1.0 - c["v_strain"])), "k:", lw=0.8,
              label="ln(L0/L)")
    twin.set_ylabel("plastic strain")
    ax.legend(loc="upper left", fontsize=8)
    twin.legend(loc="lower right", fontsize=8)
    strain = c["v_strain"][-1]
    print(f"compression: strain {strain:.4f}, stress {c['v_stress'][-1] / 1e6:.1f} MPa, mean "
          f"eps_p {c['c_epmean'][-1]:.4f} (ln(L0/L) - sigma/E "
          f"{np.log(1 / (1 - strain)) - c['v_stress'][-1] / 70e9:.4f}), max eps_p "
          f"{c['c_epmax'][-1]:.4f}, balance {worst:.2e}")

    fig.tight_layout()
    fig.savefig(HERE / "hard_cases.png", dpi=110)


if __name__ == "__main__":
    main()
