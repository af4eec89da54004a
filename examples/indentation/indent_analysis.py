"""Spherical indentation against its continuum references: Hertz's elastic
contact, the first yield under it, Tabor's fully plastic mean pressure and
Sneddon's unloading stiffness (shared by plot.py and
unittest/python/test_indentation.py)."""

import math

import numpy as np
from scipy.optimize import brentq, minimize_scalar

R_AUTOMATON = 12.7e-6
D = 2.0 * R_AUTOMATON             # automaton diameter, the unit of the scene's lengths
GAP = 0.005 * D                   # in.indent: the lens starts this far above the sample

# the thesis's tables (E, nu, sigma_y, hardening) of Al-6061 as received and aged
MATERIALS = {"AR": (69e9, 0.33, 315e6, 225e6), "T274": (40e9, 0.33, 189e6, 816.95e6),
             "T413": (66.95e9, 0.33, 55e6, 1076.18e6), "elastic": (69e9, 0.33, None, None)}


def read_dat(path):
    """Columns of indent.<label>.dat by name."""
    data = np.loadtxt(path, comments="#", ndmin=2)
    names = ["step", "travel", "load", "w_ring", "touching", "epsp_max", "base", "lateral",
             "x_lens", "cells", "ke", "pe", "plastic_work", "friction", "contact_work"]
    return {name: data[:, k] for k, name in enumerate(names)}


def contact_modulus(material):
    """E* of a rigid indenter on the sample: the lens is driven by fix move,
    so only the sample deforms (its automata's contact halves aside)."""
    E, nu = MATERIALS[material][:2]
    return E / (1.0 - nu * nu)


def hertz_radius(load, R, Estar):
    return (3.0 * load * R / (4.0 * Estar)) ** (1.0 / 3.0)


def surface_deflection(r, a, load, E, nu):
    """Downward displacement of the surface at radius r under Hertz's
    pressure of total load on a contact of radius a (Johnson, Contact
    Mechanics, eq. 3.42): the far field's reference."""
    p0 = 1.5 * load / (math.pi * a * a)
    c = (1.0 - nu * nu) / E
    if r <= a:
        return c * math.pi * p0 / (4.0 * a) * (2.0 * a * a - r * r)
    return c * p0 / (2.0 * a) * ((2.0 * a * a - r * r) * math.asin(a / r)
                                 + r * a * math.sqrt(1.0 - a * a / (r * r)))


def hertz_relative_depth(load, R, material, r_ref):
    """Approach of the indenter to the surface point at r_ref: Hertz's depth
    a^2/R less that point's deflection (both from the far field, which a
    finite sample held at its base does not have)."""
    E, nu = MATERIALS[material][:2]
    a = hertz_radius(load, R, contact_modulus(material))
    return a * a / R - surface_deflection(r_ref, a, load, E, nu)


def hertz_load(relative_depth, R, material, r_ref):
    """The Hertz load that gives this approach to the point at r_ref (while
    the contact is inside the ring: once a reaches r_ref the ring follows
    the sphere and the approach stays r_ref^2 / 2R; nan beyond)."""
    upper = 4.0 * contact_modulus(material) * r_ref ** 3 / (3.0 * R)
    f = lambda P: hertz_relative_depth(P, R, material, r_ref) - relative_depth  # noqa: E731
    if f(upper) <= 0.0:
        return math.nan
    return brentq(f, 1e-15 * upper, upper, xtol=1e-14 * upper, rtol=1e-12)


def first_yield_factor(nu):
    """p0 / sigma_y at the first yield (von Mises) under Hertz's pressure:
    the largest sigma_z - sigma_r on the axis (Johnson eq. 3.45), where
    von Mises' sigma_eq is |sigma_z - sigma_r|; returns (factor, z/a)."""
    def sigma_eq(z):   # over p0, z in units of a
        s_z = -1.0 / (1.0 + z * z)
        s_r = -(1.0 + nu) * (1.0 - z * math.atan(1.0 / z)) + 0.5 / (1.0 + z * z)
        return abs(s_z - s_r)
    best = minimize_scalar(lambda z: -sigma_eq(z), bounds=(0.05, 2.0), method="bounded",
                           options={"xatol": 1e-10})
    return 1.0 / sigma_eq(best.x), best.x


def hertz_peak_pressure(load, R, Estar):
    return (6.0 * load * Estar * Estar / (math.pi ** 3 * R * R)) ** (1.0 / 3.0)


def loading_part(t):
    """Rows of the loading half (up to the largest travel)."""
    end = int(np.argmax(t["travel"])) + 1
    return {k: v[:end] for k, v in t.items()}


def hertz_errors(t, R, material, r_ref, a_min, a_max):
    """Measured load over Hertz's at the measured approach to the ring at
    r_ref, for the rows of the loading whose Hertz contact radius lies in
    [a_min, a_max]: (radius / D, relative depth, load, Hertz load)."""
    t = loading_part(t)
    depth = t["travel"] - GAP + t["w_ring"]
    Estar = contact_modulus(material)
    rows = []
    for delta, P in zip(depth, t["load"]):
        if P <= 0.0 or delta <= 0.0:
            continue
        a = hertz_radius(P, R, Estar)
        if a_min <= a <= a_max:
            rows.append((a / D, delta, P, hertz_load(delta, R, material, r_ref)))
    return np.array(rows)


def yield_onset(t, R, material):
    """Load at the first plastic strain (linear between the rows around it),
    the Hertz peak pressure there over sigma_y, and the contact radius."""
    t = loading_part(t)
    k = int(np.argmax(t["epsp_max"] > 0.0))
    if t["epsp_max"][k] <= 0.0:
        raise ValueError("the sample never yields")
    P = 0.5 * (t["load"][k - 1] + t["load"][k])
    Estar = contact_modulus(material)
    sigma_y = MATERIALS[material][2]
    return P, hertz_peak_pressure(P, R, Estar) / sigma_y, hertz_radius(P, R, Estar) / D


def contact_area(t):
    """The contact area of each row: the lens automata stand over the
    hollows of the sample's (001) top plane, each touching four top
    automata, so the interface has one contact per d^2 / 4 and each contact
    that pushes stands for that area (in.indent counts them, at most four
    per lens automaton).  Counting whole cells of the lens automata that
    touch instead would take in a rim half a cell wide (12 % more area at
    a = 5 d)."""
    return t["cells"] * D * D


def mean_pressure(t, material):
    """At the deepest point: the mean contact pressure over sigma_y and the
    contact radius a / D (contact_area)."""
    t = loading_part(t)
    area = contact_area(t)[-1]
    return t["load"][-1] / area / MATERIALS[material][2], math.sqrt(area / math.pi) / D


def unloading_stiffness(t, fraction=0.3):
    """dP/dh over the first part of the unloading (load from P_max down to
    (1 - fraction) P_max; least squares), and P_max."""
    top = int(np.argmax(t["travel"]))
    P, h = t["load"][top:], t["travel"][top:]
    Pmax = P[0]
    keep = P >= (1.0 - fraction) * Pmax
    slope = np.polyfit(h[keep], P[keep], 1)[0]
    return slope, Pmax


def plastic_index_curve(t, material, R):
    """Over the loading: Johnson's index x = E* a / (sigma_y R) and the mean
    contact pressure over sigma_y (contact_area)."""
    t = loading_part(t)
    keep = t["cells"] > 0
    area = contact_area(t)[keep]
    a = np.sqrt(area / math.pi)
    sigma_y = MATERIALS[material][2]
    return (contact_modulus(material) * a / (sigma_y * R), t["load"][keep] / area / sigma_y)


def cavity_model(x):
    """Johnson's expanding cavity model of the elastic-plastic range of a
    sphere: p_m / sigma_y = 2/3 (1 + ln(x / 3)) (Contact Mechanics, 6.4)."""
    return 2.0 / 3.0 * (1.0 + np.log(np.asarray(x) / 3.0))


LATTICE_PERIOD = math.sqrt(2.0) * D   # of the (001) surface along x: the fcc lattice constant


def last_periods(t, periods=1):
    """Indices of the scratch's rows over its last lattice periods along x."""
    slide = t["x_lens"] - t["x_lens"][0]
    if slide.max() < periods * LATTICE_PERIOD:
        raise ValueError("the scratch is shorter than the periods asked for")
    return np.nonzero((slide >= slide.max() - periods * LATTICE_PERIOD) & (slide > 0.0))[0]


def scratch_friction(t, periods=1):
    """F_x / F_N of the scratch over its last lattice periods along x (the
    ratio of the means), and half the range of the ratio there."""
    keep = last_periods(t, periods)
    ratio = t["lateral"][keep] / t["load"][keep]
    return t["lateral"][keep].mean() / t["load"][keep].mean(), 0.5 * np.ptp(ratio)


def tabor_flow_stress(material, a, R):
    """Tabor's representative flow stress: the hardening line at the strain
    0.2 a / R (elastic strain sigma_y / E included), over sigma_y."""
    E, nu, sigma_y, H = MATERIALS[material]
    strain = 0.2 * a / R
    return 1.0 + H * max(0.0, strain - sigma_y / E) / sigma_y


def lens_work(t):
    """Work of the lens on the sample up to each row: load over the travel
    plus the lateral force over the slide (trapezoids between rows)."""
    from scipy.integrate import cumulative_trapezoid
    return (cumulative_trapezoid(t["load"], t["travel"], initial=0.0)
            + cumulative_trapezoid(t["lateral"], t["x_lens"], initial=0.0))


def stored_and_dissipated(t):
    """kinetic + pe + plastic work + friction + contact work of each row."""
    return t["ke"] + t["pe"] + t["plastic_work"] + t["friction"] + t["contact_work"]


def energy_balance(t):
    """Largest |stored and dissipated - lens work| over the largest work."""
    work = lens_work(t)
    return np.abs(stored_and_dissipated(t) - work).max() / work.max()


def scratch_parts(t, periods=1):
    """F_x / F_N over the last lattice periods of the scratch split by the
    energy it went into: (friction part, ploughing part), each the energy
    over (mean F_N x slide); the ploughing part is what the normal forces
    of the contacts do (plastic work, elastic and kinetic energy)."""
    keep = last_periods(t, periods)
    first, last = keep[0], keep[-1]
    scale = t["load"][keep].mean() * (t["x_lens"][last] - t["x_lens"][first])
    friction = t["friction"][last] - t["friction"][first]
    total = stored_and_dissipated(t)
    return friction / scale, (total[last] - total[first] - friction) / scale
