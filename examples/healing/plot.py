#!/usr/bin/python3
"""Plot of the healing example (after run.sh): the force on the plane
against the lift of the block's top for a healing pressure below the press
(the contacts weld and carry the pull until the welds break) and above it
(nothing welds: the plane never feels a pull); the links healed and broken.
Prints the figures the README quotes."""
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent
AREA = 4.0e-6        # m^2, reference area of a link of the sc packing (2R)^2
SIGMA0 = 40.0e6      # Pa, tensile strength of the welds (elliptic criterion)
WELDS = 16           # contacts under the 4 x 4 block
PRESS = 1500 * 5e-8  # s, the press (the first run of in.weld)

fig, (force_ax, count_ax) = plt.subplots(1, 2, figsize=(11, 4.2))
for heal, colour in (("3.5e6", "C0"), ("28e6", "C3")):
    t, lift, force, pushing, healed, broken = np.loadtxt(HERE / f"weld.{heal}.dat", unpack=True)
    pull = t > PRESS
    force_ax.plot((lift[pull] - lift[pull][0]) * 1e6, force[pull], colour,
                  label=f"heal at {float(heal) / 1e6:g} MPa")
    count_ax.plot(t * 1e6, healed, colour, label=f"healed, {float(heal) / 1e6:g} MPa")
    count_ax.plot(t * 1e6, broken, colour, ls="--", label=f"broken, {float(heal) / 1e6:g} MPa")
    press = force[~pull][-1]
    peak = force[pull].max()
    first = t[np.argmax(healed > 0)] * 1e6 if healed.max() > 0 else float("nan")
    print(f"heal at {float(heal) / 1e6:g} MPa: press {-press:.2f} N on the plane "
          f"({WELDS} x 28 = {WELDS * 28} N applied); {healed[-1]:.0f} links healed, "
          f"{broken[-1]:.0f} broken (first heal at {first:.1f} us); largest pull on the plane {peak:.2f} N "
          f"(welds' strength {WELDS} A0 sigma0 = {WELDS * AREA * SIGMA0:.0f} N); force at the "
          f"end {force[-1]:.3g} N; contacts pushing at the end {pushing[-1]:.0f}")
force_ax.axhline(WELDS * AREA * SIGMA0, color="k", ls=":", lw=0.8, label="16 A0 sigma0")
force_ax.set_xlabel("lift of the block's top since the press (um)")
force_ax.set_ylabel("force on the plane, up (N)")
force_ax.set_title("block pressed at 7 MPa, then pulled off")
force_ax.legend(fontsize=8)
count_ax.set_xlabel("time (us)")
count_ax.set_ylabel("links")
count_ax.set_title("plane-block links healed and broken")
count_ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(HERE / "healing.png", dpi=100)
