"""bond_style beam: stochastic melting and re-freezing (keywords melt,
refreeze; doc/src/bond_beam.rst; digest A.8, requirement R4, reference
case 16).

A bond melts during a step dt with probability P = 1 - exp(-lambda dt),
lambda a constant rate or Glen's lambda = 2 A E^2 U / L0^d; the draw is a
hash of the seed, the two atom IDs and the step.  The hash is written out
again here (melts() below), so the tests know which bond melts at which
step:

* dimers at rest (constant rate) and stretched dimers of two strains
  (Glen: lambda from their energy U = EA u^2 / 2 L0): the bond count after
  every step is the one the hash predicts, exactly; the same on 2 ranks,
  with newton_bond off, continued from a restart file, and with the kk
  variant on 1 and 2 threads.  The predicted survivals follow
  exp(-lambda t) within 4 standard deviations of the binomial count (the
  draws are uniform and independent);
* re-freezing (refreeze): chains pulled by a constant force F, damped
  (quasi-static).  A melted bond freezes again stress-free at its
  stretched length, so each event lengthens its bond's rest length by the
  elastic strain F / EA: settled at the end, each chain is longer by the
  predicted events times that strain (to the transients between events:
  measured below); the bonds beyond the capture distance break instead;
* Glen's law (case 16) at reduced size: the chains' creep under F and 2F
  with melt glen: the events come at the rate lambda(F) = A E F^2 / (A_s
  L0) (4 standard deviations of the Poisson count), and the creep rate
  lambda F / EA grows as F^3: the exponent n = 3 (the digest's fitted
  slope b = 2 is that of the fluidity, 1 / mu ~ sigma^2);
* the example examples/beam_glen (case 16 in a sheared lattice) at
  reduced size: elastic shear strain tau / mu, creep rate ~ tau^3;
* a melted bond that freezes again is stress-free (2-D patch, 3-D
  cluster, CPU and kk): energy and forces vanish to round-off;
* bad input gives clear errors; write_data and restart files keep the
  keywords.
"""

import importlib.util
import math
import re
import sys

import numpy as np
import pytest

import mcatest
import test_bond_beam as beam2d
import test_bond_beam_3d as beam3d
from mcatest import read_dump
from test_bond_beam import beam_data, expect_error, header

M64 = (1 << 64) - 1
E_, A_, I_ = 100.0, 0.1, 0.001    # EA = 10


def mix64(z):
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & M64
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & M64
    return z ^ (z >> 31)


def bond_hash(seed, lo, hi):
    z = (seed * 0x9E3779B97F4A7C15) & M64
    z ^= (lo + 0x632BE59BD9B4E019 + ((z << 6) & M64) + (z >> 2)) & M64
    z ^= (hi + 0x85157AF5 + ((z << 6) & M64) + (z >> 2)) & M64
    return mix64(z)


def melts(seed, lo, hi, step, rate, dt):
    """BeamKernels::melts: whether bond (lo, hi) melts at `step`."""
    z = bond_hash(seed, lo, hi)
    z ^= (step + 0x2545F4914F6CDD1D + ((z << 6) & M64) + (z >> 2)) & M64
    u = ((mix64(z) >> 11) + 0.5) / 9007199254740992.0
    return u < -math.expm1(-rate * dt)


def first_melt(seed, lo, hi, steps, rate, dt):
    for step in range(1, steps + 1):
        if melts(seed, lo, hi, step, rate, dt):
            return step
    return steps + 1


# ---------------------------------------------------------------------------
# dimers: every bond on its own, no integrator (the atoms stay put)

NCOL, NROW = 15, 20    # 300 dimers, atom IDs 2k + 1, 2k + 2
DT, STEPS, SEED = 0.01, 400, 4242
RATE = 0.5
GLEN_A, STRAIN = 0.025, 0.01    # lambda = 10 A (u / 0.01)^2 at L0 = 1: 0.25 and 1.0


def dimer_data(directory):
    sites = []
    for r in range(NROW):
        for c in range(NCOL):
            sites += [(3.0 * c, 3.0 * r), (3.0 * c + 1.0, 3.0 * r)]
    bonds = [(2 * k, 2 * k + 1) for k in range(NCOL * NROW)]
    return beam_data(directory / "dimers.data", sites, bonds, ((-1, 3 * NCOL), (-1, 3 * NROW)))


def dimer_strain(k, glen):
    """The strain of dimer k: none (constant rate), or 1 and 2 times STRAIN."""
    return STRAIN * (1 + k % 2) if glen else 0.0


def dimer_rate(k, glen):
    if not glen:
        return RATE
    u = dimer_strain(k, glen)    # L0 = 1
    energy = 0.5 * E_ * A_ * u * u
    return 2.0 * GLEN_A * E_ * E_ * energy


def dimer_script(data, glen, newton="on", steps=STEPS, tail=""):
    melt = f"glen {GLEN_A}" if glen else f"rate {RATE}"
    script = header(data, newton=newton) + f"""
bond_style      beam
bond_coeff      1 {E_} {A_} {I_} melt {melt} {SEED}
thermo_style    custom step bonds
thermo_modify   norm no
thermo          1
timestep        {DT}
"""
    if glen:
        # the references at rest (a run's setup melts nothing), then each
        # dimer's second atom moved by its strain
        script += f"""run 0 post no
variable        dx atom "(id%2==0)*{STRAIN}*(1+(floor((id-1)/2)%2))"
displace_atoms  all move v_dx 0.0 0.0
"""
    return script + (tail or f"run {steps}\n")


def predicted_counts(glen, steps=STEPS):
    first = np.array([first_melt(SEED, 2 * k + 1, 2 * k + 2, steps, dimer_rate(k, glen), DT)
                      for k in range(NCOL * NROW)])
    return np.array([np.sum(first > s) for s in range(1, steps + 1)]), first


def measured_counts(directory):
    """Bonds after each step of the log's runs (the setup rows left out)."""
    text = (directory / "log.lammps").read_text()
    rows = {}
    for block in re.findall(r"^\s*Step\s+Bonds\s*\n(.*?)^Loop", text, re.M | re.S):
        for line in block.strip().splitlines():
            step, bonds = line.split()
            rows[int(step)] = int(bonds)
    return np.array([rows[s] for s in range(1, STEPS + 1)])


def assert_predicted(directory, glen, name):
    expected, _ = predicted_counts(glen)
    got = measured_counts(directory)
    print(f"{name}: bonds {got[0]} after step 1, {got[-1]} after step {STEPS} "
          f"(predicted {expected[0]}, {expected[-1]}); steps that differ: "
          f"{int(np.sum(got != expected))}")
    assert np.array_equal(got, expected)


@pytest.mark.parametrize("glen", [False, True], ids=["rate", "glen"])
def test_dimers_melt_at_the_steps_the_hash_gives(build, tmp_path, glen):
    data = dimer_data(tmp_path)
    build.run(dimer_script(data, glen), tmp_path / "one")
    assert_predicted(tmp_path / "one", glen, "1 rank")
    build.run(dimer_script(data, glen, newton="off"), tmp_path / "two", nprocs=2)
    assert_predicted(tmp_path / "two", glen, "2 ranks, newton_bond off")
    build.run(dimer_script(data, glen), tmp_path / "four", nprocs=4)
    assert_predicted(tmp_path / "four", glen, "4 ranks")
    build.run(dimer_script(data, glen, tail=f"run {STEPS // 2}\nwrite_restart half.restart\n"),
              tmp_path / "split")
    build.run(f"""
units           lj
dimension       2
read_restart    half.restart
comm_modify     cutoff 2.5
thermo_style    custom step bonds
thermo_modify   norm no
thermo          1
run             {STEPS // 2}
""", tmp_path / "split", name="in.continue")
    halves = (tmp_path / "split" / "log.lammps").read_text()
    expected, _ = predicted_counts(glen)
    rows = re.findall(r"^\s*(\d+)\s+(\d+)\s*$", halves, re.M)
    second = {int(s): int(b) for s, b in rows if int(s) > STEPS // 2}
    assert [second[s] for s in range(STEPS // 2 + 1, STEPS + 1)] == list(expected[STEPS // 2:])


def test_melting_survival_follows_the_exponential_law():
    """The predicted first melts (the model's draws) against exp(-lambda
    t): uniform, independent draws give a binomial count of survivors."""
    for glen in (False, True):
        counts_first = predicted_counts(glen)[1]
        for group in ((0, 1) if glen else (None,)):
            ks = [k for k in range(NCOL * NROW) if group is None or k % 2 == group]
            rate = dimer_rate(ks[0], glen)
            for step in (50, 100, 200, 400):
                n = len(ks)
                p = math.exp(-rate * DT * step)
                alive = sum(1 for k in ks if counts_first[k] > step)
                sd = math.sqrt(n * p * (1 - p))
                print(f"lambda {rate}: t = {step * DT}: {alive} of {n} left, "
                      f"expected {n * p:.1f} +- {sd:.1f}")
                assert abs(alive - n * p) < 4.0 * sd + 1.0


@pytest.mark.parametrize("glen", [False, True], ids=["rate", "glen"])
def test_kokkos_dimers_melt_as_the_cpu_style(tmp_path, glen):
    kk = mcatest.kokkos_build()
    data = dimer_data(tmp_path)
    for threads in mcatest.kokkos_thread_counts():
        d = tmp_path / f"kk{threads}"
        kk.run(dimer_script(data, glen), d, extra_args=mcatest.kokkos_args(threads))
        assert_predicted(d, glen, f"kk {threads} threads")


# ---------------------------------------------------------------------------
# re-freezing is stress-free: a deformed patch (2-D) and cluster (3-D)


def frozen_scene(build, directory, dim, capture, extra_args=()):
    """The deformed scene of the beam tests, then one step at which every
    bond melts (P = 1 - exp(-1e3) = 1) and freezes again if not longer than
    `capture`, then run 0 without melting: (energy and forces before, after,
    bonds left, the deformed bond lengths)."""
    mod = beam2d if dim == 2 else beam3d
    if dim == 2:
        sites, bonds = beam2d.hex_patch()
        data = beam2d.beam_data(directory / "scene.data", sites, bonds, ((-6, 6), (-6, 6)))
        coeff = f"{E_} {A_} {I_}"
    else:
        sites, bonds = beam3d.cluster()
        data = beam3d.beam_data(directory / "scene.data", sites, bonds,
                                ((-3, 3), (-3, 3), (-3, 3)))
        coeff = beam3d.BEAM
    columns = "id x y z fx fy fz tqx tqy tqz"
    script = mod.header(data) + f"bond_style beam\nbond_coeff 1 {coeff}\n" + mod.DEFORM + f"""
thermo_style    custom step pe ebond bonds
thermo_modify   norm no format float %.17g
run             0 post no
write_dump      all custom before.dump {columns} modify format float %.17g
bond_coeff      1 {coeff} melt rate 1.0e6 5 refreeze {capture}
timestep        0.001
run             1 post no
bond_coeff      1 {coeff}
run             0 post no
write_dump      all custom after.dump {columns} modify format float %.17g
"""
    build.run(script, directory, extra_args=extra_args)
    blocks = re.findall(r"^\s*Step\s+PotEng\s+E_bond\s+Bonds\s*\n(.*?)^Loop",
                        (directory / "log.lammps").read_text(), re.M | re.S)
    first, last = blocks[0].split(), blocks[-1].split()
    before, after = read_dump(directory / "before.dump")[0], read_dump(directory / "after.dump")[0]
    pos = np.stack([before[c] for c in ("x", "y", "z")], axis=1)
    lengths = np.array([np.linalg.norm(pos[j] - pos[i]) for i, j in bonds])
    return (float(first[2]), float(last[2]), int(last[3]), before, after, lengths)


def force_size(snap):
    return max(np.abs(snap[c]).max() for c in ("fx", "fy", "fz", "tqx", "tqy", "tqz"))


@pytest.mark.parametrize("dim", [2, 3])
def test_a_melted_bond_freezes_again_stress_free(build, tmp_path, dim):
    """Every bond of a deformed scene melts and freezes again: the energy
    and the forces and torques vanish to round-off of the deformed ones
    (1e-12); with a capture distance between the bond lengths, the
    bonds longer than it break and the others freeze (their count
    exactly)."""
    energy, frozen, left, before, after, lengths = frozen_scene(build, tmp_path / "all", dim,
                                                                 capture=2.0)
    print(f"{dim}-D: energy {energy:.3e} -> {frozen:.1e}, forces {force_size(before):.3e} -> "
          f"{force_size(after):.1e}, {left} of {len(lengths)} bonds left")
    assert energy > 1e-3 and left == len(lengths)
    assert abs(frozen) < 1e-12 * energy and force_size(after) < 1e-12 * force_size(before)
    capture = float(np.median(lengths))
    _, frozen, left, _, after, _ = frozen_scene(build, tmp_path / "some", dim, capture)
    print(f"capture {capture:.6f}: {left} bonds left (expected {np.sum(lengths <= capture)})")
    assert left == np.sum(lengths <= capture) and abs(frozen) < 1e-12 * energy


def test_kokkos_melted_bonds_freeze_again_stress_free(tmp_path):
    kk = mcatest.kokkos_build()
    for dim in (2, 3):
        for threads in mcatest.kokkos_thread_counts():
            energy, frozen, left, before, after, lengths = frozen_scene(
                kk, tmp_path / f"{dim}d{threads}", dim, 2.0,
                extra_args=mcatest.kokkos_args(threads))
            print(f"kk {threads} threads, {dim}-D: energy {energy:.3e} -> {frozen:.1e}, "
                  f"forces -> {force_size(after):.1e}")
            assert left == len(lengths) and abs(frozen) < 1e-12 * energy
            assert force_size(after) < 1e-12 * force_size(before)


# ---------------------------------------------------------------------------
# chains pulled by a constant force: re-freezing and Glen's law

NCHAIN, NBOND = 40, 10
CHAIN_DT = 0.05
GAMMA = 1.0    # nve/damped: the slowest mode relaxes in about 3 time units


def chain_data(directory):
    sites = [(float(i), 3.0 * r) for r in range(NCHAIN) for i in range(NBOND + 1)]
    bonds = [(r * (NBOND + 1) + i, r * (NBOND + 1) + i + 1)
             for r in range(NCHAIN) for i in range(NBOND)]
    return beam_data(directory / "chains.data", sites, bonds,
                     ((-1, 3 * NBOND), (-1, 3 * NCHAIN)))


def chain_script(data, melt, force, steps, newton="on", settle=3000, tail=""):
    """Chains with their first atom held, their last pulled by `force`:
    settle, `steps` with melting, settle again without it (the final
    lengths at rest); dump of the settled state."""
    plain = f"bond_coeff      1 {E_} {A_} {I_}"
    script = header(data, newton=newton) + f"""
bond_style      beam
{plain}
variable        root atom "x < 0.5"
variable        tip atom "x > {NBOND - 0.5}"
group           root variable root
group           tip variable tip
group           mobile subtract all root
fix             1 mobile nve/damped {GAMMA}
fix             2 all enforce2d
fix             3 tip addforce {force} 0.0 0.0
timestep        {CHAIN_DT}
thermo_style    custom step bonds
thermo_modify   norm no
thermo          1000
run             {settle}
{plain} {melt}
run             {steps}
"""
    return script + (tail or f"""{plain}
run             {settle}
write_dump      all custom settled.dump id x y modify sort id format float %.17g
""")


def settled_lengths(directory):
    """Each chain's settled length (tip x - root x)."""
    state = read_dump(directory / "settled.dump")[-1]
    x = state["x"][np.argsort(state["id"])]
    x = x.reshape(NCHAIN, NBOND + 1)
    return x[:, -1] - x[:, 0]


def chain_events(seed, rate, dt, first_step, steps):
    """Events per chain of a constant rate in the steps
    first_step .. first_step + steps - 1."""
    events = np.zeros(NCHAIN, dtype=int)
    for r in range(NCHAIN):
        for i in range(NBOND):
            lo = r * (NBOND + 1) + i + 1
            events[r] += sum(melts(seed, lo, lo + 1, s, rate, dt)
                             for s in range(first_step, first_step + steps))
    return events


def test_refrozen_bonds_creep_by_the_elastic_strain(build, tmp_path):
    """melt rate with refreeze: every event lengthens the rest length of
    its bond by the strain eps = F / EA of the (quasi-static) chain; the
    settled chain is (1 + eps) times the sum of the rest lengths.  The
    events are those of the hash (a constant rate: independent of the
    state).  Tolerance: an event that comes while the chain still moves
    after an earlier one (the slowest mode relaxes in 3 time units; the
    events of a chain are 1 / (10 lambda) = 50 apart on average) freezes
    another strain; measured below.  With a capture distance shorter than
    the stretched bonds they break instead."""
    rate, force, steps, seed = 0.002, 0.1, 6000, 77
    eps = force / (E_ * A_)
    data = chain_data(tmp_path)
    build.run(chain_script(data, f"melt rate {rate} {seed} refreeze 1.5", force, steps), tmp_path)
    length = settled_lengths(tmp_path)
    events = chain_events(seed, rate, CHAIN_DT, 3001, steps)
    # each event multiplies one rest length (about 1) by 1 + eps
    measured = (length / (1.0 + eps) - NBOND) / eps
    print(f"events per chain {events.min()}..{events.max()} (total {events.sum()}); "
          f"measured from the lengths {measured.sum():.3f}; largest difference of a chain "
          f"{np.abs(measured - events).max():.3f}")
    assert events.sum() > 100
    # the rest lengths grow as (1 + eps)^k: k events give k + O(k^2 eps / 2 NBOND)
    assert abs(measured.sum() - events.sum()) < 0.02 * events.sum()
    assert np.abs(measured - events).max() < 1.0

    # a capture distance below the stretched length 1 + eps: the first event
    # of a chain breaks its bond; later ones find the chain slack or moving
    build.run(chain_script(data, f"melt rate {rate} {seed} refreeze 1.005", force, 400,
                           tail="print done\n"), tmp_path / "break")
    thermo = mcatest.read_thermo(tmp_path / "break" / "log.lammps")
    events = chain_events(seed, rate, CHAIN_DT, 3001, 400)
    broken = int(thermo["Bonds"][0] - thermo["Bonds"][-1])
    print(f"capture 1.005: {broken} broken; events {events.sum()} in "
          f"{np.count_nonzero(events)} chains")
    assert 0 < np.count_nonzero(events) <= broken <= events.sum()


def glen_creep(build, directory, force, glen_a, steps, extra_args=(), nprocs=1, newton="on"):
    data = chain_data(directory)
    script = chain_script(data, f"melt glen {glen_a} 99 refreeze 1.5", force, steps,
                          newton=newton)
    if nprocs == 2:
        # the ranks split the chains: bonds between owned and ghost atoms
        script = script.replace("read_data", "processors 2 1 1\nread_data")
    build.run(script, directory, extra_args=extra_args, nprocs=nprocs)
    eps = force / (E_ * A_)
    length = settled_lengths(directory)
    return np.log(length / (1.0 + eps) / NBOND) / math.log(1.0 + eps) * NBOND, length


# lambda = 5e-4 per time at F = 0.1, 2e-3 at 0.2 (the events of a chain 50
# time units apart, 17 relaxation times)
GLEN_CHAIN_A = 5.0e-5


def test_glen_creep_rate_grows_as_the_cube_of_the_stress(build, tmp_path):
    """Case 16 at reduced size.  Under F the bonds melt at lambda = 2 A E^2
    U / L0^2 with U = F^2 L0 / (2 EA): lambda = A E F^2 / (A L0); each event
    adds the strain F / EA, so the chains creep at lambda F / EA = A F^3 /
    (A^2 L0), Glen's law with n = 3.  The events, counted from the settled
    lengths, against the expected count (L0 grows with the events:
    lambda ~ 1 / L0, integrated as the mean; a Poisson count, 4 standard
    deviations), and the exponent from F and 2F within 0.25 of 3."""
    glen_a, steps = GLEN_CHAIN_A, 24000
    counts = {}
    for force in (0.1, 0.2):
        events, _ = glen_creep(build, tmp_path / f"f{force}", force, glen_a, steps)
        eps = force / (E_ * A_)
        rate0 = glen_a * E_ * force * force / A_    # at L0 = 1
        t = steps * CHAIN_DT
        # mean rest length y = (1 + eps)^k: dy/dt = rate0 ln(1 + eps) (lambda ~ 1 / L0)
        expected = NCHAIN * NBOND * math.log1p(rate0 * t * math.log1p(eps)) / math.log1p(eps)
        total = events.sum()
        counts[force] = total
        print(f"F = {force}: {total:.1f} events (creep rate {total * eps / (NCHAIN * NBOND * t):.3e}"
              f" per time), expected {expected:.1f} +- {math.sqrt(expected):.1f}")
        assert abs(total - expected) < 4.0 * math.sqrt(expected)
    exponent = 1.0 + math.log(counts[0.2] / counts[0.1]) / math.log(2.0)
    print(f"creep rate ~ F^{exponent:.3f}")
    assert abs(exponent - 3.0) < 0.25


# a faster Glen scene for the comparisons (the events a few relaxation times apart)
GLEN_FAST = dict(force=0.2, glen_a=1.0e-3, steps=4000)


def compare_creep(build, tmp_path, runs):
    """Melting with re-freezing under Glen's law (the rates follow the
    state: a difference in the forces could change a decision): the
    settled lengths of each run against one rank's, to 1e-9 of a length
    (round-off carried through the events)."""
    events, ref = glen_creep(build, tmp_path / "ref", **GLEN_FAST)
    assert events.sum() > 100
    for name, options in runs:
        _, other = glen_creep(build, tmp_path / re.sub(r"\W+", "_", name), **GLEN_FAST,
                              **options)
        diff = np.abs(other - ref).max()
        print(f"{name}: settled lengths differ by {diff:.1e} ({events.sum():.0f} events)")
        assert diff < 1e-9


def test_refreezing_chains_are_the_same_on_ranks_and_newton(build, tmp_path):
    compare_creep(build, tmp_path, [("2 ranks", dict(nprocs=2)),
                                    ("4 ranks", dict(nprocs=4)),
                                    ("newton_bond off", dict(newton="off")),
                                    ("2 ranks, newton_bond off", dict(nprocs=2, newton="off"))])


def test_kokkos_refreezing_chains_follow_the_cpu_style(tmp_path):
    kk = mcatest.kokkos_build()
    compare_creep(kk, tmp_path, [(f"kk {t} threads", dict(extra_args=mcatest.kokkos_args(t)))
                                 for t in mcatest.kokkos_thread_counts()])


# ---------------------------------------------------------------------------
# the example examples/beam_glen at reduced size (12 x 6 cells, 500 time
# units of creep; the example: 24 x 12, 1000, five stresses)

EXAMPLE = mcatest.ROOT / "examples" / "beam_glen"


def test_glen_example_creeps_with_exponent_three(build, tmp_path):
    """A sheared hexagonal beam lattice (h/L = 0.3 from the radii) under
    tau = 0.1 and 0.2: before melting its shear strain is tau / mu with
    the lattice's mu = (sqrt3/4)(k_n + k_s) (reference case 7; 2 %: the
    held and pulled rows), and its steady creep rate grows as tau^n with
    n within 0.3 of Glen's 3 (measured 2.92 here, 2.97 at full size: the
    events of a small layer are fewer)."""
    spec = importlib.util.spec_from_file_location("glen_plot", EXAMPLE / "plot.py")
    plot = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(plot)
    kn, ks = 100.0 * 0.3, 12.0 * 100.0 * 0.3 ** 3 / 12.0
    mu = math.sqrt(3.0) / 4.0 * (kn + ks)
    rates = {}
    for tau in (0.1, 0.2):
        d = tmp_path / f"tau{tau}"
        build.run((EXAMPLE / "in.glen").read_text(), d, name="in.glen",
                  variables={"tau": tau, "nx": 12, "ny": 6, "time": 500})
        t, elastic, rate = plot.creep_rate(d / "log.lammps")
        print(f"tau {tau}: elastic strain {elastic:.6g} (tau / mu {tau / mu:.6g}), creep rate "
              f"{rate:.4e}")
        assert abs(elastic / (tau / mu) - 1.0) < 0.02
        rates[tau] = rate
    exponent = math.log(rates[0.2] / rates[0.1]) / math.log(2.0)
    print(f"creep rate ~ tau^{exponent:.3f}")
    assert abs(exponent - 3.0) < 0.3


# ---------------------------------------------------------------------------
# the creep rate derived (tools/lattice_calibration.py glen_creep_prefactor):
# Levin's theorem for one event, and the elastic state's bond energies

def event_layer(build, directory, tau, angle):
    """The layer of examples/beam_glen at 12 x 6 cells under tau, settled;
    one interior bond at `angle` degrees to the shear direction (nearest
    the layer's centre) has type 2, which melts and freezes again at one
    step (melt rate 1000: P = 1 - 2e-9), then the layer settles again.
    Returns the bond's energy before the event, the shear strain before
    and after, the layer's area and every bond's energy before."""
    head = EXAMPLE.joinpath("in.glen").read_text()
    head = head[:head.index("# elastic: the layer settles")]
    head = head.replace("create_box      1 box bond/types 1", "create_box      1 box bond/types 2")
    head = head.replace("bond_coeff      1 100.0 radii 0.3\n", "bond_coeff      * 100.0 radii 0.3\n")
    variables = {"tau": tau, "nx": 12, "ny": 6}
    build.run(head + "write_dump all custom sites.dump id x y\n", directory / "sites",
              variables=variables)
    sites = read_dump(directory / "sites" / "sites.dump")[0]
    ids, x, y = sites["id"].astype(int), sites["x"], sites["y"]
    centre = np.array([x.mean(), 0.5 * (y.min() + y.max())])
    best = None
    for i in range(len(ids)):
        d = np.stack([x - x[i], y - y[i]], axis=1)
        for j in np.flatnonzero(np.abs(np.hypot(d[:, 0], d[:, 1]) - 1.0) < 1e-6):
            if abs(math.degrees(math.atan2(d[j, 1], d[j, 0])) - angle) > 1e-3:
                continue
            r = np.hypot(*(0.5 * np.array([x[i] + x[j], y[i] + y[j]]) - centre))
            if best is None or r < best[0]:
                best = (r, ids[i], ids[j])
    a, b = best[1], best[2]
    script = head.replace("bond_style      beam", f"""group           event id {a} {b}
delete_bonds    event bond 1 remove special
create_bonds    single/bond 2 {a} {b}
bond_style      beam""") + """
thermo_style    custom step time v_strain bonds pe ke
thermo_modify   norm no format float %.15g
thermo          5000
run             15000
print           "before $(v_strain:%.17g) area $(v_height*lx:%.17g)"
compute         be all property/local batom1 batom2 btype
compute         bu all bond/local engpot
dump            be all local 1 bonds.local c_be[3] c_bu
dump_modify     be format float %.17g
run             0
undump          be
bond_coeff      2 100.0 radii 0.3 melt rate 1000.0 7 refreeze 1.2
run             1
bond_coeff      2 100.0 radii 0.3
run             15000
print           "after $(v_strain:%.17g)"
"""
    build.run(script, directory / "event", variables=variables)
    log = (directory / "event" / "log.lammps").read_text()
    before, area = map(float, re.search(r"^before (\S+) area (\S+)", log, re.M).groups())
    after = float(re.search(r"^after (\S+)", log, re.M).group(1))
    text = (directory / "event" / "bonds.local").read_text().split("ITEM: ENTRIES")[-1]
    rows = np.array([[float(w) for w in line.split()] for line in text.splitlines()[1:]])
    energy = rows[rows[:, 0] == 2, 1][0]
    return energy, before, after, area, rows[:, 1]


def calibration():
    sys.path.insert(0, str(mcatest.ROOT / "tools"))
    import lattice_calibration
    return lattice_calibration


@pytest.mark.parametrize("angle", [60, 0])
def test_a_frozen_bond_adds_the_strain_of_levins_theorem(build, tmp_path, angle):
    """At a fixed load, a bond that freezes again stress-free adds the
    macroscopic strain whose work is twice its elastic energy (Levin's
    theorem of eigenstrains, linear elasticity): tau A d(gamma) = 2 U_b,
    A the layer's area (lx times its height).  Measured on an interior
    bond of the glen example's layer, settled before and after (tolerance
    1 %: the co-rotational beams' nonlinearity at strain 0.007 and the
    settling; measured 0.05 % at 60 degrees, 0.2 % at 0 degrees, whose
    bond carries the bending energy only).  Its energy is the uniform
    lattice's L^2 e^2 (k_n sin^2 2 theta + k_s cos^2 2 theta) / 2, e =
    tau / 2 mu, to 2 % (the layer is not periodic in y)."""
    tau = 0.1
    energy, before, after, area, _ = event_layer(build, tmp_path, tau, angle)
    predicted = 2.0 * energy / (tau * area)
    measured = after - before
    kn, ks = 100.0 * 0.3, 12.0 * 100.0 * 0.3 ** 3 / 12.0
    e = tau / (2.0 * math.sqrt(3.0) / 4.0 * (kn + ks))
    th = math.radians(angle)
    uniform = 0.5 * e * e * (kn * math.sin(2 * th) ** 2 + ks * math.cos(2 * th) ** 2)
    print(f"{angle} degrees: U_b {energy:.6e} (uniform lattice {uniform:.6e}), strain added "
          f"{measured:.6e}, 2 U_b / (tau A) {predicted:.6e}, ratio {measured / predicted:.5f}")
    assert abs(measured / predicted - 1.0) < 0.01
    assert abs(energy / uniform - 1.0) < 0.02


def test_elastic_state_gives_the_glen_prefactor(build, tmp_path):
    """Summed over the bonds, Levin's theorem gives the creep rate at the
    start of melting: tau A gamma' = sum_b lambda_b 2 U_b = 4 A E^2
    sum_b U_b^2 / L^2.  From the settled layer's bond energies (12 x 6
    cells) that is the periodic lattice's k tau^3 of
    glen_creep_prefactor to 2 % (measured 1.1 %: the held and pulled
    rows), k = 19.42 A for h/L = 0.3; the example's layer (24 x 12) starts
    to creep at that rate (0.96-1.02 of it over the first 50-400 time
    units at tau = 0.1) and creeps steadily 21-27 % faster once the frozen
    bonds' rest states add residual stresses (its README)."""
    lc = calibration()
    tau, glen, e_beam = 0.1, 3.0e-4, 100.0
    _, _, _, area, energies = event_layer(build, tmp_path, tau, 60)
    from_state = 4.0 * glen * e_beam ** 2 * np.sum(energies ** 2) / (area * tau)
    kn, ks = lc.beam_stiffness(e_beam, 0.3, 0.3 ** 3 / 12.0, 1.0)
    k = lc.glen_creep_prefactor(kn, ks, e_beam, glen)
    print(f"creep rate from the elastic state {from_state:.5e} ({from_state / tau ** 3 / glen:.4f} "
          f"A tau^3); the periodic lattice's {k * tau ** 3:.5e} ({k / glen:.4f} A tau^3)")
    assert abs(from_state / (k * tau ** 3) - 1.0) < 0.02


# ---------------------------------------------------------------------------
# input

BAD = [
    ("rate", "bond_coeff 1 1.0 0.1 0.001 melt rate -1 5",
     r"melt rate lambda = -1 must be > 0"),
    ("glen", "bond_coeff 1 1.0 0.1 0.001 melt glen 0 5", r"melt glen A = 0 must be > 0"),
    ("kind", "bond_coeff 1 1.0 0.1 0.001 melt fast 1 5",
     r"melt fast is unknown \(allowed: rate, glen\)"),
    ("seed", "bond_coeff 1 1.0 0.1 0.001 melt rate 1 0", r"melt seed = 0 must be > 0"),
    ("args", "bond_coeff 1 1.0 0.1 0.001 melt rate 1", r"bond_coeff beam melt"),
    ("springs", "bond_coeff 1 shearbeam 10.0 0.05 melt glen 1 5",
     r"melt glen \(Glen's law needs the beam's E\) applies to beams"),
    ("refreeze", "bond_coeff 1 1.0 0.1 0.001 refreeze 1.2",
     r"refreeze needs the melt keyword"),
    ("capture", "bond_coeff 1 1.0 0.1 0.001 melt rate 1 5 refreeze 0",
     r"refreeze capture distance = 0 must be > 0"),
    ("respa", "bond_coeff 1 1.0 0.1 0.001 melt rate 1 5\nrun_style respa 2 2 bond 1 pair 2",
     r"with melt does not support run_style respa"),
]


@pytest.mark.parametrize("case", BAD, ids=[c[0] for c in BAD])
def test_bad_melting_input_gives_clear_errors(build, tmp_path, case):
    expect_error(build, tmp_path, 2, case[1], case[2])


def test_data_file_and_restart_keep_the_melting_keywords(build, tmp_path):
    data = dimer_data(tmp_path)
    words = "melt glen 0.025000000000000001 4242 refreeze 1.5"
    build.run(header(data) + f"""
bond_style      beam
bond_coeff      1 {E_} {A_} {I_} melt glen 0.025 4242 refreeze 1.5
run             0 post no
write_data      written.data
write_restart   written.restart
""", tmp_path / "a")
    assert words in (tmp_path / "a" / "written.data").read_text()
    build.run("""
units           lj
dimension       2
read_restart    ../a/written.restart
comm_modify     cutoff 2.5
write_data      again.data
""", tmp_path / "b")
    assert words in (tmp_path / "b" / "again.data").read_text()
