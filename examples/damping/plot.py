"""Energies of the vibrating block with viscous link damping: where the
energy goes, and how well kinetic + elastic + dissipated is conserved."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 4.3))
CASES = ((r"no damping", "0_0"), (r"links $\eta$ = 2e5 Pa s", "2e5_0"),
         (r"links $\eta$ = 1e6 Pa s", "1e6_0"), (r"global $\gamma$ = 50/s", "0_50"))
for k, (label, tag) in enumerate(CASES):
    t, ke, erot, pe, dissipated, etot = np.loadtxt(f"damping.{tag}.dat", unpack=True)
    e0 = etot[0]
    style = dict(color=f"C{k}")
    ax1.plot(1e3 * t, (ke + erot) / e0, "-", label=f"{label}: kinetic", **style)
    ax1.plot(1e3 * t, pe / e0, "--", label="elastic", **style)
    if tag != "0_0":
        ax1.plot(1e3 * t, dissipated / e0, ":", label="dissipated", **style)
    error = (etot - e0) / e0
    ax2.plot(1e3 * t, error, label=f"{label}: max {np.abs(error).max():.2e}", **style)
    print(f"{tag}: dissipated {dissipated[-1] / e0:.3f} of E0, kinetic left "
          f"{(ke[-1] + erot[-1]) / e0:.3f}, elastic {pe[-1] / e0:.3f}, "
          f"max |E - E0|/E0 {np.abs(error).max():.3e}")
ax1.set_xlabel("time (ms)")
ax1.set_ylabel("energy / initial energy")
ax1.set_title("free fcc block, 864 automata, shear velocity field")
ax1.legend(fontsize=6, ncol=2)
ax2.set_xlabel("time (ms)")
ax2.set_ylabel(r"$(E(t) - E(0))/E(0)$, E = kinetic + elastic + dissipated")
ax2.set_title(r"energy balance ($\Delta t$ = 0.47 $R/c_p$)")
ax2.legend(fontsize=8)
for ax in (ax1, ax2):
    ax.grid(alpha=0.3)
fig.tight_layout()
fig.savefig("damping.png", dpi=110)
print("wrote damping.png")
