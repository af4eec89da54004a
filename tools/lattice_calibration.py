#!/usr/bin/python3
"""Elastic constants of 2-D hexagonal particle lattices and the spring and
pair parameters that give them (doc/src/Howto_mlp.rst, "Calibrating a
lattice"; the NUMFRAC/MLP notes, Part A.4 and Part B.2).

Two lattices of nearest-neighbour bonds (spacing c, triangular, the area
per particle sqrt(3) c^2 / 2; moduli per unit area of the plane, i.e. per
unit thickness):

* MLP, movable lattice particles (pair_style mlp): each bond is the linear
  spring k1 I + k2 e e^T of the paper's Eq. 2 on the full relative
  displacement; k1 = n f0 / c (the return force), k2 = U''(c) - k1.  The
  k1 part is not objective: for a displacement gradient H the energy per
  area is
    w = (sqrt3/2) k1 H:H + (sqrt3/8) k2 ((tr H)^2 + H:H + H:H^T),
  the isotropic energy of mu = sqrt3 (k1 + k2/4), lambda = sqrt3 (k2/4 - k1)
  (the corrected Eq. 11; the paper's has half these values) plus the null
  Lagrangian sqrt3 k1 det H (which holds the energy of a rotation too).  Two
  sets of moduli follow (kind "waves" or "static" below):
    waves   Eq. 11's: those of the field equations in the bulk, so of
            long waves and of the displacements of problems with
            prescribed displacements;
    static  mu = (sqrt3/2)(k1 + k2/2), lambda = (sqrt3/4) k2: the stress
            of a homogeneous strain (the null Lagrangian's included), so
            those of a tension or compression test loaded by forces
            (nu_2D = k2 / (3 k2 + 4 k1),
            E_2D = 2 sqrt3 (2 k1 + k2)(k1 + k2) / (4 k1 + 3 k2)).
* beams and shear beams (NUMFRAC): a normal stiffness k_n and an objective
  transverse stiffness k_s on the strain part of the relative displacement
  (the particles' rotations relax): mu = (sqrt3/4)(k_n + k_s),
  lambda = (sqrt3/4)(k_n - k_s).  An Euler-Bernoulli beam has k_n = EA/L,
  k_s = 12 EI/L^3; a shear beam of rotational stiffness k_r has
  k_s = 2 k_r / L0^2.

Both reach only nu_2D <= 1/3 with a restoring transverse stiffness
(k1 >= 0, k_s >= 0): nu <= 1/4 in plane strain (nu_2D = nu / (1 - nu)).

Command line (prints the parameters and the moduli they give back):

  tools/lattice_calibration.py mlp  --E2 E --nu2 NU [--c 1] [--n 6]
                                    [--potential harmonic|morse|lj] [--D0 1]
                                    [--moduli waves|static]
  tools/lattice_calibration.py beam --E2 E --nu2 NU [--c 1] [--E-bond E [--glen A]]
  (--E E --nu NU --thickness T --plane strain|stress instead of --E2 --nu2)

From Python: import lattice_calibration as lc; lc.mlp_springs(E2, nu2) ...
"""

import argparse
import math
import sys

import numpy as np

SQRT3 = math.sqrt(3.0)


class CalibrationError(ValueError):
    """Moduli that the lattice cannot have."""


# --------------------------------------------------------------------------
# isotropic 2-D elasticity


def lame(e2, nu2):
    """(mu, lambda) of a 2-D isotropic medium from E_2D and nu_2D."""
    if not -1.0 < nu2 < 1.0:
        raise CalibrationError(f"nu_2D = {nu2:g} must be in (-1, 1)")
    if e2 <= 0.0:
        raise CalibrationError(f"E_2D = {e2:g} must be > 0")
    return e2 / (2.0 * (1.0 + nu2)), e2 * nu2 / ((1.0 + nu2) * (1.0 - nu2))


def young(mu, lam):
    """(E_2D, nu_2D) from the 2-D Lame constants."""
    return 4.0 * mu * (lam + mu) / (lam + 2.0 * mu), lam / (lam + 2.0 * mu)


def in_plane(e, nu, thickness=1.0, plane="strain"):
    """(E_2D, nu_2D) of a 3-D material (E, nu) in plane strain or plane
    stress, per layer of the given thickness."""
    if plane == "strain":
        return thickness * e / (1.0 - nu * nu), nu / (1.0 - nu)
    if plane == "stress":
        return thickness * e, nu
    raise CalibrationError(f"plane must be strain or stress, not {plane}")


def moduli(mu, lam):
    e2, nu2 = young(mu, lam)
    return {"mu": mu, "lambda": lam, "E2": e2, "nu2": nu2, "K2": lam + mu}


def _check_reachable(nu2, model):
    # a little room for round-off at the limit itself (f0 = 0, k_s = 0)
    if nu2 > 1.0 / 3.0 + 1e-12:
        raise CalibrationError(
            f"nu_2D = {nu2:g} > 1/3: a {model} lattice with a restoring transverse stiffness "
            "reaches at most 1/3 (nu <= 1/4 in plane strain)")


# --------------------------------------------------------------------------
# movable lattice particles (pair_style mlp)


def mlp_moduli(k1, k2):
    """Moduli of the hexagonal k1/k2 lattice (corrected Eq. 11)."""
    return moduli(SQRT3 * (k1 + k2 / 4.0), SQRT3 * (k2 / 4.0 - k1))


def mlp_static_moduli(k1, k2):
    """Moduli of the stress of a homogeneous strain of the hexagonal k1/k2
    lattice (C11 = lambda + 2 mu, C12 = lambda): those of a body loaded by
    forces in a uniform state (a tension test, a pressed slab)."""
    return moduli(SQRT3 / 2.0 * (k1 + k2 / 2.0), SQRT3 / 4.0 * k2)


def mlp_dynamical_matrix(k1, k2, q, c=1.0):
    """The 2 x 2 dynamical matrix (unit masses) of the hexagonal k1/k2
    lattice of spacing c at the wave vectors q (shape (..., 2)):
    D(q) = sum over the six neighbours e of (k1 I + k2 e e^T)(1 - cos(c q.e))."""
    q = np.asarray(q, dtype=float)
    d = np.zeros(q.shape[:-1] + (2, 2))
    for k in range(6):
        e = np.array([math.cos(k * math.pi / 3.0), math.sin(k * math.pi / 3.0)])
        weight = 1.0 - np.cos(c * q @ e)
        d += weight[..., None, None] * (k1 * np.eye(2) + k2 * np.outer(e, e))
    return d


def mlp_lowest_mode(k1, k2, c=1.0, n=61):
    """The lowest eigenvalue of the dynamical matrix over the Brillouin zone
    (an n x n grid of the reciprocal cell, the zone-boundary points M
    included for odd n) and its wave vector: >= 0 (0 at q = 0) where the
    lattice is stable.  A negative k1 (nu_2D > 1/3) is stable down to
    k1 = -k2/4, where the wave modulus mu = sqrt3 (k1 + k2/4) vanishes and
    the zone-boundary mode M goes soft with it (D_min(M) = 8 (k1 + k2/4))."""
    b1 = 2.0 * math.pi / c * np.array([1.0, -1.0 / SQRT3])
    b2 = 2.0 * math.pi / c * np.array([0.0, 2.0 / SQRT3])
    u, v = np.meshgrid(np.linspace(0.0, 1.0, n), np.linspace(0.0, 1.0, n), indexing="ij")
    q = u[..., None] * b1 + v[..., None] * b2
    lowest = np.linalg.eigvalsh(mlp_dynamical_matrix(k1, k2, q, c))[..., 0]
    at = np.unravel_index(np.argmin(lowest), lowest.shape)
    return float(lowest[at]), q[at]


def mlp_springs(e2, nu2, kind="waves"):
    """(k1, k2) that give E_2D and nu_2D as the moduli of the given kind
    (waves: Eq. 11's, mlp_moduli; static: mlp_static_moduli)."""
    _check_reachable(nu2, "movable lattice particle")
    mu, lam = lame(e2, nu2)
    if kind == "static":
        return 2.0 * (mu - lam) / SQRT3, 4.0 * lam / SQRT3
    if kind != "waves":
        raise CalibrationError(f"moduli {kind}: allowed waves, static")
    return (mu - lam) / (2.0 * SQRT3), 2.0 * (lam + mu) / SQRT3


def mlp_pair(e2, nu2, c=1.0, n=6, kind="waves"):
    """(U''(c), f0) of pair_style mlp for E_2D, nu_2D (moduli of the given
    kind) on a hexagonal lattice of spacing c: k1 = n f0 / c, U'' = k1 + k2."""
    if n != 6:
        raise CalibrationError("the isotropic moduli are those of the hexagonal lattice (n = 6); "
                               "a square lattice (n = 4) is cubic: C11 = U'', C44 = 4 f0 / c")
    k1, k2 = mlp_springs(e2, nu2, kind)
    return k1 + k2, c * k1 / n


def central_potential(kind, upp, c=1.0, d0=1.0):
    """pair_coeff words of a central potential with its minimum at c and the
    curvature U''(c) = upp: harmonic K r0; morse D0 alpha r0 (2 alpha^2 D0 =
    U'', D0 given); lj epsilon sigma (sigma = 2^(-1/6) c)."""
    if upp <= 0.0:
        raise CalibrationError(f"U'' = {upp:g} must be > 0")
    if kind == "harmonic":
        return f"harmonic {upp:.12g} {c:.12g}"
    if kind == "morse":
        if d0 <= 0.0:
            raise CalibrationError(f"D0 = {d0:g} must be > 0")
        return f"morse {d0:.12g} {math.sqrt(upp / (2.0 * d0)):.12g} {c:.12g}"
    if kind == "lj":
        sigma = c * 2.0 ** (-1.0 / 6.0)
        return f"lj {2.0 ** (1.0 / 3.0) * sigma * sigma * upp / 72.0:.12g} {sigma:.12g}"
    raise CalibrationError(f"potential must be harmonic, morse or lj, not {kind}")


# --------------------------------------------------------------------------
# beams and shear beams (NUMFRAC)


def beam_moduli(kn, ks):
    """Moduli of the hexagonal lattice of normal stiffness k_n and objective
    transverse stiffness k_s (rotations relaxed)."""
    return moduli(SQRT3 / 4.0 * (kn + ks), SQRT3 / 4.0 * (kn - ks))


def beam_springs(e2, nu2):
    """(k_n, k_s) that give E_2D and nu_2D:
    k_n = E_2D / (sqrt3 (1 - nu_2D)), k_s = E_2D (1 - 3 nu_2D) / (sqrt3 (1 - nu_2D^2))."""
    _check_reachable(nu2, "beam")
    lame(e2, nu2)    # the range checks
    return e2 / (SQRT3 * (1.0 - nu2)), e2 * (1.0 - 3.0 * nu2) / (SQRT3 * (1.0 - nu2 * nu2))


def beam_stiffness(e, area, inertia, length):
    """(k_n, k_s) of an Euler-Bernoulli beam: EA/L, 12 EI/L^3."""
    for name, value in (("E", e), ("A", area), ("I", inertia), ("L", length)):
        if value <= 0.0:
            raise CalibrationError(f"{name} = {value:g} must be > 0")
    return e * area / length, 12.0 * e * inertia / length ** 3


def rectangular_beam_nu2(height_over_length):
    """nu_2D of the lattice of rectangular beams of height h per unit
    thickness (k_s / k_n = (h/L)^2)."""
    r = height_over_length * height_over_length
    return (1.0 - r) / (3.0 + r)


def shear_beam_kr(ks, length):
    """The rotational stiffness k_r of a shear beam with the transverse
    stiffness k_s: k_s = 2 k_r / L0^2."""
    return 0.5 * ks * length * length


def glen_creep_prefactor(kn, ks, e, a_glen):
    """k of the initial shear creep rate k tau^3 (engineering shear strain
    per time, tau the shear stress) of the hexagonal beam lattice whose
    bonds melt by Glen's law (bond_coeff ... melt glen A; E the beams' E)
    and freeze again at once, stress-free (doc/src/Howto_mlp.rst, "Viscous
    flow").

    Levin's theorem: at a fixed load, a bond that freezes again stress-free
    adds the macroscopic strain whose work is twice its elastic energy,
    V tau d(gamma) = 2 U_b, so the lattice creeps at
    V tau gamma' = sum_b lambda_b 2 U_b = (4 A E^2 / L^2) sum_b U_b^2.
    Under a uniform shear stress (tensor strain e = tau / 2 mu) a bond at
    the angle theta to the shear direction has
    U_b = L^2 e^2 (k_n sin^2 2theta + k_s cos^2 2theta) / 2; over the three
    directions, per area sqrt3 L^2 / 2:
    gamma' = 2 A E^2 S tau^3 / (sqrt3 (2 mu)^4), S = k_s^2 + 2 (3 k_n / 4 + k_s / 4)^2,
    independent of L.  It holds until the frozen bonds' rest states, no
    longer compatible, add residual stresses (the steady rate is higher)."""
    for name, value in (("k_n", kn), ("E", e), ("A", a_glen)):
        if value <= 0.0:
            raise CalibrationError(f"{name} = {value:g} must be > 0")
    if ks < 0.0:
        raise CalibrationError(f"k_s = {ks:g} must be >= 0")
    mu = SQRT3 / 4.0 * (kn + ks)
    s = ks * ks + 2.0 * (0.75 * kn + 0.25 * ks) ** 2
    return 2.0 * a_glen * e * e * s / (SQRT3 * (2.0 * mu) ** 4)


# --------------------------------------------------------------------------
# command line


def _report(lines, values):
    lines.append("moduli given back: " + ", ".join(f"{k} {v:.10g}" for k, v in values.items()))
    return "\n".join(lines)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("lattice", choices=("mlp", "beam"))
    ap.add_argument("--E2", type=float, help="2-D Young's modulus (energy / area)")
    ap.add_argument("--nu2", type=float, help="2-D Poisson ratio")
    ap.add_argument("--E", type=float, help="3-D Young's modulus (with --nu, --thickness)")
    ap.add_argument("--nu", type=float, help="3-D Poisson ratio")
    ap.add_argument("--thickness", type=float, default=1.0)
    ap.add_argument("--plane", choices=("strain", "stress"), default="strain")
    ap.add_argument("--c", type=float, default=1.0, help="lattice spacing")
    ap.add_argument("--potential", choices=("harmonic", "morse", "lj"), default="harmonic")
    ap.add_argument("--D0", type=float, default=1.0, help="Morse bond energy")
    ap.add_argument("--moduli", choices=("waves", "static"), default="waves",
                    help="mlp: the moduli to give E and nu: of the field equations and long "
                    "waves (Eq. 11), or of a homogeneous strain's stress (a body loaded by forces)")
    ap.add_argument("--E-bond", type=float, default=None,
                    help="beam: the beam material's E (gives A and I of the section)")
    ap.add_argument("--glen", type=float, default=None, metavar="A",
                    help="beam, with --E-bond: the initial shear creep rate k tau^3 of the "
                    "lattice whose bonds melt with melt glen A and freeze again")
    args = ap.parse_args(argv)
    try:
        if args.E2 is not None and args.nu2 is not None:
            e2, nu2 = args.E2, args.nu2
        elif args.E is not None and args.nu is not None:
            e2, nu2 = in_plane(args.E, args.nu, args.thickness, args.plane)
        else:
            raise CalibrationError("give --E2 and --nu2, or --E and --nu")
        lines = [f"target: E_2D {e2:.10g}, nu_2D {nu2:.10g}, spacing c {args.c:g}"]
        if args.lattice == "mlp":
            upp, f0 = mlp_pair(e2, nu2, args.c, kind=args.moduli)
            k1, k2 = mlp_springs(e2, nu2, args.moduli)
            lines += [f"k1 {k1:.10g}, k2 {k2:.10g}, U''(c) {upp:.10g}, f0 {f0:.10g}",
                      f"pair_coeff * * {central_potential(args.potential, upp, args.c, args.D0)}"
                      f" {f0:.12g} 6 0.0"]
            other = "static" if args.moduli == "waves" else "waves"
            given = mlp_moduli(k1, k2) if args.moduli == "waves" else mlp_static_moduli(k1, k2)
            back = mlp_static_moduli(k1, k2) if args.moduli == "waves" else mlp_moduli(k1, k2)
            lines.append(f"({other} moduli of these parameters: E_2D {back['E2']:.10g}, "
                         f"nu_2D {back['nu2']:.10g})")
            print(_report(lines, given))
        else:
            if args.moduli != "waves":
                raise CalibrationError("--moduli applies to mlp lattices (a beam lattice's "
                                       "moduli are of one kind)")
            kn, ks = beam_springs(e2, nu2)
            lines.append(f"k_n {kn:.10g}, k_s {ks:.10g}, shear beam k_r {shear_beam_kr(ks, args.c):.10g}")
            if args.E_bond:
                # EA / c = k_n, 12 EI / c^3 = k_s
                lines.append(f"beam of E {args.E_bond:g}: A {kn * args.c / args.E_bond:.10g}, "
                             f"I {ks * args.c ** 3 / (12.0 * args.E_bond):.10g}")
            if args.glen is not None:
                if not args.E_bond:
                    raise CalibrationError("--glen needs --E-bond (Glen's rate has the beams' E)")
                k = glen_creep_prefactor(kn, ks, args.E_bond, args.glen)
                lines.append(f"melt glen {args.glen:g}: initial shear creep rate {k:.10g} tau^3 "
                             f"({k / args.glen:.6g} A)")
            print(_report(lines, beam_moduli(kn, ks)))
    except CalibrationError as err:
        print(f"lattice_calibration: {err}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
