"""Bad input gives a clear LAMMPS error naming the argument; never a crash or a hang.

Each case is a small input that must stop with exit status 1, print
"ERROR" and the expected message, within a time limit (a hang fails).
"""

import re

import pytest

from mca_inputs import lattice_box

BOX = lattice_box("fcc", 0.7184, 2)
SPHERE_BOX = """
units           si
atom_style      sphere
region          box block 0 2 0 2 0 2 units box
create_box      1 box
create_atoms    1 single 1 1 1 units box
"""

TWO_D = """
units           si
dimension       2
atom_style      mca
region          box block 0 2 0 2 -0.5 0.5 units box
create_box      1 box
create_atoms    1 single 1 1 0 units box
"""

DATA_HEADER = """LAMMPS data file for bad-input tests

1 atoms
1 atom types

0 2 xlo xhi
0 2 ylo yhi
0 2 zlo zhi

Atoms # mca

"""


def data_case(line):
    """Read a one-atom data file whose Atoms line is `line`."""
    return ("data", DATA_HEADER + line + "\n", """
units           si
atom_style      mca
read_data       bad.data
""")


# (case id, input, regular expression the error message must match)
CASES = [
    ("atom_style args", "atom_style mca 1\n", r"atom_style mca takes no arguments"),
    ("2d run", TWO_D + "pair_style zero 1.0\npair_coeff * *\nrun 0\n",
     r"Atom style mca requires a 3d simulation \(dimension 3\), found dimension 2"),
    ("2d fix", TWO_D + "fix 1 all nve/mca\n", r"Fix nve/mca requires a 3d simulation"),
    ("fix wrong atom style", SPHERE_BOX + "fix 1 all nve/mca\n",
     r"Fix nve/mca requires atom_style mca, not atom_style sphere"),
    ("fix extra keyword", BOX + "fix 1 all nve/mca update dipole\n",
     r"unexpected argument 'update'.*takes no keywords"),
    ("mca_set no args", BOX + "mca_set all\n", r"mca_set"),
    ("mca_set group", BOX + "mca_set nogroup density 1\n", r"could not find group ID nogroup"),
    ("mca_set keyword", BOX + "mca_set all size 1.0\n", r"Unknown mca_set keyword size"),
    ("mca_set radius 0", BOX + "mca_set all radius 0\n", r"mca_set radius must be > 0, got 0"),
    ("mca_set radius <0", BOX + "mca_set all radius -0.1\n", r"mca_set radius must be > 0"),
    ("mca_set diameter", BOX + "mca_set all diameter 0.0\n", r"mca_set diameter must be > 0"),
    ("mca_set density", BOX + "mca_set all density -2700\n", r"mca_set density must be > 0"),
    ("mca_set mass", BOX + "mca_set all mass 0\n", r"mca_set mass must be > 0"),
    ("mca_set inertia", BOX + "mca_set all inertia 0\n", r"mca_set inertia must be > 0"),
    ("mca_set damage", BOX + "mca_set all damage 1.5\n", r"mca_set damage must be in \[0, 1\]"),
    ("mca_set epsp", BOX + "mca_set all epsp -1e-3\n", r"mca_set epsp must be >= 0"),
    ("mca_set packing", BOX + "mca_set all packing bcc\n",
     r"mca_set packing must be one of none, sc, fcc, hcp; got bcc"),
    ("mca_set missing value", BOX + "mca_set all density\n", r"mca_set density"),
    ("mca_set stress", BOX + "mca_set all stress 1 2 3\n", r"mca_set stress"),
    ("mca_set mass+density", BOX + "mca_set all mass 1 density 1\n",
     r"use either mass or density, not both"),
    ("mca_set radius+diameter", BOX + "mca_set all radius 1 diameter 1\n",
     r"use either radius or diameter, not both"),
    ("mca_set variable missing", BOX + "mca_set all density v_nothing\n",
     r"variable nothing does not exist"),
    ("mca_set variable style", BOX + "variable d equal 3\nmca_set all density v_d\n",
     r"variable d is not atom-style"),
    ("mca_set variable range", BOX + "variable d atom 1-id\nmca_set all density v_d\n",
     r"mca_set density: atom-style variable gives a value outside the allowed range \(> 0\)"),
    ("mca_set before box", "atom_style mca\nmca_set all density 1\n",
     r"mca_set command before simulation box is defined"),
    ("mca_set atom style", SPHERE_BOX + "mca_set all density 1\n",
     r"mca_set requires atom_style mca, not sphere"),
    ("mca_set not a number", BOX + "mca_set all density heavy\n", r"heavy"),
    data_case("1 1 1 5 0.5 0 1.0 0 1 1 1") + (r"Invalid packing 5 in Atoms section",),
    data_case("1 1 1 12 0.0 0 1.0 0 1 1 1") + (r"Invalid diameter 0 .*must be > 0",),
    data_case("1 1 1 12 -0.5 0 1.0 0 1 1 1") + (r"Invalid diameter -0.5",),
    data_case("1 1 1 12 0.5 0 0.0 0 1 1 1") + (r"Invalid mass 0 .*must be > 0",),
    data_case("1 1 1 12 0.5 -1 1.0 0 1 1 1") + (r"Invalid volume -1 or inertia 0",),
    data_case("1 1 1 12 0.5 0 1.0 -2 1 1 1") + (r"Invalid volume 0 or inertia -2",),
]


def _case_id(case):
    return case[0]


def _run_case(build, tmp_path, case, nprocs=1):
    if case[0] == "data":
        _, data, script, pattern = case
        (tmp_path / "bad.data").write_text(data)
    else:
        _, script, pattern = case
    result = build.run(script, tmp_path, nprocs=nprocs, check=False, timeout=120)
    output = result.stdout + result.stderr
    assert result.returncode != 0, f"no error for:\n{script}\n{output[-2000:]}"
    assert result.returncode < 128, f"crashed with status {result.returncode}:\n{output[-2000:]}"
    errors = [line for line in output.splitlines() if "ERROR" in line]
    assert errors, f"no ERROR line:\n{output[-2000:]}"
    assert re.search(pattern, " ".join(errors)), f"'{pattern}' not in: {errors}"


@pytest.mark.parametrize("case", CASES, ids=[f"{k:02d}-{c[0] if c[0] != 'data' else 'data'}"
                                             for k, c in enumerate(CASES)])
def test_bad_input_is_reported(build, tmp_path, case):
    _run_case(build, tmp_path, case)


@pytest.mark.mpi
@pytest.mark.parametrize("case", [c for c in CASES if "variable range" in c[0]
                                  or "radius 0" in c[0]], ids=_case_id)
def test_bad_input_on_two_ranks_does_not_hang(build, tmp_path, case):
    """An error found by one rank must stop all ranks (collective check)."""
    _run_case(build, tmp_path, case, nprocs=2)
