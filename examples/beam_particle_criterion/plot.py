"""Uniaxial strain of a periodic hexagonal beam lattice to failure: the
stresses against the lattice's elastic constants, and the strain of the
first break against the criteria's analytic strains (bond: sigma0 / E;
particle: the ellipse of the particles' mean stress and sqrt(J2), each the
continuum stress over the discs' area fraction); the figures printed."""

import math
import os
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# (tools/mca run copies the example elsewhere and sets MCA_ROOT)
ROOT = pathlib.Path(os.environ.get("MCA_ROOT", pathlib.Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(ROOT / "tools"))
import lattice_calibration as lc  # noqa: E402

E, H, SIGMA0, TAU0 = 100.0, 0.3, 0.2, 0.2
PHI = math.pi / (2.0 * math.sqrt(3.0))    # area fraction of touching discs


def read(path):
    """Thermo rows of all runs of a log, and the first break's step and strain."""
    names, rows, first = None, [], None
    for line in open(path):
        words = line.split()
        if words[:1] == ["Step"]:
            names = words
        elif words[:2] == ["first", "break:"]:
            first = int(words[3]), float(words[5])
        elif names and len(words) == len(names):
            try:
                rows.append([float(w) for w in words])
            except ValueError:
                pass
    return dict(zip(names, np.array(rows).T)), first


kn, ks = lc.beam_stiffness(E, H, H ** 3 / 12.0, 1.0)
moduli = lc.beam_moduli(kn, ks)
nu = moduli["nu2"]
c11 = moduli["E2"] / (1.0 - nu * nu)
c12 = nu * c11
# uniaxial strain: sigma_xx = c11 eps, sigma_yy = c12 eps; a particle's
# stress is that over PHI: mean (c11 + c12) eps / (2 PHI), sqrt(J2)
# (c11 - c12) eps / (2 PHI)
analytic = {
    "bond": SIGMA0 / E,
    "particle": 1.0 / math.hypot((c11 + c12) / (2 * PHI * SIGMA0),
                                 (c11 - c12) / (2 * PHI * TAU0)),
}
print(f"lattice h/L = {H}: C11 {c11:.6f}, C12 {c12:.6f} (E_2D {moduli['E2']:.6f}, "
      f"nu_2D {nu:.6f})")

fig, ax = plt.subplots(figsize=(7.5, 4.8))
for criterion, colour in (("bond", "C0"), ("particle", "C3")):
    t, (step, strain) = read(f"log.{criterion}")
    delta = strain / step    # strain per step
    # the forces of step k see the box of step k - 1; the particle
    # criterion decides at the step before the break
    seen = strain - (2 if criterion == "particle" else 1) * delta
    intact = t["Bonds"] == t["Bonds"][0]
    # (the stresses of a step are those of the box of the step before)
    eps = t["v_strain"][intact][-1] - delta
    print(f"{criterion}: before the first break (strain {eps:.6f}) sigma_xx / eps = "
          f"{t['v_sxx'][intact][-1] / eps:.6f} (C11 {c11:.6f}), sigma_yy / eps = "
          f"{t['v_syy'][intact][-1] / eps:.6f} (C12 {c12:.6f})")
    print(f"{criterion}: first break at step {step}, its forces at strain {seen:.7f}; "
          f"analytic {analytic[criterion]:.7f} (ratio {seen / analytic[criterion]:.5f})")
    ax.plot(t["v_strain"], t["v_sxx"], "-", color=colour, label=f"{criterion}: sigma_xx")
    ax.plot(t["v_strain"], t["v_syy"], "--", color=colour, label=f"{criterion}: sigma_yy")
    ax.axvline(analytic[criterion], color=colour, lw=0.8, ls=":")
grid = np.linspace(0.0, 0.0065, 50)
ax.plot(grid, c11 * grid, "k-", lw=0.6, label="C11 eps (elastic lattice)")
ax.plot(grid, c12 * grid, "k--", lw=0.6, label="C12 eps")
ax.set_xlabel("strain eps_xx (eps_yy = 0)")
ax.set_ylabel("stress (force per length)")
ax.set_title("hexagonal beam lattice, h/L = 0.3, sigma0 = tau0 = 0.2\n"
             "dotted: analytic first-break strains")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig("uniaxial.png", dpi=110)
