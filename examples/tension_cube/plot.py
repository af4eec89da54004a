"""Stress-strain curves of the tension cube and the shear layer with the
analytic lines sigma = E eps, tau = G gamma and lateral strain = -nu eps."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

E, NU = 70.0e9, 0.3
G = E / (2.0 * (1.0 + NU))

fig, (ax1, ax2, ax3) = plt.subplots(1, 3, figsize=(14, 4.3))

t, eps, sig, lat = np.loadtxt("cube.free.tension.dat", unpack=True)
ax1.plot(1e6 * eps, 1e-6 * sig, "C0", label="MCA, frictionless grips")
_, eps_c, sig_c, _ = np.loadtxt("cube.clamped.tension.dat", unpack=True)
ax1.plot(1e6 * eps_c, 1e-6 * sig_c, "C1", label="MCA, clamped grips (thesis set-up)")
e = np.array([0.0, max(eps.max(), eps_c.max())])
ax1.plot(1e6 * e, 1e-6 * E * e, "k--", lw=1, label=r"$\sigma = E\varepsilon$")
ax1.set_xlabel(r"axial strain $\varepsilon$ ($10^{-6}$)")
ax1.set_ylabel("axial stress (MPa)")
ax1.set_title("10a fcc cube in tension")
ax1.legend(fontsize=8)

ax2.plot(1e6 * eps, 1e6 * lat, "C0", label="MCA, frictionless grips")
ax2.plot(1e6 * e, -1e6 * NU * e, "k--", lw=1, label=r"$-\nu\varepsilon$")
ax2.set_xlabel(r"axial strain $\varepsilon$ ($10^{-6}$)")
ax2.set_ylabel(r"lateral strain ($10^{-6}$)")
ax2.set_title("lateral contraction at mid height")
ax2.legend(fontsize=8)

_, gam, tau = np.loadtxt("layer.shear.dat", unpack=True)
ax3.plot(1e6 * gam, 1e-6 * tau, "C2", label="MCA, layer 10a, periodic in x, y")
tb, gam_b, tau_b = np.loadtxt("box.shear.dat", unpack=True)
ax3.plot(1e6 * gam_b, 1e-6 * tau_b, "C3", label="MCA, periodic box (fix deform)")
_, gam_c, tau_c, _ = np.loadtxt("cube.clamped.shear.dat", unpack=True)
ax3.plot(1e6 * gam_c, 1e-6 * tau_c, "C1", label="MCA, cube, clamped grips")
g = np.array([0.0, max(gam.max(), gam_c.max(), gam_b.max())])
ax3.plot(1e6 * g, 1e-6 * G * g, "k--", lw=1, label=r"$\tau = G\gamma$")
ax3.set_xlabel(r"shear strain $\gamma$ ($10^{-6}$)")
ax3.set_ylabel("shear stress (MPa)")
ax3.set_title("simple shear")
ax3.legend(fontsize=8)

for ax in (ax1, ax2, ax3):
    ax.grid(alpha=0.3)
fig.tight_layout()
fig.savefig("tension_cube.png", dpi=110)
print("wrote tension_cube.png")



def slope(x, y, first=0.8):
    """slope over the last part of a curve (quasi-static by then)"""
    sel = slice(int(first * len(x)), None)
    return np.polyfit(x[sel], y[sel], 1)[0]


print(f"frictionless grips: E_app/E = {slope(eps, sig) / E:.5f}, "
      f"nu_app = {-slope(eps, lat):.5f} (nu = {NU})")
print(f"clamped grips:      E_app/E = {slope(eps_c, sig_c) / E:.5f}, "
      f"G_app/G = {slope(gam_c, tau_c) / G:.5f}")
print(f"shear layer 10a:    G_app/G = {slope(gam, tau) / G:.5f}")
print(f"periodic box:       G_app/G = {slope(gam_b, tau_b, 0.2) / G:.5f}")
