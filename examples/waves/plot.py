"""Dispersion of P and S waves: phase speed / continuum speed against
automata per wavelength, from the zero crossings of the standing waves."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from dispersion_model import p_wave_speed_ratio  # noqa: E402

A, E, RHO = 0.7184, 70.0e9, 2700.0
MS = (4, 6, 10, 20, 40)


def continuum_speed(label):
    nu = 0.0 if label == "p0" else 0.3
    g, k = E / (2 * (1 + nu)), E / (3 * (1 - 2 * nu))
    return np.sqrt((k + 4 * g / 3) / RHO) if label.startswith("p") else np.sqrt(g / RHO)


def speed_error(label, m):
    c0 = continuum_speed(label)
    t, amp = np.loadtxt(f"wave.{label}.{m}.dat", unpack=True)
    crossings = [t[i] - amp[i] * (t[i + 1] - t[i]) / (amp[i + 1] - amp[i])
                 for i in range(len(amp) - 1) if amp[i] * amp[i + 1] < 0]
    period = 2.0 * np.mean(np.diff(crossings))
    return (m * A / 2) / period / c0 - 1.0


errors = {label: np.array([speed_error(label, m) for m in MS]) for label in ("p", "s", "p0")}
with open("dispersion.txt", "w") as f:
    f.write("# automata_per_wavelength  cP/c_p-1(nu=0.3)  cS/c_s-1(nu=0.3)  cP/c_p-1(nu=0)"
            "  cP/c_p-1(nu=0.3, MCA dispersion relation)\n")
    for i, m in enumerate(MS):
        f.write(f"{m:4d} {errors['p'][i]:+.5e} {errors['s'][i]:+.5e} {errors['p0'][i]:+.5e}"
                f" {p_wave_speed_ratio(m, 0.3) - 1:+.5e}\n")
print(open("dispersion.txt").read(), end="")

fig, ax = plt.subplots(figsize=(7, 4.5))
ms = np.array(MS, dtype=float)
ax.loglog(ms, np.abs(errors["p"]), "o-", label=r"P wave, $\nu = 0.3$")
ax.loglog(ms, np.abs(errors["s"]), "s-", label=r"S wave, $\nu = 0.3$")
ax.loglog(ms, np.abs(errors["p0"]), "^-", label=r"P wave, $\nu = 0$")
mm = np.linspace(4, 40, 100)
x = np.pi / mm
ax.loglog(mm, 1 - np.sin(x) / x, "k:", lw=1, label=r"chain of planes $1 - \sin(x)/x$, $x = \pi/m$")
ax.loglog(mm, [1 - p_wave_speed_ratio(m, 0.3) for m in mm], "k--", lw=1,
          label=r"MCA dispersion relation, P, $\nu = 0.3$")
ax.axhline(0.01, color="grey", lw=0.8, ls="--", label="1 %")
ax.set_xlabel("automata (planes) per wavelength m")
ax.set_ylabel(r"$|c/c_0 - 1|$ (all slower than $c_0$)")
ax.set_title("dispersion of elastic waves along [100], fcc")
ax.legend(fontsize=8)
ax.grid(alpha=0.3, which="both")
fig.tight_layout()
fig.savefig("waves.png", dpi=110)
print("wrote waves.png")
