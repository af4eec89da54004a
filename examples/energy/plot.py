"""Energy conservation of a vibrating bar (two time steps) and objectivity
of a rigidly rotating cluster."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 4.3))
deviation = {}
for factor, label in ((1, r"$\Delta t = R/(2c_p)$"), (2, r"$\Delta t = R/(4c_p)$")):
    t, ke, erot, pe, etot = np.loadtxt(f"energy.{factor}.dat", unpack=True)
    rel = (etot - etot[0]) / etot[0]
    deviation[factor] = np.max(np.abs(rel))
    ax1.plot(1e3 * t, rel, label=f"{label}: max {deviation[factor]:.2e}")
ax1.set_xlabel("time (ms)")
ax1.set_ylabel(r"$(E(t) - E(0))/E(0)$")
ax1.set_title("free bar, first longitudinal mode: total energy")
ax1.legend(fontsize=8)

t, pe, etot = np.loadtxt("rigid.dat", unpack=True)
ax2.plot(t * 10.0, pe / etot[0], "C2", label="elastic energy / total")
ax2.plot(t * 10.0, np.abs(etot - etot[0]) / etot[0], "C3", label="|E(t) - E(0)| / E(0)")
ax2.set_yscale("log")
ax2.set_xlabel("rotation angle (rad)")
ax2.set_title("rigid translation + rotation at 10 rad/s")
ax2.legend(fontsize=8)
for ax in (ax1, ax2):
    ax.grid(alpha=0.3)
fig.tight_layout()
fig.savefig("energy.png", dpi=110)
print(f"max |E(t)-E(0)|/E(0): {deviation[1]:.3e} at dt, {deviation[2]:.3e} at dt/2, "
      f"ratio {deviation[1] / deviation[2]:.2f}")
first, second = t * 10.0 <= 1.0, t * 10.0 > 1.0
print(f"rigid rotation: max PE/E = {pe.max() / etot[0]:.3e} (first radian {pe[first].max() / etot[0]:.3e}, "
      f"second {pe[second].max() / etot[0]:.3e}); max |dE|/E = {np.max(np.abs(etot - etot[0])) / etot[0]:.3e}")
print("wrote energy.png")
