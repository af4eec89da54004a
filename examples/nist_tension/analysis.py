"""Figures of a tension curve of examples/nist_tension against its inputs:
the initial slope (E), the yield stress (where the lines fitted to the
elastic and the post-yield parts of the curve meet) and the engineering
stress at 5 % strain, with the input curve's values.  Used by plot.py and
unittest/python/test_plasticity.py."""

import numpy as np

# digest table 5-1: E, sigma_y, sigma_u, tangent modulus E_t (Pa); eps_u = 0.08
SAMPLES = {"AR": (69e9, 315e6, 329e6, 225e6),
           "T274": (40e9, 189e6, 230.47e6, 816.95e6),
           "T413": (66.95e9, 55e6, 138.189e6, 1076.18e6)}
EPS_U = 0.08


def input_curve(sample, strain, hardening="linear"):
    """The input engineering curve: E strain up to sigma_y, then the
    tangent E_t; with the table, flat from sigma_u at eps_u on."""
    e, sy, su, et = SAMPLES[sample]
    stress = np.minimum(e * strain, sy + et * (strain - sy / e))
    if hardening == "table":
        stress = np.minimum(stress, su)
    return stress


def figures(sample, strain, stress):
    """E, sigma_y and the stress at 5 % strain of a measured curve."""
    e, sy, _, _ = SAMPLES[sample]
    loading = np.arange(len(strain)) <= np.argmax(strain)
    elastic = loading & (stress > 0.2 * sy) & (stress < 0.7 * sy)
    plastic = loading & (strain > 3 * sy / e) & (strain < 0.06)
    e1, e0 = np.polyfit(strain[elastic], stress[elastic], 1)
    p1, p0 = np.polyfit(strain[plastic], stress[plastic], 1)
    x = (p0 - e0) / (e1 - p1)
    at5 = np.interp(0.05, strain[loading], stress[loading])
    return {"E": e1, "sigma_y": e1 * x + e0, "stress_5": at5}
