"""pair_style mca precision mixed: link rows stored with their lengths and
normal (and step numbers) in doubles, the rest in floats (mca_row_codec.h,
doc/src/pair_mca.rst "Precision of the link rows").

* the mixed rows change the run by what rounding the stored tractions,
  strains, couples, areas and energies to float does (2^-24 = 6e-8 of each
  value per step), and not more: the forces, spins and stresses of a
  sheared periodic box with every part of the law that keeps floats
  (damping, plasticity, fracture, contacts) and of the weld example
  (contacts healing into links) stay within TOL_MIXED of the double run,
  and differ from it (the option acts);
* the breaks and heals of those scenes are the same events at the same
  steps (every automaton's count of links and of pushing contacts agrees
  at every dump; a criterion met within 1e-7 of its threshold would show
  here, and none is in these scenes);
* a restart file holds the rows as doubles: a mixed run continues from
  one bit for bit, and the file read with precision double gives the
  forces of the mixed rows bit for bit at the setup (the double row holds
  the floats' values exactly);
* 2 MPI ranks and 1 agree to TOL_RANKS, kk on one thread is the CPU style
  bit for bit, and the rows take 128 bytes instead of 192 (LAMMPS's memory
  estimate).
"""

import pathlib
import re

import numpy as np
import pytest

from mcatest import kokkos_args, kokkos_build, read_dump

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "examples"

# the mixed run against the double run: each stored float is the value
# rounded to 6e-8 relative, at every step; the forces follow the stored
# tractions and the positions integrate them, so the differences grow with
# the steps (measured, over each field's scale: 5.8e-7 at most in the 150
# steps of the box, 2.0e-6 in the 2500 of the weld); 1e-5 leaves room and
# is still far below what the scenes resolve (their strain grows by 1e-4
# of itself in a step)
TOL_MIXED = 1.0e-5
# 2 ranks against 1, and 2 threads against 1, in mixed: the sums of an
# automaton are added in another order (1e-16 relative), which may round
# a stored value to the other neighbouring float (6e-8 of it) where it
# lies near the midpoint of two; no more than that
# (measured: 1.1e-11 on 2 ranks, 2.6e-15 on 2 threads)
TOL_RANKS = 1.0e-6
NSTEPS = 150

# every part of the law that keeps floats in its block; the shear yields
# the automata and breaks links (from about step 60), whose broken pairs
# then push and rub
PAIR = """pair_style      mca damping viscous plasticity mises fracture links contacts coulomb &
                precision {precision}
pair_coeff      1 1 E 70e9 nu 0.3 rho 2700 eta 2e4 yield 2e5 hardening 1e9 break strain 0.012
pair_coeff      2 2 E 200e9 nu 0.25 rho 7800 eta 2e4 yield 4e5 hardening 2e9 break strain 0.012
pair_coeff      * * friction 0.3
"""
MOTION = """fix             integrate all nve/mca
fix             strain all deform 1 {deform} erate 5.0 remap v
timestep        2.0e-5
"""
SETUP = """
units           si
atom_style      mca
atom_modify     map array
read_data       {data}
set             group all type/fraction 2 0.3 4321
comm_modify     vel yes
neighbor        0.05 bin
neigh_modify    delay 0 every 1 check yes
""" + PAIR + """
velocity        all create 1.0e-2 8765 loop geom
""" + MOTION
# the shear of the triclinic box, or a stretch of the orthogonal one along
# x (the restart test: read_restart maps the atoms of a triclinic box
# through its lamda coordinates, which changes their last bits)
SHEAR, STRETCH = "xy", "x"

OUTPUT = """compute         s all mca/atom smean seq links contacts
compute         frac all mca/fracture
dump            d all custom {every} {dump} id x y z vx vy vz fx fy fz omegax omegay omegaz &
                tqx tqy tqz c_s[*]
dump_modify     d sort id format float %.17g
thermo_style    custom step pe c_frac[1]
thermo_modify   format float %.17g
thermo          25
"""

FIELDS = ["x", "y", "z", "vx", "vy", "vz", "fx", "fy", "fz", "omegax", "omegay", "omegaz",
          "tqx", "tqy", "tqz", "c_s[1]", "c_s[2]"]
COUNTS = ["c_s[3]", "c_s[4]"]


def box_data(build, directory, region="prism 0 3 0 3 0 3 0 0 0"):
    """A data file of a periodic fcc box of 108 automata, triclinic by
    default (the same atom IDs on any number of ranks)."""
    build.run(f"""
units           si
atom_style      mca
atom_modify     map array
boundary        p p p
lattice         fcc 0.7184 origin 0.25 0.25 0.25
region          box {region}
create_box      2 box
create_atoms    1 box
write_data      box.data
""", directory, name="in.data")
    return directory / "box.data"


def run_box(build, directory, precision, nprocs=1, extra_args=()):
    data = box_data(build, directory)
    script = (SETUP.format(data=data, precision=precision, deform=SHEAR)
              + OUTPUT.format(every=25, dump="dump.txt") + f"run {NSTEPS}\n")
    build.run(script, directory, nprocs=nprocs, extra_args=extra_args)
    return read_dump(directory / "dump.txt")


def weld(build, directory, precision):
    """The weld example (visevery 0): its press (1500 steps, where the
    contacts heal) and 1000 steps of the pull, where the welds break."""
    text = (EXAMPLES / "healing" / "in.weld").read_text()
    line = "pair_style      mca contacts coulomb healing weld fracture links"
    press = "run             1500"
    assert text.count(line) == 1 and text.count(press) == 1
    text = text.replace(line, line + f" precision {precision}")
    text = text.replace(press, """compute         s all mca/atom smean seq links contacts
dump            d all custom 100 dump.txt id x y z vx vy vz fx fy fz omegax omegay omegaz &
                tqx tqy tqz c_s[*]
dump_modify     d sort id format float %.17g
""" + press)
    text = text.replace("run             4000", "run             1000")
    build.run(text, directory, variables={"visevery": 0}, name="in.weld")
    return read_dump(directory / "dump.txt")


def largest_difference(a, b, fields):
    """Largest difference of each field over its scale in a (all snapshots)."""
    out = {}
    for name in fields:
        scale = max(np.abs(s[name]).max() for s in a) or 1.0
        out[name] = max(np.abs(sa[name] - sb[name]).max() for sa, sb in zip(a, b)) / scale
    return out


def thermo_column(log, column):
    lines = pathlib.Path(log).read_text().splitlines()
    start = max(k for k, line in enumerate(lines) if line.split()[:1] == ["Step"])
    names = lines[start].split()
    values = []
    for line in lines[start + 1:]:
        words = line.split()
        if len(words) != len(names) or not words[0].isdigit():
            break
        values.append(float(words[names.index(column)]))
    return values


@pytest.mark.parametrize("scene", ["box", "weld"])
def test_mixed_rows_differ_by_float_rounding(build, tmp_path, scene):
    run = run_box if scene == "box" else weld
    double = run(build, tmp_path / "double", "double")
    mixed = run(build, tmp_path / "mixed", "mixed")
    assert len(double) == len(mixed) and len(double) >= 5
    worst = largest_difference(double, mixed, FIELDS)
    print(f"{scene}: mixed vs double, largest difference over scale: "
          + ", ".join(f"{k} {v:.2e}" for k, v in worst.items()))
    assert max(worst.values()) > 0.0, "precision mixed changed nothing"
    for name, value in worst.items():
        assert value <= TOL_MIXED, f"{name} differs by {value:.2e}"
    # links, contacts: the same breaks and heals at the same steps
    for sd, sm in zip(double, mixed):
        for name in COUNTS:
            assert np.array_equal(sd[name], sm[name]), (sd["timestep"], name)
    if scene == "box":
        broken = thermo_column(tmp_path / "mixed" / "log.lammps", "c_frac[1]")
        assert broken[-1] > 0, "the box scene broke no link: it does not test fracture"


def test_mixed_restart_continues_bit_for_bit(build, tmp_path):
    """A run split by a restart file continues as the same run split in
    memory, bit for bit (the file holds the decoded rows, encoded again as
    they are read: the same bytes); the same file read with precision
    double gives the setup forces of the mixed rows bit for bit."""
    data = box_data(build, tmp_path, region="block 0 3 0 3 0 3")
    output = OUTPUT.format(every=10, dump="{dump}") + "run             50\n"
    first = (SETUP.format(data=data, precision="mixed", deform=STRETCH)
             + "run 100\nwrite_restart mid.restart\n")
    build.run(first + output.format(dump="memory.txt"), tmp_path)
    restart = """read_restart    mid.restart
comm_modify     vel yes
neighbor        0.05 bin
neigh_modify    delay 0 every 1 check yes
""" + MOTION.format(deform=STRETCH)
    build.run(restart + output.format(dump="file.txt"), tmp_path, name="in.file")
    in_memory = read_dump(tmp_path / "memory.txt")
    from_file = read_dump(tmp_path / "file.txt")
    assert len(in_memory) == len(from_file) == 6
    for a, b in zip(in_memory, from_file):
        for name in FIELDS + COUNTS:
            assert np.array_equal(a[name], b[name]), (a["timestep"], name)

    as_double = restart + PAIR.format(precision="double") + output.format(dump="double.txt")
    build.run(as_double, tmp_path, name="in.double")
    double = read_dump(tmp_path / "double.txt")
    assert double[0]["timestep"] == from_file[0]["timestep"] == 100
    for name in ("fx", "fy", "fz", "tqx", "tqy", "tqz", "c_s[1]", "c_s[2]"):
        assert np.array_equal(double[0][name], from_file[0][name]), name
    worst = largest_difference(from_file, double, FIELDS)
    assert 0.0 < max(worst.values()) <= TOL_MIXED, worst


@pytest.mark.mpi
def test_mixed_mpi_ranks(build, tmp_path):
    one = run_box(build, tmp_path / "one", "mixed")
    two = run_box(build, tmp_path / "two", "mixed", nprocs=2)
    worst = largest_difference(one, two, FIELDS)
    print("mixed, 2 ranks vs 1: " + ", ".join(f"{k} {v:.2e}" for k, v in worst.items()))
    for name, value in worst.items():
        assert value <= TOL_RANKS, f"{name} differs by {value:.2e}"
    for s1, s2 in zip(one, two):
        for name in COUNTS:
            assert np.array_equal(s1[name], s2[name]), (s1["timestep"], name)


def test_kk_mixed_is_cpu_mixed(tmp_path):
    """The kk styles decode and encode rows with the same functions: on one
    thread, the CPU style's bits; on two threads, to TOL_RANKS (sums in
    another order, as between ranks)."""
    build = kokkos_build()
    cpu = run_box(build, tmp_path / "cpu", "mixed")
    for threads in (1, 2):
        kk = run_box(build, tmp_path / f"kk{threads}", "mixed", extra_args=kokkos_args(threads))
        worst = largest_difference(cpu, kk, FIELDS)
        print(f"mixed, kk {threads} threads vs cpu: "
              + ", ".join(f"{k} {v:.2e}" for k, v in worst.items()))
        limit = 0.0 if threads == 1 else TOL_RANKS
        for name, value in worst.items():
            assert value <= limit, f"kk {threads}: {name} differs by {value:.2e}"


def memory_mbytes(log):
    text = pathlib.Path(log).read_text()
    values = re.findall(r"Per MPI rank memory allocation \(min/avg/max\) = [\d.]+ \| ([\d.]+)",
                        text)
    links = int(re.search(r"(\d+) links made", text).group(1))
    return float(values[-1]), links


def test_mixed_rows_take_a_third_less_memory(build, tmp_path):
    """LAMMPS's estimate falls by 64 bytes per row of the pool (192 -> 128
    for the elastic row).  The pool holds at least a row per link and, after
    the links are made across periodic boundaries (a row at each end until
    they are shared), at most twice that plus the quarter it grows by."""
    script = """
units           si
atom_style      mca
atom_modify     map array
boundary        p p p
lattice         fcc 0.7184
region          box block 0 8 0 8 0 8
create_box      1 box
create_atoms    1 box
comm_modify     vel yes
pair_style      mca precision {precision}
pair_coeff      * * E 70e9 nu 0.3 rho 2700
fix             integrate all nve/mca
run             1
"""
    usage = {}
    for precision in ("double", "mixed"):
        directory = tmp_path / precision
        build.run(script.format(precision=precision), directory)
        usage[precision] = memory_mbytes(directory / "log.lammps")
    (double, links), (mixed, links_mixed) = usage["double"], usage["mixed"]
    assert links == links_mixed == 8 ** 3 * 4 * 6
    saved = (double - mixed) * 1024 * 1024 / (64 * links)
    print(f"memory estimate: double {double} MB, mixed {mixed} MB, saved {saved:.2f} x 64 B "
          "per link")
    # (the estimate is printed to 4 digits: +-0.005 MB)
    slack = 0.01 * 1024 * 1024 / (64 * links)
    assert 1.0 - slack <= saved <= 2.5 + slack
