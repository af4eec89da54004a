"""bond_style beam with the particle criterion (bond_coeff ... break s0 t0
criterion particle; doc/src/bond_beam.rst, beam_kernels.h): the stress
of a particle averaged over its bonds, sigma = -(1/V) sym sum d (x) f / 2
(V = pi r^2 in 2-D, 4 pi r^3 / 3 in 3-D), its mean normal stress and
sqrt(J2) in the ellipse; a particle that fails loses its candidate bond
(the largest elliptic measure of its own loads) at the next evaluation.

* the particles' stresses and candidates of a T of three particles equal
  those computed here from the 2-D element written out, and the bonds
  that break are the candidates of the particles beyond the ellipse (one
  of the two bonds of the failing particle, where the bond criterion with
  the same strengths breaks both);
* the mean stress is the trace of compute stress/atom of the bonds over
  d V, in 2-D and 3-D, on 1 and 2 ranks, newton_bond on and off;
* a periodic hexagonal lattice of touching discs under a biaxial strain
  eps has the mean stress 6 N (1 + eps) / pi (N = E A eps) of the analytic
  sum and no shear; below the strength nothing breaks, above it every
  particle's candidate breaks one step after the decision, not before;
* a strip torn by the criterion is the same on 1 and 2 ranks, with
  newton_bond off, after a restart and in two runs split at a step with
  decisions pending; the Kokkos variant equals the CPU style; bad input
  gives clear errors; data files keep the keyword;
* the example examples/beam_particle_criterion (uniaxial strain of a
  periodic lattice) breaks first at the analytic strains of both criteria.
"""

import math

import numpy as np
import pytest

import mcatest
import test_bond_beam as beam2d
import test_bond_beam_3d as beam3d
from mcatest import read_dump

E_, A_, I_ = 100.0, 0.1, 0.001
STATE = "f_BEAM_STATE[1] f_BEAM_STATE[2] f_BEAM_STATE[3]"


def wrap(a):
    return math.remainder(a, 2.0 * math.pi)


def element_2d(xi, xj, ti, tj, a0, l0, e_=E_, a_=A_, i_=I_):
    """The 2-D Euler-Bernoulli element (beam_kernels.h beam_force_2d) of
    particles at rest along a0 with angle 0: chord d, force on j, N, V."""
    d = np.asarray(xj, float) - np.asarray(xi, float)
    length = math.hypot(*d)
    e = d / length
    a = math.atan2(d[1], d[0])
    qi, qj = wrap(ti + a0 - a), wrap(tj + a0 - a)
    k = e_ * i_ / l0
    mi, mj = k * (4 * qi + 2 * qj), k * (2 * qi + 4 * qj)
    n = e_ * a_ * (length - l0) / l0
    v = (mi + mj) / length
    f = np.array([-n * e[0] - v * e[1], -n * e[1] + v * e[0]])
    return d, f, n, v


def ellipse(sigma, tau, sigma0, tau0):
    return (max(sigma, 0.0) / sigma0) ** 2 + (tau / tau0) ** 2


def invariants(w, volume):
    """Mean normal stress and sqrt(J2) of the 2-D stress -w / volume."""
    s = -w / volume
    mean = 0.5 * (s[0, 0] + s[1, 1])
    dx, dy = s[0, 0] - mean, s[1, 1] - mean
    return mean, math.sqrt(0.5 * (dx * dx + dy * dy) + s[0, 1] ** 2)


# ---------------------------------------------------------------------------
# a T of three particles: 1 at the origin, 2 along x, 3 along y; 2 pulled
# by U, 3 by U / 2 and turned by THETA


U, THETA = 0.01, 3.0
SIGMA0, TAU0 = 0.04, 1.0
SITES = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)]
BONDS = [(0, 1), (0, 2)]
RADIUS = 0.5


def t_shape_expected():
    x = [np.array(p) for p in SITES]
    x[1] = x[1] + [U, 0.0]
    x[2] = x[2] + [0.0, 0.5 * U]
    turn = [0.0, 0.0, math.radians(THETA)]
    w = [np.zeros((2, 2)) for _ in SITES]
    bond_measure = {}
    for i, j in BONDS:
        a0 = math.atan2(SITES[j][1] - SITES[i][1], SITES[j][0] - SITES[i][0])
        d, f, n, v = element_2d(x[i], x[j], turn[i], turn[j], a0, 1.0)
        share = 0.25 * (np.outer(d, f) + np.outer(f, d))
        w[i] += share
        w[j] += share
        bond_measure[(i, j)] = ellipse(n / A_, abs(v) / A_, SIGMA0, TAU0)
    volume = math.pi * RADIUS ** 2
    states = [invariants(wi, volume) for wi in w]
    candidate = []
    for p in range(len(SITES)):
        mine = [(m, b[1] if b[0] == p else b[0]) for b, m in bond_measure.items() if p in b]
        best = max(m for m, _ in mine)
        candidate.append(min(q for m, q in mine if m == best))
    failing = [ellipse(s, t, SIGMA0, TAU0) >= 1.0 for s, t in states]
    broken = {tuple(sorted((p, candidate[p]))) for p in range(len(SITES)) if failing[p]}
    return states, candidate, broken, bond_measure


def t_shape(build, directory, criterion="particle", nprocs=1, newton="on", extra_args=()):
    data = beam2d.beam_data(directory / "t.data", SITES, BONDS, ((-2, 3), (-2, 3)),
                            radius=2 * RADIUS)
    script = beam2d.header(data, newton=newton) + f"""
bond_style      beam
bond_coeff      1 {E_} {A_} {I_} break {SIGMA0} {TAU0} criterion {criterion}
thermo_style    custom step bonds
run             0 post no
group           two id 2
group           three id 3
displace_atoms  two move {U} 0 0
displace_atoms  three move 0 {0.5 * U} 0
mca_set         three angle {THETA}
run             0 post no
write_dump      all custom decided.dump id {STATE} modify format float %.17g
write_data      decided.data
run             1 post no
write_data      after.data
"""
    build.run(script, directory, nprocs=nprocs, extra_args=extra_args)
    return read_dump(directory / "decided.dump")[0]


def bond_pairs(path):
    text = path.read_text()
    if "\nBonds" not in text:
        return set()
    section = text[text.index("\nBonds") + 1:].split("\n\n")[1]
    return {tuple(sorted((int(w[2]) - 1, int(w[3]) - 1)))
            for w in (line.split() for line in section.splitlines() if line.strip())}


def test_particle_stress_and_candidates_of_a_t(build, tmp_path):
    states, candidate, broken, bond_measure = t_shape_expected()
    snap = t_shape(build, tmp_path)
    sigma, tau, partner = (snap[c] for c in STATE.split())
    for p, (s, t) in enumerate(states):
        print(f"particle {p + 1}: sigma {sigma[p]:.12g} ({s:.12g}), tau {tau[p]:.12g} ({t:.12g}),"
              f" candidate {partner[p]:.0f} ({candidate[p] + 1}), ellipse "
              f"{ellipse(s, t, SIGMA0, TAU0):.3f}")
        # the same arithmetic (the element, the symmetric virial, the
        # invariants) in another order: round-off
        assert sigma[p] == pytest.approx(s, rel=1e-12)
        assert tau[p] == pytest.approx(t, rel=1e-12, abs=1e-15)
        assert partner[p] == candidate[p] + 1
    print(f"bond measures {bond_measure}; expected broken {broken}")
    # the scene is built so that particle 1 alone fails and loses the
    # more loaded of its two bonds, the one to 2
    assert broken == {(0, 1)}
    # decided at step 0, broken at step 1
    assert bond_pairs(tmp_path / "decided.data") == set(BONDS)
    assert bond_pairs(tmp_path / "after.data") == set(BONDS) - broken
    # the bond criterion with the same strengths breaks both bonds at once
    t_shape(build, tmp_path / "bond", criterion="bond")
    assert bond_pairs(tmp_path / "bond" / "decided.data") == set()


@pytest.mark.parametrize("nprocs,newton", [(2, "on"), (2, "off"), (1, "off"), (4, "on")])
def test_t_decides_the_same_on_ranks_and_newton(build, tmp_path, nprocs, newton):
    ref = t_shape(build, tmp_path / "ref")
    snap = t_shape(build, tmp_path / "run", nprocs=nprocs, newton=newton)
    for column in STATE.split():
        assert np.allclose(snap[column], ref[column], rtol=1e-14, atol=0.0), column
    assert bond_pairs(tmp_path / "run" / "after.data") == \
        bond_pairs(tmp_path / "ref" / "after.data")


# ---------------------------------------------------------------------------
# the mean stress is the trace of the bonds' per-atom stress over d V


SCENES = {
    2: (lambda: beam2d.hex_patch(2.1), beam2d.DEFORM,
        f"{E_} {A_} {I_} shear 40.0 0.8333333333333334"),
    3: (beam3d.cluster, beam3d.DEFORM, beam3d.TIMOSHENKO),
}


def deformed(build, directory, dim, nprocs=1, newton="on", extra_args=()):
    make, deform, words = SCENES[dim]
    sites, bonds = make()
    if dim == 3:
        data = beam3d.beam_data(directory / "scene.data", sites, bonds,
                                ((-3, 3), (-3, 3), (-3, 3)))
        script = beam3d.header(data, newton=newton)
    else:
        data = beam2d.beam_data(directory / "scene.data", sites, bonds, ((-4, 4), (-4, 4)))
        script = beam2d.header(data, newton=newton)
    script += f"bond_style beam\nbond_coeff 1 {words} break 1e6 1e6 criterion particle\n"
    script += deform + f"""
compute         st all stress/atom NULL bond
dump            d all custom 1 state.dump id radius c_st[1] c_st[2] c_st[3] {STATE}
dump_modify     d format float %.17g
run             0 post no
"""
    build.run(script, directory, nprocs=nprocs, extra_args=extra_args)
    return read_dump(directory / "state.dump")[0], len(bonds)


@pytest.mark.parametrize("dim", [2, 3])
def test_mean_stress_is_the_trace_of_the_bond_stress(build, tmp_path, dim):
    snap, nbonds = deformed(build, tmp_path / "one", dim)
    r = snap["radius"]
    volume = math.pi * r ** 2 if dim == 2 else 4.0 / 3.0 * math.pi * r ** 3
    trace = sum(snap[f"c_st[{k}]"] for k in range(1, dim + 1))
    expected = trace / (dim * volume)
    sigma = snap["f_BEAM_STATE[1]"]
    worst = np.abs(sigma - expected).max() / np.abs(expected).max()
    print(f"{dim}-D, {nbonds} bonds: mean stress against stress/atom: {worst:.1e}; "
          f"sqrt(J2) {snap['f_BEAM_STATE[2]'].min():.3g} to {snap['f_BEAM_STATE[2]'].max():.3g}")
    # the same sums in another order (compute stress/atom sums d f / 2 as
    # the bond style tallies them): round-off
    assert worst < 1e-12
    assert np.all(snap["f_BEAM_STATE[2]"] > 0.0) and np.all(snap["f_BEAM_STATE[3]"] > 0)
    for nprocs, newton in ((2, "on"), (2, "off"), (1, "off"), (4, "on")):
        other, _ = deformed(build, tmp_path / f"{nprocs}{newton}", dim, nprocs, newton)
        for column in STATE.split():
            diff = np.abs(other[column] - snap[column]).max() / np.abs(snap[column]).max()
            # candidates (partner IDs) exactly; stresses to round-off
            assert diff < (1e-12 if column != "f_BEAM_STATE[3]" else 1e-300), (nprocs, newton)


def dilated(build, directory, dim, nprocs=1):
    """The scene of `deformed` dilated by 1 % about its centre instead:
    every bond stretched along its chord, no turn (no shear force, no end
    moment), so d (x) f is symmetric and stress/atom is the whole tensor."""
    make, _, words = SCENES[dim]
    sites, bonds = make()
    if dim == 3:
        data = beam3d.beam_data(directory / "scene.data", sites, bonds,
                                ((-3, 3), (-3, 3), (-3, 3)))
        script = beam3d.header(data)
    else:
        data = beam2d.beam_data(directory / "scene.data", sites, bonds, ((-4, 4), (-4, 4)))
        script = beam2d.header(data)
    scale = " ".join(f"{a} scale 1.01" for a in "xyz"[:dim])
    script += f"""bond_style beam
bond_coeff 1 {words} break 1e6 1e6 criterion particle
run             0 post no
change_box      all {scale} remap
compute         st all stress/atom NULL bond
dump            d all custom 1 state.dump id radius {' '.join(f'c_st[{k}]' for k in range(1, 7))} &
                {STATE}
dump_modify     d format float %.17g
run             0 post no
"""
    build.run(script, directory, nprocs=nprocs)
    return read_dump(directory / "state.dump")[0]


@pytest.mark.parametrize("dim", [2, 3])
def test_shear_invariant_is_that_of_the_bond_stress(build, tmp_path, dim):
    snap = dilated(build, tmp_path, dim)
    r = snap["radius"]
    volume = math.pi * r ** 2 if dim == 2 else 4.0 / 3.0 * math.pi * r ** 3
    # stress/atom: xx yy zz xy xz yz of -(1/2) sum d f, here symmetric
    s = [snap[f"c_st[{k}]"] / volume for k in range(1, 7)]
    mean = (s[0] + s[1] + (s[2] if dim == 3 else 0.0)) / dim
    dev = [s[0] - mean, s[1] - mean, (s[2] - mean) if dim == 3 else 0.0]
    shear = s[3] ** 2 + ((s[4] ** 2 + s[5] ** 2) if dim == 3 else 0.0)
    tau = np.sqrt(0.5 * (dev[0] ** 2 + dev[1] ** 2 + dev[2] ** 2) + shear)
    worst = max(np.abs(snap["f_BEAM_STATE[1]"] - mean).max() / np.abs(mean).max(),
                np.abs(snap["f_BEAM_STATE[2]"] - tau).max() / tau.max())
    print(f"{dim}-D dilated by 1 %: sigma, sqrt(J2) against stress/atom: {worst:.1e} "
          f"(sqrt(J2) {tau.min():.3g} to {tau.max():.3g}, mean {mean.min():.3g} to {mean.max():.3g})")
    # round-off of sums in another order; the surface particles have a
    # shear invariant of the size of their mean stress
    assert worst < 1e-12
    assert tau.max() > 0.1 * np.abs(mean).max()


# ---------------------------------------------------------------------------
# a tie: particle 1 between 3 (left) and 2 (right), both bonds stretched by
# the same exactly representable length; the bond to 3 comes first in the
# list, and with 2 ranks the bond to 2 is evaluated on the other rank


TIE_SITES = [(0.25, 0.0), (1.25, 0.0), (-0.75, 0.0)]
TIE_BONDS = [(0, 2), (1, 0)]    # stored by atom 1 and by atom 2
TIE_U = 0.0078125


def tie(build, directory, nprocs=1, newton="on", extra_args=()):
    data = beam2d.beam_data(directory / "tie.data", TIE_SITES, TIE_BONDS, ((-2, 3), (-2, 2)))
    script = beam2d.header(data, newton=newton) + f"""
bond_style      beam
bond_coeff      1 {E_} {A_} {I_} break 0.2 0.2 criterion particle
run             0 post no
group           two id 2
group           three id 3
displace_atoms  two move {TIE_U} 0 0
displace_atoms  three move {-TIE_U} 0 0
run             0 post no
write_dump      all custom decided.dump id {STATE} modify format float %.17g
run             1 post no
write_data      after.data
"""
    build.run(script, directory, nprocs=nprocs, extra_args=extra_args)
    return read_dump(directory / "decided.dump")[0]


def check_tie(snap, directory, name):
    partner = snap["f_BEAM_STATE[3]"]
    print(f"{name}: candidates {partner}, bonds left {bond_pairs(directory / 'after.data')}")
    # equal measures: the partner of lower ID; particle 1 alone fails
    # (two bonds: 4 times the ellipse of 2 and 3, 2.01 against 0.50)
    assert list(partner) == [2, 1, 1]
    assert bond_pairs(directory / "after.data") == {(0, 2)}


@pytest.mark.parametrize("nprocs,newton", [(1, "on"), (2, "on"), (2, "off")])
def test_a_tie_goes_to_the_lower_partner_id(build, tmp_path, nprocs, newton):
    check_tie(tie(build, tmp_path, nprocs, newton), tmp_path, f"{nprocs} ranks, newton {newton}")


# ---------------------------------------------------------------------------
# a periodic hexagonal lattice of touching discs (r = L / 2) under a
# biaxial strain eps: every bond carries N = E A eps, a particle's six
# bonds sum to W = -(3/2) N L 1, so sigma_m = 3 N L / (2 pi r^2) =
# 6 N L / (pi L^2) per unit L, and no shear


EPS_STAR = 0.01


def lattice(build, directory, eps, sigma0, extra_args=()):
    nx, ny = 6, 4
    sites = []
    for j in range(ny):
        for i in range(nx):
            sites.append((i, j * math.sqrt(3.0)))
            sites.append((i + 0.5, (j + 0.5) * math.sqrt(3.0)))
    sites = np.array(sites) + 0.25
    lx, ly = nx, ny * math.sqrt(3.0)
    bonds = set()
    for a in range(len(sites)):
        for b in range(a + 1, len(sites)):
            d = sites[b] - sites[a]
            d -= np.array([lx, ly]) * np.round(d / np.array([lx, ly]))
            if np.hypot(*d) < 1.01:
                bonds.add((a, b))
    data = beam2d.beam_data(directory / "lattice.data", sites, sorted(bonds), ((0, lx), (0, ly)),
                            radius=1.0)
    script = beam2d.header(data, "p p p") + f"""
bond_style      beam
bond_coeff      1 {E_} {A_} {I_} break {sigma0!r} 1.0 criterion particle
thermo_style    custom step bonds
run             0 post no
change_box      all x scale {1.0 + eps!r} y scale {1.0 + eps!r} remap
run             0 post no
write_dump      all custom decided.dump id {STATE} modify format float %.17g
write_data      decided.data
run             1 post no
write_data      after.data
"""
    build.run(script, directory, extra_args=extra_args)
    return read_dump(directory / "decided.dump")[0], sorted(bonds)


def lattice_sigma(eps):
    return 6.0 * E_ * A_ * eps * (1.0 + eps) / math.pi


@pytest.mark.parametrize("factor", [0.99, 1.01])
def test_hexagonal_lattice_fails_at_its_mean_stress(build, tmp_path, factor):
    sigma0 = lattice_sigma(EPS_STAR)
    eps = factor * EPS_STAR
    snap, bonds = lattice(build, tmp_path, eps, sigma0)
    sigma, tau = snap["f_BEAM_STATE[1]"], snap["f_BEAM_STATE[2]"]
    expected = lattice_sigma(eps)
    print(f"eps {eps}: sigma_m {sigma.min():.15g} to {sigma.max():.15g} (analytic "
          f"{expected:.15g}), sqrt(J2) <= {tau.max():.1e}")
    # the lattice's sites and the strain carry round-off of 1e-16 against a
    # strain of 1e-2
    assert np.allclose(sigma, expected, rtol=1e-12, atol=0.0)
    assert tau.max() < 1e-12 * expected
    before = bond_pairs(tmp_path / "decided.data")
    after = bond_pairs(tmp_path / "after.data")
    assert before == set(bonds)    # the decision takes effect at the next evaluation
    if factor < 1.0:
        assert after == before
        return
    partner = snap["f_BEAM_STATE[3]"].astype(int) - 1
    chosen = {tuple(sorted((p, int(q)))) for p, q in enumerate(partner)}
    print(f"{len(bonds)} bonds, {len(chosen)} chosen by the {len(partner)} particles, "
          f"{len(after)} left")
    # every particle fails and loses its candidate (a bond chosen from both ends once)
    assert after == set(bonds) - chosen
    assert len(partner) / 2 <= len(chosen) <= len(partner)


# ---------------------------------------------------------------------------
# a strip torn by the particle criterion (test_bond_beam.py's strip: the
# right edge pulled, strengths scattered from bond to bond): the decisions
# and their one-step lag are the same on any number of ranks, with
# newton_bond off, and across a restart (the run after it decides again
# at its setup, from the state the decisions were made in)


STRIP = f"{E_} {A_} {I_} break 0.1 0.1 scatter uniform 0.3 77 criterion particle"


def step_before_a_break(build, directory):
    """A step after which the strip's next step breaks bonds (decisions
    pending at its end), from a run printing every step."""
    thermo, _ = beam2d.strip_run(build, directory, coeff=STRIP,
                                 tail="thermo 1\nrun 2000\n" + beam2d.WRITE_FINAL)
    steps, bonds = thermo["Step"].astype(int), thermo["Bonds"]
    breaking = steps[1:][np.diff(bonds) < 0]
    later = breaking[breaking > 800]
    assert len(later) > 0
    return int(later[0]) - 1


def test_torn_strip_is_the_same_on_ranks_newton_and_restart(build, tmp_path):
    split = step_before_a_break(build, tmp_path / "probe")
    thermo, _ = beam2d.strip_on_ranks_newton_and_restart(build, tmp_path, STRIP, split)
    bonds = thermo["Bonds"]
    print(f"bonds {bonds[0]:.0f} -> {bonds[-1]:.0f}; split at step {split}, before a break")
    # two runs in one input, split there: the second run's setup decides
    # again and breaks nothing (applying the first run's last decisions
    # there would break them a step early)
    ref = beam2d.strip_run(build, tmp_path / "ref2", coeff=STRIP)
    twice = beam2d.strip_run(build, tmp_path / "twice", coeff=STRIP,
                             tail=f"run {split}\nrun {2000 - split}\n" + beam2d.WRITE_FINAL)
    beam2d.compare_strips(ref, twice, f"two runs split at step {split}")


# ---------------------------------------------------------------------------
# Kokkos: the same sums (atomic), candidates (largest measure, then lowest
# partner ID, in a second pass) and decisions


@pytest.mark.parametrize("threads", [1, 2])
def test_kokkos_t_and_scenes_match_the_cpu_style(tmp_path, threads):
    kk = mcatest.kokkos_build()
    args = mcatest.kokkos_args(threads)
    ref = t_shape(kk, tmp_path / "cpu")
    dev = t_shape(kk, tmp_path / "kk", extra_args=args)
    for column in STATE.split():
        assert np.allclose(dev[column], ref[column], rtol=1e-14, atol=0.0), column
    assert bond_pairs(tmp_path / "kk" / "after.data") == bond_pairs(tmp_path / "cpu" / "after.data")
    for dim in (2, 3):
        cpu, _ = deformed(kk, tmp_path / f"cpu{dim}", dim)
        dev, _ = deformed(kk, tmp_path / f"kk{dim}", dim, extra_args=args)
        worst = max(np.abs(dev[c] - cpu[c]).max() / np.abs(cpu[c]).max() for c in STATE.split())
        print(f"kk, {threads} thread(s), {dim}-D: largest relative difference {worst:.1e}")
        # the sums in another order on two threads; candidates exactly
        assert worst < 1e-12
        assert np.array_equal(dev["f_BEAM_STATE[3]"], cpu["f_BEAM_STATE[3]"])


@pytest.mark.parametrize("threads", [1, 2])
def test_kokkos_tie_goes_to_the_lower_partner_id(tmp_path, threads):
    kk = mcatest.kokkos_build()
    check_tie(tie(kk, tmp_path, extra_args=mcatest.kokkos_args(threads)), tmp_path,
              f"kk, {threads} thread(s)")


def test_kokkos_strip_tears_as_the_cpu_style(tmp_path):
    kk = mcatest.kokkos_build()
    ref = beam2d.strip_run(kk, tmp_path / "cpu", coeff=STRIP)
    beam2d.compare_strips(ref, beam2d.strip_run(kk, tmp_path / "kk", coeff=STRIP,
                                                extra_args=mcatest.kokkos_args(2)),
                          "kk 2 threads")


# ---------------------------------------------------------------------------
# input


def test_data_file_keeps_the_criterion(build, tmp_path):
    t_shape(build, tmp_path)
    text = (tmp_path / "after.data").read_text()
    coeffs = text[text.index("Bond Coeffs"):].split("\n\n")[1]
    print(coeffs)
    assert coeffs.strip() == f"1 100 {A_:.17g} 0.001 break {SIGMA0:.17g} 1 criterion particle"
    again = """
units           lj
dimension       2
atom_style      mca
bond_style      beam
read_data       after.data
write_data      again.data
"""
    build.run(again, tmp_path)
    text = (tmp_path / "again.data").read_text()
    assert text[text.index("Bond Coeffs"):].split("\n\n")[1] == coeffs


BAD = [
    ("without break", "bond_coeff 1 1.0 0.1 0.001 criterion particle",
     r"bending, mohr, scatter and criterion need the break keyword"),
    ("kind", "bond_coeff 1 1.0 0.1 0.001 break 1 1 criterion voronoi",
     r"criterion voronoi is unknown \(allowed: bond, particle\)"),
    ("missing", "bond_coeff 1 1.0 0.1 0.001 break 1 1 criterion",
     r"[Mm]issing argument|Illegal"),
    ("radius 0", "set atom 1 diameter 0.0\nbond_coeff 1 1.0 0.1 0.001 break 1 1 criterion particle",
     r"a bond of type 1 \(criterion particle\) joins a particle of radius 0"),
]


@pytest.mark.parametrize("case", BAD, ids=[c[0] for c in BAD])
def test_bad_criterion_input_gives_clear_errors(build, tmp_path, case):
    beam2d.expect_error(build, tmp_path, 2, case[1], case[2])


# ---------------------------------------------------------------------------
# the example examples/beam_particle_criterion at a reduced size: a
# periodic lattice (h/L = 0.3 from the radii, sigma0 = tau0 = 0.2) under
# uniaxial strain breaks first where the analytic lattice does


EXAMPLE = mcatest.ROOT / "examples" / "beam_particle_criterion"


def first_break(build, directory, criterion, rate):
    script = (EXAMPLE / "in.uniaxial").read_text()
    build.run(script, directory, extra_args=["-var", "criterion", criterion, "-var", "nx", "6",
                                             "-var", "ny", "4", "-var", "rate", str(rate),
                                             "-var", "final", "0.0065"])
    text = (directory / "log.lammps").read_text()
    words = text[text.index("\nfirst break: step"):].split()
    return int(words[3]), float(words[5])


def particle_failure_strain():
    """The strain at which a particle of the lattice under uniaxial strain
    reaches the ellipse: its six bonds (0, 60, ..., 300 degrees) mapped by
    diag(1 + eps, 1), the particles unturned (a Bravais lattice), the
    element of h = 0.3, bisected."""
    h = 0.3
    volume = math.pi * 0.25

    def measure(eps):
        w = np.zeros((2, 2))
        for k in range(6):
            a0 = k * math.pi / 3
            tip = [(1 + eps) * math.cos(a0), math.sin(a0)]
            d, f, _, _ = element_2d([0.0, 0.0], tip, 0.0, 0.0, a0, 1.0, 100.0, h, h ** 3 / 12)
            w += 0.25 * (np.outer(d, f) + np.outer(f, d))
        return ellipse(*invariants(w, volume), 0.2, 0.2)

    lo, hi = 0.0, 0.02
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if measure(mid) < 1.0 else (lo, mid)
    return hi


def test_uniaxial_example_breaks_at_the_analytic_strain(build, tmp_path):
    rate = 0.0013
    delta = rate * 0.001    # strain per step
    step, strain = first_break(build, tmp_path / "bond", "bond", rate)
    # the bonds along x: N / A = E eps = sigma0 (no shear: they do not
    # turn), broken at the step whose forces reach it; the forces of a step
    # see the box of the step before (fix deform changes it at the end of
    # a step, after the forces)
    star = 0.2 / 100.0
    print(f"bond: first break at step {step}, strain {strain:.9g} (sigma0 / E = {star})")
    assert strain - 2 * delta < star <= strain - delta + 1e-12
    step, strain = first_break(build, tmp_path / "particle", "particle", rate)
    star = particle_failure_strain()
    print(f"particle: first break at step {step}, strain {strain:.9g}; the lattice's particle "
          f"reaches the ellipse at {star:.9g}: decided at step {step - 1} (its forces at "
          f"strain {strain - 2 * delta:.9g})")
    # decided at the step whose forces reach it, broken at the next
    assert strain - 3 * delta < star <= strain - 2 * delta + 1e-12
