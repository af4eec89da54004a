"""The GP model builder, tools/gp_build.py (doc/src/Howto_gp.rst).

* tiling: a three-level Fe model (bcc, X = [110], Y = [-110], Z = [001],
  k = 2, nested blocks, periodic) stands for exactly the atoms of the
  fully atomistic box (the level regions are snapped onto the coarser
  lattice, so the levels tile the volume);
* its imaginary shells are complete: linked in the perfect lattice and
  strained uniformly (the patch test of fix gp/link) every real particle,
  at the interfaces, edges and corners of the nested blocks too, feels
  the force of the strained crystal, zero: below 1e-8 of the rms force
  after random displacements of 0.02 A (the issue's bound);
* the real particles carry the energy and the stress of the atoms they
  stand for: under uniaxial strain of 1 to 4 % (a quasi-static loading;
  with coupling force the uniformly strained model is in equilibrium) the
  energy per atom and sigma_yy of the real particles equal those of a
  pure level-1 crystal strained alike to round-off (1e-10; the issue
  asks for 1 % between the two-level and the pure S1 stress-strain curve);
* sites centroid: the coarse particles at the centroids of their atoms
  (the real particles have the atomic crystal's centre of mass, 1e-9 A;
  the common origin is off by more than 1 A), the patch test as above;
* cut-outs and surface images: a two-level model with an edge crack, a
  hole, free x faces and images beyond the y faces has no particle in a
  cut, images only beyond the y faces, every imaginary particle and image
  linked, and the real level-2 particles at the y faces feel no force in
  the perfect lattice (with images; 1e-10 eV/A) where without images
  they feel the coarse surface (> 1e-2 eV/A);
* the LAMMPS Python module: Model.create(lmp) gives the model of the data
  file (same energy);
* bad input: clear errors naming the argument.
"""

import json
import math
import re
import subprocess
import sys

import numpy as np
import pytest

import mcatest

sys.path.insert(0, str(mcatest.ROOT / "tools"))
import gp_build  # noqa: E402

A0 = 2.855324               # Fe_mm.eam.fs
PX = A0 * math.sqrt(2)      # periods along X = [110], Y = [-110]
PZ = A0                     # along Z = [001]
FE = {"lattice": "bcc", "a0": A0, "orient": [[1, 1, 0], [-1, 1, 0], [0, 0, 1]],
      "element": "Fe", "potential": {"style": "eam/fs", "file": "Fe_mm.eam.fs"}, "ratio": 2}


@pytest.fixture(autouse=True)
def potentials(monkeypatch):
    tree = mcatest.build_named("current") or mcatest.builds()[0]
    monkeypatch.setenv("LAMMPS_POTENTIALS", tree.environment()["LAMMPS_POTENTIALS"])


def three_levels():
    """12 x 12 x 4 level-3 periods, level 1 and 2 nested blocks (x, y)."""
    L, Z = 12 * 4 * PX, 4 * 4 * PZ
    return dict(FE, box=[0, L, 0, L, 0, Z], periodic="xyz",
                levels=[{"block": [80, 113, 80, 113, None, None]},
                        {"block": [32, 162, 32, 162, None, None]}, None])


def write(spec, directory, name="model"):
    model = gp_build.build(spec)
    model.write(directory / name)
    return model


def test_tiling_and_snapping(tmp_path):
    spec = three_levels()
    model = write(spec, tmp_path)
    atoms = sum(len(model.real[n]) * 8 ** n for n in range(3))
    L, Z = spec["box"][1], spec["box"][5]
    full = L * L * Z / (A0 ** 3 / 2)
    print(f"\n{sum(map(len, model.real))} real particles for {atoms} atoms, the full box has "
          f"{full:.6f}")
    assert atoms == round(full) and abs(full - round(full)) < 1e-6
    # the faces were moved onto the coarser lattice: multiples of its period
    assert len(model.snapped) == 8
    for n, p in ((0, 2 * PX), (1, 4 * PX)):
        block = model.regions[n]
        for v in (block.lo[0], block.hi[0], block.lo[1], block.hi[1]):
            assert abs(v / p - round(v / p)) < 1e-12
    # every site of a level is a site of the finer levels (common origin)
    fine = {tuple(np.round(x, 6)) for x in model.sites(0, np.zeros(3), np.array([40.0, 40.0, 20.0]))}
    coarse = model.sites(2, np.zeros(3), np.array([40.0, 40.0, 20.0]))
    assert len(coarse) and all(tuple(np.round(x, 6)) in fine for x in coarse)


def test_centroid_sites():
    """sites centroid: every coarse particle sits at the centroid of the
    atoms it stands for, so the real particles, weighted by the atoms they
    stand for, have the centre of mass of the atomic crystal of the box
    (round-off); with the thesis's common origin a level-n particle sits
    on the first atom of its cell and the model's centre of mass is off
    by about (s_n - 1)/4 of a lattice period (Angstroms).  The regions,
    and so the particle counts, are the same."""
    spec = dict(three_levels(), periodic="z")
    models = {sites: gp_build.build(dict(spec, sites=sites)) for sites in ("origin", "centroid")}
    atoms = models["origin"].sites(0, np.array(spec["box"][0::2], dtype=float),
                                   np.array(spec["box"][1::2], dtype=float))
    offsets = {}
    for sites, model in models.items():
        weights = np.concatenate([np.full(len(model.real[n]), 8.0 ** n) for n in range(3)])
        centre = np.average(np.concatenate(model.real), axis=0, weights=weights)
        offsets[sites] = np.abs(centre - atoms.mean(axis=0)).max()
        assert weights.sum() == len(atoms)
        assert [len(r) for r in model.real] == [len(r) for r in models["origin"].real]
    print(f"\ncentre of mass of the real particles - the atoms': origin {offsets['origin']:.3f} A, "
          f"centroid {offsets['centroid']:.1e} A")
    assert offsets["centroid"] < 1e-9
    assert offsets["origin"] > 1.0
    shift = models["centroid"].shift
    # bcc X = [110], Y = [-110], Z = [001]: a quarter period per level step
    assert np.allclose(shift[1], [PX / 4, PX / 4, PZ / 4]) and np.allclose(shift[2], 3 * shift[1])


PATCH = """
include         in.model
variable        f2 atom fx*fx+fy*fy+fz*fz
compute         fmax real reduce max v_f2
compute         frms real reduce ave v_f2
thermo_style    custom step pe c_fmax c_frms f_gplink[1] f_gplink[2]
run             0
change_box      all triclinic
change_box      real x scale 1.01 y scale 0.995 xy final $(0.01*ly) remap units box
run             0
print           "PATCH $(sqrt(c_fmax):%.6e)"
displace_atoms  real random 0.02 0.02 0.02 97531 units box
run             0
print           "BULK $(sqrt(c_frms):%.6e)"
"""


@pytest.mark.parametrize("sites", ["origin", "centroid"])
def test_patch_test_three_levels(build, tmp_path, sites):
    model = write(dict(three_levels(), sites=sites), tmp_path)
    out = build.run(PATCH, tmp_path).stdout
    largest = float(re.search(r"^PATCH (\S+)", out, re.M).group(1))
    bulk = float(re.search(r"^BULK (\S+)", out, re.M).group(1))
    linked = re.search(r"fix gp/link: (\d+) imaginary particles linked to ([0-9.]+)", out)
    print(f"\nthree levels, sites {sites}: largest force {largest:.3e} eV/A = {largest / bulk:.1e} of the rms "
          f"force {bulk:.3f} eV/A of a displaced model; {linked.group(1)} imaginary particles")
    assert int(linked.group(1)) == sum(map(len, model.imaginary))
    assert float(linked.group(2)) == 12.0
    assert largest <= 1e-8 * bulk


LOADING = """
include         in.model
compute         pe real pe/atom
compute         s real stress/atom NULL virial
compute         pesum real reduce sum c_pe
compute         syy real reduce sum c_s[2]
thermo_style    custom step pe c_pesum c_syy
change_box      all triclinic
run             0
print           "LOAD 0 $(c_pesum/v_atoms:%.15e) $(c_syy/vol*1e-4:%.15e)"
variable        e loop 4
label           step
change_box      real y scale $((1+0.01*v_e)/(1+0.01*(v_e-1))) remap units box
run             0
print           "LOAD $(0.01*v_e) $(c_pesum/v_atoms:%.15e) $(c_syy/vol*1e-4:%.15e)"
next            e
jump            SELF step
"""


def loading_curve(build, directory, spec, atoms):
    write(spec, directory)
    out = build.run(LOADING, directory, variables={"atoms": atoms}).stdout
    return np.array([[float(v) for v in m] for m in re.findall(r"^LOAD (\S+) (\S+) (\S+)", out, re.M)])


def test_stress_strain_equals_level_one(build, tmp_path):
    spec = three_levels()
    model = gp_build.build(spec)
    atoms = sum(len(model.real[n]) * 8 ** n for n in range(3))
    gp = loading_curve(build, tmp_path / "gp", spec, atoms)
    # the pure level-1 crystal: 3 x 3 x 4 atomic periods
    pure = dict(FE, box=[0, 3 * PX, 0, 3 * PX, 0, 4 * PZ], periodic="xyz", levels=[None])
    s1 = loading_curve(build, tmp_path / "s1", pure, 3 * 3 * 4 * 4)
    assert len(gp) == len(s1) == 5
    de = np.max(np.abs(gp[:, 1] / s1[:, 1] - 1))
    ds = np.max(np.abs(gp[1:, 2] / s1[1:, 2] - 1))
    for row_gp, row_s1 in zip(gp, s1):
        print(f"strain {row_gp[0]:.2f}: energy/atom {row_gp[1]:.10f} / {row_s1[1]:.10f} eV, "
              f"sigma_yy {row_gp[2]:.8f} / {row_s1[2]:.8f} GPa")
    print(f"largest relative difference: energy {de:.1e}, stress {ds:.1e}")
    assert abs(s1[0, 1] + 4.1224) < 1e-3     # Fe_mm's cohesive energy (sanity of the set-up)
    assert abs(s1[0, 2]) < 1e-3               # GPa: the perfect crystal is stress free
    # the loading reaches the non-linear range: the tangent modulus falls by > 10 %
    assert (s1[4, 2] - s1[3, 2]) < 0.9 * (s1[1, 2] - s1[0, 2])
    assert de < 1e-10 and ds < 1e-10


def cracked(images):
    """Two levels, free x faces, periodic z; an edge crack and a hole."""
    return dict(FE, box=[0, 24 * PX, -12 * PX, 12 * PX, 0, 22 * PZ], periodic="z",
                levels=[{"block": [30, 70, -20, 20, None, None]}, None],
                cuts=[{"crack": {"tip": 45, "y": 0, "height": 4.5}},
                      {"cylinder": {"axis": "z", "center": [85, -20], "radius": 6}}],
                images=images)


FORCES = """
include         in.model
thermo_style    custom step pe
run             0
write_dump      all custom forces.dump id type x y z fx fy fz modify sort id format float %.17g
"""


def test_cuts_and_surface_images(build, tmp_path):
    results = {}
    for case, faces in (("images", ["ylo", "yhi"]), ("free", [])):
        directory = tmp_path / case
        directory.mkdir()
        model = write(cracked(faces), directory)
        out = build.run(FORCES, directory).stdout
        x, types = model.particles()
        # nothing inside a cut
        for cut in model.cuts:
            assert not np.any(cut.contains(x))
        images = np.concatenate(model.images)
        if faces:
            assert len(images) > 0
            # (a site on the upper face is beyond it: the box is half open)
            tol = gp_build.TOLERANCE
            assert np.all((images[:, 1] < model.box[1, 0] - tol) | (images[:, 1] >= model.box[1, 1] - tol))
            assert np.all((images[:, 0] >= 0) & (images[:, 0] < model.box[0, 1]))
            linked = re.findall(r"fix gp/link: (\d+) imaginary particles linked", out)
            assert [int(n) for n in linked] == [sum(map(len, model.imaginary)), len(images)]
        else:
            assert len(images) == 0
        dump = mcatest.read_dump(directory / "forces.dump")[0]
        f = np.linalg.norm(np.array([dump["fx"], dump["fy"], dump["fz"]]), axis=0)
        pos = np.array([dump["x"], dump["y"]]).T
        t = dump["type"]
        # level-2 real particles within 10 A of a y face, far from x faces, crack and hole
        face = np.minimum(pos[:, 1] - model.box[1, 0], model.box[1, 1] - pos[:, 1])
        far = (pos[:, 0] > 30) & (pos[:, 0] < model.box[0, 1] - 30) & \
            (np.hypot(pos[:, 0] - 85, pos[:, 1] + 20) > 30)
        select = (t == 2) & (face < 10) & far
        assert np.sum(select) > 20
        results[case] = np.max(f[select])
    print(f"\nlargest force on a level-2 particle at a y face: {results['images']:.2e} eV/A with "
          f"images, {results['free']:.3f} eV/A free")
    assert results["images"] < 1e-10
    assert results["free"] > 1e-2


def test_python_module(tmp_path):
    lammps = pytest.importorskip("lammps", reason="LAMMPS Python module not on PYTHONPATH")
    current = mcatest.build_named("current")
    if current is None:
        pytest.skip("the Python module belongs to the 'current' build")
    spec = cracked(["ylo", "yhi"])
    model = write(spec, tmp_path)
    out = current.run("include in.model\nrun 0\nprint \"PE $(pe:%.15e)\"\n", tmp_path).stdout
    from_file = float(re.search(r"^PE (\S+)", out, re.M).group(1))
    lmp = lammps.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    try:
        model.create(lmp)
        lmp.command("run 0")
        direct = lmp.get_thermo("pe")
        natoms = lmp.get_natoms()
    finally:
        lmp.close()
    print(f"\ndata file {from_file:.12f} eV, Python module {direct:.12f} eV")
    assert natoms == len(model.particles()[0])
    assert abs(direct - from_file) <= 1e-10 * abs(from_file)


def test_command_line(tmp_path):
    spec = tmp_path / "crack.json"
    spec.write_text(json.dumps(cracked(["ylo", "yhi"])))
    run = subprocess.run([sys.executable, str(mcatest.ROOT / "tools" / "gp_build.py"), str(spec),
                          "-o", str(tmp_path / "crack")], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert (tmp_path / "crack.data").is_file() and (tmp_path / "in.crack").is_file()
    fragment = (tmp_path / "in.crack").read_text()
    assert "fix             gplink imaginary gp/link real coupling force\n" in fragment
    assert "fix             gpimages images gp/link real level same" in fragment
    # fit quadratic goes to the interface links only (images keep theirs)
    spec.write_text(json.dumps(dict(cracked(["ylo", "yhi"]), fit="quadratic")))
    run = subprocess.run([sys.executable, str(mcatest.ROOT / "tools" / "gp_build.py"), str(spec),
                          "-o", str(tmp_path / "crackq")], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    fragment = (tmp_path / "in.crackq").read_text()
    assert "fix             gplink imaginary gp/link real coupling force fit quadratic\n" in fragment
    assert re.search(r"^fix +gpimages images gp/link real level same cutoff \S+ coupling force$",
                     fragment, re.M)
    bad = dict(cracked([]), ratio=1)
    spec.write_text(json.dumps(bad))
    run = subprocess.run([sys.executable, str(mcatest.ROOT / "tools" / "gp_build.py"), str(spec)],
                         capture_output=True, text=True, cwd=tmp_path)
    assert run.returncode != 0 and "ratio 1 must be an integer from 2 to 10" in run.stderr


@pytest.mark.parametrize("change, message", [
    ({"ratio": 2.5}, r"ratio 2.5 must be an integer from 2 to 10"),
    ({"ratio": 1}, r"ratio 1 must be an integer from 2 to 10"),
    ({"depth": 0.5}, r"depth 0.5 must be at least 1"),
    ({"element": "Cu"}, r"element 'Cu' is not in the potential file Fe_mm.eam.fs"),
    ({"lattice": "hcp"}, r"lattice 'hcp': use bcc or fcc"),
    ({"orient": [[1, 1, 0], [1, 1, 0], [0, 0, 1]]}, r"orient: x and y are not orthogonal"),
    ({"box": [0, 100, 0, 12 * 4 * PX, 0, 16 * PZ]},
     r"periodic x length 100 is not a multiple of the level-3 lattice period 16.15"),
    ({"box": [0, 12 * 4 * PX, 0, 12 * 4 * PX, 0, 4 * PZ]},
     r"periodic z length 11.42\S* must exceed twice the level-3 cutoff 21.2 \(use 45.68"),
    ({"levels": [{"block": [80, 113, 80, 113, None, None]},
                 {"block": [90, 162, 32, 162, None, None]}, None]},
     r"region of level 1 reaches outside the region of level 2 \(overlapping level regions"),
    ({"levels": [{"block": [80, 113, 80, 113, None, None]},
                 {"block": [64, 130, 64, 130, None, None]}, None]},
     r"imaginary level-3 particles fall in the region of level 1, not next to level 3"),
    ({"levels": [None, {"block": [64, 130, 64, 130, None, None]}, None]},
     r"only the last level's region may be null \(level 1\)"),
    ({"cuts": [{"torus": {}}]}, r"unknown shape 'torus'"),
    ({"images": ["ylo"]}, r"images: face ylo is on a periodic axis"),
    ({"box": [0, 12 * 4 * PX, -6 * 4 * PX, 6 * 4 * PX, 0, 16 * PZ], "periodic": "xz",
      "images": ["ylo", "yhi"]},
     r"periodic z length 45.68\S* must exceed twice the search distance \S+ of the surface"),
    ({"potential": {"style": "tersoff"}}, r"potential style 'tersoff'"),
    ({"coupling": "both"}, r"coupling 'both': force or energy"),
    ({"fit": "cubic"}, r"fit 'cubic': linear or quadratic"),
    ({"sites": "corner"}, r"sites 'corner': origin or centroid"),
])
def test_bad_input(change, message):
    spec = dict(three_levels(), **change)
    with pytest.raises(gp_build.BuildError, match=message):
        gp_build.build(spec)
