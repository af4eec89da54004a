"""MLP lattice assembly: the final particles and their structure factor,
with the return force (axes at 0 and at 10 degrees) and without it; the
bond orientational order relative to the prescribed axes (order.py)."""

import cmath
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import order  # noqa: E402

RUNS = (("aligned", 0.0, r"$f_0 = 0.2$, $\theta_0 = 0$"),
        ("turned", 10.0, r"$f_0 = 0.2$, $\theta_0 = 10^\circ$"),
        ("free", 0.0, r"$f_0 = 0$"))

fig, axes = plt.subplots(2, 3, figsize=(14, 9.2))
for column, (name, theta0, label) in enumerate(RUNS):
    x, y = order.read_positions(f"{name}.final.dump")
    psi = order.orientation_order(x, y, theta0)
    axis = math.degrees(cmath.phase(psi)) / 6.0 + theta0
    print(f"{name}: {len(order.bonds(x, y))} bonds, <exp(6i(phi - theta0))> = "
          f"{psi.real:.3f} {psi.imag:+.3f}i, |psi6| {abs(psi):.3f}, "
          f"mean axis {axis:.2f} deg")
    ax = axes[0, column]
    phi = order.bonds(x, y)
    ax.scatter(x, y, s=18, c="C0")
    ax.set_aspect("equal")
    ax.set_title(f"{label}\n$\\psi_6$ = {abs(psi):.2f}, axes at {axis:.1f}$^\\circ$ "
                 f"({len(phi)} bonds)", fontsize=10)
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    q, s = order.structure_factor(x - x.mean(), y - y.mean())
    ax = axes[1, column]
    ax.imshow(np.log10(s + 1e-3), origin="lower", extent=(q[0], q[-1], q[0], q[-1]),
              vmin=-1, vmax=2, cmap="magma")
    ax.set_title(r"$\log_{10} S(\mathbf{q})$", fontsize=10)
    ax.set_xlabel(r"$q_x$")
    ax.set_ylabel(r"$q_y$")
fig.suptitle("movable lattice particles: 256 particles from a random start "
             "(Langevin, T = 0.02 cooled to 0.0002)")
fig.tight_layout()
fig.savefig("assembly.png", dpi=80)
