"""The density of the pressed slab (the paper's Eq. 22 and Fig. 4): the
Gaussian-smoothed density rho(r) = sum_k exp(-|r - r_k|^2 / ell) (ell: a
smoothing length squared, 1 here: the spacing) at every particle, its
histogram at each dumped step as a grey map over time, its mean, and the
plastic rate |d(dh)/dt| of the width ratio (Eq. 23) against the mean
density.  Reads NAME.traj.dump (in.slab -var dumpevery N) and log.NAME;
writes NAME.density.png and prints the figures.

    /usr/bin/python3 density.py p1.5        # after: lmp -in in.slab -var press 1.5
                                             #   -var name p1.5 -var dumpevery 100 -log log.p1.5
"""

import math
import sys

import numpy as np

ELL = 1.0      # smoothing length squared (spacing 1)
CUTOFF = 6.0   # exp(-36) = 2e-16 of a particle's own term


def read_frames(path):
    """[(step, positions N x 2)] of a dump of id x y, sorted by id."""
    frames = []
    lines = open(path).read().splitlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1])
            n = int(lines[i + 3])
            rows = np.array([lines[i + 9 + k].split() for k in range(n)], dtype=float)
            rows = rows[np.argsort(rows[:, 0])]
            frames.append((step, rows[:, 1:3]))
            i += 9 + n
        else:
            i += 1
    return frames


def densities(xy, ell=ELL, cutoff=CUTOFF):
    """rho at each particle: sum over all particles (itself included) within
    the cutoff of exp(-r^2 / ell)."""
    d2 = ((xy[:, None, :] - xy[None, :, :]) ** 2).sum(axis=2)
    return np.where(d2 < cutoff * cutoff, np.exp(-d2 / ell), 0.0).sum(axis=1)


def lattice_density(ell=ELL, cutoff=CUTOFF):
    """rho at a site of the infinite hexagonal lattice of spacing 1."""
    n = int(cutoff) + 2
    total = 0.0
    for j in range(-2 * n, 2 * n + 1):
        for i in range(-2 * n, 2 * n + 1):
            r2 = (i + 0.5 * j) ** 2 + (0.75 * j * j)
            if r2 < cutoff * cutoff:
                total += math.exp(-r2 / ell)
    return total


def width_ratio(frames):
    h0 = np.ptp(frames[0][1][:, 1])
    return np.array([np.ptp(xy[:, 1]) / h0 for _, xy in frames])


def analyse(name, dt=0.02, directory="."):
    frames = read_frames(f"{directory}/{name}.traj.dump")
    steps = np.array([s for s, _ in frames])
    time = steps * dt
    rho = [densities(xy) for _, xy in frames]
    mean = np.array([r.mean() for r in rho])
    spread = np.array([r.std() for r in rho])
    dh = width_ratio(frames)
    rate = np.abs(np.gradient(dh, time))
    return time, rho, mean, spread, dh, rate


def main(name="p1.5"):
    time, rho, mean, spread, dh, rate = analyse(name)
    bulk = lattice_density()
    first = rho[0]
    print(f"{name}: lattice density {bulk:.12f}; at t = 0 the interior's largest "
          f"{first.max():.12f}, the mean {first.mean():.6f}, the lowest (corners) "
          f"{first.min():.6f}")
    k_rho, k_rate, k_spread = int(np.argmax(mean)), int(np.argmax(rate)), int(np.argmax(spread))
    print(f"largest mean density {mean[k_rho]:.6f} at t = {time[k_rho]:.1f}; largest plastic "
          f"rate |d dh/dt| {rate[k_rate]:.4e} at t = {time[k_rate]:.1f}; largest spread of the "
          f"densities {spread[k_spread]:.6f} at t = {time[k_spread]:.1f}")
    print(f"final: dh {dh[-1]:.6f}, mean density {mean[-1]:.6f} (its mode "
          f"{mode(rho[-1]):.6f})")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    edges = np.linspace(min(r.min() for r in rho), max(r.max() for r in rho), 80)
    grid = np.array([np.histogram(r, bins=edges)[0] for r in rho]).T
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    left.imshow(np.log1p(grid), origin="lower", aspect="auto", cmap="Greys",
                extent=(time[0], time[-1], edges[0], edges[-1]))
    left.plot(time, mean, "r-", lw=1.5, label="mean")
    left.axhline(bulk, color="b", ls=":", label="hexagonal lattice")
    left.set_xlabel("time")
    left.set_ylabel("density rho (Eq. 22)")
    left.set_title(f"density histogram over time ({name})")
    left.legend(loc="lower right")
    right.plot(time, mean - mean[0], label="mean density - its start")
    right.plot(time, rate / rate.max() * (mean.max() - mean[0]), label="|d dh/dt| (scaled)")
    right.plot(time, dh - 1.0, label="dh - 1")
    right.set_xlabel("time")
    right.legend()
    right.set_title("density and plastic rate")
    fig.tight_layout()
    fig.savefig(f"{name}.density.png", dpi=110)


def mode(values, bins=80):
    counts, edges = np.histogram(values, bins=bins)
    k = int(np.argmax(counts))
    return 0.5 * (edges[k] + edges[k + 1])


if __name__ == "__main__":
    main(*sys.argv[1:])
