"""Plot the indentation scenes of run.sh into indentation.png and print the
figures of README.md."""

import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import indent_analysis as ia  # noqa: E402

D_UM = ia.D * 1e6
fig, ax = plt.subplots(2, 2, figsize=(11, 8.5))

# (a) Hertz: lens of radius 500 d, elastic sample, ring at 10 d
R = 500 * ia.D
t = ia.read_dat("indent.elastic.dat")
rows = ia.hertz_errors(t, R, "elastic", 10 * ia.D, 1.0 * ia.D, 9.0 * ia.D)
fit = rows[rows[:, 0] >= 3.0]
err = fit[:, 2] / fit[:, 3] - 1.0
print(f"Hertz (R_ind = 500 d): load / Hertz's - 1 for a = {fit[0, 0]:.2f}..{fit[-1, 0]:.2f} d: "
      f"{err.min():+.4f}..{err.max():+.4f}")
a = ax[0, 0]
a.plot(rows[:, 1] * 1e6, rows[:, 2], "o", ms=3, label="MCA (elastic sample)")
depth = np.linspace(rows[0, 1], rows[-1, 1], 200)
a.plot(depth * 1e6, [ia.hertz_load(x, R, "elastic", 10 * ia.D) for x in depth], "k-",
       label="Hertz, rigid sphere")
onset = ia.read_dat("indent.onset.dat")
P, factor, a_yield = ia.yield_onset(onset, R, "AR")
exact = ia.first_yield_factor(0.33)[0]
print(f"first yield (AR): P = {P:.3f} N, a = {a_yield:.2f} d, p0 / sigma_y = {factor:.4f} "
      f"against {exact:.4f} ({factor / exact - 1:+.4f})")
a.axhline(P, color="r", ls=":", label=f"AR: first yield, p0 = {factor:.2f} $\\sigma_y$")
a.set_xlabel("approach of the lens to the ring at 10 d (um)")
a.set_ylabel("load P (N)")
a.set_title("elastic contact (lens radius 500 d)")
a.legend(fontsize=8)
inset = a.inset_axes([0.58, 0.12, 0.38, 0.3])
inset.plot(rows[:, 0], 100 * (rows[:, 2] / rows[:, 3] - 1.0), "o", ms=2)
inset.axhspan(-5, 5, color="0.9")
inset.set_xlabel("a / d", fontsize=7)
inset.set_ylabel("error %", fontsize=7)
inset.tick_params(labelsize=7)

# (b) I1-I3: load against travel, lens of radius 25 d
R = 25 * ia.D
b, c = ax[0, 1], ax[1, 0]
for mat, colour in (("AR", "C0"), ("T274", "C1"), ("T413", "C2")):
    t = ia.read_dat(f"indent.{mat}.dat")
    b.plot((t["travel"] - ia.GAP) * 1e6, t["load"], color=colour, label=mat)
    S, Pmax = ia.unloading_stiffness(t)
    pm, a_c = ia.mean_pressure(t, mat)
    E, nu, sy, H = ia.MATERIALS[mat]
    Estar = ia.contact_modulus(mat)
    print(f"{mat}: P_max = {Pmax:.2f} N, a = {a_c:.2f} d, p_m / sigma_y = {pm:.3f}, "
          f"x = E* a / (sigma_y R) = {Estar * a_c * ia.D / (sy * R):.1f}, unloading stiffness "
          f"{S:.4e} N/m = {S / (2 * Estar * a_c * ia.D):.3f} x 2 E* a; energy balance "
          f"{ia.energy_balance(t):.1e}")
    # (c) mean pressure against Johnson's index over the loading
    x, p = ia.plastic_index_curve(t, mat, R)
    full = x >= 50.0
    flow = ia.tabor_flow_stress(mat, a_c * ia.D, R)
    print(f"    fully plastic (x >= 50, {full.sum()} rows): p_m / sigma_y = {p[full].mean():.3f} "
          f"({p[full].mean() / 2.8 - 1:+.4f} against 2.8); Tabor's flow stress at 0.2 a/R = "
          f"{flow:.3f} sigma_y, p_m / it = {p[full].mean() / flow:.3f}")
    c.plot(x, p, ".", ms=3, color=colour, label=f"MCA {mat}")
b.set_xlabel("travel of the lens after touching (um)")
b.set_ylabel("load P (N)")
b.set_title("I1-I3: Al-6061 AR, aged 274 C, 413 C (lens radius 25 d)")
b.legend(fontsize=8)
xs = np.logspace(0, math.log10(600), 200)
c.plot(xs, 4 * xs / (3 * math.pi), "k:", label="Hertz, 4x/3pi")
c.plot(xs[xs > 3], ia.cavity_model(xs[xs > 3]), "k--",
       label="expanding cavity, 2/3 (1 + ln x/3)")
c.axhspan(2.8 * 0.85, 2.8 * 1.15, color="0.9", label="Tabor 2.8 +- 15 %")
c.axhline(exact * 2 / 3, color="r", ls=":", lw=1, label="first yield (p_m = 2 p0 / 3)")
c.set_xscale("log")
c.set_ylim(0, 4)
c.set_xlabel("x = E* a / (sigma_y R_ind)")
c.set_ylabel("mean contact pressure / sigma_y")
c.set_title("mean pressure (area: the contacts that push, d^2/4 each)")
c.legend(fontsize=7, loc="upper left")

# (d) scratch
d = ax[1, 1]
for mu in ("0.0", "0.3"):
    t = ia.read_dat(f"indent.scratch.{mu}.dat")
    slide = t["x_lens"] / ia.D
    moving = slide > 1e-3
    d.plot(slide[moving], t["lateral"][moving] / t["load"][moving], label=f"mu = {mu}")
    mean, spread = ia.scratch_friction(t)
    friction, ploughing = ia.scratch_parts(t)
    balance = ia.energy_balance(t)
    print(f"scratch mu = {mu}: F_x / F_N = {mean:.3f} over the last lattice period (+- "
          f"{spread:.3f} within it) = friction {friction:.3f} + ploughing {ploughing:.3f}; "
          f"energy balance {balance:.1e} of the lens's work")
d.set_xlabel("slide along x / d")
d.set_ylabel("F_x / F_N")
d.set_title("scratch at 0.25 d (lens radius 25 d)")
d.legend(fontsize=8)
fig.tight_layout()
fig.savefig("indentation.png", dpi=110)
print("wrote indentation.png")
