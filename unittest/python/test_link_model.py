"""The link model and its restart files (doc/src/Developer_mca.rst).

* restart files of the previous version (links without block names,
  materials without keyword names; data/v1.*.restart.gz, written by commit
  fc225c0 at step 100 of SCENE) are read, and a run continued from them is
  the same, bit for bit, as one continued from a file the present version
  wrote at the same step: the elastic law is unchanged, so both files hold
  the same numbers, and any value read into the wrong place shows;
* restart files of history layout 1 with named blocks (a couple in each
  half; data/layout1.plastic.*.restart.gz, written by commit 3346f0f at
  step 100 of PLASTIC_SCENE: damping, plasticity and fracture, the automata
  yielding) are converted as they are read, and a run continued from them
  is the same, bit for bit, as one continued from the present version's
  file: the hi couple moves into the plasticity block, every other value
  to its new place, and any value put in the wrong place shows;
* a file whose link blocks or material keywords this version does not know
  is refused with an error naming them;
* parts of the link law are chosen by keyword, unknown ones refused.
"""

import gzip
import pathlib
import re

DATA = pathlib.Path(__file__).resolve().parent / "data"

SCENE = """
# a periodic fcc box with links across the boundaries, sheared and rattled
units           si
atom_style      mca
atom_modify     map array
boundary        p p p
lattice         fcc 0.7184 origin 0.25 0.25 0.25
region          box prism 0 2 0 2 0 2 0 0 0
create_box      2 box
create_atoms    1 box
set             group all type/fraction 2 0.3 4321
comm_modify     vel yes
pair_style      mca
pair_coeff      1 1 E 70e9 nu 0.3 rho 2700
pair_coeff      2 2 E 200e9 nu 0.25 rho 7800
velocity        all create 1.0e-3 8765 loop geom
fix             integrate all nve/mca
fix             shear all deform 1 xy erate 1.0e-3 remap v
timestep        2.0e-5
run             100
write_restart   new.restart
"""

CONTINUE = """
read_restart    {restart}
fix             integrate all nve/mca
fix             shear all deform 1 xy erate 1.0e-3 remap v
timestep        2.0e-5
compute         s all mca/atom smean seq links
dump            d all custom 25 dump.txt id x y z vx vy vz fx fy fz tqx tqy tqz c_s[*]
dump_modify     d sort id format float %.17g
thermo_style    custom step pe press pxy
thermo_modify   format float %.17g
run             50
"""


# the scene of the layout-1 files: blocks before and after the plasticity
# block, which gained the couple of hi; the shear yields the automata
# (the largest plastic strain at step 100 is about 0.0095), so the halves'
# couples differ
PLASTIC_SCENE = SCENE.replace(
    """pair_style      mca
pair_coeff      1 1 E 70e9 nu 0.3 rho 2700
pair_coeff      2 2 E 200e9 nu 0.25 rho 7800
velocity        all create 1.0e-3 8765 loop geom""",
    """pair_style      mca damping viscous plasticity mises fracture links
pair_coeff      1 1 E 70e9 nu 0.3 rho 2700 eta 2e4 yield 2e5 hardening 1e9 break strain 0.5
pair_coeff      2 2 E 200e9 nu 0.25 rho 7800 eta 2e4 yield 4e5 hardening 2e9 break strain 0.5
velocity        all create 1.0e-2 8765 loop geom""").replace("erate 1.0e-3", "erate 5.0")
PLASTIC_CONTINUE = CONTINUE.replace("erate 1.0e-3", "erate 5.0").replace("seq links", "seq links epsp")


def previous_version_file(build, directory):
    """The previous version's restart file for this build's LAMMPS version."""
    name = "kokkos" if build.name == "kokkos" else "current"
    data = (DATA / f"v1.{name}.restart.gz").read_bytes()
    path = directory / "old.restart"
    path.write_bytes(gzip.decompress(data))
    return path


def thermo_lines(directory):
    log = (directory / "log.lammps").read_text()
    return [line for line in log.splitlines() if re.match(r"\s+\d+\s+-?\d", line)]


def continued(build, directory, restart):
    build.run(CONTINUE.format(restart=restart.name), directory)
    return (directory / "dump.txt").read_text(), thermo_lines(directory)


def test_previous_version_restart_continues_bit_for_bit(build, tmp_path):
    new_dir, old_dir = tmp_path / "new", tmp_path / "old"
    build.run(SCENE, new_dir)
    dump_new, thermo_new = continued(build, new_dir, new_dir / "new.restart")
    old_dir.mkdir()
    dump_old, thermo_old = continued(build, old_dir, previous_version_file(build, old_dir))
    assert len(dump_new.splitlines()) > 3 * 32, "the continued run wrote no dump"
    assert thermo_new and thermo_old == thermo_new
    assert dump_old == dump_new


def test_layout1_restart_with_plasticity_continues_bit_for_bit(build, tmp_path):
    assert "pair_style      mca damping" in PLASTIC_SCENE and "erate 5.0" in PLASTIC_SCENE
    name = "kokkos" if build.name == "kokkos" else "current"
    old_dir, new_dir = tmp_path / "old", tmp_path / "new"
    old_dir.mkdir()
    new_dir.mkdir()
    old = old_dir / "old.restart"
    old.write_bytes(gzip.decompress((DATA / f"layout1.plastic.{name}.restart.gz").read_bytes()))
    build.run(PLASTIC_SCENE, new_dir)
    runs = []
    for directory, restart in ((old_dir, old), (new_dir, new_dir / "new.restart")):
        build.run(PLASTIC_CONTINUE.format(restart=restart.name), directory)
        runs.append(((directory / "dump.txt").read_text(), thermo_lines(directory)))
    (dump_old, thermo_old), (dump_new, thermo_new) = runs
    # the test means something only where the automata yield: the last
    # column of the dump is the plastic strain
    last = dump_new.rsplit("ITEM: ATOMS", 1)[1].splitlines()[1:]
    epsp = [float(line.split()[-1]) for line in last if line.strip()]
    assert max(epsp) > 1.0e-3, max(epsp)
    assert thermo_old == thermo_new
    assert dump_old == dump_new


def refused(build, tmp_path, old, new):
    """Write a restart file, change one name in it, read it: the output."""
    build.run(SCENE, tmp_path)
    restart = tmp_path / "new.restart"
    data = restart.read_bytes()
    # the last occurrence: the links fix (the pair style, written before it,
    # names its link model's parts too)
    assert data.count(old) in (1, 2), f"{old!r} is not in the restart file once or twice"
    head, _, tail = data.rpartition(old)
    restart.write_bytes(head + new + tail)
    result = build.run(CONTINUE.format(restart="new.restart"), tmp_path, check=False,
                       timeout=120)
    output = result.stdout + result.stderr
    assert 0 < result.returncode < 128, output[-2000:]
    return output


def test_restart_with_unknown_link_block_is_refused(build, tmp_path):
    output = refused(build, tmp_path, b"elastic\0", b"elastix\0")
    assert re.search(r"ERROR: Restart file holds MCA links with the blocks \(elastix 24 2\) as "
                     r"name, values per link, values per automaton; the link model of the pair "
                     r"style has \(elastic 24 2\)", output), output[-2000:]


def test_restart_with_unknown_material_keyword_is_refused(build, tmp_path):
    output = refused(build, tmp_path, b"E nu rho eta yield hardening\0",
                     b"E nu rhx eta yield hardening\0")
    assert re.search(r"ERROR: Restart file holds the material parameter rhx of pair mca, which "
                     r"this version does not know \(it knows E, nu, rho, eta, yield and "
                     r"hardening\)", output), \
        output[-2000:]


def test_parts_are_chosen_by_keyword(build, tmp_path):
    """'pair_style mca elastic elastic' names the default part: same run;
    an unknown part or slot is refused with the allowed values."""
    chosen = SCENE.replace("pair_style      mca\n", "pair_style      mca elastic elastic\n")
    build.run(SCENE.replace("run             100", "run 20"), tmp_path / "default")
    build.run(chosen.replace("run             100", "run 20"), tmp_path / "chosen")
    assert thermo_lines(tmp_path / "chosen") == thermo_lines(tmp_path / "default")

    for style, message in (
            ("mca elastic hooke", r"Unknown elastic part hooke for pair_style mca "
                                  r"\(allowed: elastic\)"),
            ("mca plastic vonmises", r"Unknown pair_style mca keyword plastic \(allowed: "
                                     r"tolerance, capacity, cutoff, precision, batch, scatter, elastic, "
                                     r"damping, plasticity, fracture, contacts, healing\)")):
        bad = SCENE.replace("pair_style      mca\n", f"pair_style      {style}\n")
        result = build.run(bad, tmp_path / style.split()[1], check=False, timeout=120)
        output = result.stdout + result.stderr
        assert 0 < result.returncode < 128, output[-2000:]
        assert re.search("ERROR: " + message, output), output[-2000:]
