"""A spinning MLP disc: its angle and angular momentum against time with
axes that turn with it (fix mlp/frame every step and every 20 steps) and
with fixed axes; the run's figures printed."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

RUNS = (("frame", "axes turn with the disc (measured every step)"),
        ("frame20", "axes turn with the disc (every 20 steps)"),
        ("fixed", "fixed axes"))
OMEGA = 0.02


def thermo(path):
    """The thermo table of a log: its columns by name."""
    lines = open(path).read().splitlines()
    start = next(k for k, line in enumerate(lines) if line.split()[:2] == ["Step", "Time"])
    names = lines[start].split()
    rows = []
    for line in lines[start + 1:]:
        if line.startswith("Loop time"):
            break
        rows.append([float(v) for v in line.split()])
    return dict(zip(names, np.array(rows).T))


fig, axes = plt.subplots(1, 3, figsize=(15, 4.4))
for name, label in RUNS:
    t = thermo(f"log.{name}")
    time, angle, lz, etotal = t["Time"], t["f_fr[1]"], t["c_lz"], t["TotEng"]
    print(f"{name}: angle {angle[-1]:.3f} deg after {time[-1]:.2f} time units "
          f"(rigid spin: {np.degrees(OMEGA * time[-1]):.3f}), largest {angle.max():.3f}; "
          f"L/L0 from {lz.min() / lz[0]:.6f} to {lz.max() / lz[0]:.6f}; "
          f"etotal drift {np.abs(etotal - etotal[0]).max() / abs(etotal[0]):.1e} of its start")
    axes[0].plot(time, angle, label=label)
    axes[1].plot(time, lz / lz[0], label=label)
    axes[2].plot(time, etotal - etotal[0], label=label)
axes[0].plot(time, np.degrees(OMEGA * time), "k:", lw=1, label=r"rigid spin $\omega_0 t$")
axes[0].set_ylabel("angle of the disc (degrees, fix mlp/frame)")
axes[1].set_ylabel(r"angular momentum $L_z / L_z(0)$")
axes[2].set_ylabel(r"$E_{total} - E_{total}(0)$")
for ax in axes:
    ax.set_xlabel("time (lj units)")
axes[0].legend(fontsize=8)
fig.tight_layout()
fig.savefig("spin.png", dpi=110)
