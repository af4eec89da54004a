"""Order of an assembled MLP lattice from a LAMMPS dump: the bond
orientational order relative to the prescribed axes and the structure
factor (used by plot.py and by unittest/python/test_pair_mlp.py)."""

import numpy as np


def read_positions(path):
    """x, y of the last snapshot of a LAMMPS text dump with x and y columns."""
    lines = open(path).read().splitlines()
    start = max(k for k, line in enumerate(lines) if line.startswith("ITEM: ATOMS"))
    names = lines[start].split()[2:]
    natoms = int(lines[start - 5])
    rows = np.array([line.split() for line in lines[start + 1:start + 1 + natoms]], dtype=float)
    return rows[:, names.index("x")], rows[:, names.index("y")]


def bonds(x, y, cut=1.2):
    """Bond angles (radians) of the pairs closer than cut, each pair once."""
    dx = x[None, :] - x[:, None]
    dy = y[None, :] - y[:, None]
    i, j = np.nonzero(np.triu(np.hypot(dx, dy) < cut, k=1))
    return np.arctan2(dy[i, j], dx[i, j])


def orientation_order(x, y, theta0_deg, n=6, cut=1.2):
    """<exp(i n (phi - theta0))> over the bonds: its real part is 1 when
    every bond lies on an axis theta0 + m 360/n deg, its modulus is 1 when
    all bonds share some set of axes (one orientation)."""
    phi = bonds(x, y, cut)
    return complex(np.mean(np.exp(1j * n * (phi - np.radians(theta0_deg)))))


def structure_factor(x, y, qmax=10.0, nq=161):
    """S(q) = |sum_k exp(i q.r_k)|^2 / N on a square grid of q."""
    q = np.linspace(-qmax, qmax, nq)
    qx, qy = np.meshgrid(q, q)
    phase = np.exp(1j * (qx[..., None] * x + qy[..., None] * y))
    return q, np.abs(phase.sum(axis=-1)) ** 2 / len(x)
