"""The examples' output for visualisation programs (doc/src/Howto_mca.rst,
"Output for visualisation").

* every MCA example input writes snapshots with the documented columns and,
  at its end, the final state and (where the build writes PNG) a picture;
  so do the GP wave scenes and the GP crack plate (its final state);
* on the tension cube (3 cells, 60 steps) the snapshots come every
  ceil(nsteps/20) steps, sorted by ID, with the columns a reader maps by
  name; the columns are what they say: c_vis[7] is the von Mises stress
  of c_vis[1..6] (to 1e-5, the dump's 6 digits), and the final snapshot
  is the state of the last step; the picture is an 800 x 600 PNG.
"""

import pathlib
import re
import struct

import numpy as np
import pytest

import mcatest
from mcatest import read_dump

EXAMPLES = mcatest.ROOT / "examples"
COLUMNS = ("id type x y z vx vy vz radius c_vis[1] c_vis[2] c_vis[3] c_vis[4] c_vis[5] "
           "c_vis[6] c_vis[7]")
MCA_INPUTS = sorted(p for p in EXAMPLES.glob("*/in.*")
                    if not p.parent.name.startswith(("gp_", "mlp_", "numfrac_", "beam_", "batch", "python"))
                    and p.parent.name != "rolling")


@pytest.mark.parametrize("path", MCA_INPUTS, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_every_mca_example_writes_snapshots_and_a_picture(path):
    text = path.read_text()
    assert re.search(r"^compute +vis all mca/atom sxx syy szz sxy sxz syz seq\b", text, re.M)
    assert re.search(r'"dump vis all custom \$\{visevery\} \S+\.\*\.dump id type x y z vx vy vz '
                     r'radius c_vis\[\*\]"', text)
    assert re.search(r"^dump +visfinal all custom 1 \S+\.final\.dump ", text, re.M)
    assert re.search(r'if "\$\(is_available\(feature,png\)\)" then &\n  "write_dump all image '
                     r'\S+\.png c_vis\[[78]\] diameter', text)


GP_INPUTS = [EXAMPLES / "gp_scaling" / "in.wave", EXAMPLES / "gp_interface" / "in.wave",
             EXAMPLES / "gp_crack" / "in.tension"]


@pytest.mark.parametrize("path", GP_INPUTS, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_gp_examples_write_their_final_state_and_a_picture(path):
    """The GP scenes: snapshots of the dynamic ones with each particle's
    energy (compute pe/atom) and level (type), the final state and a
    picture (coloured by the energy; the crack plate by the level)."""
    text = path.read_text()
    assert re.search(r"^compute +vispe all pe/atom$", text, re.M)
    assert re.search(r"^dump +visfinal all custom 1 \S+\.final\.dump id type x y z ", text, re.M)
    assert re.search(r'if "\$\(is_available\(feature,png\)\)" then &\n  "write_dump all image '
                     r'\S+\.png (c_vispe|type) type view', text)
    if path.parent.name != "gp_crack":
        assert re.search(r'"dump vis all custom \$\{visevery\} \S+\.\*\.dump id type x y z '
                         r'vx vy vz c_vispe"', text)


def png_size(path):
    data = pathlib.Path(path).read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    return struct.unpack(">II", data[16:24])


def test_tension_cube_snapshots_and_picture(build, tmp_path):
    script = (EXAMPLES / "tension_cube" / "in.tension_cube").read_text()
    build.run(script, tmp_path, variables={"n": 3, "nsteps": 60}, name="in.tension_cube")
    steps = sorted(int(p.name.split(".")[3]) for p in tmp_path.glob("cube.free.tension.*.dump")
                   if p.name.split(".")[3].isdigit())
    assert steps == list(range(0, 61, 3))    # ceil(60/20) = 3
    final = tmp_path / "cube.free.tension.final.dump"
    header = final.read_text().splitlines()[8]
    assert header == "ITEM: ATOMS " + COLUMNS
    last = read_dump(final)[-1]
    at60 = read_dump(tmp_path / "cube.free.tension.60.dump")[-1]
    assert last["timestep"] == 60
    for name in ("x", "y", "z", "c_vis[3]"):
        assert np.array_equal(last[name], at60[name]), name
    ids = np.loadtxt(final, skiprows=9)[:, 0]
    assert np.all(np.diff(ids) > 0)    # sorted by ID
    s = [last[f"c_vis[{k}]"] for k in range(1, 8)]
    mises = np.sqrt(0.5 * ((s[0] - s[1])**2 + (s[1] - s[2])**2 + (s[2] - s[0])**2)
                    + 3.0 * (s[3]**2 + s[4]**2 + s[5]**2))
    assert np.max(np.abs(mises - s[6])) < 1e-5 * np.max(np.abs(s[6]))
    assert np.mean(s[2]) > 0.0    # the cube is pulled along z: tension positive
    if has_png(build, tmp_path / "png"):
        assert png_size(tmp_path / "cube.free.tension.png") == (800, 600)
    else:
        assert not (tmp_path / "cube.free.tension.png").exists()


def has_png(build, directory):
    """Whether the build writes PNG (LAMMPS's own answer: is_available)."""
    result = build.run('print "PNG $(is_available(feature,png))"\n', directory)
    return re.search(r"^PNG 1$", result.stdout, re.M) is not None
