#!/usr/bin/python3
"""The size study (in.tension, make_tension.py): u_y on the Y axis above
the tip of edge-cracked Fe plates of half height H = 8, 16, 32 level-2
periods (64.6, 129.2, 258.4 A; width 387.7 A) pulled by grips to 1 %
strain, GP (tgp.n) and full MD (tmd.n where run).  u_y is half the
opening: the mean u_y of the atoms in a rectangle 8 x 2 A at (tip, r)
less that at (tip, -r), halved.  Also the two-term LEFM field of a
single-edge-notched strip under the grips' mean stress (the SENT K and
biaxiality of the GP digest sec. 4.7; load control, an infinitely long
strip: the limit a large plate approaches).  Writes size.txt, size.png.

  crack_size.py tgp.8 tmd.8 tgp.16 ...   (logs log.tension.<model>, dumps
                                    tension.<model>.dump)
"""
import math
import re
import sys

import numpy as np

import crack_fields as analysis

TIP, W = 81.0, 387.651641   # make_tension.py's defaults
R = [3, 5, 8, 10, 15, 20, 25]


def opening(d, r):
    return 0.5 * (analysis.mean_box(d, "uy", TIP, r, 8, 2) - analysis.mean_box(d, "uy", TIP, -r, 8, 2))


def sent(sigma):
    """K (MPa m^0.5) and T (GPa) of a SENT strip, a/W = TIP/W, sigma in GPa."""
    a, w = TIP * 1e-10, W * 1e-10
    x = math.pi * a / (2 * w)
    K = sigma * 1e9 * math.sqrt(math.pi * a) * math.sqrt(2 * w / (math.pi * a) * math.tan(x)) \
        / math.cos(x) * (0.752 + 2.02 * a / w + 0.37 * (1 - math.sin(x)) ** 3)
    B = -0.52 - 1.50 * a / w + 12.70 * (a / w) ** 2 - 20.70 * (a / w) ** 3
    return K * 1e-6, B * K * 1e-6 / math.sqrt(math.pi * a) * 1e-3


def main(models):
    rows, curves = [], {}
    for m in models:
        log = open(f"log.tension.{m}").read()
        sigma = float(re.search(r"^TENSION \S+ eps \S+ grip stress (\S+) GPa", log, re.M).group(1))
        loops = re.findall(r"Loop time of ([0-9.]+) on \d+ procs for (\d+) steps with (\d+) atoms", log)
        seconds, n = sum(float(l[0]) for l in loops), int(loops[-1][2])
        d = analysis.read(f"tension.{m}.dump")
        curves[m] = np.array([opening(d, r) for r in R])
        rows.append((m, sigma, seconds, n))
    out = ["# u_y (A) on the Y axis at r = " + " ".join(map(str, R)) + " A"]
    for m, sigma, seconds, n in rows:
        out.append(f"{m} " + " ".join(f"{u:.4f}" for u in curves[m]) +
                   f"  grip stress {sigma:.4f} GPa, {n} particles, {seconds:.1f} s")
    # the two-term field under the largest plate's stress (the limit)
    m_big, sigma_big = rows[-1][0], rows[-1][1]
    K, T = sent(sigma_big)
    analysis.K, analysis.T = K, T
    ref = np.array([analysis.lefm(r, math.pi / 2)[1] for r in R])
    out.append("LEFM " + " ".join(f"{u:.4f}" for u in ref) +
               f"  (SENT strip, sigma {sigma_big:.4f} GPa: K {K:.4f} MPa m^0.5, T {T:.3f} GPa)")
    for m, *_ in rows:
        if m.startswith("tmd"):
            g = "tgp." + m.split(".")[1]
            if g in curves:
                err = np.max(np.abs(curves[g][1:] / curves[m][1:] - 1))
                out.append(f"RESULT {g} against {m} (r >= 5 A): u_y {err:.4f}")
    gp = [m for m, *_ in rows if m.startswith("tgp")]
    for m in gp:
        out.append(f"RESULT {m}: u_y(10 A) {curves[m][R.index(10)]:.4f} A = "
                   f"{curves[m][R.index(10)] / curves[gp[-1]][R.index(10)]:.3f} of {gp[-1]}'s")
    open("size.txt", "w").write("\n".join(out) + "\n")
    print("\n".join(out))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    rr = np.linspace(2, 26, 80)
    plt.figure(figsize=(6, 4.2))
    plt.plot(rr, [analysis.lefm(r, math.pi / 2)[1] for r in rr], "k-", label="two-term LEFM (SENT strip)")
    for m in models:
        plt.plot(R, curves[m], ("o" if m.startswith("tmd") else "x") + "-", lw=0.8, label=m)
    plt.xlabel("r above the tip (A)")
    plt.ylabel("u_y (A)")
    plt.legend(fontsize=7)
    plt.title("Edge-cracked Fe plates, 1 % strain, H = 64.6 / 129 / 258 A")
    plt.tight_layout()
    plt.savefig("size.png", dpi=110)


if __name__ == "__main__":
    main(sys.argv[1:])
