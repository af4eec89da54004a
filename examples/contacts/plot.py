#!/usr/bin/python3
"""Plots of the contacts example: the friction force over the normal force
of the sliding block against its slide (mu = 0.3 and 0), with the Coulomb
value corrected for the tilt of the contact normals (slide over the
diameter 2R), and the energies of the oblique impact."""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

R = 1.0e-3
fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
for mu, colour in ((0.3, "C0"), (0.0, "C1")):
    t, slide, fx, fz, ratio, friction = np.loadtxt(f"sliding.{mu}.dat", unpack=True)
    left.plot(slide * 1e6, ratio, colour, label=f"MCA, mu = {mu}")
    s = np.linspace(0, slide.max(), 50)
    left.plot(s * 1e6, mu - s / (2 * R) * (1 + mu * mu), colour + "--", lw=0.8,
              label=f"mu - (slide / 2R)(1 + mu^2)")
left.set_xlabel("slide of the block (um)")
left.set_ylabel("F_x / N on the plane")
left.set_title("block dragged on a plane")
left.legend(fontsize=8)

d = np.loadtxt("impact.0.3.dat")
t = d[:, 0] * 1e6
for k, name in ((1, "kinetic"), (2, "spin"), (3, "elastic"), (4, "friction"), (6, "total")):
    right.plot(t, d[:, k] / d[0, 6], label=name)
right.set_xlabel("time (us)")
right.set_ylabel("energy / initial")
right.set_title("oblique impact, mu = 0.3")
right.legend(fontsize=8)
fig.tight_layout()
fig.savefig("contacts.png", dpi=110)
