"""pair_style mca: the elastic MCA interaction, checked against elasticity theory.

Each test states the physical fact it checks and the reason for its
tolerance.  Material: aluminium of the thesis, E = 70 GPa, rho = 2700 kg/m^3.
"""

import math
import sys

import numpy as np
import pytest

from mcatest import ROOT, kokkos_args, kokkos_build, read_dump, read_thermo, relative_difference

sys.path.insert(0, str(ROOT / "examples" / "waves"))
from dispersion_model import p_wave_speed_ratio  # noqa: E402

E = 70.0e9
RHO = 2700.0
A_FCC = 0.7184
EXAMPLES = ROOT / "examples"


def run_example(build, directory, example, script, variables=None, nprocs=1):
    """Run the input examples/<example>/<script> in directory: the tests
    check the scenes of the examples, not copies of them."""
    text = (EXAMPLES / example / script).read_text()
    return build.run(text, directory, variables=variables, nprocs=nprocs, name=script)


def moduli(nu, e=E):
    g = e / (2 * (1 + nu))
    k = e / (3 * (1 - 2 * nu))
    return g, k, k - 2 * g / 3


# ---------------------------------------------------------------------------
# 1. affine deformations reproduce Hooke's law exactly

AFFINE = """
units           si
atom_style      mca
atom_modify     map array
boundary        p p p
lattice         ${lat} 0.7184
region          box prism 0 4 0 4 0 4 0 0 0
create_box      1 box
create_atoms    1 box
comm_modify     vel yes
pair_style      mca
pair_coeff      * * E 70.0e9 nu ${nu} rho 2700
fix             integrate all nve/mca
timestep        1.0e-6
run             0
variable        e equal 1.0e-7
variable        L equal ly
if "${mode} == xx" then "change_box all x scale $(1+v_e) remap"
if "${mode} == vol" then "change_box all x scale $(1+v_e) y scale $(1+v_e) z scale $(1+v_e) remap"
if "${mode} == xy" then "change_box all xy delta $(2*v_e*v_L) remap units box"
compute         s all mca/atom sxx syy szz sxy sxz syz smean
dump            d all custom 1 stress.dump id c_s[1] c_s[2] c_s[3] c_s[4] c_s[5] c_s[6] c_s[7]
dump_modify     d sort id format float %.17g
thermo_style    custom step pe press pxx pyy pzz pxy
thermo_modify   format float %.17g
run             0
"""

STRAINS = {"xx": np.diag([1.0, 0.0, 0.0]), "vol": np.eye(3),
           "xy": np.array([[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]])}


@pytest.mark.parametrize("lat", ["fcc", "sc"])
@pytest.mark.parametrize("nu", [0.0, 0.25, 0.3, 0.45])
@pytest.mark.parametrize("mode", ["xx", "xy", "vol"])
def test_affine_strain_gives_hooke_stress(build, tmp_path, lat, nu, mode):
    """A uniform strain of 1e-7 of a periodic lattice gives sigma = 2G eps + lambda tr(eps) I.

    This pins down the corrected equations: D = 1 - 2G/(3K) in the normal
    law, the Newton-3 splits, the shear increment dl = q_i dg_i + q_j dg_j and
    the homogenisation.  Every automaton must carry the same stress, the
    mean stress must be K tr(eps), and the virial pressure must be minus the
    mean stress.  Tolerance 1e-6 relative to the largest stress component:
    geometric nonlinearity is of order of the strain, 1e-7.
    """
    build.run(AFFINE, tmp_path, variables={"lat": lat, "nu": nu, "mode": mode})
    g, k, lam = moduli(nu)
    eps = 1.0e-7 * STRAINS[mode]
    expected = 2 * g * eps + lam * np.trace(eps) * np.eye(3)
    s = read_dump(tmp_path / "stress.dump")[-1]
    got = np.array([s["c_s[1]"], s["c_s[2]"], s["c_s[3]"], s["c_s[4]"], s["c_s[5]"], s["c_s[6]"]]).T
    voigt = np.array([expected[0, 0], expected[1, 1], expected[2, 2], expected[0, 1],
                      expected[0, 2], expected[1, 2]])
    scale = np.max(np.abs(voigt))
    assert np.max(np.abs(got - voigt)) < 1.0e-6 * scale
    assert np.max(np.abs(s["c_s[7]"] - k * np.trace(eps))) < 1.0e-6 * scale
    thermo = read_thermo(tmp_path / "log.lammps")
    assert abs(thermo["Press"][-1] + k * np.trace(eps)) < 1.0e-6 * scale


# ---------------------------------------------------------------------------
# 2. the thesis verification cube

def run_cube(build, directory, grips, load, n=10, nsteps=2500, nprocs=1):
    result = run_example(build, directory, "tension_cube", "in.tension_cube",
                         variables={"grips": grips, "load": load, "n": n, "nsteps": nsteps},
                         nprocs=nprocs)
    t, strain, stress, lateral = np.loadtxt(directory / f"cube.{grips}.{load}.dat", unpack=True)
    return result, t, strain, stress, lateral


def quasi_static_slope(t, x, y, tstart=0.015):
    """Slope of y(x) fitted after the smooth start (tau = 5 ms)."""
    m = t > tstart
    return np.polyfit(x[m], y[m], 1)[0]


def test_cube_with_frictionless_grips_is_in_uniaxial_stress(build, tmp_path):
    """Thesis cube (4631 automata) pulled with frictionless grips: slope E, lateral ratio nu.

    The grips slide freely sideways, so the state is uniaxial stress: the
    slope of stress against strain is E and the lateral strain is -nu times
    the axial strain.  Stress is force / load-bearing area n(n + 1/2) a^2
    (the links that cross a (001) plane, a^2/8 each).  Tolerances from the
    issue: 0.5 % on E, 0.01 on nu; measured -0.15 % and 1e-4 (the loading
    is quasi-static: the smooth start lasts 4 wave transits).
    """
    result, t, strain, stress, lateral = run_cube(build, tmp_path, "free", "tension")
    assert "4631 atoms" in result.stdout
    e_app = quasi_static_slope(t, strain, stress)
    nu_app = -quasi_static_slope(t, strain, lateral)
    print(f"frictionless grips: E_app/E = {e_app / E:.5f}, nu_app = {nu_app:.5f}")
    assert abs(e_app / E - 1.0) < 0.005
    assert abs(nu_app - 0.3) < 0.01


def test_cube_with_clamped_grips_thesis_setup(build, tmp_path):
    """The thesis set-up: grips clamped laterally; apparent moduli are reported.

    Clamped grips stop the lateral contraction near the loaded faces, so the
    apparent tension modulus lies between E and the constrained modulus
    K + 4G/3 (measured 1.07 E).  In shear the cube also bends, so the
    apparent shear modulus is below G (measured 0.69 G).  The bounds are the
    elasticity theory statements; the numbers are printed for the record.
    """
    if build.name == "kokkos":
        pytest.skip("one LAMMPS version suffices for this scene (the same pair mca in both; "
                    "the frictionless cube runs on both)")
    g, k, _ = moduli(0.3)
    _, t, strain, stress, _ = run_cube(build, tmp_path / "tension", "clamped", "tension")
    e_app = quasi_static_slope(t, strain, stress)
    _, t, strain, stress, _ = run_cube(build, tmp_path / "shear", "clamped", "shear")
    g_app = quasi_static_slope(t, strain, stress)
    print(f"clamped grips: tension E_app/E = {e_app / E:.4f}, shear G_app/G = {g_app / g:.4f}")
    assert E < e_app < k + 4 * g / 3
    assert 0.3 * g < g_app < g


def test_shear_modulus_from_simple_shear_of_a_periodic_box(build, tmp_path):
    """Simple shear of a periodic box (fix deform, velocities remapped): slope G.

    The box is sheared at 1e-3/s from rest, so shear waves ring; a fit over
    the last 80 % of the run averages them out.  Tolerance 0.5 % (issue);
    measured 0.01 %.
    """
    run_example(build, tmp_path, "tension_cube", "in.shear_box")
    t, strain, stress = np.loadtxt(tmp_path / "box.shear.dat", unpack=True)
    g, _, _ = moduli(0.3)
    g_app = quasi_static_slope(t, strain, stress, tstart=0.01)
    print(f"periodic shear: G_app/G = {g_app / g:.5f}")
    assert abs(g_app / g - 1.0) < 0.005


# ---------------------------------------------------------------------------
# 3. waves

def wave_speed(build, directory, pol, m, nu=0.3):
    """Phase speed of a standing wave of m (200) planes per wavelength."""
    g, k, _ = moduli(nu)
    c0 = math.sqrt((k + 4 * g / 3) / RHO) if pol == "p" else math.sqrt(g / RHO)
    lam = m * A_FCC / 2
    # examples/waves/in.wave: 400 steps per period (time-step error
    # (omega dt)^2/24 < 1e-5), 6.6 periods
    run_example(build, directory, "waves", "in.wave", variables={"m": m, "pol": pol, "nu": nu})
    t, amp = np.loadtxt(directory / f"wave.{pol}.{m}.dat", unpack=True)
    crossings = [t[i] - amp[i] * (t[i + 1] - t[i]) / (amp[i + 1] - amp[i])
                 for i in range(len(amp) - 1) if amp[i] * amp[i + 1] < 0]
    assert len(crossings) >= 8, "the wave did not oscillate"
    measured = 2.0 * np.mean(np.diff(crossings))
    return lam / measured / c0 - 1.0


def test_wave_speeds_converge_to_the_continuum(build, tmp_path):
    """P and S waves along [100]: phase speed vs c_p = sqrt((K + 4G/3)/rho), c_s = sqrt(G/rho).

    The dispersion error is printed for 4, 6, 10, 20 and 40 (200) planes of
    automata per wavelength, and must fall at least 3x per doubling (the
    lattice is second-order accurate).  The S wave is within 1 % at 10
    automata per wavelength (measured -0.86 %).  The P wave follows the
    dispersion relation of the linearised MCA law (examples/waves/
    dispersion_model.py, derived in pair_mca.rst): measured minus predicted
    c/c_p within 1e-4 at every m, the time-step error of 400 steps per
    period (measured up to 4.4e-5; it falls 16x for 4x smaller steps).
    That relation is 1 % slow only from 26.1 planes (18.4 automaton
    diameters) per wavelength for nu = 0.3: the issue's 1 % at 10 cannot be
    met by this law (see the note in pair_mca.rst), so it is not asserted.
    """
    errors = {}
    for pol in ("p", "s"):
        for m in (4, 6, 10, 20, 40):
            errors[pol, m] = wave_speed(build, tmp_path / f"{pol}{m}", pol, m)
    for pol in ("p", "s"):
        print(f"{pol.upper()} wave, c/c0 - 1 at 4, 6, 10, 20, 40 automata per wavelength: " +
              ", ".join(f"{errors[pol, m]:+.3e}" for m in (4, 6, 10, 20, 40)))
        for m in (10, 20):
            assert errors[pol, m] / errors[pol, 2 * m] > 3.0
    assert abs(errors["s", 10]) < 0.01 and abs(errors["s", 40]) < 0.001
    for m in (4, 6, 10, 20, 40):
        predicted = p_wave_speed_ratio(m, 0.3) - 1.0
        print(f"P wave, m = {m}: measured {errors['p', m]:+.5e}, MCA dispersion relation "
              f"{predicted:+.5e}, difference {errors['p', m] - predicted:+.1e}")
        assert abs(errors["p", m] - predicted) < 1.0e-4


def test_p_wave_without_mean_stress_coupling_is_a_spring_chain(build, tmp_path):
    """For nu = 0 (D = 0) a P wave along [100] sees a chain of planes of spacing h = a/2.

    The exact lattice dispersion of such a chain is c/c0 = sin(kh/2)/(kh/2);
    at 10 planes per wavelength that is -1.64 %.  Tolerance 1e-4 absolute:
    the period is measured from zero crossings to about 1e-5.
    """
    err = wave_speed(build, tmp_path, "p", 10, nu=0.0)
    x = math.pi / 10
    assert abs(err - (math.sin(x) / x - 1.0)) < 1.0e-4


# ---------------------------------------------------------------------------
# 4. energy and rigid motion

def test_energy_is_conserved_in_elastic_vibration(build, tmp_path):
    """A free bar (1 x 1 x 50 cells) vibrating in its first longitudinal mode keeps its energy.

    Kinetic + rotational + elastic energy (the work of the link forces,
    tallied with the incremental law) may not drift: over 10^4 steps at half
    the stability limit (dt = R/(2 c_p)) it stays within 1e-4 of the
    start, and the deviation, the O(dt^2) error of velocity Verlet, falls by
    3 to 5 times when dt is halved.
    """
    deviation = {}
    for factor in (1, 2):
        # examples/energy/in.energy: dt = R/(2 c_p)/factor, 10^4 factor steps
        d = tmp_path / f"dt{factor}"
        run_example(build, d, "energy", "in.energy", variables={"factor": factor})
        e = np.loadtxt(d / f"energy.{factor}.dat", unpack=True)[4]
        deviation[factor] = np.max(np.abs(e - e[0])) / e[0]
    print(f"max |E(t) - E(0)|/E(0): {deviation[1]:.3e} at dt, {deviation[2]:.3e} at dt/2")
    assert deviation[1] < 1.0e-4
    assert 3.0 < deviation[1] / deviation[2] < 5.0


def test_rigid_translation_gives_no_forces(build, tmp_path):
    """A linked cluster moving at constant velocity stays force-free (to round-off)."""
    run_example(build, tmp_path, "energy", "in.rigid",
                variables={"omega": 0.0, "V": 1.0, "nsteps": 2000})
    s = read_dump(tmp_path / "final.dump")[-1]
    reference = E * 1.0e-12 * A_FCC ** 2    # force of a strain of 1e-12 on one cell face
    assert np.max(np.abs([s["fx"], s["fy"], s["fz"]])) < reference


def test_rigid_rotation_is_objective(build, tmp_path):
    """A linked cluster spinning rigidly at 10 rad/s through 2 rad stores no spurious strain.

    Automata turning with the body see no relative slip and no relative
    rotation, so the only strain is the small centrifugal stretching
    (rho W^2 L^2 / E ~ 1e-5): the elastic energy stays below 1e-4 of the
    kinetic energy and does not grow from the first radian to the second,
    and the total energy is conserved to 1e-6 (the rotation dominates it).
    Shear history or couples that did not turn with the pairs would act
    against the rotation and grow with the angle.
    """
    run_example(build, tmp_path, "energy", "in.rigid",
                variables={"omega": 10.0, "V": 0.0, "nsteps": 10000})
    t, pe, etot = np.loadtxt(tmp_path / "rigid.dat", unpack=True)
    first, second = t <= 0.1, t > 0.1    # 1 rad at 10 rad/s
    print(f"rigid rotation: max PE/E = {pe.max() / etot[0]:.3e}, PE max first/second radian "
          f"{pe[first].max():.3e}/{pe[second].max():.3e}")
    assert pe.max() < 1.0e-4 * etot[0]
    assert pe[second].max() < 1.5 * pe[first].max()
    assert np.max(np.abs(etot - etot[0])) < 1.0e-6 * etot[0]


# ---------------------------------------------------------------------------
# 5. MPI and restart

@pytest.mark.mpi
def test_mpi_ranks_agree_on_the_cube(build, tmp_path):
    """1000 steps of the cube test on 1, 2 and 4 ranks agree to 1e-10 relative."""
    finals = {}
    for nprocs in (1, 2, 4):
        d = tmp_path / f"np{nprocs}"
        run_cube(build, d, "free", "tension", nsteps=1000, nprocs=nprocs)
        finals[nprocs] = np.loadtxt(d / "cube.free.tension.dat")[-1]
    for nprocs in (2, 4):
        assert relative_difference(finals[1][1:], finals[nprocs][1:]) < 1.0e-10


RESTART_RUN = """
units           si
atom_style      mca
atom_modify     map array
boundary        f f f
lattice         fcc 0.7184
region          box block -1 5 -1 5 -1 5
create_box      1 box
region          body block -0.01 4.01 -0.01 4.01 -0.01 4.01
create_atoms    1 region body
comm_modify     vel yes
pair_style      mca
pair_coeff      * * E 70.0e9 nu 0.3 rho 2700
variable        vz atom 0.01*(z-1.4368)/2.8736
variable        wx atom 0.01*sin(id)
velocity        all set 0 0 v_vz units box
set             group all omega v_wx 0 0
fix             integrate all nve/mca
timestep        2.0e-5
"""

RESTART_CONTINUE = """
read_restart    half.restart
pair_style      mca
pair_coeff      * * E 70.0e9 nu 0.3 rho 2700
fix             integrate all nve/mca
"""

FINAL_DUMP = """
compute         s all mca/atom sxx syy szz sxy sxz syz smean
dump            d all custom ${n} final.dump id x y z vx vy vz omegax omegay omegaz &
                c_s[1] c_s[2] c_s[3] c_s[4] c_s[5] c_s[6] c_s[7]
dump_modify     d sort id format float %.17g
thermo_style    custom step pe
thermo_modify   format float %.17g
run             ${n}
"""


@pytest.mark.mpi
@pytest.mark.parametrize("nprocs", [1, 2])
def test_restart_continues_the_run_exactly(build, tmp_path, nprocs):
    """write_restart/read_restart continues a run bit for bit.

    The links, both halves of their history and the mean-stress history
    travel with the restart file: a run continued from it equals the same
    run continued in memory (both start with a setup that recomputes the
    forces) in every value.  Against one uninterrupted run the split run
    differs by round-off only: the setup recomputes the forces of the last
    step from the stored history with other arithmetic; the net force on an
    automaton is a difference of link forces about 1e6 times larger, so the
    relative differences are 1e-10 in forces and stay below 1e-6 after 200
    more steps.
    """
    build.run(RESTART_RUN + "run 200\n" + FINAL_DUMP, tmp_path / "memory", nprocs=nprocs,
              variables={"n": 200})
    build.run(RESTART_RUN + FINAL_DUMP, tmp_path / "whole", nprocs=nprocs,
              variables={"n": 400})
    build.run(RESTART_RUN + "run 200\nwrite_restart half.restart\n", tmp_path / "split",
              nprocs=nprocs)
    build.run(RESTART_CONTINUE + FINAL_DUMP, tmp_path / "split", nprocs=nprocs,
              variables={"n": 200}, name="in.continue")
    a = read_dump(tmp_path / "memory" / "final.dump")[-1]
    b = read_dump(tmp_path / "split" / "final.dump")[-1]
    c = read_dump(tmp_path / "whole" / "final.dump")[-1]
    assert a["timestep"] == b["timestep"] == c["timestep"] == 400
    for name in a:
        if name not in ("timestep", "box"):
            assert np.array_equal(a[name], b[name]), name
            assert relative_difference(b[name], c[name]) < 1.0e-6, name
    pe = [read_thermo(tmp_path / d / "log.lammps")["PotEng"][-1] for d in ("memory", "split")]
    assert pe[0] == pe[1]


# ---------------------------------------------------------------------------
# per-link output, and links that migrate between ranks

# the affine input without its final run 0 and thermo settings
LINK_OUTPUT = AFFINE[:AFFINE.rindex("thermo_style")] + """
compute         l all mca/link id1 id2 state length strain normal shear area force energy
dump            l all local 1 links.dump c_l[1] c_l[2] c_l[3] c_l[4] c_l[5] c_l[6] c_l[7] &
                c_l[8] c_l[9] c_l[10]
dump_modify     l format float %.17g
thermo_style    custom step pe
thermo_modify   format float %.17g
run             1
"""


@pytest.mark.mpi
@pytest.mark.parametrize("nprocs", [1, 2])
def test_link_compute_reports_every_link_once_with_its_tractions(build, tmp_path, nprocs):
    """compute mca/link on a periodic fcc box stretched by 1e-7 along x.

    Every link appears once (4 x 4 x 4 cells: 1536 links) whatever the
    number of ranks; each link's normal traction is lambda eps + 2G eps_l and
    its shear traction 2G eps sqrt(n_x^2 (1 - n_x^2)), with eps_l = n_x^2 eps
    its strain (tolerance 1e-6 of the largest traction: the strain is 1e-7);
    the link energies add up to the pair energy to 1e-8 relative: a link
    across the periodic boundary is evaluated from both of its automata,
    once through a ghost image, and the energy increment is a force times a
    length change dr ~ 5e-8 m found as a difference of lengths ~0.5 m, so
    the two rows agree only to about 1e-16 x 0.5/5e-8 = 1e-9.
    """
    build.run(LINK_OUTPUT, tmp_path, nprocs=nprocs, variables={"lat": "fcc", "nu": 0.3,
                                                               "mode": "xx"})
    snap = read_dump(tmp_path / "links.dump")[-1]
    id1, id2 = snap["c_l[1]"], snap["c_l[2]"]
    assert len(id1) == 1536
    assert np.all(id1 < id2)
    assert len({(a, b) for a, b in zip(id1, id2)}) == 1536
    assert np.all(snap["c_l[3]"] == 1.0)
    r0 = 0.7184 / math.sqrt(2.0)
    assert np.allclose(snap["c_l[5]"], snap["c_l[4]"] / r0 - 1.0, rtol=0, atol=1e-13)
    g, _, lam = moduli(0.3)
    eps = 1.0e-7
    nx2 = np.clip(snap["c_l[5]"] / eps, 0.0, 1.0)    # n_x^2 from the link strain
    scale = (lam + 2 * g) * eps
    assert np.max(np.abs(snap["c_l[6]"] - (lam * eps + 2 * g * nx2 * eps))) < 1e-6 * scale
    assert np.max(np.abs(snap["c_l[7]"] - 2 * g * eps * np.sqrt(nx2 * (1 - nx2)))) < 1e-6 * scale
    assert np.allclose(snap["c_l[9]"], snap["c_l[8]"] * np.hypot(snap["c_l[6]"], snap["c_l[7]"]),
                       rtol=1e-12, atol=0)
    pe = read_thermo(tmp_path / "log.lammps")["PotEng"][-1]
    assert abs(np.sum(snap["c_l[10]"]) - pe) < 1e-8 * abs(pe) and pe > 0


MIGRATE = """
units           si
atom_style      mca
atom_modify     map array
boundary        p p p
processors      * 1 1
lattice         fcc 0.7184
region          box block 0 12 0 4 0 4
create_box      1 box
region          body block 4.99 8.01 -0.01 3.01 -0.01 3.01
create_atoms    1 region body
comm_modify     vel yes
pair_style      mca
pair_coeff      * * E 70.0e9 nu 0.3 rho 2700
variable        vx atom 100.0+0.05*sin(3*y)
variable        vz atom 0.05*cos(2*x)
velocity        all set v_vx 0 v_vz units box
variable        wz atom 0.2*sin(7*x+3*y+5*z)
set             group all omega 0 0 v_wz
fix             integrate all nve/mca
timestep        2.0e-5
compute         s all mca/atom sxx syy szz sxy sxz syz smean
dump            d all custom 3000 states.dump id x y z vx vy vz omegax omegay omegaz fx fy fz &
                c_s[1] c_s[2] c_s[3] c_s[4] c_s[5] c_s[6] c_s[7]
dump_modify     d sort id format float %.17g
thermo_style    custom step pe
thermo_modify   format float %.17g
thermo          500
run             3000
"""


@pytest.mark.mpi
def test_links_migrate_between_ranks(build, tmp_path):
    """A vibrating linked cluster flies through a periodic box at 100 m/s.

    In 3000 steps it moves 6 m, once around the 8.6 m box: its automata and
    their links cross rank boundaries and the periodic boundary many times
    (reneighbouring every step or two).  On 1, 2 and 4 ranks the final
    states agree up to round-off: the ranks see partners through different
    periodic images and sum link forces in another order, so each step adds
    about 1e-15 x 8.6 m of noise to positions.  Measured after 3000 steps:
    positions 1e-11 m (tolerance 1e-10 of the box length) and velocities
    5e-10 m/s (1e-10 of the 100 m/s flight); the vibration itself (spins,
    forces, stresses, transverse velocities), whose displacements are only
    ~1e-5 m, to 3e-8 of its size (tolerance 1e-6).  A link that lost its
    history or its partner on the way would change these by O(1).
    (create_atoms numbers the automata by rank, so they are matched by
    their initial positions.)
    """
    finals = {}
    for nprocs in (1, 2, 4):
        d = tmp_path / f"np{nprocs}"
        build.run(MIGRATE, d, nprocs=nprocs)
        first, last = read_dump(d / "states.dump")
        assert last["timestep"] == 3000
        order = np.lexsort(np.round([first["z"], first["y"], first["x"]], 6))
        finals[nprocs] = {name: last[name][order] for name in last
                          if name not in ("timestep", "box", "id")}
    scales = {"x": 8.6208, "y": 8.6208, "z": 8.6208, "vx": 100.0}
    for nprocs in (2, 4):
        for name, ref in finals[1].items():
            diff = np.max(np.abs(ref - finals[nprocs][name]))
            if name in scales:
                assert diff < 1.0e-10 * scales[name], name
            else:
                assert diff < 1.0e-6 * np.max(np.abs(ref)), name
    # the cluster flew once around the box and still vibrates as one body
    assert np.max(np.abs(finals[1]["c_s[7]"])) > 1.0e4


def migrate_final(build, directory, script, nprocs, extra_args=()):
    build.run(script, directory, nprocs=nprocs, extra_args=extra_args)
    first, last = read_dump(directory / "states.dump")[:2]
    order = np.lexsort(np.round([first["z"], first["y"], first["x"]], 6))
    return last["timestep"], {name: last[name][order] for name in last
                              if name not in ("timestep", "box", "id")}


def assert_same_flight(a, b):
    """The tolerances of test_links_migrate_between_ranks (round-off)."""
    scales = {"x": 8.6208, "y": 8.6208, "z": 8.6208, "vx": 100.0}
    for name, ref in a.items():
        diff = np.max(np.abs(ref - b[name]))
        assert diff < (1.0e-10 * scales[name] if name in scales else
                       1.0e-6 * np.max(np.abs(ref))), name


@pytest.mark.mpi
def test_links_migrate_with_load_balancing_and_restart_files(build, tmp_path):
    """The flight of test_links_migrate_between_ranks on 2 ranks, three ways.

    A link between two local automata has one row, which both automata
    share; an automaton that moves to another rank takes a copy of each of
    its rows, and at the next reneighbouring the rows are shared again (the
    lower ID's kept).  (1) With fix balance rcb, which itself sends atoms to
    other ranks at pre-exchange, before the links fix acts; (2) a restart
    file written in the middle of the run (restart command), whose rows
    hold both ends' copies, read back continues the flight.  Both agree with
    the plain run to round-off.
    """
    _, plain = migrate_final(build, tmp_path / "plain", MIGRATE, 2)
    # recursive bisection with weights that change in time: fix balance
    # itself sends automata to other ranks (irregular communication)
    balanced = MIGRATE.replace("processors      * 1 1\n", "comm_style      tiled\n").replace(
        "fix             integrate all nve/mca\n",
        "variable        wt atom 1.0+0.9*sin(0.01*step+2*x)\n"
        "fix             bal all balance 100 1.0 rcb weight var wt\n"
        "fix             integrate all nve/mca\n")
    assert balanced.count("rcb") == 1 and "tiled" in balanced
    _, other = migrate_final(build, tmp_path / "balance", balanced, 2)
    assert_same_flight(plain, other)
    log = (tmp_path / "balance" / "log.lammps").read_text()

    # a restart file every 1500 steps; continue from the one at step 1500
    with_restart = MIGRATE.replace("run             3000\n",
                                   "restart         1500 flight.*.restart\nrun             3000\n")
    build.run(with_restart, tmp_path / "restart", nprocs=2)
    assert (tmp_path / "restart" / "flight.1500.restart").exists()
    cont = ("read_restart    flight.1500.restart\n" +
            MIGRATE[MIGRATE.index("pair_style"):MIGRATE.index("variable        vx")] +
            "fix             integrate all nve/mca\n" +
            MIGRATE[MIGRATE.index("compute         s all"):].replace("run             3000",
                                                                    "run             1500"))
    build.run(cont, tmp_path / "restart", nprocs=2, name="in.continue")
    # the continued run's dump has its first snapshot at 1500: match by the
    # positions of the plain run's first snapshot instead
    first_plain = read_dump(tmp_path / "plain" / "states.dump")[0]
    order_plain = np.lexsort(np.round([first_plain["z"], first_plain["y"], first_plain["x"]], 6))
    last = read_dump(tmp_path / "restart" / "states.dump")[-1]
    assert last["timestep"] == 3000
    ids = first_plain["id"][order_plain]
    index = {int(t): k for k, t in enumerate(last["id"])}
    rows = [index[int(t)] for t in ids]
    continued = {name: last[name][rows] for name in plain}
    assert_same_flight(plain, continued)
    assert "balance" in log


# ---------------------------------------------------------------------------
# automata created after the links were made

# the cluster of MIGRATE at rest (vibrating only), sorted every 50 steps;
# LATER: what comes after its links are made
LATER_ATOMS = MIGRATE[:MIGRATE.index("compute         s all")].replace(
    "atom_modify     map array\n", "atom_modify     map array sort 50 0.0\n").replace(
    "vx atom 100.0+0.05*sin(3*y)", "vx atom 0.05*sin(3*y)") + """
thermo_style    custom step pe
thermo_modify   format float %.17g
run             200
LATER
compute         s all mca/atom links sxx smean
dump            d all custom 200 states.dump id x y z vx vy vz omegax omegay omegaz fx fy fz &
                c_s[1] c_s[2] c_s[3]
dump_modify     d sort id format float %.17g
run             400
"""
assert "sort 50" in LATER_ATOMS and "100.0" not in LATER_ATOMS
# a second body as large as the first, 0.72 m away (the link length is 0.51 m)
LATER_BODY = "region extra block 0.99 4.01 -0.01 3.01 -0.01 3.01\ncreate_atoms 1 region extra\n"
BODY_ATOMS = 172    # fcc points of a 3 x 3 x 3 cell block, faces included


def later_atoms_runs(build, directory, nprocs, extra_args=()):
    """The vibrating body with and without a second body created after its
    links were made; the last snapshot of each, by atom ID."""
    finals = {}
    for name, later in (("alone", ""), ("later", LATER_BODY)):
        build.run(LATER_ATOMS.replace("LATER\n", later), directory / name, nprocs=nprocs,
                  extra_args=extra_args)
        last = read_dump(directory / name / "states.dump")[-1]
        assert last["timestep"] == 600
        finals[name] = last
    return finals["alone"], finals["later"]


def assert_later_atoms_change_nothing(alone, later):
    """The automata created after the links were made have no links and no
    force, so they stay where they were made; the first body moves as it
    does alone, up to round-off: measured, bit for bit on 1 and 2 ranks and
    on one kk thread (the new automata come after the body's in the atom
    order), and on 2 kk threads, whose chunks of automata move with the atom
    count, 2e-14 m in positions and 5e-9 of the vibration (a strain of
    5e-6: the round-off of a position over a link length, times E, is 4e-9
    of its stress).  Tolerances 1e-10 of the box length and 1e-6 of the
    vibration (velocities, spins, forces, stresses), as in
    test_links_migrate_between_ranks: a link given to a new automaton, or a
    body's link lost when the tables grew, changes them by O(1)."""
    assert len(alone["id"]) == BODY_ATOMS and len(later["id"]) == 2 * BODY_ATOMS
    ids = alone["id"]
    first = np.isin(later["id"], ids)
    assert np.array_equal(later["id"][first], ids)
    new = ~first
    assert np.all(later["c_s[1]"][new] == 0)
    for name in ("vx", "vy", "vz", "omegax", "omegay", "omegaz", "fx", "fy", "fz", "c_s[2]"):
        assert np.all(later[name][new] == 0), name
    # (create_atoms put them on the lattice: x = 0.3592 k)
    step = 0.7184 / 2
    for name in ("x", "y", "z"):
        k = later[name][new] / step
        assert np.max(np.abs(k - np.round(k))) < 1e-12, name
    assert np.array_equal(later["c_s[1]"][first], alone["c_s[1]"])
    assert np.min(alone["c_s[1]"]) >= 3    # every automaton of the body is linked
    for name in alone:
        if name in ("timestep", "box", "id", "c_s[1]"):
            continue
        diff = np.max(np.abs(later[name][first] - alone[name]))
        if name in ("x", "y", "z"):
            assert diff < 1.0e-10 * 8.6208, name
        else:
            scale = np.max(np.abs(alone[name]))
            assert scale > 0 and diff < 1.0e-6 * scale, (name, diff / scale)
        print(f"{name}: largest difference {diff:.2e}"
              + ("" if name in ("x", "y", "z") else f", relative {diff / scale:.1e}"))


@pytest.mark.mpi
@pytest.mark.parametrize("nprocs", [1, 2])
def test_automata_created_after_the_links_start_without_links(build, tmp_path, nprocs):
    """create_atoms after a run: a second body of 172 automata next to a
    linked, vibrating one.  The links fix holds its tables for the local
    automata only (not the ghosts), with a margin of 1/32 and 64 atoms:
    172 new automata make them grow (set_arrays).  The new automata start
    without links and the first body does not notice them."""
    alone, later = later_atoms_runs(build, tmp_path, nprocs)
    assert_later_atoms_change_nothing(alone, later)


@pytest.mark.parametrize("threads", [1, 2])
def test_automata_created_after_the_links_start_without_links_kokkos(tmp_path, threads):
    """The same with pair mca/kk on 1 and 2 host threads (the links fix's
    tables in DualViews, grown on the host and sent to the device)."""
    build = kokkos_build()
    alone, later = later_atoms_runs(build, tmp_path, 1, extra_args=kokkos_args(threads))
    assert_later_atoms_change_nothing(alone, later)
