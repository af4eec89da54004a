"""The slab with compensated surfaces (fix mlp/traction): the interior
strains per unit load, extrapolated to P -> 0 from P = 0.01 and 0.02, at
three sizes, with the fix and without (the pressed columns loaded as the
uniform stress -P: ends half), against uniaxial stress with the lattice's
wave moduli and with its static ones; and with the fix, the columns loaded
by P on every particle (ends full, P = 0.01 only).  Prints the table and
draws traction.png (the strains against 1 / width)."""

import os
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# (tools/mca run copies the example elsewhere and sets MCA_ROOT)
ROOT = pathlib.Path(os.environ.get("MCA_ROOT", pathlib.Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(ROOT / "tools"))
import lattice_calibration as lc  # noqa: E402

SIZES = (12, 24, 48)
K1 = 6 * 0.2
K2 = 8.0 - K1
WAVES = lc.mlp_moduli(K1, K2)
STATIC = lc.mlp_static_moduli(K1, K2)


def loaded(path):
    for line in open(path):
        words = line.split()
        if words[:1] == ["LOADED"]:
            return dict(zip(words[2::2], map(float, words[3::2])))
    raise SystemExit(f"{path}: no LOADED line (did the run finish?)")


def per_load(case, size, name):
    """eyy or exx per unit load at P -> 0 (the Morse anharmonicity is linear in P)."""
    one = loaded(f"log.tr.{case}.{size}.p0.01")[name] / 0.01
    two = loaded(f"log.tr.{case}.{size}.p0.02")[name] / 0.02
    return 2.0 * one - two


def width(size):
    return size * 1.7320508075688772    # between the outer columns


expected = {"yes": (WAVES["nu2"] / WAVES["E2"], -1.0 / WAVES["E2"]),
            "no": (STATIC["nu2"] / STATIC["E2"], -1.0 / STATIC["E2"])}
print(f"uniaxial stress per unit load: wave moduli eyy {expected['yes'][0]:.6f}, exx "
      f"{expected['yes'][1]:.6f} (nu_2D {WAVES['nu2']:.5f}); static eyy {expected['no'][0]:.6f}, "
      f"exx {expected['no'][1]:.6f} (nu_2D {STATIC['nu2']:.5f})")
fig, ax = plt.subplots(1, 2, figsize=(10, 4.2))
for case, label in (("yes", "with fix mlp/traction"), ("no", "without")):
    eyy = [per_load(case, s, "eyy") for s in SIZES]
    exx = [per_load(case, s, "exx") for s in SIZES]
    for s, y, x in zip(SIZES, eyy, exx):
        print(f"{label}, ends half, {s} x {int(s * 5 / 3)} cells ({width(s):.1f} wide): eyy/P "
              f"{y:.6f} ({y / expected[case][0] - 1:+.4f}), exx/P {x:.6f} "
              f"({x / expected[case][1] - 1:+.4f}), nu {-y / x:.5f}")
    infinite = 2.0 * eyy[-1] - eyy[-2]
    print(f"{label}: eyy/P extrapolated to an infinite slab {infinite:.6f} "
          f"({infinite / expected[case][0] - 1:+.4f})")
    inverse = [1.0 / width(s) for s in SIZES]
    ax[0 if case == "yes" else 1].plot(inverse, eyy, "o-", label=f"{label}, ends half")
full = [loaded(f"log.tr.full.{s}.p0.01")["eyy"] / 0.01 for s in SIZES]
for s, y in zip(SIZES, full):
    print(f"with the fix, ends full (P on every pressed particle), {s}: eyy/P at P = 0.01 "
          f"{y:.6f} ({y / expected['yes'][0] - 1:+.4f})")
ax[0].plot([1.0 / width(s) for s in SIZES], full, "s--", label="with the fix, ends full (P = 0.01)")
for k, case in enumerate(("yes", "no")):
    name = "wave" if case == "yes" else "static"
    ax[k].axhline(expected[case][0], color="k", lw=0.8, ls=":", label=f"uniaxial stress, {name} moduli")
    ax[k].set_xlabel("1 / width of the slab")
    ax[k].set_ylabel("interior eyy / P")
    ax[k].set_xlim(left=0.0)
    ax[k].legend(fontsize=8)
ax[0].set_title("compensated surfaces")
ax[1].set_title("plain MLP surfaces")
fig.tight_layout()
fig.savefig("traction.png", dpi=110)
print("wrote traction.png")
