"""Bad input gives a clear LAMMPS error naming the argument; never a crash or a hang.

Each case is a small input that must stop with exit status 1, print
"ERROR" and the expected message, within a time limit (a hang fails).
"""

import re
import struct

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


PAIR = "comm_modify vel yes\npair_style mca\npair_coeff * * E 70e9 nu 0.3 rho 2700\n"
PAIR_RUN = BOX + PAIR + "run 0\n"

TWO = """
units           si
processors      * 1 1
atom_style      mca
atom_modify     map array
boundary        f f f
region          box block -4 4 -4 4 -4 4 units box
create_box      1 box
create_atoms    1 single -0.254 0 0 units box
create_atoms    1 single 0.254 0 0 units box
mca_set         all packing fcc radius 0.254
comm_modify     vel yes
pair_style      mca
pair_coeff      * * E 70e9 nu 0.3 rho 2700
run             0
"""

# a link of length 0.75 made in a periodic box of 3, then the box made 1.5
HALF_BOX_LINK = """
units           si
atom_style      mca
atom_modify     map array
boundary        p f f
region          box block 0 3 -4 4 -4 4 units box
create_box      1 box
create_atoms    1 single 0.18521411864172255 0 0 units box
create_atoms    1 single 0.9352141186417225 0 0 units box
mca_set         all packing fcc radius 0.375
comm_modify     vel yes
pair_style      mca
pair_coeff      * * E 70e9 nu 0.3 rho 2700
run             0
change_box      all x final 0 1.5 units box
run             0
"""

# pair_style mlp: a 2-D box of two atoms
MLP_BOX = """
units           lj
dimension       2
atom_style      atomic
region          box block 0 4 0 4 -0.5 0.5
create_box      2 box
create_atoms    1 single 1 1 0
create_atoms    1 single 2 1 0
mass            * 1.0
"""
MLP_3D = """
units           lj
atom_style      atomic
region          box block 0 4 0 4 0 4
create_box      1 box
create_atoms    1 single 1 1 1
mass            * 1.0
pair_style      mlp 1.3
pair_coeff      1 1 harmonic 2 1 0.05 6 0
run             0
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
    # atom_style mca and fix nve/mca are 2-D too (bond_style beam); MCA is 3-D
    ("2d run", TWO_D + PAIR + "run 0\n", r"Pair style mca requires a 3d simulation"),
    ("fix wrong atom style", SPHERE_BOX + "fix 1 all nve/mca\n",
     r"Fix nve/mca requires atom_style mca, not atom_style sphere"),
    ("fix extra keyword", BOX + "fix 1 all nve/mca update dipole\n",
     r"unexpected argument 'update'.*takes no keywords"),
    ("mca_set no args", BOX + "mca_set all\n", r"mca_set"),
    ("mca_set group", BOX + "mca_set nogroup density 1\n", r"could not find group ID nogroup"),
    ("mca_set keyword", BOX + "mca_set all size 1.0\n", r"Unknown mca_set keyword size"),
    ("mca_set radius 0", BOX + "mca_set all radius 0\n",
     r"mca_set radius must be > 0 and <= 1e\+300, got 0"),
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
     r"mca_set density: atom-style variable gives a value outside the allowed range "
     r"\(> 0 and <= 1e\+300\)"),
    # each value in range, but the cell volume (radius^3) overflows
    ("mca_set radius range", BOX + "mca_set all radius 1e308\n",
     r"mca_set radius must be > 0 and <= 1e\+300, got 1e308"),
    ("mca_set radius overflow", BOX + "mca_set all radius 1e200\n",
     r"mca_set: automaton \d+ would get radius 1e\+200, cell volume inf.*each must be finite"),
    ("mca_set mass overflow", BOX + "mca_set all volume 1e300 density 1e300\n",
     r"mca_set: automaton \d+ would get .* mass inf"),
    ("mca_set before box", "atom_style mca\nmca_set all density 1\n",
     r"mca_set command before simulation box is defined"),
    ("mca_set atom style", SPHERE_BOX + "mca_set all density 1\n",
     r"mca_set requires atom_style mca, not sphere"),
    ("mca_set not a number", BOX + "mca_set all density heavy\n", r"heavy"),
    # pair_style mca
    ("pair atom style", SPHERE_BOX + "pair_style mca\npair_coeff * * E 1 nu 0.3 rho 1\nrun 0\n",
     r"Pair style mca requires atom_style mca, not sphere"),
    ("pair keyword", BOX + "pair_style mca size 2\n", r"Unknown pair_style mca keyword size"),
    ("pair tolerance", BOX + "pair_style mca tolerance 0.7\n",
     r"tolerance must be in \[0, 0.5\), got 0.7"),
    ("pair capacity", BOX + "pair_style mca capacity 0\n", r"capacity must be in \[1, 64\]"),
    ("pair cutoff", BOX + "pair_style mca cutoff -1\n", r"cutoff must be > 0"),
    ("pair precision", BOX + "pair_style mca precision single\n",
     r"Pair style mca precision must be double or mixed, got single"),
    ("pair precision missing", BOX + "pair_style mca precision\n",
     r"Illegal pair_style mca precision command: missing argument"),
    # the links exist in one precision: another needs a restart file
    ("pair precision changed", BOX + "comm_modify vel yes\npair_style mca\n"
     "pair_coeff * * E 1e9 nu 0.3 rho 1\nrun 0\npair_style mca precision mixed\n"
     "pair_coeff * * E 1e9 nu 0.3 rho 1\nrun 0\n",
     r"Pair mca: precision mixed differs from the precision the links are stored in \(double\); "
     r"write a restart file and read it with the new precision"),
    ("pair E", BOX + "pair_style mca\npair_coeff * * E 0 nu 0.3 rho 2700\n",
     r"Young's modulus E must be > 0"),
    ("pair nu high", BOX + "pair_style mca\npair_coeff * * E 1e9 nu 0.5 rho 2700\n",
     r"Poisson's ratio nu must be in \(-1, 0.5\), got 0.5"),
    ("pair nu low", BOX + "pair_style mca\npair_coeff * * E 1e9 nu -1 rho 2700\n",
     r"Poisson's ratio nu must be in \(-1, 0.5\)"),
    ("pair nu predictor", BOX + "pair_style mca\npair_coeff * * E 1e9 nu -0.3 rho 2700\n",
     r"nu = -0.3 is not supported: the mean-stress predictor needs nu > -0.25"),
    # the law squares stresses of the order of 3K + 4G: E = 1e308 gave NaN
    ("pair E overflow", BOX + "pair_style mca\npair_coeff * * E 1e308 nu 0.3 rho 2700\n",
     r"Young's modulus E = 1e\+308 with nu = 0.3 is too large.*E must be < 3.3\d*e\+153"),
    ("pair rho", BOX + "pair_style mca\npair_coeff * * E 1e9 nu 0.3 rho 0\n",
     r"density rho must be > 0"),
    ("pair coeff keyword", BOX + "pair_style mca\npair_coeff * * E 1e9 G 1e9\n",
     r"Unknown pair_coeff keyword G for pair mca"),
    ("pair coeff partial", BOX + "pair_style mca\npair_coeff * * E 1e9 nu 0.3\n",
     r"a material needs all of E, nu and rho"),
    ("pair coeff ranges", BOX + "pair_style mca\npair_coeff 1 2 E 1e9 nu 0.3 rho 1\n",
     r"the material keywords \(E, nu, rho, eta, yield and hardening, hardening table\) "
     r"belong to atom types"),
    ("pair coeff missing", BOX + "comm_modify vel yes\npair_style mca\n"
     "pair_coeff 1 1 E 1e9 nu 0.3 rho 1\nrun 0\n",
     r"All pair coeffs are not set|no material \(E, nu, rho\) for atom type 2"),
    ("pair ghost velocity", BOX + "pair_style mca\npair_coeff * * E 1e9 nu 0.3 rho 1\nrun 0\n",
     r"requires ghost atoms to carry velocities: use 'comm_modify vel yes'"),
    ("pair capacity exceeded", BOX + "comm_modify vel yes\npair_style mca capacity 6\n"
     "pair_coeff * * E 1e9 nu 0.3 rho 1\nrun 0\n",
     r"has 12 neighbours to link, more than the capacity 6"),
    ("pair periodic images", lattice_box("fcc", 0.7184, 1) + PAIR + "run 0\n",
     r"would link to two periodic images of the same automaton"),
    # a box shrunk (no remap) to twice a link: the two automata are half a
    # box apart, and at these coordinates the closest images differ by
    # round-off (1 sees 2, 2 sees the image of 1 at x + 1.5): each would
    # take the link for one the other evaluates, or for one to a ghost
    ("pair images differ", HALF_BOX_LINK,
     r"the link of automaton 1 to automaton 2 is lost: 2 sees another periodic image of 1 \(the "
     r"link is longer than the communication cutoff \S+, or half a periodic box length\)"),
    # fix mca/setvelocity
    ("setvel args", PAIR_RUN + "fix 1 all mca/setvelocity 0 0\n", r"mca/setvelocity"),
    ("setvel extra", PAIR_RUN + "fix 1 all mca/setvelocity 0 0 0 1\n",
     r"unexpected argument '1'"),
    ("setvel all NULL", PAIR_RUN + "fix 1 all mca/setvelocity NULL NULL NULL\n",
     r"all of vx, vy, vz are NULL"),
    ("setvel variable", PAIR_RUN + "fix 1 all mca/setvelocity v_none 0 0\nrun 0\n",
     r"vx: variable none does not exist"),
    ("setvel variable style", PAIR_RUN + "variable s string abc\n"
     "fix 1 all mca/setvelocity 0 v_s 0\nrun 0\n", r"vy: variable s must be equal- or atom-style"),
    # computes
    ("compute atom keyword", PAIR_RUN + "compute 1 all mca/atom stress\n",
     r"Unknown compute mca/atom keyword stress"),
    ("compute atom style", SPHERE_BOX + "compute 1 all mca/atom smean\n",
     r"Compute mca/atom requires atom_style mca, not sphere"),
    ("compute atom pair", BOX + "pair_style zero 1.0\npair_coeff * *\n"
     "compute 1 all mca/atom smean\nrun 0\n", r"Compute mca/atom requires pair_style mca"),
    ("compute link keyword", PAIR_RUN + "compute 1 all mca/link length width\n",
     r"Unknown compute mca/link keyword width"),
    ("compute link pair", BOX + "pair_style zero 1.0\npair_coeff * *\n"
     "compute 1 all mca/link length\nrun 0\n", r"Compute mca/link requires pair_style mca"),
    ("mlp order", MLP_BOX + "pair_style mlp 1.3\npair_coeff * * harmonic 2 1 0.05 5 0\n",
     r"Pair coeff mlp: n must be 4 \(square lattice\) or 6 \(hexagonal\), not 5"),
    ("mlp f0", MLP_BOX + "pair_style mlp 1.3\npair_coeff * * harmonic 2 1 -0.05 6 0\n",
     r"Pair coeff mlp: f0 must be >= 0 .*not -0.05"),
    ("mlp central", MLP_BOX + "pair_style mlp 1.3\npair_coeff * * buck 2 1 0.05 6 0\n",
     r"central potential must be harmonic, morse or lj, not buck"),
    ("mlp count", MLP_BOX + "pair_style mlp 1.3\npair_coeff * * morse 1 1 0.05 6 0\n",
     r"Pair coeff mlp morse: expected I J morse D0 alpha r0 f0 n theta0 \[cutoff\]"),
    ("mlp sigma", MLP_BOX + "pair_style mlp 1.3\npair_coeff * * lj 1 0 0.05 6 0\n",
     r"Pair coeff mlp lj: sigma must be > 0, not 0"),
    ("mlp taper", MLP_BOX + "pair_style mlp 1.3 taper 1.3\n",
     r"Pair style mlp: taper width must be >= 0 and < the cutoff 1.3, not 1.3"),
    ("mlp taper pair", MLP_BOX + "pair_style mlp 1.3 taper 0.5\n"
     "pair_coeff * * harmonic 2 1 0.05 6 0 0.4\nrun 0\n",
     r"Pair style mlp: taper width 0.5 must be < the cutoff 0.4 of types 1 1"),
    ("mlp return", MLP_BOX + "pair_style mlp 1.3 return paper\n",
     r"Pair style mlp: return must be literal or conservative, not paper"),
    ("mlp keyword", MLP_BOX + "pair_style mlp 1.3 shift yes\n",
     r"Pair style mlp: unknown keyword shift \(allowed: return, taper, frame\)"),
    ("mlp frame missing", MLP_BOX + "pair_style mlp 1.3 frame fr\n"
     "pair_coeff * * harmonic 2 1 0.05 6 0\nrun 0\n",
     r"Pair style mlp: frame fr: there is no fix with that ID"),
    ("mlp frame style", MLP_BOX + "pair_style mlp 1.3 frame fr\n"
     "pair_coeff * * harmonic 2 1 0.05 6 0\nfix fr all nve\nrun 0\n",
     r"Pair style mlp: frame fr must be a fix mlp/frame, not fix nve"),
    ("frame N", MLP_BOX + "fix fr all mlp/frame 0\n",
     r"Fix mlp/frame: N must be an integer >= 1, not 0"),
    ("frame body", MLP_BOX + "fix fr all mlp/frame 1 body grain\n",
     r"Fix mlp/frame: body must be group or molecule, not grain"),
    ("frame molecule", MLP_BOX + "fix fr all mlp/frame 1 body molecule\n",
     r"Fix mlp/frame body molecule requires an atom style with molecule IDs "
     r"\(atom_style atomic has none\)"),
    ("frame keyword", MLP_BOX + "fix fr all mlp/frame 1 every 2\n",
     r"Fix mlp/frame: unknown keyword every \(allowed: body\)"),
    ("frame empty", MLP_BOX + "group none empty\nfix fr none mlp/frame 1\n",
     r"Fix mlp/frame: group none has no atoms of positive mass"),
    ("traction args", MLP_BOX + "fix tr all mlp/traction 1\n",
     r"Fix mlp/traction takes no arguments after the style, found 1"),
    ("traction map", MLP_BOX + "fix tr all mlp/traction\n",
     r"Fix mlp/traction requires an atom map \(atom_modify map array or hash\)"),
    ("traction pair", MLP_BOX.replace("dimension       2\n", "dimension       2\n"
                                      "atom_modify     map array\n")
     + "pair_style lj/cut 1.3\npair_coeff * * 1 1\nfix tr all mlp/traction\nrun 0\n",
     r"Fix mlp/traction requires pair_style mlp \(or mlp/kk\), not lj/cut"),
    ("traction 3d", MLP_3D.replace("pair_style      mlp 1.3\n",
                                   "fix tr all mlp/traction\npair_style      mlp 1.3\n"),
     r"Fix mlp/traction requires dimension 2"),
    ("frame 3d", MLP_3D.replace("pair_style      mlp 1.3\n",
                                "fix fr all mlp/frame 1\npair_style      mlp 1.3\n"),
     r"Fix mlp/frame requires dimension 2"),
    ("mlp mixing", MLP_BOX + "pair_style mlp 1.3\npair_coeff 1 1 harmonic 2 1 0.05 6 0\n"
     "pair_coeff 2 2 harmonic 2 1 0.05 6 0\nrun 0\n",
     r"Pair style mlp: no coefficients for types 1 2 .*no mixing rule"),
    ("mlp 3d", MLP_3D, r"Pair style mlp(/kk)? requires dimension 2"),
    ("damped gamma", MLP_BOX + "fix 1 all nve/damped -1\n",
     r"Fix nve/damped: gamma must be >= 0 and finite \(1/time units\), got -1"),
    ("damped angular", MLP_BOX + "fix 1 all nve/damped 1 angular -2\n",
     r"Fix nve/damped: angular gamma_r must be >= 0"),
    ("damped keyword", MLP_BOX + "fix 1 all nve/damped 1 lagged yes\n",
     r"Unknown fix nve/damped keyword lagged \(allowed: angular, spin, disc\)"),
    ("damped spin", MLP_BOX + "fix 1 all nve/damped 1 spin yes\n",
     r"Fix nve/damped spin yes requires finite-size spheres .*not atom_style atomic"),
    ("damped disc", MLP_3D.replace("pair_style      mlp 1.3\n", "").replace(
        "pair_coeff      1 1 harmonic 2 1 0.05 6 0\nrun             0\n",
        "fix 1 all nve/damped 1 disc\n"),
     r"Fix nve/damped disc requires dimension 2"),
    ("damped automata", BOX + "fix 1 all nve/damped 1 spin no\n",
     r"Fix nve/damped spin no: automata \(atom_style mca\) always spin"),
    ("damped respa", MLP_BOX + "pair_style mlp 1.3\npair_coeff * * harmonic 2 1 0.05 6 0\n"
     "fix 1 all nve/damped 1\nrun_style respa 2 2\nrun 1\n",
     r"Fix nve/damped does not support run_style respa"),
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
                                  or "radius 0" in c[0] or "capacity exceeded" in c[0]],
                         ids=_case_id)
def test_bad_input_on_two_ranks_does_not_hang(build, tmp_path, case):
    """An error found by one rank must stop all ranks (collective check)."""
    _run_case(build, tmp_path, case, nprocs=2)


def test_time_step_above_the_stability_limit_is_warned(build, tmp_path):
    """A time step above the stable time step gives a warning with the
    recommended value, 0.7 of the estimate (test_stable_timestep.py checks
    the estimate against measured limits); 0.7 of it gives none."""
    result = build.run(BOX + PAIR + "timestep 1.0e-3\nrun 0\n", tmp_path)
    warnings = [line for line in result.stdout.splitlines() if "WARNING" in line]
    found = [re.search(r"Time step 0.001 is above the stable time step (\S+) of pair mca "
                       r"\((\S+) times it\); use a time step <= (\S+) \(0.7 of the stable time "
                       r"step\)", w) for w in warnings]
    found = [m for m in found if m]
    assert found, warnings
    estimate, ratio, recommended = (float(v) for v in found[0].groups())
    assert ratio == pytest.approx(1.0e-3 / estimate, rel=1e-3)
    assert recommended == pytest.approx(0.7 * estimate, rel=1e-5)
    quiet = build.run(BOX + PAIR + f"timestep {recommended}\nrun 0\n", tmp_path / "ok")
    assert "above the stable time step" not in quiet.stdout


STRETCH = TWO + "set atom 1 x -3.5\nset atom 2 x 3.5\nrun 0\n"


def test_stretched_link_is_reported(build, tmp_path):
    """A link stretched beyond the cutoff keeps acting and is reported, never dropped."""
    result = build.run(STRETCH, tmp_path)
    assert re.search(r"WARNING: Pair mca: 1 links are longer than the cutoff", result.stdout)
    thermo = result.stdout.split("Step")[-1].split("\n")[1].split()
    assert float(thermo[2]) > 0.0    # the stretched link stores elastic energy


@pytest.mark.mpi
def test_lost_link_stops_the_run(build, tmp_path):
    """A link whose partner is not even a ghost atom stops the run with a
    clear error that names the communication cutoff in force: here the one
    of comm_modify (2.5 m, larger than the neighbour lists' 0.646 m, which
    it named before, smaller than the 7 m the link is stretched to)."""
    stretch = STRETCH.replace("set atom 1", "comm_modify cutoff 2.5\nset atom 1", 1)
    result = build.run(stretch, tmp_path, nprocs=2, check=False, timeout=120)
    assert result.returncode != 0
    assert re.search(r"ERROR on proc \d: Pair mca: the link of automaton \d to automaton \d is "
                     r"lost: the partner is farther than the communication cutoff 2\.5 ",
                     result.stdout + result.stderr), (result.stdout + result.stderr)[-2000:]


def test_restart_with_another_history_layout_is_refused(build, tmp_path):
    """A restart file whose link rows are laid out differently (here: the
    unnumbered layout 0 of files written before the layout was recorded) is
    refused with a clear error instead of being read field by field into the
    wrong places."""
    build.run(TWO + "write_restart two.restart\n", tmp_path)
    restart = tmp_path / "two.restart"
    data = restart.read_bytes()
    # the links fix records (capacity, created, 1000 x layout + values per link)
    current = struct.pack("<d", 2024.0)
    assert data.count(current) == 1, "the layout record of the links fix was not found once"
    restart.write_bytes(data.replace(current, struct.pack("<d", 27.0)))
    result = build.run("read_restart two.restart\n" + PAIR.split("\n", 1)[1] + "run 0\n",
                       tmp_path, check=False, timeout=120)
    output = result.stdout + result.stderr
    assert 0 < result.returncode < 128, output[-2000:]
    assert re.search(r"ERROR: Restart file holds MCA links in history layout 0 with 27 values "
                     r"each; this version reads layout 2 with 24", output), output[-2000:]
