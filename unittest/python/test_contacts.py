"""Contacts with Coulomb friction between unlinked automata ("pair_style mca
contacts coulomb", pair_coeff keyword friction; doc/src/pair_mca.rst,
"Contacts").

* sliding block (validation 3 of the issue): a block of linked automata
  pressed onto a plane of other automata (not linked to it) and dragged
  along it: once it slides, the friction force on the plane is mu times
  the normal force within 1 % (mu = 0.3; and 0 for mu = 0), and every
  contact that slides has |t| = mu |sigma| to round-off;
* stick: a tangential force below mu N never lets a contact slip: friction
  dissipates exactly nothing and the block does not creep;
* oblique impact of a free cube on a free plate: contacts are made when
  the bodies come within reach and dropped after they part; kinetic
  (translation and spin) + elastic + friction energy stays constant to the
  integrator's error while friction takes a large share; the same run on
  2 MPI ranks, with the kk styles on 1 and 2 threads and across a restart
  file written while the bodies touch gives the same trajectory;
* a box compressed by fix deform brings two automata into contact: the
  kk styles rebuild their neighbor lists as the CPU styles do (LAMMPS's
  Kokkos check alone never rebuilds when the box moved more than the
  skin) and see the contact;
* bad input gives errors that name the argument and the allowed values.
"""

import pathlib

import numpy as np
import pytest

from mca_inputs import CONTACT_NEIGHBOR, block_on_plane, two_bodies
from mcatest import kokkos_args, read_dump, read_thermo

ROOT = pathlib.Path(__file__).resolve().parents[2]

R = 1.0e-3          # m, radius of the automata (sc packing, spacing 2R)
E, NU = 70.0e9, 0.3
G = E / (2.0 * (1.0 + NU))
DT = 5.0e-8         # s; the stable time step of these scenes is about 2e-7 s

# a 3 x 3 x 2 block (type 2) on a 5 x 5 plane (type 1), not linked to it,
# pressed by its top layer and dragged along x at speed v (ramped); the
# plane is held.  Normal traction about 7 MPa: the contacts stick over a
# slip of mu sigma c_t ~ 8e-8 m and then slide over the rest of 2e-6 m
BLOCK = block_on_plane("-2 7 -2 7 -2 6", "-0.5 4.5 -0.5 4.5 -0.5 0.5", "0.5 3.5 0.5 3.5 0.5 2.5",
                       1.5) + """pair_style      mca contacts coulomb
pair_coeff      * * E {E} nu {nu} rho 2700 friction {mu}
pair_coeff      1 2 link no
fix             nve all nve/mca
fix             plane plane mca/setvelocity 0 0 0
fix             load top addforce 0 0 -{load}
fix             damp block mca/damping 2e5
variable        vx equal {v}*(1.0-exp(-(((step-{settle})*dt/{ramp})^2)))*(step>{settle})
fix             drag block mca/setvelocity v_vx 0 NULL
timestep        {dt}
compute         L all mca/link state normal shear friction
compute         F all reduce sum c_L[4]{inputs}
thermo_style    custom step f_plane[1] f_plane[3] f_drag[1] c_F
thermo_modify   format float %.17g
thermo          20
run             {settle}
dump            d all local {nslide} contacts.dump c_L[1] c_L[2] c_L[3]
dump_modify     d format float %.17g
run             {nslide}
"""
SLIDE_V = 0.02        # m/s
SLIDE_STEPS = 2000    # slide of v (t - ramp) ~ 1.9e-6 m = 1e-3 of 2R
LOAD = 28.0           # N per automaton of the top layer: sigma ~ 7 MPa


def local_inputs(build):
    """compute reduce of local values: LAMMPS 2021 takes them as they come,
    later versions want 'inputs local'."""
    return "" if build.name == "kokkos" else " inputs local"


def sliding_block(build, directory, mu, extra_args=(), nprocs=1):
    script = BLOCK.format(spacing=2 * R, radius=R, skin=0.2 * R, E=E, nu=NU, mu=mu, load=LOAD,
                          v=SLIDE_V, ramp=2.0e-5, settle=1000, dt=DT, nslide=SLIDE_STEPS,
                          inputs=local_inputs(build))
    build.run(script, directory, nprocs=nprocs, extra_args=extra_args)
    return read_thermo(directory / "log.lammps")


@pytest.mark.parametrize("mu", [0.3, 0.0])
def test_sliding_block(build, tmp_path, mu):
    thermo = sliding_block(build, tmp_path, mu)
    step = np.asarray(thermo["Step"])
    fx = np.asarray(thermo["f_plane[1]"])
    fz = np.asarray(thermo["f_plane[3]"])
    friction = np.asarray(thermo["c_F"])
    # the normal force on the plane is the load (the block pushes it down)
    normal = -fz
    settled = step == 1000
    # (to the ringing the damping leaves after 1000 steps)
    assert abs(normal[settled][0] - 9 * LOAD) < 1e-2 * 9 * LOAD
    # sliding: from the second half of the slide on (the stick phase ends
    # after ~ 4 % of it).  The contact normals tilt by the slide over the
    # diameter, d / 2R <= 1e-3, which adds -d/2R (1 + mu^2) to the ratio
    sliding = step >= 1000 + SLIDE_STEPS // 2
    ratio = fx[sliding] / normal[sliding]
    tilt = SLIDE_V * SLIDE_STEPS * DT / (2 * R)
    print(f"\nmu {mu}: F_x / N over the slide {ratio.min():.6f} .. {ratio.max():.6f} "
          f"(normal force {normal[sliding].mean():.4f} N, contact tilt <= {tilt:.1e}), "
          f"friction energy {friction[-1]:.4e} J")
    if mu > 0:
        assert np.abs(ratio / mu - 1.0).max() < 0.01
        # what friction dissipated while sliding is the work of the friction
        # force over the slip, v dt per step (the contacts' tangential
        # springs hold a constant energy): sampled every 20 steps, the sum
        # of F v dt is within the change of F over one sample of it
        work = np.sum(0.5 * (fx[sliding][1:] + fx[sliding][:-1])) * 20 * SLIDE_V * DT
        gained = friction[sliding][-1] - friction[sliding][0]
        print(f"friction energy over the slide {gained:.6e} J, work of F_x {work:.6e} J")
        assert abs(gained / work - 1.0) < 0.01
    else:
        assert np.abs(ratio).max() < 1.5 * tilt * (1 + mu * mu)
        assert friction[-1] == 0.0
    # every contact that pushes slides at the cap: |t| = mu |sigma|
    rows = read_dump(tmp_path / "contacts.dump")[-1]
    state, normal_traction, shear = (rows[f"c_L[{k}]"] for k in (1, 2, 3))
    pushing = (state == 3) & (normal_traction < 0)
    assert pushing.sum() == 9
    assert np.abs(shear[pushing] - mu * np.abs(normal_traction[pushing])).max() < \
        1e-12 * np.abs(normal_traction[pushing]).max()


def test_stick_below_threshold(build, tmp_path):
    """A tangential force of 0.3 mu N on the block automata, ramped in once
    the load has settled, with the block free along x: no contact ever
    reaches the cap, so
    friction dissipates exactly nothing, and once the damping has settled
    the block it stays where it is (no creep)."""
    mu = 0.3
    script = BLOCK.format(spacing=2 * R, radius=R, skin=0.2 * R, E=E, nu=NU, mu=mu, load=LOAD,
                          v=0.0, ramp=1.0, settle=1000, dt=DT, nslide=4000,
                          inputs=local_inputs(build))
    # the drag holds y only; a ramped force along x pulls every automaton
    push = 0.3 * mu * 9 * LOAD / 18
    script = script.replace("fix             drag block mca/setvelocity v_vx 0 NULL",
                            "fix             drag block mca/setvelocity NULL 0 NULL\n"
                            f"variable        fx equal {push}*(1.0-exp(-(((step-1000)*dt/2e-5)^2)))*(step>1000)\n"
                            "fix             push block addforce v_fx 0 0\n"
                            "compute         xb block com")
    script = script.replace("thermo_style    custom step f_plane[1] f_plane[3] f_drag[1] c_F",
                            "thermo_style    custom step f_plane[1] f_plane[3] c_xb[1] c_F")
    build.run(script, tmp_path)
    thermo = read_thermo(tmp_path / "log.lammps")
    x = np.asarray(thermo["c_xb[1]"])
    friction = np.asarray(thermo["c_F"])
    fx = np.asarray(thermo["f_plane[1]"])
    step = np.asarray(thermo["Step"])
    late = step >= 4000
    shift = x[-1] - x[0]
    drift = np.abs(x[late] - x[late][-1]).max()
    print(f"\nstick: tangential force {18 * push:.3f} N = 0.3 mu N; block moved {shift:.4e} m, "
          f"then stays within {drift:.2e} m over the last 1000 steps; friction energy "
          f"{friction[0]:.6e} J at the settling (the block's Poisson expansion slips the "
          f"contacts while they load), {friction[-1]:.6e} J at the end")
    # not one slip once the tangential force acts (bit for bit)
    assert np.all(friction == friction[0])
    # the plane carries the whole tangential force once settled
    assert abs(fx[-1] / (18 * push) - 1.0) < 1e-3
    # the block moved elastically (the contacts' tangential springs) and
    # then stays put: its centre moves by less than 1e-3 of that shift over
    # the last 1000 steps (the ringing, damped by e^-15 by then; no creep)
    assert shift > 0
    assert drift < 1e-3 * shift


# a cube (3 x 3 x 3, type 2) thrown obliquely at a plate (6 x 6 x 2, type
# 1), both free; they are 0.5 R apart (beyond reach, 0.2 R: the contacts
# are made on the way, after ~ 1000 steps); the restart case writes a
# restart file while they touch
IMPACT = two_bodies("-3 9 -3 9 -2 9", ("plate", "-0.5 5.5 -0.5 5.5 -0.5 1.5"),
                    ("cube", "1.5 4.5 1.5 4.5 2.75 5.25"), atom_modify="map array sort 0 0") + """\
displace_atoms  cube move 0 0 {drop} units box
velocity        cube set 3.0 1.0 -10.0 units box
""" + CONTACT_NEIGHBOR + """\
pair_style      mca contacts coulomb
pair_coeff      * * E {E} nu {nu} rho 2700 friction 0.3
pair_coeff      1 2 link no
fix             nve all nve/mca
timestep        {dt}
"""
IMPACT_OUTPUT = """
compute         p all property/atom inertia omegax omegay omegaz
variable        erot atom 0.5*c_p[1]*(c_p[2]^2+c_p[3]^2+c_p[4]^2)
compute         erot all reduce sum v_erot
compute         a all mca/atom friction contact_work contacts
compute         A all reduce sum c_a[1] c_a[2] c_a[3]
variable        etot equal ke+c_erot+pe+c_A[1]+c_A[2]
thermo_style    custom step ke c_erot pe c_A[1] c_A[2] c_A[3] v_etot
thermo_modify   format float %.17g
thermo          10
dump            d all custom 100 impact.dump id x y z vx vy vz omegax omegay omegaz
dump_modify     d format float %.17g sort id
"""
IMPACT_STEPS = 2400


def impact(build, directory, nprocs=1, extra_args=(), split_at=None, restart=False):
    """The run, or two runs split at step split_at in memory or (restart)
    through a restart file (the second run dumps to impact2.dump)."""
    script = IMPACT.format(spacing=2 * R, radius=R, skin=0.2 * R, E=E, nu=NU, dt=DT, drop=-1.5 * R)
    second = IMPACT_OUTPUT.replace("dump            d all custom 100 impact.dump",
                                   "dump            d all custom 100 impact2.dump")
    if split_at is None:
        script += IMPACT_OUTPUT + f"run {IMPACT_STEPS}\n"
    elif not restart:
        dump = "\n".join(line for line in second.splitlines() if line.startswith("dump"))
        script += (IMPACT_OUTPUT + f"run {split_at}\nundump d\n" + dump
                   + f"\nrun {IMPACT_STEPS - split_at}\n")
    else:
        script += (IMPACT_OUTPUT + f"run {split_at}\nwrite_restart impact.restart\nclear\n"
                   "atom_modify map array sort 0 0\nread_restart impact.restart\n"
                   "comm_modify vel yes\nneighbor {skin} bin\n"
                   "neigh_modify delay 0 every 1 check yes\n"
                   "fix nve all nve/mca\ntimestep {dt}\n".format(skin=0.2 * R, dt=DT)
                   + second + f"run {IMPACT_STEPS - split_at}\n")
    build.run(script, directory, nprocs=nprocs, extra_args=extra_args)
    return read_thermo(directory / "log.lammps")


def test_impact_energy_balance(build, tmp_path):
    thermo = impact(build, tmp_path)
    total = np.asarray(thermo["v_etot"])
    friction = np.asarray(thermo["c_A[1]"])
    dropped = np.asarray(thermo["c_A[2]"])
    touching = np.asarray(thermo["c_A[3]"])
    e0 = total[0]
    error = np.abs(total - e0).max() / e0
    print(f"\nimpact: friction dissipated {friction[-1] / e0:.4f} of the energy, contacts "
          f"touching at most {touching.max():.0f}, at the end {touching[-1]:.0f}; work left by "
          f"dropped contacts {dropped[-1]:.3e} J ({dropped[-1] / e0:.2e}); balance error "
          f"{error:.2e}")
    assert touching.max() > 0 and touching[-1] == 0    # they touched, then parted
    assert friction[-1] > 0.01 * e0
    assert error < 2e-3


def final_state(directory, name="impact.dump", by_position=True):
    """Positions, velocities and spins of the last snapshot of a dump, the
    automata in the order of their positions in the first (create_atoms
    numbers them differently on different numbers of ranks), or of their
    IDs."""
    snaps = read_dump(directory / name)
    first, snap = snaps[0], snaps[-1]
    order = np.arange(len(snap["id"]))
    if by_position:
        order = np.lexsort(np.round(np.column_stack([first[c] for c in ("z", "y", "x")]) / R,
                                    3).T)
    return np.column_stack([snap[c][order] for c in ("x", "y", "z", "vx", "vy", "vz", "omegax",
                                                     "omegay", "omegaz")])


def state_difference(a, b):
    """Largest difference of positions (relative to the spacing 2R) and of
    velocities and spins (relative to their largest value)."""
    dx = np.abs(a[:, :3] - b[:, :3]).max() / (2 * R)
    dv = np.abs(a[:, 3:6] - b[:, 3:6]).max() / np.abs(b[:, 3:6]).max()
    dw = np.abs(a[:, 6:] - b[:, 6:]).max() / np.abs(b[:, 6:]).max()
    return max(dx, dv, dw)


@pytest.fixture(scope="module")
def impact_reference(tmp_path_factory):
    """The oblique impact on one rank with the CPU styles of the current
    build (or the first one tested)."""
    from mcatest import builds
    build = builds()[0]
    directory = tmp_path_factory.mktemp("impact_reference")
    impact(build, directory)
    return build, directory


# the trajectory after the impact (contacts made, slid and dropped) on 2
# ranks: the sums over the links and contacts of an automaton come in
# another order; the difference is round-off grown by the contact events
# (measured 1e-13 .. 1e-11)
def test_impact_mpi(impact_reference, tmp_path):
    build, reference = impact_reference
    impact(build, tmp_path, nprocs=2)
    difference = state_difference(final_state(tmp_path), final_state(reference))
    print(f"\nimpact on 2 ranks against 1: largest difference {difference:.2e}")
    assert difference < 1e-8


def test_impact_restart(build, tmp_path):
    """A restart file written while the bodies touch (step 1040: contact
    rows with friction history) continues as the run split in memory, bit
    for bit."""
    memory = impact(build, tmp_path / "memory", split_at=1040)
    restart = impact(build, tmp_path / "restart", split_at=1040, restart=True)
    assert restart["c_A[3]"][0] > 0    # touching when the file was written
    a = final_state(tmp_path / "memory", "impact2.dump", by_position=False)
    b = final_state(tmp_path / "restart", "impact2.dump", by_position=False)
    print(f"\nimpact across a restart file against the run split in memory: largest "
          f"difference {state_difference(b, a):.2e}")
    assert np.array_equal(a, b)
    assert np.array_equal(memory["v_etot"], restart["v_etot"])


@pytest.mark.parametrize("threads", [1, 2])
def test_impact_kk(tmp_path, threads):
    """The kk styles: on one thread in the CPU style's order (the same
    bits), on two threads (or a GPU) to round-off grown by the events."""
    from mcatest import kokkos_build
    kk = kokkos_build()
    impact(kk, tmp_path, extra_args=kokkos_args(threads))
    host = tmp_path / "cpu"
    impact(kk, host)
    difference = state_difference(final_state(tmp_path), final_state(host))
    print(f"\nimpact with the kk styles on {threads} thread(s) against the CPU styles: "
          f"largest difference {difference:.2e}")
    assert difference < (1e-14 if threads == 1 else 1e-8)


# two automata in a periodic box compressed along x by fix deform without
# remapping them (remap none): the box moves, the automata hardly (one
# drifts at 0.01 m/s), so that the box moves more than the skin between
# builds.  Automaton A (x = 2R) comes into touch with the image of B (x =
# 12R) as the box length shrinks from 16R to 11.9R (their gap from 4R, 20
# skins, to -0.1R; they bounce).  LAMMPS's CPU check rebuilds once the box moved more
# than the skin and any atom moved; its Kokkos check never does, and the
# pair would never be in a neighbor list
DEFORM = """
units           si
atom_style      mca
atom_modify     map array
boundary        p p p
region          box block 0 {L} 0 {L2} 0 {L2} units box
create_box      1 box
create_atoms    1 single {x1} {y} {y} units box
create_atoms    1 single {x2} {y} {y} units box
mca_set         all packing sc radius {radius}
group           a id 1
velocity        a set 0.01 0 0 units box
comm_modify     vel yes
neighbor        {skin} bin
neigh_modify    delay 0 every 1 check yes
pair_style      mca contacts coulomb
pair_coeff      * * E {E} nu {nu} rho 2700 friction 0.3 link no
fix             nve all nve/mca
fix             squeeze all deform 1 x final 0 {Lend} remap none units box
timestep        {dt}
compute         a all mca/atom contacts
compute         A all reduce sum c_a
thermo_style    custom step c_A pe
thermo_modify   format float %.17g
thermo          10
run             {nsteps}
variable        forced equal f_MCA_REBUILD
print           "rebuilds forced by MCA_REBUILD: ${{forced}}"
"""


def deform(build, directory, extra_args=()):
    L = 16 * R
    script = DEFORM.format(L=L, L2=8 * R, x1=2 * R, x2=12 * R, y=4 * R, radius=R, skin=0.2 * R,
                           E=E, nu=NU, dt=DT, Lend=11.9 * R, nsteps=1000)
    build.run(script, directory, extra_args=extra_args)
    log = (directory / "log.lammps").read_text()
    builds = int(log.split("Neighbor list builds =")[1].split()[0])
    forced = float(log.split("rebuilds forced by MCA_REBUILD:")[-1].split()[0])
    return read_thermo(directory / "log.lammps"), builds, forced


def test_deform_rebuilds_kk(tmp_path):
    """(two threads, or the GPU: the pair's sums are the same in any order)"""
    from mcatest import kokkos_build
    kk = kokkos_build()
    cpu, cpu_builds, cpu_forced = deform(kk, tmp_path / "cpu")
    kokkos, kk_builds, kk_forced = deform(kk, tmp_path / "kk", extra_args=kokkos_args(2))
    print(f"\nbox compressed by fix deform: neighbor list builds CPU {cpu_builds}, kk "
          f"{kk_builds}; asked for by MCA_REBUILD CPU {cpu_forced:.0f}, kk {kk_forced:.0f}; "
          f"automata in touch at most CPU {cpu['c_A'].max():.0f}, kk {kokkos['c_A'].max():.0f}")
    assert cpu_builds > 10
    assert kk_builds == cpu_builds
    assert kk_forced > 0
    # they meet (at ~ 80 m/s: the box shrinks by 4.1R in 50 us) and bounce
    assert cpu["c_A"].max() == 2 and kokkos["c_A"].max() == 2
    assert np.array_equal(cpu["PotEng"], kokkos["PotEng"])


BAD = """
units           si
atom_style      mca
atom_modify     map array
boundary        f f f
region          box block -0.01 0.01 -0.01 0.01 -0.01 0.01 units box
create_box      2 box
create_atoms    1 single 0 0 0 units box
create_atoms    2 single 0 0 0.0021 units box
mca_set         all packing sc radius 0.001
comm_modify     vel yes
neighbor        0.0002 bin
{neigh}
pair_style      mca {style}
pair_coeff      * * E 70e9 nu 0.3 rho 2700 {coeff}
fix             nve all nve/mca
run             0
"""

DEFAULT_NEIGH = "neigh_modify delay 0 every 1 check yes"


@pytest.mark.parametrize("case", [
    dict(style="contacts coulomb", coeff="friction -0.1",
         error="friction (Coulomb coefficient mu) must be >= 0, got -0.1"),
    dict(style="contacts coulomb", coeff="friction 0.2", neigh="neigh_modify delay 10",
         error="use 'neigh_modify delay 0 every 1 check yes' (now delay 10 every 1 check yes)"),
    dict(style="contacts coulomb", coeff="friction 0.2", neigh="neigh_modify every 2 delay 0",
         error="(now delay 0 every 2 check yes)"),
    dict(style="contacts coulomb cutoff 0.0015", coeff="friction 0.2",
         error="contacts need a cutoff of at least the largest touch distance 2 R_max = 0.002"),
    dict(style="contacts stick", coeff="",
         error="Unknown contacts part stick for pair_style mca (allowed: coulomb)"),
])
def test_bad_input(build, tmp_path, case):
    script = BAD.format(style=case["style"], coeff=case["coeff"],
                        neigh=case.get("neigh", DEFAULT_NEIGH))
    result = build.run(script, tmp_path, check=False)
    output = result.stdout + result.stderr
    assert result.returncode != 0
    assert case["error"] in output, output[-2000:]


def test_friction_without_contacts_warns(build, tmp_path):
    script = BAD.format(style="", coeff="friction 0.2", neigh=DEFAULT_NEIGH)
    result = build.run(script, tmp_path)
    assert "friction is given but the link model has no contact part" in result.stdout


def test_capacity_exceeded(build, tmp_path):
    """A user's capacity caps the tables: the automaton that needs more rows
    for its links and contacts is named."""
    script = BAD.format(style="contacts coulomb capacity 1", coeff="friction 0.2",
                        neigh=DEFAULT_NEIGH)
    script = script.replace("create_atoms    2 single 0 0 0.0021 units box",
                            "create_atoms    2 single 0 0 0.0021 units box\n"
                            "create_atoms    2 single 0 0.0021 0 units box\n"
                            "create_atoms    1 single 0.0021 0 0 units box")
    result = build.run(script, tmp_path, check=False)
    output = result.stdout + result.stderr
    assert result.returncode != 0
    assert "links and contacts at step 0, more than the capacity 1" in output, output[-2000:]


# hard cases: a projectile perforates a plate (examples/contacts/in.impact_plate)
HARD = ROOT / "examples" / "hard_cases"    # plate_analysis.py
CONTACTS = ROOT / "examples" / "contacts"


def impact_plate(build, directory, factor, nsteps, every=50, m=10, n=2, extra_args=()):
    """The projectile (n^3 steel automata at 150 m/s) and the plate (m x m x
    2, its links breaking), at time step factor R/c_p; the thermo columns and
    the pieces the intact links hold together at the end (sizes, largest
    first)."""
    import sys
    sys.path.insert(0, str(HARD))
    from plate_analysis import pieces, read_snapshots
    directory.mkdir(parents=True, exist_ok=True)
    build.run((CONTACTS / "in.impact_plate").read_text(), directory, name="in.impact_plate",
              variables={"m": m, "n": n, "factor": factor, "nsteps": nsteps, "every": every},
              extra_args=extra_args)
    thermo = read_thermo(directory / "log.lammps")
    atoms = read_snapshots(directory / "dump.impact.atoms")[-1][2]
    links = read_snapshots(directory / "dump.impact.links")[-1][2]
    labels = pieces(atoms[:, 0], links)
    sizes = np.sort(np.bincount(np.array(list(labels.values()))))[::-1]
    return thermo, sizes


def test_impact_plate_fragments(build, tmp_path):
    """The plate is perforated: the links break, the pieces fly, rub and
    meet again as contacts; no NaN, no lost automaton (thermo_modify lost
    error), and kinetic + elastic + released + friction + the work left by
    dropped contacts and forgotten broken pairs stays that of the start."""
    thermo, sizes = impact_plate(build, tmp_path, factor=0.0591, nsteps=5000)
    balance = np.asarray(thermo["v_balance"])
    broken = np.asarray(thermo["c_f[1]"])
    friction = np.asarray(thermo["c_A[1]"])
    ke0 = thermo["KinEng"][0]
    print(f"\nimpact on a plate: {broken[-1]:.0f} links broken, {len(sizes)} pieces "
          f"(largest {sizes[:6]}), friction {friction[-1] / ke0:.4f} of the energy, dropped "
          f"contacts and forgotten pairs left {thermo['c_A[2]'][-1] / ke0:.2e}; energy balance "
          f"{np.abs(balance).max():.2e}")
    assert np.all(np.isfinite(balance))
    assert broken[-1] > 50
    # the plate is holed: its rim (the largest piece), the projectile, and
    # a plug in pieces
    assert len(sizes) >= 4
    assert friction[-1] > 0
    assert np.abs(balance).max() < 2e-3


def packing(build, directory, factor, n=5, h=8, extra_args=()):
    """examples/contacts/in.packing: a packing of unlinked automata
    compressed by 50 % between two plates; its thermo columns."""
    directory.mkdir(parents=True, exist_ok=True)
    build.run((CONTACTS / "in.packing").read_text(), directory, name="in.packing",
              variables={"n": n, "h": h, "factor": factor, "every": 100},
              extra_args=extra_args)
    return read_thermo(directory / "log.lammps")


def packing_balance(t):
    """(etot - work) over the final work, at every output (the printed
    balance divides by the work so far, 0 before the plate touches)."""
    return (np.asarray(t["v_etot"]) - np.asarray(t["v_work"])) / t["v_work"][-1]


def packing_summary(t):
    return (f"strain {t['v_strain'][-1]:.3f}, contacts pushing at the end "
            f"{t['c_A[3]'][-1] / 2:.0f}, friction {t['c_A[1]'][-1] / t['v_work'][-1]:.3f} of the "
            f"work, dropped contacts left {t['c_A[2]'][-1] / t['v_work'][-1]:.2e}, energy balance "
            f"{np.abs(packing_balance(t)).max():.2e} (largest)")


# the balance error is the integrator's, second order in the time step:
# measured 2.0e-3 / 8.3e-3 / 3.2e-2 of the work at 0.15 / 0.3 / 0.6 R/c_p
def test_packing_compressed_by_50_percent(build, tmp_path):
    """200 automata that touch only through contacts, squeezed to half
    their height at 20 m/s (factor 0.15): no NaN, no automaton lost
    (thermo_modify lost error), the packing jams (contacts made by the
    dozen), friction takes a large share of the work, and the energy
    balance holds within 5e-3."""
    t = packing(build, tmp_path, factor=0.15)
    print("\npacking: " + packing_summary(t))
    assert np.all(np.isfinite(packing_balance(t)))
    assert np.all(t["Atoms"] == t["Atoms"][0])
    assert t["v_strain"][-1] > 0.5
    assert t["c_A[3]"][-1] / 2 > 20
    assert t["c_A[1]"][-1] > 0.3 * t["v_work"][-1]
    assert np.abs(packing_balance(t)).max() < 5e-3


def packing_is_stable(build, directory, factor):
    """Stable at this factor: the packing is halved without NaN and its
    energy balance stays within 0.5 (unstable runs blow up by orders of
    magnitude; a stable run at 1.3 R/c_p misses it by 0.17)."""
    try:
        t = packing(build, directory / f"f{factor:.4f}", factor=factor)
    except AssertionError:    # LAMMPS stopped (lost automata, a link lost)
        return False
    balance = packing_balance(t)
    return bool(np.all(np.isfinite(balance)) and np.abs(balance).max() < 0.5
                and t["v_strain"][-1] > 0.5)


def test_packing_at_0_9_of_the_stable_time_step(build, tmp_path):
    """The largest stable time step of the packing, bisected to 0.02 R/c_p
    (the pair style's estimate from its links, at the start, is 1.53 R/c_p;
    the contacts of the jammed packing count as links do), then the
    compression at 0.9 of it: no NaN, no lost automaton, the balance within
    0.3 (measured 0.17 at 1.3 R/c_p: the integrator's error, dt^2 times
    that at 0.15 R/c_p)."""
    import sys
    sys.path.insert(0, str(HARD))
    from plate_analysis import stable_factor
    if build.name != "current":
        pytest.skip("the bisection runs once, with the current build")
    lo, hi = stable_factor(lambda f: packing_is_stable(build, tmp_path, f), 1.0, 2.0, 0.02)
    factor = 0.9 * lo
    t = packing(build, tmp_path / "run", factor=factor)
    print(f"\nstable time step of the packing: {lo:.4f} to {hi:.4f} R/c_p; at {factor:.4f}: "
          + packing_summary(t))
    assert 1.0 < lo < 2.0
    assert np.all(np.isfinite(packing_balance(t)))
    assert t["v_strain"][-1] > 0.5
    assert np.abs(packing_balance(t)).max() < 0.3


def test_packing_kokkos_and_mpi(tmp_path):
    """The packing at 0.3 R/c_p (contacts made and dropped by the hundred,
    the tables growing) with the kk styles on one thread: the CPU styles'
    numbers bit for bit; on two threads and on 2 MPI ranks (contacts with
    ghost partners) it jams the same way (the sums in another order: the
    jamming packing takes the round-off to the percent) with its energy
    balance within the bound of the CPU run (measured 8.3e-3 of the work
    at this step)."""
    from mcatest import kokkos_build
    kk = kokkos_build()
    cpu = packing(kk, tmp_path / "cpu", factor=0.3)
    one = packing(kk, tmp_path / "kk1", factor=0.3, extra_args=kokkos_args(1))
    two = packing(kk, tmp_path / "kk2", factor=0.3, extra_args=kokkos_args(2))
    (tmp_path / "mpi2").mkdir()
    kk.run((CONTACTS / "in.packing").read_text(), tmp_path / "mpi2", name="in.packing", nprocs=2,
           variables={"n": 5, "h": 8, "factor": 0.3, "every": 100})
    mpi = read_thermo(tmp_path / "mpi2" / "log.lammps")
    for name, t in (("cpu", cpu), ("kk 1 thread", one), ("kk 2 threads", two), ("2 ranks", mpi)):
        print(f"\npacking, {name}: " + packing_summary(t), end="")
    print()
    assert np.array_equal(cpu["v_etot"], one["v_etot"])
    assert np.array_equal(cpu["v_stress"], one["v_stress"])
    for t in (two, mpi):
        assert np.all(np.isfinite(packing_balance(t)))
        assert t["v_strain"][-1] > 0.5
        assert np.abs(packing_balance(t)).max() < 1.5e-2


# bodies: an indenter of 2 x 2 x 2 automata (type 2), 0.02 R above a sample
# of 6 x 6 x 2 (type 1, its bottom layer held), driven into it by fix move
# at 0.5 m/s, or as a rigid body of fix rigid pushed by 8 x 10 N; they touch
# through contacts only
INDENTER = two_bodies("-2 8 -2 8 -2 7", ("sample", "-0.5 5.5 -0.5 5.5 -0.5 1.5"),
                      ("tip", "1.5 3.5 1.5 3.5 1.5 3.5")) + """\
displace_atoms  tip move 0 0 {gap} units box
region          base block INF INF INF INF INF 0.5
group           base region base
group           free subtract sample base
""" + CONTACT_NEIGHBOR + """\
pair_style      mca contacts coulomb
pair_coeff      * * E {E} nu {nu} rho 2700 friction 0.3
pair_coeff      1 2 link {link}
fix             nve sample nve/mca
fix             hold base mca/setvelocity 0 0 0
{drive}
timestep        {dt}
compute         ftip tip reduce sum fz
compute         ffree free reduce sum fz
compute         xtip tip reduce max x
variable        newton equal c_ftip+c_ffree+f_hold[3]
thermo_style    custom step c_ftip c_ffree f_hold[3] v_newton {extra}
thermo_modify   format float %.17g
thermo          50
run             2000
"""
MOVE = "fix             push tip move linear 0 0 -0.5 units box"
RIGID = ("fix             body tip rigid single\n"
         "fix             push tip addforce 0 0 -10.0")


def indenter(build, directory, drive, link="no", extra="", extra_args=(), check=True):
    script = INDENTER.format(spacing=2 * R, radius=R, gap=0.02 * R, skin=0.2 * R, E=E, nu=NU,
                             dt=DT, drive=drive, link=link, extra=extra)
    result = build.run(script, directory, extra_args=extra_args, check=check)
    return result if not check else read_thermo(directory / "log.lammps")


def test_indenter_moved_by_fix_move(build, tmp_path):
    """fix move drives the indenter (its automata integrated by fix move,
    not nve/mca): the contacts push on it, the reaction on the indenter is
    the force the held base and the free sample carry, opposite (Newton 3
    to round-off), and it grows with the depth."""
    t = indenter(build, tmp_path, MOVE)
    reaction = np.asarray(t["c_ftip"])
    scale = np.abs(reaction).max()
    newton = np.abs(np.asarray(t["v_newton"])).max() / scale
    print(f"\nindenter by fix move: reaction on the indenter up to {scale:.2f} N; tip + sample "
          f"+ held base {newton:.1e} of it")
    # it touches after 0.02 R / 0.5 m/s = 800 steps, then goes 0.06 R deep
    assert reaction[0] == 0.0 and reaction[-1] > 1.0
    assert newton < 1e-10


def test_indenter_as_a_rigid_body(build, tmp_path):
    """fix rigid carries the indenter, pushed by 10 N on each of its 8
    automata: the body hits the sample and presses on it; the force fix
    rigid sums on the body (fcm) is the push plus the contacts' reaction,
    and the sample carries the opposite of the contacts' (Newton 3 to
    round-off).  (Step 0 is left out: at the setup fix rigid sums the
    forces before fix addforce adds its own.)"""
    t = indenter(build, tmp_path, RIGID, extra="f_body[1][9]")
    fcm = np.asarray(t["f_body[1][9]"])[1:]
    tip = np.asarray(t["c_ftip"])[1:]
    sample = (np.asarray(t["c_ffree"]) + np.asarray(t["f_hold[3]"]))[1:]
    push = -80.0
    print(f"\nindenter as a rigid body: contact force on the body up to "
          f"{np.abs(tip - push).max():.2f} N, body force at the end {fcm[-1]:.3f} N")
    assert np.abs(fcm - tip).max() < 1e-9 * np.abs(fcm).max()
    assert np.abs(tip - push + sample).max() < 1e-10 * np.abs(sample).max()
    assert np.abs(sample).max() > 80.0


def test_rigid_body_linked_to_free_automata_is_an_error(build, tmp_path):
    result = indenter(build, tmp_path, RIGID, link="yes", check=False)
    output = result.stdout + result.stderr
    assert result.returncode != 0
    assert "links join automata of the rigid bodies of fix body (group tip) to automata " \
        "outside them" in output, output[-2000:]


def test_indenter_kokkos(tmp_path):
    """The fix move indenter with the kk styles on one thread: the CPU
    styles' reaction bit for bit."""
    from mcatest import kokkos_build
    kk = kokkos_build()
    cpu = indenter(kk, tmp_path / "cpu", MOVE)
    one = indenter(kk, tmp_path / "kk1", MOVE, extra_args=kokkos_args(1))
    assert np.array_equal(cpu["c_ftip"], one["c_ftip"])
