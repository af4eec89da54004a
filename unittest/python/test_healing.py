"""Healing of contacts into links ("pair_style mca ... contacts coulomb
healing weld", pair_coeff keyword heal; doc/src/pair_mca.rst, "Healing").

* press and pull (validation 4 of the issue): a block of linked automata
  pressed onto a plane of other automata, not linked to it, and then
  pulled off.  With a healing pressure below the contact traction of the
  press the four contacts weld, and the welds carry the pull (the plane
  feels tension, the block stays on it); above it, or where the type pair
  may not heal, nothing welds and the block comes off without a pull on
  the plane;
* a weld breaks like any link: with the fracture part and an elliptic
  criterion on the type pair, the pull peaks at the strength of the welds;
  that run (contacts made, healed, broken) gives the same trajectory and
  the same counts on 2 MPI ranks, with the kk styles on 1 thread (bit for
  bit) and 2 threads, and across a restart file written while welded;
* the energy balance of a free impact that welds a cube onto a plate:
  kinetic + elastic + friction + the energy the contacts left (their
  elastic energy when they healed) stays constant to the integrator's
  error;
* bad input: errors that name the argument and what is allowed.
"""

import numpy as np
import pytest

from mca_inputs import block_on_plane
from mcatest import kokkos_args, kokkos_build, read_thermo

R = 1.0e-3          # m, radius of the automata (sc packing, spacing 2R)
E, NU = 70.0e9, 0.3
DT = 5.0e-8         # s; the stable time step of these scenes is about 2e-7 s
LOAD = 28.0         # N per automaton of the top layer: 28 N on each contact
AREA = 4.0 * R * R  # reference area of a link or contact of the sc packing
PRESSURE = LOAD / AREA    # 7 MPa, the static traction of the press
PRESS_STEPS = 1000
PULL_STEPS = 2000
V_PULL = 0.1        # m/s

# a 2 x 2 x 2 block (type 2) on a 4 x 4 plane (type 1), not linked to it
# (four contacts under the block), pressed by a load on its top layer
# while damped, then pulled up at V_PULL by its top layer, undamped; the
# plane is held: its fix's force is what the block does to it
PRESS_PULL = block_on_plane("-2 6 -2 6 -2 8", "-0.5 3.5 -0.5 3.5 -0.5 0.5",
                            "0.5 2.5 0.5 2.5 0.5 2.5", 1.5, atom_modify="map array sort 0 0") + """region          low block INF INF INF INF 0.5 1.5
group           bottom region low
pair_style      mca contacts coulomb healing weld {parts}
pair_coeff      * * E {E} nu {nu} rho 2700 friction 0.3 {heal_all}
pair_coeff      1 2 link no {heal}
fix             nve all nve/mca
fix             plane plane mca/setvelocity 0 0 0
fix             load top addforce 0 0 -{load}
fix             damp block mca/damping 2e5
timestep        {dt}
{outputs}
run             {press}
unfix           load
unfix           damp
fix             pull top mca/setvelocity NULL NULL {v}
"""
# (groups are in the restart file)
OUTPUT = """
compute         a all mca/atom healed contacts
compute         A all reduce sum c_a[1] c_a[2]
compute         zb bottom com
{outputs}
thermo_style    custom step f_plane[3] c_A[1] c_A[2] c_zb[3] {columns}
thermo_modify   format float %.17g
thermo          10
"""
PULL_OUTPUT = """
dump            d all custom 500 pull.dump id x y z vx vy vz omegax omegay omegaz
dump_modify     d format float %.17g sort id
"""


def press_pull(build, directory, heal, heal_all="", parts="", outputs="", columns="",
               nprocs=1, extra_args=(), split_at=None, restart=False):
    """The run; split_at: the pull in two runs, split after split_at of its
    steps in memory or (restart) through a restart file."""
    output = OUTPUT.format(outputs=outputs, columns=columns)
    script = PRESS_PULL.format(spacing=2 * R, radius=R, skin=0.2 * R, E=E, nu=NU, load=LOAD,
                               dt=DT, press=PRESS_STEPS, v=V_PULL, heal=heal,
                               heal_all=heal_all, parts=parts, outputs=output)
    if split_at is None:
        script += PULL_OUTPUT + f"run {PULL_STEPS}\n"
    elif not restart:
        script += f"run {split_at}\n" + PULL_OUTPUT + f"run {PULL_STEPS - split_at}\n"
    else:
        script += (f"run {split_at}\nwrite_restart pull.restart\nclear\n"
                   "atom_modify map array sort 0 0\nread_restart pull.restart\n"
                   "comm_modify vel yes\nneighbor {skin} bin\n"
                   "neigh_modify delay 0 every 1 check yes\n"
                   "fix nve all nve/mca\ntimestep {dt}\n"
                   "fix plane plane mca/setvelocity 0 0 0\n"
                   "fix pull top mca/setvelocity NULL NULL {v}\n".format(skin=0.2 * R, dt=DT,
                                                                          v=V_PULL)
                   + output + PULL_OUTPUT + f"run {PULL_STEPS - split_at}\n")
    build.run(script, directory, nprocs=nprocs, extra_args=extra_args)
    return all_runs(directory / "log.lammps")


def all_runs(log):
    """The thermo output of every run of a log (the press and the pull),
    one after the other (the step that ends a run and starts the next
    appears once)."""
    lines = log.read_text().splitlines()
    starts = [k for k, line in enumerate(lines) if line.split()[:1] == ["Step"]]
    runs = []
    for k, start in enumerate(starts):
        piece = log.with_name(f"{log.name}.run{k}")
        piece.write_text("\n".join(lines[start:(starts + [len(lines)])[k + 1]]) + "\n")
        runs.append(read_thermo(piece))
    merged = {}
    for key in runs[-1]:
        parts = [run[key][(1 if k > 0 else 0):] for k, run in enumerate(runs)]
        merged[key] = np.concatenate(parts)
    return merged


def phases(t):
    """The press (up to its last step) and the pull."""
    pull = t["Step"] > PRESS_STEPS
    return ~pull, pull


def test_weld_carries_tension(build, tmp_path):
    """Healing pressure half the static traction: the four contacts weld
    while pressed, and the pull stretches the welds: the plane is pulled
    up, the bottom of the block stays on it."""
    t = press_pull(build, tmp_path, heal=f"heal {0.5 * PRESSURE}")
    press, pull = phases(t)
    push = -t["f_plane[3]"][press][-1]     # > 0: the block pushes the plane down
    pulled = t["f_plane[3]"][pull].max()
    healed = t["c_A[1]"]
    rise = t["c_zb[3]"][-1] - t["c_zb[3]"][press][-1]
    lift = V_PULL * PULL_STEPS * DT
    print(f"\nweld: press {push:.2f} N on the plane ({4 * LOAD:.0f} N applied), "
          f"{healed[-1]:.0f} links healed (at step {t['Step'][np.argmax(healed > 0)]}); "
          f"pull: the plane feels up to {pulled:.1f} N of tension; the bottom of the block "
          f"rose {rise:.3e} m while its top rose {lift:.1e} m")
    assert healed[-1] == 4
    # the press settled to the load (damped; 1 %)
    assert abs(push / (4 * LOAD) - 1.0) < 1e-2
    # tension: the welds carry much more than the press (the top moved
    # 1e-5 m against a stiffness of ~ 1.4e8 N/m per column)
    assert pulled > 10 * 4 * LOAD
    # the block stays on the plane: its bottom rises by the stretch of the
    # welds, which are in series with the block's links of the same
    # stiffness: half the lift (not all of it, as a block that came off)
    assert rise < 0.6 * lift


@pytest.mark.parametrize("case", [
    dict(name="pressure above the press", heal=f"heal {4.0 * PRESSURE}", coeff=""),
    dict(name="type pair forbidden", heal="heal no", coeff=f"heal {0.5 * PRESSURE}"),
])
def test_no_weld(build, tmp_path, case):
    """No weld: with a healing pressure four times the static traction
    (the dynamic press peaks at about twice it), or with the plane-block
    pair forbidden while each material may heal with itself: the contacts
    only push, the plane never feels a pull and the block comes off."""
    t = press_pull(build, tmp_path, heal=case["heal"], heal_all=case["coeff"])
    press, pull = phases(t)
    push = -t["f_plane[3]"][press][-1]
    pulled = t["f_plane[3]"].max()
    rise = t["c_zb[3]"][-1] - t["c_zb[3]"][press][-1]
    lift = V_PULL * PULL_STEPS * DT
    print(f"\n{case['name']}: healed {t['c_A[1]'].max():.0f}; press {push:.2f} N, largest "
          f"upward force on the plane {pulled:.3e} N; the block's bottom rose {rise:.3e} m "
          f"of the top's {lift:.1e} m; contacts pushing at the end {t['c_A[2]'][-1]:.0f}")
    assert t["c_A[1]"].max() == 0
    # contacts push only: the plane is never pulled (a tilt of the normals
    # could give 1e-3 of the press at most)
    assert pulled < 1e-3 * push
    # the block came off: nothing touches at the end, its bottom follows
    # its top
    assert t["c_A[2]"][-1] == 0
    assert rise > 0.9 * lift


# the work criterion: the block yields under the press (yield 5 MPa,
# hardening 1 GPa, pressed at 7 MPa), the plane stays elastic
PLASTIC_BLOCK = (f"pair_coeff      2 2 E {E} nu {NU} rho 2700 yield 5e6 hardening 1e9\n"
                 "compute         ep bottom mca/atom epsp\n"
                 "compute         EP bottom reduce max c_ep")


def test_work_criterion(build, tmp_path):
    """heal p work w: a contact welds once one of its automata has done the
    plastic work w per volume.  A probe press (no healing) gives the
    largest plastic strain of the block's bottom at the end of the press,
    eps_p, and so its plastic work density w_p = sigma_y eps_p + H eps_p^2/2
    (linear hardening); with w = w_p / 2 the contacts weld, later than on
    pressure alone, at the same steps on 2 ranks; with w = 2 w_p never."""
    probe = press_pull(build, tmp_path / "probe", heal="heal no", parts="plasticity mises",
                       outputs=PLASTIC_BLOCK, columns="c_EP")
    press, _ = phases(probe)
    eps = probe["c_EP"][press][-1]
    w_p = 5e6 * eps + 0.5 * 1e9 * eps * eps
    runs = {}
    for factor in (0.5, 2.0):
        runs[factor] = press_pull(build, tmp_path / f"w{factor}",
                                  heal=f"heal {0.5 * PRESSURE} work {factor * w_p}",
                                  parts="plasticity mises", outputs=PLASTIC_BLOCK, columns="c_EP")
    pressure_only = press_pull(build, tmp_path / "pressure", heal=f"heal {0.5 * PRESSURE}",
                               parts="plasticity mises", outputs=PLASTIC_BLOCK, columns="c_EP")
    # on 2 ranks the plastic strain of a ghost automaton is that of the step
    # (sent after the return): the same heals at the same steps
    two = press_pull(build, tmp_path / "mpi2", heal=f"heal {0.5 * PRESSURE} work {0.5 * w_p}",
                     parts="plasticity mises", outputs=PLASTIC_BLOCK, columns="c_EP", nprocs=2)

    def first_heal(t):
        return t["Step"][np.argmax(t["c_A[1]"] > 0)] if t["c_A[1]"].max() > 0 else None

    print(f"\nwork criterion: the block's bottom reaches eps_p {eps:.3e}, w_p {w_p:.4e} J/m^3; "
          f"healed with w = w_p/2: {runs[0.5]['c_A[1]'][-1]:.0f} (first at step "
          f"{first_heal(runs[0.5])}), with 2 w_p: {runs[2.0]['c_A[1]'][-1]:.0f}; on pressure "
          f"alone: first at step {first_heal(pressure_only)}")
    assert eps > 0
    assert runs[0.5]["c_A[1]"][-1] == 4
    assert runs[2.0]["c_A[1]"].max() == 0
    # the work comes after the pressure: the weld waits for it
    assert first_heal(runs[0.5]) > first_heal(pressure_only)
    assert np.array_equal(two["c_A[1]"], runs[0.5]["c_A[1]"])


# the welds break: elliptic criterion on the plane-block pair with a
# strength sigma0 well above the press (no break while pressed) and tau0
STRENGTH = 40.0e6
BREAK = f"pair_coeff      1 2 break elliptic {STRENGTH} {STRENGTH}"
FRACTURE_OUTPUT = """compute         frac all mca/fracture
variable        broken equal c_frac[1]"""


def weld_break(build, directory, **kwargs):
    return press_pull(build, directory, heal=f"heal {0.5 * PRESSURE}", parts="fracture links",
                      outputs=BREAK + "\n" + FRACTURE_OUTPUT, columns="v_broken", **kwargs)


def test_weld_breaks_at_its_strength(build, tmp_path):
    """The welds are links: they break by their criterion.  The tension of
    the plane peaks at the strength of the four welds, 4 A sigma0 (their
    tractions are sigma0 at the break, the area within the strain of the
    link of A0), and falls to zero once they broke."""
    t = weld_break(build, tmp_path)
    press, pull = phases(t)
    peak = t["f_plane[3]"][pull].max()
    strength = 4 * AREA * STRENGTH
    print(f"\nweld breaks: healed {t['c_A[1]'][-1]:.0f}, broken {t['v_broken'][-1]:.0f}; "
          f"peak pull {peak:.1f} N against 4 A0 sigma0 = {strength:.1f} N "
          f"({peak / strength - 1:+.2e}); force at the end {t['f_plane[3]'][-1]:.3e} N")
    assert t["c_A[1]"][-1] == 4 and t["v_broken"][-1] == 4
    assert t["v_broken"][press].max() == 0
    # sampled every 10 steps while the load rises by ~ 0.4 % of it per
    # step: within 5 %
    assert abs(peak / strength - 1.0) < 5e-2
    assert abs(t["f_plane[3]"][-1]) < 1e-3 * strength


def final_state(directory):
    """The last snapshot of the pull's dump, the automata in the order of
    their positions in its first (create_atoms numbers them differently on
    different numbers of ranks)."""
    from test_contacts import final_state as ordered_state
    return ordered_state(directory, name="pull.dump")


def difference(a, b):
    """Largest difference of positions (relative to the spacing 2R) and of
    velocities and spins (relative to their largest value)."""
    dx = np.abs(a[:, :3] - b[:, :3]).max() / (2 * R)
    dv = np.abs(a[:, 3:6] - b[:, 3:6]).max() / np.abs(b[:, 3:6]).max()
    dw = np.abs(a[:, 6:] - b[:, 6:]).max() / max(np.abs(b[:, 6:]).max(), 1e-300)
    return max(dx, dv, dw)


@pytest.fixture(scope="module")
def weld_reference(tmp_path_factory):
    from mcatest import available_builds
    build = available_builds()[0]
    directory = tmp_path_factory.mktemp("weld_reference")
    thermo = weld_break(build, directory)
    return build, thermo, final_state(directory)


def same_events(a, b):
    for key in ("c_A[1]", "v_broken"):
        assert np.array_equal(a[key], b[key]), key


@pytest.mark.parametrize("mode", ["mpi2", "mpi4", "restart"])
def test_weld_break_mpi_and_restart(weld_reference, tmp_path, mode):
    """Heal and break on 2 and 4 ranks (against one), and across a restart file
    written while welded (against the same split in memory: a new run's
    setup rounds differently, as in test_contacts)."""
    build, thermo, state = weld_reference
    if mode.startswith("mpi"):
        t = weld_break(build, tmp_path, nprocs=int(mode[3:]))
        bound = 1e-8
    else:
        split = PULL_STEPS // 4
        t = weld_break(build, tmp_path, split_at=split, restart=True)
        memory = tmp_path / "memory"
        weld_break(build, memory, split_at=split)
        state = final_state(memory)
        bound = 0.0
    d = difference(final_state(tmp_path), state)
    print(f"\nweld breaks, {mode}: healed {t['c_A[1]'][-1]:.0f}, broken "
          f"{t['v_broken'][-1]:.0f}; largest difference from the reference {d:.2e}")
    assert t["c_A[1]"][-1] == 4 and t["v_broken"][-1] == 4
    if mode.startswith("mpi"):
        same_events(t, thermo)
    assert d <= bound


@pytest.mark.parametrize("threads", [1, 2])
def test_weld_break_kk(tmp_path, threads):
    """The kk styles: one thread in the CPU style's order (the same bits),
    two threads (or a GPU) to round-off; the same heals and breaks."""
    kk = kokkos_build()
    t = weld_break(kk, tmp_path, extra_args=kokkos_args(threads))
    host = tmp_path / "cpu"
    t_host = weld_break(kk, host)
    d = difference(final_state(tmp_path), final_state(host))
    print(f"\nweld breaks with the kk styles on {threads} thread(s): largest difference "
          f"from the CPU styles {d:.2e}")
    same_events(t, t_host)
    assert d < (1e-14 if threads == 1 else 1e-8)


def test_impact_welds_energy_balance(build, tmp_path):
    """The oblique impact of test_contacts with the cube and the plate
    free to weld at 20 MPa (the impact presses their contacts to ~ 80
    MPa): kinetic (translation and spin) + elastic + friction + what the
    contacts left (their elastic energy when they healed) stays constant
    to the integrator's error, as without healing (2e-3)."""
    from test_contacts import IMPACT, IMPACT_OUTPUT, IMPACT_STEPS
    script = IMPACT.format(spacing=2 * R, radius=R, skin=0.2 * R, E=E, nu=NU, dt=DT,
                           drop=-1.5 * R)
    script = script.replace("pair_style      mca contacts coulomb",
                            "pair_style      mca contacts coulomb healing weld")
    script = script.replace("pair_coeff      1 2 link no", "pair_coeff      1 2 link no heal 20e6")
    script += IMPACT_OUTPUT + (
        "compute         h all mca/atom healed\n"
        "compute         H all reduce sum c_h\n"
        "thermo_style    custom step ke c_erot pe c_A[1] c_A[2] c_A[3] v_etot c_H\n"
        f"run {IMPACT_STEPS}\n")
    build.run(script, tmp_path)
    t = {k: np.asarray(v) for k, v in read_thermo(tmp_path / "log.lammps").items()}
    total, healed, left = t["v_etot"], t["c_H"], t["c_A[2]"]
    e0 = total[0]
    error = np.abs(total - e0).max() / e0
    print(f"\nimpact that welds: {healed[-1]:.0f} contacts healed (first at step "
          f"{t['Step'][np.argmax(healed > 0)]:.0f}); their elastic energy then "
          f"{left[-1] / e0:.2e} of the energy, friction {t['c_A[1]'][-1] / e0:.2e}; kinetic at "
          f"the end {(t['KinEng'][-1] + t['c_erot'][-1]) / e0:.3f}; balance error {error:.2e}")
    assert healed[-1] >= 4
    assert left[-1] > 0
    assert error < 2e-3


def bad_script(style, coeff):
    """Two automata 0.1 R apart, not linked (test_contacts.BAD): bad input
    is found at the setup."""
    from test_contacts import BAD, DEFAULT_NEIGH
    return BAD.format(style=style, coeff=coeff, neigh=DEFAULT_NEIGH)


@pytest.mark.parametrize("case", [
    dict(style="contacts coulomb healing weld", coeff="heal 0",
         error="heal pressure (compressive normal traction) must be > 0, got 0 ('heal no' "
               "forbids healing)"),
    dict(style="contacts coulomb healing weld", coeff="heal 1e6 work -1",
         error="heal work (plastic work per volume of an automaton) must be >= 0, got -1"),
    dict(style="contacts coulomb healing weld", coeff="heal 1e6 work",
         error="Illegal pair_coeff heal ... work command: missing argument"),
    dict(style="healing weld", coeff="heal 1e6",
         error="healing weld needs contacts to heal: add 'contacts coulomb'"),
    dict(style="contacts coulomb", coeff="heal 1e6",
         error="pair_coeff heal is given but the link model has no healing part: add "
               "'healing weld'"),
    dict(style="contacts coulomb healing weld", coeff="heal 1e6 work 1e5",
         error="pair_coeff heal ... work needs the plastic work of the automata: add "
               "'plasticity mises'"),
    dict(style="contacts coulomb healing stick", coeff="",
         error="Unknown healing part stick for pair_style mca (allowed: weld)"),
    dict(style="contacts coulomb", coeff="weld 1",
         error="Unknown pair_coeff keyword weld for pair mca"),
])
def test_bad_input(build, tmp_path, case):
    result = build.run(bad_script(case["style"], case["coeff"]), tmp_path, check=False)
    output = result.stdout + result.stderr
    assert result.returncode != 0
    assert case["error"] in output, output[-2000:]


def test_healing_without_criterion_warns(build, tmp_path):
    result = build.run(bad_script("contacts coulomb healing weld", ""), tmp_path)
    assert "healing weld without a healing criterion for any pair of atom types heals " \
        "nothing" in result.stdout
