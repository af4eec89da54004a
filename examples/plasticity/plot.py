"""Plot examples/plasticity: left, shear stress against shear strain of
the periodic box (box.linear.dat, box.table.dat) with the continuum J2
solution of shear_model.py; right, the thesis cube loaded and unloaded
(cube.free.tension.dat: V3 with frictionless grips, with the uniaxial
bilinear curve; cube.clamped.shear.dat: V4, clamped grips).  Prints the
largest difference from J2, and the yield stress and slopes of the cube.

    /usr/bin/python3 plot.py     (after run.sh)
"""

import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from shear_model import Hardening, bilinear_yield, shear_response  # noqa: E402

G = 70.0e9 / 2.6
SY, H = 2.0e6, 10.0e9
CURVES = {"linear": Hardening.linear(SY, H),
          "table": Hardening.table("hardening.table", "AL_V4")}

E, NU = 70.0e9, 0.3


fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.6))
for name, law in CURVES.items():
    path = f"box.{name}.dat"
    if not os.path.exists(path):
        continue
    t, gamma, tau, epsp, elastic, wplastic = np.loadtxt(path, unpack=True)
    model, _ = shear_response(gamma, G, law)
    error = np.max(np.abs(tau - model)) / SY
    print(f"box, {name}: max |tau - J2| / sigma_y = {error:.2e}, final mean eps_p {epsp[-1]:.4e}")
    ax.plot(gamma * 1e3, tau / 1e6, "o", ms=2, label=f"MCA, {name} hardening")
    ax.plot(gamma * 1e3, model / 1e6, "-", lw=1, label=f"J2 continuum ({name})")
ax.set_xlabel("shear strain (1e-3)")
ax.set_ylabel("shear stress (MPa)")
ax.set_title("Periodic box: shear, unloading, reverse yield")
ax.legend(fontsize=8)

if os.path.exists("cube.free.tension.dat"):
    t, strain, stress = np.loadtxt("cube.free.tension.dat", unpack=True)[:3]
    dt, nload, nrev = 2.0e-5, 6000, 1000
    t1, t2 = nload * dt, (nload + nrev) * dt
    loading = (t < t1) & (t > 0.01)
    sy, e_load, e_plastic = bilinear_yield(
        strain, stress, loading & (stress > 0.2 * SY) & (stress < 0.8 * SY),
        loading & (strain > 1.5 * SY / E))
    unload = t > t2 + 0.005
    e_unload = np.polyfit(strain[unload], stress[unload], 1)[0]
    tangent = E * H / (E + H)
    print(f"cube V3: yield {sy / SY:.4f} sigma_y, elastic {e_load / E:.4f} E, post-yield "
          f"{e_plastic / tangent:.4f} E H/(E+H), unloading {e_unload / E:.4f} E")
    bx.plot(strain * 1e3, stress / 1e6, "o", ms=2, label="V3 tension, frictionless grips")
    e = np.linspace(0, strain.max(), 50)
    bx.plot(e * 1e3, np.minimum(E * e, SY + tangent * (e - SY / E)) / 1e6, "k-", lw=1,
            label="uniaxial bilinear (loading)")
if os.path.exists("cube.clamped.shear.dat"):
    t, strain, stress = np.loadtxt("cube.clamped.shear.dat", unpack=True)[:3]
    bx.plot(strain * 1e3, stress / 1e6, "o", ms=2, label="V4 shear, clamped grips")
bx.set_xlabel("strain (1e-3)")
bx.set_ylabel("stress (MPa)")
bx.set_title("Thesis cube, 4631 automata: load, unload")
bx.legend(fontsize=8)
fig.tight_layout()
fig.savefig("plasticity.png", dpi=120)
print("wrote plasticity.png")
