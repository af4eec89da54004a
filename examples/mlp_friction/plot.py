"""Two MLP bars pressed together and sheared back and forth: the profile of
<|F_return|> across the contact (per column, averaged along the contact
and over the second half of the run) with and without the shear, and the
tangential displacement of one bar against the other; the figures printed."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

RUNS = (("bars", "pressed and sheared (0.2 per outer particle)"),
        ("pressed", "pressed only"))


def profile(path):
    """The last block of a fix ave/chunk file: column centre x, <|F_return|>."""
    rows, block = [], []
    for line in open(path):
        if line.startswith("#"):
            continue
        words = line.split()
        if len(words) == 3:    # a block's header: step, chunks, total count
            block = []
            rows.append(block)
        else:
            block.append((float(words[1]), float(words[3])))
    return np.array(rows[-1]).T


def thermo(path):
    """time and v_slip of the runs of a log."""
    time, slip = [], []
    fields = None
    for line in open(path):
        words = line.split()
        if words[:2] == ["Step", "Time"]:
            fields = words
            continue
        if fields and words and words[0] == "Loop":
            fields = None
            continue
        if fields and len(words) == len(fields):
            time.append(float(words[1]))
            slip.append(float(words[fields.index("v_slip")]))
    return np.array(time), np.array(slip)


fig, axes = plt.subplots(1, 2, figsize=(13, 4.6))
for name, label in RUNS:
    x, fr = profile(f"{name}.profile.txt")
    # the two columns that face each other (x = -0.87 and 0), the bars'
    # inner columns, the driven outer columns
    at_contact = (x > -1.0) & (x < 0.5)
    contact = fr[at_contact].mean()
    inner = fr[~at_contact & (np.abs(x) < 15.0)]
    print(f"{name}: <|F_return|> at the contact columns {contact:.4g}; inside the bars "
          f"from {inner.min():.3g} (next to the contact) to {inner.max():.3g}; "
          f"the contact {contact / inner.max():.1f} times the largest inside; the driven "
          f"columns {fr[np.abs(x) >= 15.0].mean():.3g}")
    axes[0].semilogy(x, fr, "o-", ms=3, label=label)
    time, slip = thermo(f"log.{name}")
    axes[1].plot(time, slip, label=label)
axes[0].set_xlabel("x (column centre; contact between -0.87 and 0)")
axes[0].set_ylabel(r"$\langle|F_{return}|\rangle$ per column")
axes[0].legend(fontsize=8)
axes[1].set_xlabel("time (lj units)")
axes[1].set_ylabel("y(right bar) - y(left bar) (centres of mass)")
axes[1].legend(fontsize=8)
fig.tight_layout()
fig.savefig("friction.png", dpi=110)
