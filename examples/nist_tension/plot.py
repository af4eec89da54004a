"""Plot examples/nist_tension: engineering stress against engineering
strain of the NIST Al-6061 samples (nist.<sample>.<hardening>.n<n>.dat)
with the input curves, and a table of E, sigma_y and the stress at 5 %
strain against the inputs.

    /usr/bin/python3 plot.py     (after run.sh)
"""

import glob

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from analysis import SAMPLES, figures, input_curve  # noqa: E402

fig, ax = plt.subplots(figsize=(7, 5))
print("| sample | hardening | n | E_app/E | sigma_y/input | stress at 5 % (MPa) | input (MPa) |")
print("|---|---|---|---|---|---|---|")
for path in sorted(glob.glob("nist.*.dat")):
    _, sample, hardening, n, _ = path.split(".")
    t, strain, stress, epsp = np.loadtxt(path, unpack=True)
    f = figures(sample, strain, stress)
    e, sy, _, _ = SAMPLES[sample]
    ref5 = input_curve(sample, np.array([0.05]), hardening)[0]
    print(f"| {sample} | {hardening} | {n[1:]} | {f['E'] / e:.4f} | {f['sigma_y'] / sy:.4f} | "
          f"{f['stress_5'] / 1e6:.1f} | {ref5 / 1e6:.1f} |")
    line, = ax.plot(strain * 100, stress / 1e6, "-", lw=1.5, label=f"MCA {sample} {hardening} "
                    f"({n})")
    x = np.linspace(0, strain.max(), 200)
    ax.plot(x * 100, input_curve(sample, x, hardening) / 1e6, "--", lw=1, color=line.get_color())
ax.set_xlabel("engineering strain (%)")
ax.set_ylabel("engineering stress (MPa)")
ax.set_title("NIST Al-6061 tension (dashed: input curves)")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig("nist_tension.png", dpi=120)
print("wrote nist_tension.png")
