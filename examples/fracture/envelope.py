"""Failure load of the periodic box of in.box under the elliptic criterion.

The box stress along the load angle theta is s (cos theta e_z e_z +
sin theta (e_x e_z + e_z e_x)) and every link sees it.  A link of
direction n carries the normal traction sigma_n = n.S.n and the shear
traction |S n - sigma_n n|; it breaks when

    sqrt((max(sigma_n, 0)/sigma0)^2 + (tau_n/tau0)^2) >= 1,

an index proportional to s, so the box fails at s = 1 / max_n index(unit
load) over the six link directions of the fcc lattice.  Also the load at
which the uniform box fails under the Drucker-Prager criterion (the
equation of doc/src/pair_mca.rst).
"""

import math

import numpy as np

FCC_DIRECTIONS = [np.array(v, float) / math.sqrt(2) for v in
                  ((1, 1, 0), (1, -1, 0), (1, 0, 1), (1, 0, -1), (0, 1, 1), (0, 1, -1))]


def box_stress(angle_deg, magnitude=1.0):
    """The box stress tensor along the load angle."""
    c, s = math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg))
    stress = np.zeros((3, 3))
    stress[2, 2] = magnitude * c
    stress[0, 2] = stress[2, 0] = magnitude * s
    return stress


def link_tractions(stress, n):
    """Normal traction and shear traction magnitude on a face of normal n."""
    trac = stress @ n
    sigma = float(n @ trac)
    return sigma, float(np.linalg.norm(trac - sigma * n))


def elliptic_index(stress, sigma0, tau0):
    """Largest elliptic failure index over the fcc link directions."""
    best = 0.0
    for n in FCC_DIRECTIONS:
        sigma, tau = link_tractions(stress, n)
        best = max(best, math.hypot(max(sigma, 0.0) / sigma0, tau / tau0))
    return best


def elliptic_failure_load(angle_deg, sigma0, tau0):
    """The load magnitude s at which the first links break."""
    return 1.0 / elliptic_index(box_stress(angle_deg), sigma0, tau0)


def drucker_prager_index(stress, sigma_t, sigma_c):
    """The Drucker-Prager failure index of a stress tensor."""
    a = sigma_c / sigma_t
    mean = np.trace(stress) / 3.0
    dev = stress - mean * np.eye(3)
    seq = math.sqrt(1.5 * float(np.sum(dev * dev)))
    return (0.5 * (a + 1.0) * seq + 1.5 * (a - 1.0) * mean) / sigma_c


def envelope(sigma0, tau0, npoints=181):
    """Points (sigma_zz, tau_xz) of the box's failure envelope, theta from
    -90 to 180 degrees."""
    angles = np.linspace(-90.0, 180.0, npoints)
    loads = np.array([elliptic_failure_load(a, sigma0, tau0) for a in angles])
    return loads * np.cos(np.radians(angles)), loads * np.sin(np.radians(angles))


if __name__ == "__main__":
    for angle in (0, 30, 45, 60, 90):
        print(angle, elliptic_failure_load(angle, 2.0e6, 1.5e6))
