"""Growth factor per step of one-dimensional damped oscillators: fix
nve/damped (NUMFRAC's centred damping) and fix viscous + fix nve (lagged
damping), measured from the runs' positions and from the roots of the
schemes' characteristic polynomials:
    centred  (1 + a) z^2 - (2 - h^2) z + (1 - a) = 0
    lagged   z^2 - (2 - 2a - h^2) z + (1 - 2a) = 0
with h = omega dt, a = xi h.  Writes damping.png and stability.md."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

XIS = ("0", "0.5", "1", "3")
H = 0.1 * np.arange(1, 23)


def spectral_radius(h, xi, scheme):
    a = xi * h
    if scheme == "centred":
        coeffs = [1.0 + a, -(2.0 - h * h), 1.0 - a]
    else:
        coeffs = [1.0, -(2.0 - 2.0 * a - h * h), 1.0 - 2.0 * a]
    return float(np.abs(np.roots(coeffs)).max())


def measured(scheme, xi, directory="."):
    """Growth factor per step: the envelope |x| over the last 40 steps
    against the first 40, per step between them."""
    rows = []
    with open(f"{directory}/osc.{scheme}.{xi}.dump") as handle:
        lines = handle.read().splitlines()
    k = 0
    while k < len(lines):
        if lines[k].startswith("ITEM: ATOMS"):
            n = int(lines[k - 5])
            rows.append([float(line.split()[1]) for line in lines[k + 1:k + 1 + n]])
            k += n
        k += 1
    x = np.abs(np.array(rows))
    steps = len(x) - 1
    first, last = x[:40].max(axis=0), x[-40:].max(axis=0)
    with np.errstate(divide="ignore", invalid="ignore"):
        rho = (last / first) ** (1.0 / (steps - 39))
    return rho


def critical(h, rho):
    """First omega dt at which the measured growth factor exceeds 1."""
    above = np.nonzero(rho > 1.0 + 1e-9)[0]
    return h[above[0]] if len(above) else float("nan")


def main():
    fig, axes = plt.subplots(1, 4, figsize=(16, 4.2), sharey=True)
    table = ["| xi | centred: first unstable omega dt | lagged: first unstable omega dt | "
             "lagged limit 2(sqrt(1+xi^2) - xi) | largest error of the measured growth factor |",
             "|---|---|---|---|---|"]
    hh = np.linspace(0.05, 2.2, 400)
    for ax, xi in zip(axes, XIS):
        worst = 0.0
        crit = {}
        for scheme, colour in (("centred", "C0"), ("lagged", "C3")):
            theory = [spectral_radius(h, float(xi), scheme) for h in hh]
            ax.plot(hh, theory, colour, lw=1.2, label=f"{scheme}: roots")
            rho = measured(scheme, xi)
            ax.plot(H, rho, colour + "o", ms=4, mfc="none", label=f"{scheme}: LAMMPS")
            exact = np.array([spectral_radius(h, float(xi), scheme) for h in H])
            # (a growth factor is measured where the motion neither stops nor overflows)
            ok = np.isfinite(rho) & (exact > 0.2)
            worst = max(worst, float(np.abs(rho[ok] - exact[ok]).max()))
            crit[scheme] = critical(H, rho)
        limit = 2.0 * (np.sqrt(1.0 + float(xi) ** 2) - float(xi))
        table.append(f"| {xi} | {crit['centred']:.1f} | {crit['lagged']:.1f} | {limit:.3f} | "
                     f"{worst:.1e} |")
        ax.axhline(1.0, color="k", lw=0.6)
        ax.axvline(2.0, color="C0", lw=0.6, ls=":")
        ax.axvline(limit, color="C3", lw=0.6, ls=":")
        ax.set_ylim(0.0, 1.6)
        ax.set_xlabel(r"$\omega\,\Delta t$")
        ax.set_title(rf"$\xi$ = {xi}")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("growth factor per step |z|")
    axes[0].legend(fontsize=7)
    fig.suptitle("damped oscillators: fix nve/damped (centred damping) and fix viscous + nve "
                 "(lagged damping)")
    fig.tight_layout()
    fig.savefig("damping.png", dpi=80)
    text = "\n".join(table) + "\n"
    print(text)
    open("stability.md", "w").write(text)


if __name__ == "__main__":
    main()
