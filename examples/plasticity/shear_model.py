"""Continuum reference of examples/plasticity: simple shear of a von Mises
material with isotropic hardening, strain controlled.

Pure shear is proportional loading, for which the radial return is the
exact solution of rate-independent J2 plasticity: the trial equivalent
stress sqrt(3)|tau| falls by 3G per unit of equivalent plastic strain onto
the flow stress sigma_y(eps_p), and eps_p = gamma_p / sqrt(3).  Given a
history of shear strains gamma (any order: loading, unloading, reverse
yield) the model gives the shear stress and eps_p after each.  Also the
yield stress of a measured curve (bilinear_yield), for plot.py and the
tests."""

import math

import numpy as np


def read_table(path, keyword):
    """The points (eps_p, sigma_y) of a section of a hardening table file."""
    lines = [ln.split("#")[0].split() for ln in open(path)]
    lines = [ln for ln in lines if ln]
    start = next(k for k, ln in enumerate(lines) if ln[0] == keyword)
    n = int(lines[start + 1][1])
    points = np.array([[float(v) for v in ln[1:3]] for ln in lines[start + 2:start + 2 + n]])
    return points[:, 0], points[:, 1]


class Hardening:
    """sigma_y(eps_p): piecewise linear through (eps, sig), slope_end beyond."""

    def __init__(self, eps, sig, slope_end):
        self.eps, self.sig, self.slope_end = list(eps), list(sig), slope_end

    @classmethod
    def linear(cls, yield_stress, modulus):
        return cls([0.0], [yield_stress], modulus)

    @classmethod
    def table(cls, path, keyword):
        eps, sig = read_table(path, keyword)
        return cls(eps, sig, 0.0)

    def slope(self, k):
        if k + 1 >= len(self.eps):
            return self.slope_end
        return (self.sig[k + 1] - self.sig[k]) / (self.eps[k + 1] - self.eps[k])

    def segment(self, ep):
        k = 0
        while k + 1 < len(self.eps) and ep >= self.eps[k + 1]:
            k += 1
        return k

    def __call__(self, ep):
        k = self.segment(ep)
        return self.sig[k] + self.slope(k) * (ep - self.eps[k])

    def increment(self, ep, seq, g3):
        """dep with seq - g3 dep = sigma_y(ep + dep), segment by segment."""
        k, e = self.segment(ep), ep
        while True:
            h = self.slope(k)
            de = (seq - g3 * (e - ep) - self(e)) / (g3 + h)
            if k + 1 >= len(self.eps) or e + de <= self.eps[k + 1]:
                return e + de - ep
            k += 1
            e = self.eps[k]


def shear_response(gammas, shear_modulus, hardening):
    """Shear stress and eps_p after each strain of the history gammas."""
    tau, ep, gamma_old = 0.0, 0.0, 0.0
    taus, eps = [], []
    for gamma in gammas:
        # sub-steps keep each return small (the result does not depend on
        # them for monotone parts; they resolve a reversal inside a step)
        nsub = 10
        for s in range(1, nsub + 1):
            trial = tau + shear_modulus * (gamma - gamma_old) / nsub
            seq = math.sqrt(3.0) * abs(trial)
            if seq > hardening(ep):
                dep = hardening.increment(ep, seq, 3.0 * shear_modulus)
                ep += dep
                trial = math.copysign(hardening(ep) / math.sqrt(3.0), trial)
            tau = trial
        gamma_old = gamma
        taus.append(tau)
        eps.append(ep)
    return np.array(taus), np.array(eps)


def bilinear_yield(strain, stress, elastic, plastic):
    """The stress where the lines fitted to the elastic and the plastic
    parts of a loading curve meet, and their slopes."""
    e1, e0 = np.polyfit(strain[elastic], stress[elastic], 1)
    p1, p0 = np.polyfit(strain[plastic], stress[plastic], 1)
    x = (p0 - e0) / (e1 - p1)
    return e1 * x + e0, e1, p1
