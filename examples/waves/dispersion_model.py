"""Phase speed of a P wave along [100] of an fcc lattice of elastic MCA
automata, from the linearised MCA law (derivation in doc/src/pair_mca.rst,
"Dispersion").  Planes (001) of automata are h = a/2 apart and m planes make
one wavelength, so kh = 2 pi/m.  With the Lame constants lambda, G:

    (c/c_p)^2 = [ 2G sinc^2(kh/2)
                  + lambda sinc^2(kh) / (1 + (lambda/G) sin^2(kh/2)) ] / (lambda + 2G)

sinc(x) = sin(x)/x.  The 2G term is the nearest-neighbour chain of planes
(links and their shear tractions); the lambda term is the mean-stress
coupling D dsigma_mean: the mean stress of an automaton is a central
difference over two plane spacings (sinc(kh)), and the Newton-3 split of the
normal law couples the halves of a link through the mean stresses of both
automata (the denominator).  For nu = 0 (lambda = 0) it is the chain,
sin(kh/2)/(kh/2)."""

import math


def lame(young, nu):
    """Shear modulus G and Lame's lambda."""
    return young / (2.0 * (1.0 + nu)), young * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))


def p_wave_speed_ratio(m, nu, young=70.0e9):
    """c/c_p of the MCA lattice for m planes (001) per wavelength."""
    g, lam = lame(young, nu)
    kh = 2.0 * math.pi / m
    s = math.sin(0.5 * kh)
    chain = 2.0 * g * (s / (0.5 * kh)) ** 2
    mean_stress = lam * (math.sin(kh) / kh) ** 2 / (1.0 + lam / g * s * s)
    return math.sqrt((chain + mean_stress) / (lam + 2.0 * g))


def planes_for_error(nu, error=0.01):
    """Fewest planes per wavelength (to 0.01) at which c/c_p - 1 > -error."""
    lo, hi = 2.0, 1.0e4    # the error falls monotonically with m
    while hi - lo > 1.0e-3:
        mid = 0.5 * (lo + hi)
        if p_wave_speed_ratio(mid, nu) - 1.0 > -error:
            hi = mid
        else:
            lo = mid
    return hi
