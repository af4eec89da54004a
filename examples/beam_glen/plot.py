"""Glen's law from melting and re-freezing beams: the creep of the sheared
layer at each shear stress (logs log.glen<tau>), its steady shear strain
rate (a straight line fitted to the strain over the second half of the
creep run), and the power law fitted to the rates, rate = k tau^n, and to
the fluidity 1 / mu = rate / tau = a tau^b (the digest's case 16: b = 2,
n = 3); glen.png and the figures printed."""

import glob
import math
import os
import re
import sys

import numpy as np


def read(path):
    """The thermo rows (time, strain) of the creep run of a log, its tau
    and the elastic strain it settled at before melting."""
    text = open(path).read()
    tau = float(re.search(r"^elastic strain \S+ at tau (\S+)$", text, re.M).group(1))
    elastic = float(re.search(r"^elastic strain (\S+) at tau", text, re.M).group(1))
    blocks = re.findall(r"^\s*Step\s+Time\s+v_strain.*?\n(.*?)^Loop", text, re.M | re.S)
    rows = np.array([[float(w) for w in line.split()[:3]] for line in blocks[-1].splitlines()
                     if re.match(r"^\s*\d", line)])
    return tau, elastic, rows[:, 1], rows[:, 2]


def creep_rate(path):
    """(tau, elastic strain, steady shear strain rate) of a log: the slope of
    the strain over the second half of the creep run."""
    tau, elastic, time, strain = read(path)
    late = time >= time[0] + 0.5 * (time[-1] - time[0])
    slope = np.polyfit(time[late], strain[late], 1)[0]
    return tau, elastic, slope


def initial_rate(path, span=200.0):
    """The slope of the strain over the first `span` time units of creep
    (before the frozen bonds' residual stresses build up)."""
    _, _, time, strain = read(path)
    early = time <= time[0] + span
    return np.polyfit(time[early], strain[early], 1)[0]


def levin_prefactor(glen=3.0e-4, e=100.0, h_over_l=0.3):
    """The initial creep rate per tau^3 of the periodic lattice
    (tools/lattice_calibration.py glen_creep_prefactor: Levin's theorem),
    or None where the tool is not next to the example."""
    tools = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools")
    sys.path.insert(0, tools)
    try:
        import lattice_calibration as lc
    except ImportError:
        return None
    kn, ks = lc.beam_stiffness(e, h_over_l, h_over_l ** 3 / 12.0, 1.0)
    return lc.glen_creep_prefactor(kn, ks, e, glen)


def power_law(x, y):
    """(prefactor, exponent) of y = p x^e, least squares in log-log."""
    e, logp = np.polyfit(np.log(x), np.log(y), 1)
    return math.exp(logp), e


def main(logs):
    # (tau, elastic strain, rate, log) by tau
    results = sorted(creep_rate(p) + (p,) for p in logs)
    tau = np.array([r[0] for r in results])
    rate = np.array([r[2] for r in results])
    k, n = power_law(tau, rate)
    a, b = power_law(tau, rate / tau)
    for t, elastic, r, _ in results:
        print(f"tau {t:.4g}: elastic strain {elastic:.6g}, steady creep rate {r:.4e}, "
              f"fluidity {r / t:.4e}")
    print(f"creep rate = {k:.4g} tau^{n:.3f} (Glen: n = 3); "
          f"fluidity = {a:.4g} tau^{b:.3f} (digest case 16: b = 2.0)")
    levin = levin_prefactor()
    if levin is not None:
        for t, _, r, path in results:
            start = initial_rate(path)
            print(f"tau {t:.4g}: initial rate (first 200 time units) {start:.4e}, steady "
                  f"{r:.4e}; Levin's {levin:.5g} tau^3 = {levin * t ** 3:.4e} (initial / Levin "
                  f"{start / (levin * t ** 3):.3f}, steady / Levin {r / (levin * t ** 3):.3f})")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.2))
    for t, _, _, path in results:
        _, _, time, strain = read(path)
        left.plot(time - time[0], strain, label=f"tau = {t:g}")
    left.set_xlabel("time since melting began")
    left.set_ylabel("shear strain")
    left.set_yscale("log")
    left.legend()
    left.set_title("creep of the sheared layer")
    fine = np.geomspace(tau.min(), tau.max(), 50)
    right.loglog(tau, rate, "o", label="measured creep rate")
    right.loglog(fine, k * fine ** n, "-", label=f"fit: {k:.3g} tau^{n:.2f}")
    right.loglog(tau, rate / tau, "s", label="fluidity rate / tau")
    right.loglog(fine, a * fine ** b, "--", label=f"fit: {a:.3g} tau^{b:.2f}")
    right.set_xlabel("shear stress tau")
    right.set_title("Glen's law: rate ~ tau^3, fluidity ~ tau^2")
    right.legend()
    fig.tight_layout()
    fig.savefig("glen.png", dpi=110)


if __name__ == "__main__":
    main(sys.argv[1:] or sorted(glob.glob("log.glen*")))
