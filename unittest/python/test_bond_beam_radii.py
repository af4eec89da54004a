"""bond_style beam with sections from the particles' radii (keyword
radii lambda; doc/src/bond_beam.rst, beam_kernels.h radii_section): each
bond's section has the radius R = lambda min(r_i, r_j), a round section
in 3-D (A = pi R^2, I_y = I_z = pi R^4 / 4, J = pi R^4 / 2), a beam of
height 2R per unit thickness in 2-D (A = 2R, I = (2R)^3 / 12).

* the same forces, torques, energy and per-atom stress as a system in
  which every bond has its own type with that section written out (the
  section computed here, independently of the C++), for particles of
  unequal radii, Timoshenko shear included (Phi from each bond's section),
  and the same bonds broken with bending rim as with each bond's fibre
  distance R written out;
* a periodic hexagonal lattice of touching particles (radius L/2) with
  radii lambda has the nu_2D of a rectangular section with h / L = lambda
  (digest case 7);
* the same on 2 ranks and with newton_bond off, with bond damping of
  moving particles (the ghosts' radii give the sections);
* write_data and restart files keep radii and bending rim; the Kokkos
  variant equals the CPU style; bad input gives clear errors.
"""

import math

import numpy as np
import pytest

import mcatest
import test_bond_beam as beam2d
import test_bond_beam_3d as beam3d
from mcatest import read_dump

E_, NU, LAMBDA = 100.0, 0.25, 0.6
G_ = E_ / (2 * (1 + NU))
KS = 5.0 / 6.0


def radii_of(n):
    """Unequal radii (0.35 to 0.65), a function of the particle index."""
    return [0.5 + 0.15 * math.sin(1.7 * k + 0.3) for k in range(n)]


def section(dim, ri, rj):
    """A, I (2-D) or A, I, Iy, Iz, J (3-D) and the rim R of a bond."""
    r = LAMBDA * min(ri, rj)
    if dim == 3:
        i = 0.25 * math.pi * r * r * r * r
        return {"A": math.pi * r * r, "I": i, "J": 2.0 * i, "R": r}
    return {"A": 2.0 * r, "I": 8.0 * r * r * r / 12.0, "R": r}


def data_file(path, dim, sites, bonds, radii, per_bond_types):
    """An atom_style mca data file with per-particle radii; one bond type,
    or one type per bond."""
    ntypes = len(bonds) if per_bond_types else 1
    lines = ["radii test data", "", f"{len(sites)} atoms", "1 atom types",
             f"{len(bonds)} bonds", f"{ntypes} bond types", ""]
    lo, hi = sites.min(axis=0) - 3.0, sites.max(axis=0) + 3.0
    for k, name in enumerate("xyz"[:dim]):
        lines.append(f"{lo[k]} {hi[k]} {name}lo {name}hi")
    if dim == 2:
        lines.append("-0.5 0.5 zlo zhi")
    lines += ["", "Atoms # mca", ""]
    for k, (p, r) in enumerate(zip(sites, radii)):
        z = p[2] if dim == 3 else 0.0
        # (the data file's column is the diameter)
        lines.append(f"{k + 1} 1 1 0 {2 * r:.17g} 1.0 1.0 0.1 {p[0]:.17g} {p[1]:.17g} {z:.17g}")
    lines += ["", "Bonds", ""]
    lines += [f"{k + 1} {k + 1 if per_bond_types else 1} {i + 1} {j + 1}"
              for k, (i, j) in enumerate(bonds)]
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines) + "\n")
    return path


def scene(dim):
    if dim == 3:
        sites, bonds = beam3d.cluster()
        return sites, bonds, beam3d.DEFORM
    sites, bonds = beam2d.hex_patch(2.1)
    return sites, bonds, beam2d.DEFORM


def header(dim, data, newton="on"):
    return (beam3d.header(data, newton=newton) if dim == 3 else beam2d.header(data, newton=newton))


def coefficients(dim, bonds, radii, breaking, radii_words=True, damp=False):
    """bond_coeff lines: radii lambda, or each bond's section written out."""
    shear = f"shear {G_} {KS}" + (" damp 0.02" if damp else "")
    strength = "break 8.0 30.0 bending {}" if breaking else ""
    if radii_words:
        return f"bond_coeff 1 {E_} radii {LAMBDA} {shear} {strength.format('rim')}\n"
    lines = []
    for k, (i, j) in enumerate(bonds):
        s = section(dim, radii[i], radii[j])
        words = f"bond_coeff {k + 1} {E_} {s['A']!r} {s['I']!r} {shear}"
        if dim == 3:
            words += f" section {s['I']!r} {s['I']!r} {s['J']!r}"
        lines.append(f"{words} {strength.format(repr(s['R']))}\n")
    return "".join(lines)


# a velocity field for the bond damping (the particles' spins stay 0)
MOVING = """
variable        vx atom 0.2*sin(1.9*id)
variable        vy atom 0.3*cos(0.8*id)
variable        vz atom 0.1*sin(2.6*id+1)
velocity        all set v_vx v_vy {vz}
"""


def deformed_state(build, directory, dim, radii_words, breaking=False, extra_args=(),
                   nprocs=1, newton="on", damp=False):
    sites, bonds, deform = scene(dim)
    radii = radii_of(len(sites))
    data = data_file(directory / "scene.data", dim, np.asarray(sites), bonds, radii,
                     per_bond_types=not radii_words)
    script = header(dim, data, newton) + ("comm_modify vel yes\n" if damp else "") + \
        "bond_style beam\n" + \
        coefficients(dim, bonds, radii, breaking, radii_words, damp) + deform
    if damp:
        script += MOVING.format(vz="v_vz" if dim == 3 else "0.0")
    if nprocs == 2:
        # the ranks split the scene along x: bonds between owned and ghost atoms
        script = script.replace("read_data", "processors 2 1 1\nread_data")
    names = ["fx", "fy", "tqz", "c_pe"] + (["fz", "tqx", "tqy"] if dim == 3 else [])
    names += [f"c_st[{k}]" for k in (1, 2, 4)]
    script += f"""
compute         pe all pe/atom bond
compute         st all stress/atom NULL bond
thermo_style    custom step pe press bonds
thermo_modify   norm no format float %.17g
dump            d all custom 1 state.dump id {' '.join(names)}
dump_modify     d format float %.17g
run             0 post no
"""
    build.run(script, directory, extra_args=extra_args, nprocs=nprocs)
    thermo = mcatest.read_thermo(directory / "log.lammps")
    return read_dump(directory / "state.dump")[0], thermo, names, len(bonds)


@pytest.mark.parametrize("dim", [2, 3])
def test_radii_sections_are_the_written_out_sections(build, tmp_path, dim):
    snap, thermo, names, _ = deformed_state(build, tmp_path / "radii", dim, True)
    ref, ref_thermo, _, _ = deformed_state(build, tmp_path / "typed", dim, False)
    worst = max(np.abs(snap[c] - ref[c]).max() / np.abs(ref[c]).max() for c in names)
    de = abs(thermo["PotEng"][-1] / ref_thermo["PotEng"][-1] - 1)
    print(f"{dim}-D: largest relative difference {worst:.1e}, energy {de:.1e}")
    # the same arithmetic on the same numbers but for the section's last
    # bit (computed in C++ here, in Python there): round-off
    assert worst < 1e-13 and de < 1e-13
    # (the scene's sections differ from bond to bond by a factor 1.8 in R,
    # and many bonds join unequal radii: the equality checks lambda min(r_i, r_j))


@pytest.mark.parametrize("dim", [2, 3])
def test_bending_rim_breaks_the_written_out_bonds(build, tmp_path, dim):
    """Strengths low enough that some bonds of the deformed scene break
    (sigma0 8, tau0 30, fibre at each bond's R): the same bonds left."""
    snap, thermo, names, nbonds = deformed_state(build, tmp_path / "radii", dim, True, True)
    ref, ref_thermo, _, _ = deformed_state(build, tmp_path / "typed", dim, False, True)
    left, ref_left = thermo["Bonds"][-1], ref_thermo["Bonds"][-1]
    worst = max(np.abs(snap[c] - ref[c]).max() / np.abs(ref[c]).max() for c in names)
    print(f"{dim}-D: {nbonds - left:.0f} of {nbonds} bonds broken (written out: "
          f"{nbonds - ref_left:.0f}); forces of the rest to {worst:.1e}")
    assert 0 < left < nbonds    # some break, not all: the rim decides
    assert left == ref_left and worst < 1e-13


@pytest.mark.parametrize("dim", [2, 3])
def test_radii_with_damping_on_ranks_and_newton(build, tmp_path, dim):
    """Sections from the radii of ghost particles: the deformed scene with
    breaking (bending rim) and bond damping on moving particles, on 2 ranks
    (split across the scene), with newton_bond off and both: the same
    bonds broken, forces, torques, per-atom energy and stress to 1e-13 of
    their scale (the sums in another order); and the damping does act
    (the forces differ from the undamped ones by more than 1e-3)."""
    ref, ref_thermo, names, nbonds = deformed_state(build, tmp_path / "ref", dim, True, True,
                                                    damp=True)
    still, _, _, _ = deformed_state(build, tmp_path / "still", dim, True, True)
    moved = max(np.abs(ref[c] - still[c]).max() / np.abs(still[c]).max()
                for c in ("fx", "fy"))
    assert moved > 1e-3
    for nprocs, newton in ((2, "on"), (1, "off"), (2, "off")):
        snap, thermo, _, _ = deformed_state(build, tmp_path / f"{nprocs}{newton}", dim, True,
                                            True, nprocs=nprocs, newton=newton, damp=True)
        worst = max(np.abs(snap[c] - ref[c]).max() / np.abs(ref[c]).max() for c in names)
        print(f"{dim}-D, {nprocs} ranks, newton_bond {newton}: {nbonds - thermo['Bonds'][-1]:.0f}"
              f" of {nbonds} broken, largest relative difference {worst:.1e} (damping changes "
              f"the forces by {moved:.1e})")
        assert thermo["Bonds"][-1] == ref_thermo["Bonds"][-1] and worst < 1e-13


def test_touching_radii_give_the_lattice_of_h_over_l(build, tmp_path):
    """Touching particles (r = L/2) with radii lambda: h = lambda L, the
    lattice's nu_2D = (1 - lambda^2) / (3 + lambda^2) (case 7)."""
    lc = beam2d.calibration_tool()
    e2, nu2 = beam2d.lattice_moduli(build, tmp_path, f"50.0 radii {LAMBDA}", diameter=1.0)
    kn, ks = lc.beam_stiffness(50.0, LAMBDA, LAMBDA ** 3 / 12.0, 1.0)
    ref = lc.beam_moduli(kn, ks)
    print(f"radii {LAMBDA}: E_2D {e2:.8f} (tool {ref['E2']:.8f}), nu_2D {nu2:.8f} "
          f"(rectangle h/L = {LAMBDA}: {lc.rectangular_beam_nu2(LAMBDA):.8f})")
    # strain 1e-6: the geometric nonlinearity is of that order
    assert e2 == pytest.approx(ref["E2"], rel=1e-5)
    assert nu2 == pytest.approx(lc.rectangular_beam_nu2(LAMBDA), rel=1e-5)


@pytest.mark.parametrize("threads", [1, 2])
@pytest.mark.parametrize("dim", [2, 3])
def test_kokkos_radii_sections_match_the_cpu_style(tmp_path, dim, threads):
    kk = mcatest.kokkos_build()
    cpu, _, names, _ = deformed_state(kk, tmp_path / "cpu", dim, True, True)
    dev, _, _, _ = deformed_state(kk, tmp_path / "kk", dim, True, True,
                                  extra_args=mcatest.kokkos_args(threads))
    worst = max(np.abs(dev[c] - cpu[c]).max() / np.abs(cpu[c]).max() for c in names)
    print(f"kk, {dim}-D, {threads} thread(s): largest relative difference {worst:.1e}")
    # one thread adds in the CPU style's order; two in another
    assert worst < (1e-15 if threads == 1 else 1e-12)


def test_data_and_restart_files_keep_radii(build, tmp_path):
    sites, bonds, deform = scene(3)
    radii = radii_of(len(sites))
    data = data_file(tmp_path / "scene.data", 3, np.asarray(sites), bonds, radii, False)
    data.write_text(data.read_text().replace("1 bond types", "2 bond types"))
    script = header(3, data) + f"""
bond_style      beam
bond_coeff      1 {E_} radii {LAMBDA} poisson {NU} break 3.0 30.0 bending rim
bond_coeff      2 {E_} 0.1 0.001 poisson {NU}
""" + deform + """
run             0 post no
write_data      first.data
write_restart   state.restart
write_dump      all custom first.dump id fx fy fz tqx tqy tqz modify format float %.17g
"""
    build.run(script, tmp_path)
    text = (tmp_path / "first.data").read_text()
    coeffs = text[text.index("Bond Coeffs"):].split("\n\n")[1]
    print(coeffs)
    assert f"1 100 radii {LAMBDA:.17g} poisson 0.25 break 3 30 bending rim" in coeffs
    # read back and written again: the same lines
    again = """
units           lj
atom_style      mca
bond_style      beam
read_data       first.data
write_data      second.data
"""
    build.run(again, tmp_path)
    text = (tmp_path / "second.data").read_text()
    assert text[text.index("Bond Coeffs"):].split("\n\n")[1] == coeffs
    restart = """
read_restart    state.restart
run             0 post no
write_dump      all custom second.dump id fx fy fz tqx tqy tqz modify format float %.17g
"""
    build.run(restart, tmp_path)
    first, second = (read_dump(tmp_path / f)[0] for f in ("first.dump", "second.dump"))
    worst = max(np.abs(second[c] - first[c]).max() / np.abs(first[c]).max()
                for c in ("fx", "fy", "fz", "tqx", "tqy", "tqz"))
    print(f"restarted: forces and torques to {worst:.1e}")
    # the same bonds in the same order: round-off at most
    assert worst < 1e-14


BAD = [
    ("lambda", "bond_coeff 1 1.0 radii 0", r"radii lambda = 0 must be > 0"),
    ("section", "bond_coeff 1 1.0 radii 0.5 poisson 0.3 section 1 1 1",
     r"section and radii exclude each other"),
    ("rim", "bond_coeff 1 1.0 0.1 0.001 poisson 0.3 break 1 1 bending rim",
     r"bending rim needs a section from the radii"),
]


@pytest.mark.parametrize("case", BAD, ids=[c[0] for c in BAD])
def test_bad_radii_input_gives_clear_errors(build, tmp_path, case):
    beam2d.expect_error(build, tmp_path, 3, case[1], case[2])


def test_a_particle_without_radius_gives_a_clear_error(build, tmp_path):
    beam2d.expect_error(build, tmp_path, 3,
                        "set atom 2 diameter 0.0\nbond_coeff 1 1.0 radii 0.5 poisson 0.3",
                        r"a bond of type 1 \(section from the radii\) joins a particle of "
                        r"radius 0")
