#!/usr/bin/python3
"""Model builder of the Generalized Particle (GP) method (doc/src/Howto_gp.rst).

A GP model is one crystal seen at several scale levels: level n is the
crystal's lattice scaled by s_n = k^(n-1) about a common origin, in a
common orientation.  The user gives nested regions (level 1 innermost, the
coarsest level fills the rest of the box), cut-outs (holes, slits, cracks)
and the faces that get surface images; the builder

* fills each level's region with its own lattice (only there, so a large
  far field is cheap), snapping block faces to the lattice of the next
  coarser level so that the two levels tile the volume exactly;
* adds the imaginary particles of every interface (the rule of the
  thesis's Mater_Model8, the GP digest sec. 5.5: every level-n site of the
  other levels' regions within the imaginary depth of a real level-n
  particle; depth r_c,n for pair potentials, 2 r_c,n for EAM) and checks
  that each lies in an adjacent level's region with at least 4 real
  particles there to link to;
* adds surface images (imaginary particles of the same level beyond a
  free face of a coarse level);
* writes a LAMMPS data file and an input fragment (pair style with the
  levels of the types, groups real / imaginary / images, fix gp/link,
  neighbour settings, the temperature of the real particles), or creates
  the model in a running LAMMPS instance (the LAMMPS Python module).

Command line:  tools/gp_build.py spec.json [-o PREFIX]  (writes PREFIX.data
and in.PREFIX, default PREFIX = the spec's name without .json).
From Python:   model = gp_build.build(spec); model.write(prefix) or
               model.create(lmp) (a lammps.lammps instance).

The spec (a dict, or a JSON file) -- lengths in Angstrom:

  lattice      "bcc" | "fcc" (one element)
  a0           the atomic lattice constant
  orient       [[X], [Y], [Z]] Miller directions of the box axes (orthogonal)
  element      the element's name (for the potential file)
  mass         the atomic mass (default: from an EAM file)
  potential    {"style": "eam/fs" | "eam/alloy", "file": F}
               {"style": "morse", "D0":, "alpha":, "r0":, "cutoff":}
               {"style": "lj/cut", "epsilon":, "sigma":, "cutoff":}
  ratio        k, an integer 2 to 10 (default 2)
  box          [xlo, xhi, ylo, yhi, zlo, zhi]
  periodic     the periodic axes, e.g. "xz" (default "xyz"); a periodic
               length must be a multiple of the coarsest level's period
  levels       [region of level 1, region of level 2, ...] (each a shape
               or a list of shapes, their union; the last level may be
               null: the whole box); each region must lie inside the next
  cuts         [shape, ...] removed from every level
  images       faces ("xlo", "xhi", ...) of non-periodic axes that get
               surface images at the coarse levels (default none)
  image_levels the levels that get images (default 2 and up)
  depth        the imaginary depth in units of r_c,n (default 1 for pair
               potentials, 2 for EAM; at least 1)
  neighbor     "bin" (default; KOKKOS takes only bin) or "multi"
  coupling     "force" (default) or "energy": fix gp/link's coupling
  fit          "linear" (default) or "quadratic": fix gp/link's fit of
               the interface particles (quadratic: exact for curved
               fields too, for statics near a crack tip)
  sites        "origin" (default; the thesis: every level's lattice
               scaled about the common origin, a coarse site on an atom's
               site) or "centroid" (each level moved as a whole so that
               its particles sit at the centroids of the atoms they
               stand for: the levels' material then tiles the volume at
               every interface, upper and lower faces alike)

Shapes: {"block": [xlo, xhi, ylo, yhi, zlo, zhi]} (null = unbounded),
{"cylinder": {"axis": "z", "center": [c1, c2], "radius": R}},
{"sphere": {"center": [x, y, z], "radius": R}},
{"crack": {"tip": x, "y": y0, "height": h}} (a slit from the xlo face to
the tip along x, |y - y0| < h/2: to cut level n it must be wider than that
level's spacing of lattice planes normal to y).
"""

import json
import math
import pathlib
import sys

import numpy as np

try:
    from scipy.spatial import cKDTree
except ImportError:  # pragma: no cover - Debian's python3-scipy is a dependency
    cKDTree = None

AXES = "xyz"
BASES = {
    "bcc": np.array([[0.0, 0.0, 0.0], [0.5, 0.5, 0.5]]),
    "fcc": np.array([[0.0, 0.0, 0.0], [0.0, 0.5, 0.5], [0.5, 0.0, 0.5], [0.5, 0.5, 0.0]]),
}
# a site exactly on a region's face belongs to the region at its lower
# face and not at its upper one (half-open), whatever the round-off
TOLERANCE = 1e-6


class BuildError(ValueError):
    """A spec the builder refuses, with the argument and the allowed range."""


# ----------------------------------------------------------------------------
# shapes


class Shape:
    def contains(self, x):
        raise NotImplementedError

    def bounds(self):
        """[lo, hi] per axis (inf where unbounded)."""
        raise NotImplementedError


class Block(Shape):
    def __init__(self, values):
        if len(values) != 6:
            raise BuildError(f"block needs 6 values (xlo xhi ylo yhi zlo zhi), got {values}")
        lo, hi = [], []
        for d in range(3):
            a, b = values[2 * d], values[2 * d + 1]
            lo.append(-math.inf if a is None else float(a))
            hi.append(math.inf if b is None else float(b))
            if lo[d] >= hi[d]:
                raise BuildError(f"block {AXES[d]}lo {lo[d]} must be below {AXES[d]}hi {hi[d]}")
        self.lo, self.hi = np.array(lo), np.array(hi)

    def contains(self, x):
        return np.all((x >= self.lo - TOLERANCE) & (x < self.hi - TOLERANCE), axis=1)

    def bounds(self):
        return np.stack([self.lo, self.hi], axis=1)

    def __repr__(self):
        return "block " + " ".join(f"{a:g} {b:g}" for a, b in zip(self.lo, self.hi))


class Cylinder(Shape):
    def __init__(self, spec):
        self.axis = AXES.index(spec.get("axis", "z"))
        self.center = np.array(spec["center"], dtype=float)
        self.radius = float(spec["radius"])
        if self.radius <= 0:
            raise BuildError(f"cylinder radius {self.radius} must be > 0")
        self.others = [d for d in range(3) if d != self.axis]

    def contains(self, x):
        r2 = sum((x[:, d] - c) ** 2 for d, c in zip(self.others, self.center))
        return r2 < (self.radius - TOLERANCE) ** 2

    def bounds(self):
        b = np.array([[-math.inf, math.inf]] * 3)
        for d, c in zip(self.others, self.center):
            b[d] = [c - self.radius, c + self.radius]
        return b

    def __repr__(self):
        return f"cylinder {AXES[self.axis]} {self.center} {self.radius:g}"


class Sphere(Shape):
    def __init__(self, spec):
        self.center = np.array(spec["center"], dtype=float)
        self.radius = float(spec["radius"])
        if self.radius <= 0:
            raise BuildError(f"sphere radius {self.radius} must be > 0")

    def contains(self, x):
        return np.sum((x - self.center) ** 2, axis=1) < (self.radius - TOLERANCE) ** 2

    def bounds(self):
        return np.stack([self.center - self.radius, self.center + self.radius], axis=1)

    def __repr__(self):
        return f"sphere {self.center} {self.radius:g}"


class Union(Shape):
    def __init__(self, shapes):
        self.shapes = shapes

    def contains(self, x):
        inside = np.zeros(len(x), dtype=bool)
        for s in self.shapes:
            inside |= s.contains(x)
        return inside

    def bounds(self):
        b = np.array([s.bounds() for s in self.shapes])
        return np.stack([b[:, :, 0].min(axis=0), b[:, :, 1].max(axis=0)], axis=1)

    def __repr__(self):
        return " + ".join(map(repr, self.shapes))


def make_shape(spec):
    if isinstance(spec, list):
        if not spec:
            raise BuildError("an empty list of shapes")
        shapes = [make_shape(s) for s in spec]
        return shapes[0] if len(shapes) == 1 else Union(shapes)
    if not isinstance(spec, dict) or len(spec) != 1:
        raise BuildError(f"a shape is one of block, cylinder, sphere, crack: got {spec}")
    kind, value = next(iter(spec.items()))
    if kind == "block":
        return Block(value)
    if kind == "cylinder":
        return Cylinder(value)
    if kind == "sphere":
        return Sphere(value)
    if kind == "crack":
        h = float(value["height"])
        if h <= 0:
            raise BuildError(f"crack height {h} must be > 0")
        y0 = float(value["y"])
        return Block([None, float(value["tip"]), y0 - h / 2, y0 + h / 2, None, None])
    raise BuildError(f"unknown shape '{kind}': use block, cylinder, sphere or crack")


# ----------------------------------------------------------------------------
# potentials


def find_potential_file(name):
    import os
    for candidate in [pathlib.Path(name)] + [
            pathlib.Path(d) / name for d in os.environ.get("LAMMPS_POTENTIALS", "").split(":") if d]:
        if candidate.is_file():
            return candidate
    raise BuildError(f"potential file '{name}' not found here nor in $LAMMPS_POTENTIALS")


def read_eam_header(path, element):
    """The cutoff and the element's mass of a setfl or Finnis-Sinclair file."""
    lines = path.read_text().splitlines()
    names = lines[3].split()[1:]
    if element not in names:
        raise BuildError(f"element '{element}' is not in the potential file {path.name} "
                         f"(it has {' '.join(names)})")
    cutoff = float(lines[4].split()[4])
    # the first element's block starts at line 5 with "Z mass a lattice"
    mass = float(lines[5].split()[1]) if names.index(element) == 0 else None
    return cutoff, mass


class Potential:
    def __init__(self, spec, element):
        self.style = spec.get("style")
        self.eam = self.style in ("eam/fs", "eam/alloy")
        self.mass = None
        if self.eam:
            self.file = spec["file"]
            self.cutoff, self.mass = read_eam_header(find_potential_file(self.file), element)
        elif self.style == "morse":
            self.coeffs = [float(spec["D0"]), float(spec["alpha"]), float(spec["r0"])]
            self.cutoff = float(spec["cutoff"])
        elif self.style == "lj/cut":
            self.coeffs = [float(spec["epsilon"]), float(spec["sigma"])]
            self.cutoff = float(spec["cutoff"])
        else:
            raise BuildError(f"potential style '{self.style}': use eam/fs, eam/alloy, morse "
                             "or lj/cut")
        if self.cutoff <= 0:
            raise BuildError(f"potential cutoff {self.cutoff} must be > 0")


# ----------------------------------------------------------------------------
# the model


class Model:
    """The particles of a GP model and what LAMMPS needs to run it."""

    def __init__(self, spec):
        self.spec = spec
        self.lattice = spec.get("lattice", "bcc")
        if self.lattice not in BASES:
            raise BuildError(f"lattice '{self.lattice}': use bcc or fcc")
        self.a0 = float(spec["a0"])
        if self.a0 <= 0:
            raise BuildError(f"a0 {self.a0} must be > 0")
        ratio = spec.get("ratio", 2)
        if not float(ratio).is_integer() or not 2 <= ratio <= 10:
            raise BuildError(f"ratio {ratio} must be an integer from 2 to 10")
        self.k = int(ratio)
        self.element = spec.get("element", "X")
        self.potential = Potential(spec["potential"], self.element)
        self.mass = float(spec.get("mass") or self.potential.mass or 0)
        if self.mass <= 0:
            raise BuildError("mass: give the element's atomic mass (> 0)")
        self.orient = np.array(spec.get("orient", [[1, 0, 0], [0, 1, 0], [0, 0, 1]]), dtype=float)
        if self.orient.shape != (3, 3):
            raise BuildError("orient needs three Miller directions [[X], [Y], [Z]]")
        for a in range(3):
            for b in range(a + 1, 3):
                if abs(self.orient[a] @ self.orient[b]) > 1e-9:
                    raise BuildError(f"orient: {AXES[a]} and {AXES[b]} are not orthogonal")
        lengths = np.linalg.norm(self.orient, axis=1)
        if np.any(lengths == 0):
            raise BuildError("orient: a zero direction")
        self.rotation = self.orient / lengths[:, None]    # rows: box axes in crystal frame
        if np.linalg.det(self.rotation) < 0:
            raise BuildError("orient: X, Y, Z must form a right-handed set")
        self.period = self.a0 * lengths                   # atomic period along each axis
        self.box = Block(spec["box"]).bounds()
        if not np.all(np.isfinite(self.box)):
            raise BuildError("box needs 6 finite values")
        periodic = spec.get("periodic", "xyz")
        if any(c not in AXES for c in periodic):
            raise BuildError(f"periodic '{periodic}': a subset of xyz")
        self.periodic = [AXES[d] in periodic for d in range(3)]
        regions = spec.get("levels")
        if not regions:
            raise BuildError("levels: give the region of each level, level 1 first")
        self.nlevels = len(regions)
        if self.nlevels > 8:
            raise BuildError(f"levels: {self.nlevels} levels, at most 8")
        self.scale = [self.k ** n for n in range(self.nlevels)]
        self.check_periods()
        self.regions = []
        for n, r in enumerate(regions):
            if r is None and n != self.nlevels - 1:
                raise BuildError(f"levels: only the last level's region may be null (level {n + 1})")
            self.regions.append(Block(list(self.box.ravel())) if r is None else make_shape(r))
        self.snapped = []
        for n in range(self.nlevels - 1):
            self.snap(n)
        self.cuts = [make_shape(c) for c in spec.get("cuts", [])]
        depth = spec.get("depth", 2.0 if self.potential.eam else 1.0)
        if float(depth) < 1.0:
            raise BuildError(f"depth {depth} must be at least 1 (units of the level's cutoff: "
                             "the imaginary particles must reach as far as a real particle's "
                             "forces; EAM needs 2 for exact forces)")
        self.depth = [float(depth) * self.potential.cutoff * s for s in self.scale]
        self.faces = spec.get("images", [])
        for f in self.faces:
            if f not in ("xlo", "xhi", "ylo", "yhi", "zlo", "zhi"):
                raise BuildError(f"images: unknown face '{f}' (xlo xhi ylo yhi zlo zhi)")
            if self.periodic[AXES.index(f[0])]:
                raise BuildError(f"images: face {f} is on a periodic axis")
        self.image_levels = spec.get("image_levels", list(range(2, self.nlevels + 1)))
        for n in self.image_levels:
            if n not in range(1, self.nlevels + 1):
                raise BuildError(f"image_levels: level {n} is not one of 1..{self.nlevels}")
        self.coupling = spec.get("coupling", "force")
        if self.coupling not in ("force", "energy"):
            raise BuildError(f"coupling '{self.coupling}': force or energy (fix gp/link)")
        self.fit = spec.get("fit", "linear")
        if self.fit not in ("linear", "quadratic"):
            raise BuildError(f"fit '{self.fit}': linear or quadratic (fix gp/link)")
        self.neighbor = spec.get("neighbor", "bin")
        if self.neighbor not in ("bin", "multi"):
            raise BuildError(f"neighbor '{self.neighbor}': bin or multi")
        self.registry = spec.get("sites", "origin")
        if self.registry not in ("origin", "centroid"):
            raise BuildError(f"sites '{self.registry}': origin or centroid")
        self.shift = [self.centroid_shift(n) if self.registry == "centroid" else np.zeros(3)
                      for n in range(self.nlevels)]
        self.make_particles()

    # -- geometry ------------------------------------------------------------

    def check_periods(self):
        coarse = self.scale[-1]
        for d in range(3):
            if not self.periodic[d]:
                continue
            length = self.box[d, 1] - self.box[d, 0]
            p = coarse * self.period[d]
            cells = length / p
            # a length typed with a few decimals is taken as the exact multiple
            if abs(cells - round(cells)) * p > 1e-3 or round(cells) < 1:
                raise BuildError(
                    f"box: the periodic {AXES[d]} length {length:.6g} is not a multiple of the "
                    f"level-{self.nlevels} lattice period {p:.6g} along {AXES[d]} (use "
                    f"{max(1, math.floor(cells)) * p:.10g} or {math.ceil(cells) * p:.10g})")
            self.box[d, 1] = self.box[d, 0] + round(cells) * p
            # fix gp/link searches members within the largest cutoff and
            # must not find one particle through two periodic images
            reach = self.potential.cutoff * coarse
            if self.box[d, 1] - self.box[d, 0] <= 2 * reach:
                need = math.floor(2 * reach / p) + 1
                raise BuildError(
                    f"box: the periodic {AXES[d]} length {length:.6g} must exceed twice the "
                    f"level-{self.nlevels} cutoff {reach:.6g} (use {need * p:.10g})")

    def snap(self, n):
        """Block faces of level n's region onto planes of level n+1's lattice."""
        p = self.scale[n + 1] * self.period
        shapes = self.regions[n].shapes if isinstance(self.regions[n], Union) else [self.regions[n]]
        for shape in shapes:
            if not isinstance(shape, Block):
                continue
            for d in range(3):
                for side, values in (("lo", shape.lo), ("hi", shape.hi)):
                    v = values[d]
                    if not math.isfinite(v):
                        continue
                    snapped = round(v / p[d]) * p[d]
                    if abs(snapped - v) > TOLERANCE:
                        self.snapped.append(f"level {n + 1} {AXES[d]}{side} {v:g} -> {snapped:.6g}")
                    values[d] = snapped

    def sites(self, n, lo, hi):
        """Level-n lattice sites in the box [lo, hi) (the box axes)."""
        a = self.scale[n] * self.a0
        corners = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1])
                            for z in (lo[2], hi[2])])
        crystal = corners @ self.rotation / a       # crystal coordinates of the corners
        imin = np.floor(crystal.min(axis=0)).astype(int) - 1
        imax = np.ceil(crystal.max(axis=0)).astype(int) + 1
        out = []
        basis = BASES[self.lattice]
        grid = np.stack(np.meshgrid(*[np.arange(imin[d], imax[d] + 1) for d in range(3)],
                                    indexing="ij"), axis=-1).reshape(-1, 3).astype(float)
        for b in basis:
            x = ((grid + b) * a) @ self.rotation.T
            keep = np.all((x >= lo - TOLERANCE) & (x < hi - TOLERANCE), axis=1)
            out.append(x[keep])
        return np.concatenate(out)

    def centroid_shift(self, n):
        """The translation that puts each level-n site at the centroid of
        the atoms it stands for: in a box-aligned cell of the level-n
        lattice, the mean of the atoms minus the mean of the level-n sites
        (both lattices scaled about the origin; the cell's faces are the
        planes the regions snap to, so the atoms of a cell are those of its
        level-n particles)."""
        cell = self.scale[n] * self.period
        zero = np.zeros(3)
        return self.sites(0, zero, cell).mean(axis=0) - self.sites(n, zero, cell).mean(axis=0)

    def wrap(self, x):
        """Periodic sites into the box (a site at hi -> at lo)."""
        x = x.copy()
        for d in range(3):
            if self.periodic[d]:
                L = self.box[d, 1] - self.box[d, 0]
                x[:, d] = self.box[d, 0] + np.mod(x[:, d] - self.box[d, 0] + TOLERANCE, L) - TOLERANCE
        return x

    def level_tree(self, n):
        """The k-d tree of level n's real particles (made once)."""
        if n not in self.trees:
            self.trees[n] = self.tree(self.real[n])
        return self.trees[n]

    def tree(self, x):
        """A k-d tree with the box's periodicity (non-periodic axes get a span they cannot wrap)."""
        if cKDTree is None:
            raise BuildError("the builder needs scipy (Debian: python3-scipy)")
        lo = self.box[:, 0] - 4 * max(self.depth) - 1.0
        span = self.box[:, 1] - self.box[:, 0] + 8 * max(self.depth) + 2.0
        size = np.where(self.periodic, self.box[:, 1] - self.box[:, 0], 4 * span)
        shift = np.where(self.periodic, self.box[:, 0], lo)
        def into(y):
            z = y - shift
            return np.where(self.periodic, np.mod(z, size), z)
        return cKDTree(into(x), boxsize=size), into

    def beyond(self, x, face):
        """Points beyond a face of a non-periodic axis (a point on an upper face is beyond it)."""
        d = AXES.index(face[0])
        if face.endswith("lo"):
            return x[:, d] < self.box[d, 0] - TOLERANCE
        return x[:, d] >= self.box[d, 1] - TOLERANCE

    def open_faces(self):
        return [AXES[d] + side for d in range(3) if not self.periodic[d] for side in ("lo", "hi")]

    def level_of(self, x):
        """The level (0-based) whose domain holds each point (-1: outside the box)."""
        level = np.full(len(x), -1)
        for n in reversed(range(self.nlevels)):
            level[self.regions[n].contains(x)] = n
        for face in self.open_faces():
            level[self.beyond(x, face)] = -1
        return level

    def in_cut(self, x):
        cut = np.zeros(len(x), dtype=bool)
        for c in self.cuts:
            cut |= c.contains(x)
        return cut

    # -- particles -----------------------------------------------------------

    def make_particles(self):
        self.real, self.imaginary, self.images = [], [], []
        self.trees = {}
        lo_box, hi_box = self.box[:, 0], self.box[:, 1]
        for n in range(self.nlevels):
            # level n's sites in its region and the imaginary depth around it
            b = self.regions[n].bounds()
            margin = self.depth[n]
            lo = np.where(self.periodic, lo_box, np.maximum(b[:, 0], lo_box) - margin)
            hi = np.where(self.periodic, hi_box, np.minimum(b[:, 1], hi_box) + margin)
            x = self.wrap(self.sites(n, lo, hi))
            x = x[~self.in_cut(x)]
            level = self.level_of(x)
            real = x[level == n]
            if n < self.nlevels - 1 and len(real) == 0:
                raise BuildError(f"levels: the region of level {n + 1} holds no level-{n + 1} site")
            self.real.append(real)
            self.check_nesting(n)
            # imaginary: in another level's domain, within the depth of a real one
            elsewhere = (level != n) & (level >= 0)
            candidates = x[elsewhere]
            near = self.within(n, candidates, self.depth[n])
            imaginary = candidates[near]
            other = level[elsewhere][near]
            if np.any(np.abs(other - n) != 1):
                bad = sorted(set((other[np.abs(other - n) != 1] + 1).tolist()))
                raise BuildError(
                    f"levels: imaginary level-{n + 1} particles fall in the region of level "
                    f"{' '.join(map(str, bad))}, not next to level {n + 1}: a level's region "
                    f"between them is thinner than the imaginary depth {self.depth[n]:.4g} A of "
                    f"level {n + 1}")
            self.imaginary.append(imaginary)
            self.images.append(self.make_images(n, x))
        if any(len(i) for i in self.images):
            reach = self.image_reach()
            for d in range(3):
                length = self.box[d, 1] - self.box[d, 0]
                if self.periodic[d] and length <= 2 * reach:
                    raise BuildError(
                        f"box: the periodic {AXES[d]} length {length:.6g} must exceed twice the "
                        f"search distance {reach:.6g} of the surface images' links")
        if self.registry == "centroid":
            # the regions and depths were decided on the lattices scaled about
            # the origin (a particle belongs where its cell of atoms lies);
            # each level now moves as a whole to the centroids of its cells
            for n in range(self.nlevels):
                for group in (self.real, self.imaginary, self.images):
                    if len(group[n]):
                        group[n] = self.wrap(group[n] + self.shift[n])
            self.trees = {}
        self.check_members()
        self.check_cuts()

    def check_cuts(self):
        """A warning for each coarse level with real particles within its
        imaginary depth of a cut: a cut removes the imaginary sites inside
        it, so such particles see the cut as a coarse free surface (the
        atoms' surface is right, a coarse one is not)."""
        self.warnings = []
        if not self.cuts:
            return
        lo = np.array([max(self.box[d, 0], min(c.bounds()[d, 0] for c in self.cuts)) for d in range(3)])
        hi = np.array([min(self.box[d, 1], max(c.bounds()[d, 1] for c in self.cuts)) for d in range(3)])
        removed = self.sites(0, lo, hi)
        removed = removed[self.in_cut(removed)]       # the atoms the cuts remove
        for n in range(1, self.nlevels):
            if len(removed) == 0 or len(self.real[n]) == 0:
                continue
            tree, into = self.tree(removed)
            d, _ = tree.query(into(self.real[n]), k=1, distance_upper_bound=self.depth[n])
            near = int(np.sum(np.isfinite(d)))
            if near:
                self.warnings.append(
                    f"WARNING: {near} real level-{n + 1} particles lie within the imaginary depth "
                    f"{self.depth[n]:.4g} A of a cut: they see it as a coarse surface; put the cut's "
                    f"faces in level 1 with a margin of {self.depth[n]:.4g} A")

    def within(self, n, points, distance):
        """Which points lie within distance of a real level-n particle."""
        if len(self.real[n]) == 0 or len(points) == 0:
            return np.zeros(len(points), dtype=bool)
        tree, into = self.level_tree(n)
        d, _ = tree.query(into(points), k=1, distance_upper_bound=distance + TOLERANCE)
        return np.isfinite(d)

    def make_images(self, n, x):
        """Level-n sites beyond the faces with images (and no other face),
        within the depth of a real one."""
        if n + 1 not in self.image_levels or not self.faces:
            return np.zeros((0, 3))
        beyond = np.zeros(len(x), dtype=bool)
        elsewhere = np.zeros(len(x), dtype=bool)
        for face in self.open_faces():
            if face in self.faces:
                beyond |= self.beyond(x, face)
            else:
                elsewhere |= self.beyond(x, face)
        candidates = x[beyond & ~elsewhere]
        return candidates[self.within(n, candidates, self.depth[n])]

    def check_nesting(self, n):
        """Level n's region inside the next one's (else levels overlap)."""
        if n < self.nlevels - 1:
            x = self.real[n]
            outside = ~self.regions[n + 1].contains(x)
            if np.any(outside):
                p = x[np.argmax(outside)]
                raise BuildError(
                    f"levels: the region of level {n + 1} reaches outside the region of level "
                    f"{n + 2} (overlapping level regions: the levels must be nested), e.g. at "
                    f"({p[0]:.4g}, {p[1]:.4g}, {p[2]:.4g})")

    def image_reach(self):
        """fix gp/link's search distance for images: the deepest image's
        distance to the surface plane and one lattice period further in (the
        off-plane member the fix needs)."""
        axes = sorted({AXES.index(f[0]) for f in self.faces})
        return max(self.depth[n] + self.scale[n] * max(self.period[d] for d in axes)
                   for n in range(self.nlevels) if len(self.images[n])) + 0.5

    def check_members(self):
        """fix gp/link needs at least 4 real members within its search distance."""
        for n in range(self.nlevels):
            for kind, points, levels, cutoff in (
                    ("imaginary", self.imaginary[n], (n - 1, n + 1), self.potential.cutoff * self.scale[-1]),
                    ("image", self.images[n], (n,), self.image_reach() if len(self.images[n]) else 0)):
                if len(points) == 0:
                    continue
                count = np.zeros(len(points), dtype=int)
                for m in levels:
                    if 0 <= m < self.nlevels and len(self.real[m]):
                        tree, into = self.level_tree(m)
                        count += np.array([len(c) for c in tree.query_ball_point(into(points), cutoff)])
                if np.any(count < 4):
                    raise BuildError(
                        f"{np.sum(count < 4)} {kind} level-{n + 1} particles have fewer than 4 real "
                        f"particles to link to within {cutoff:.4g} A")

    # -- output --------------------------------------------------------------

    def type_mass(self, n):
        """The mass of a level-n particle, l_n m0."""
        return self.mass * self.scale[n] ** 3

    def atoms(self):
        """The number of atoms the real particles stand for (l_n each)."""
        return sum(len(self.real[n]) * self.scale[n] ** 3 for n in range(self.nlevels))

    def types(self):
        """(kind, level) of each atom type, 1-based order: real levels, imaginary, images."""
        t = [("real", n) for n in range(self.nlevels)]
        t += [("imaginary", n) for n in range(self.nlevels) if len(self.imaginary[n])]
        t += [("image", n) for n in range(self.nlevels) if len(self.images[n])]
        return t

    def particles(self):
        """Positions and types (1-based) of all particles."""
        x, types = [], []
        sets = {"real": self.real, "imaginary": self.imaginary, "image": self.images}
        for t, (kind, n) in enumerate(self.types(), start=1):
            x.append(sets[kind][n])
            types.append(np.full(len(sets[kind][n]), t))
        return np.concatenate(x), np.concatenate(types)

    def extent(self):
        """Box bounds holding every particle (images beyond non-periodic faces)."""
        x, _ = self.particles()
        lo, hi = self.box[:, 0].copy(), self.box[:, 1].copy()
        for d in range(3):
            if not self.periodic[d]:
                lo[d] = min(lo[d], x[:, d].min() - 0.5 * self.a0)
                hi[d] = max(hi[d], x[:, d].max() + 0.5 * self.a0)
        return lo, hi

    def summary(self):
        lines = [f"GP model: {self.lattice} {self.element} a0 {self.a0:g} A, ratio {self.k}, "
                 f"{self.nlevels} levels, potential {self.potential.style} (rc {self.potential.cutoff:g} A)"]
        for n in range(self.nlevels):
            lines.append(f"  level {n + 1}: {len(self.real[n])} real, {len(self.imaginary[n])} "
                         f"imaginary, {len(self.images[n])} images (s {self.scale[n]}, depth "
                         f"{self.depth[n]:.4g} A)")
        atoms = self.atoms()
        particles = sum(len(self.real[n]) for n in range(self.nlevels))
        total = particles + sum(len(i) + len(j) for i, j in zip(self.imaginary, self.images))
        lines.append(f"  {particles} real particles stand for {atoms} atoms "
                     f"({atoms / particles:.3g} per real particle, {atoms / total:.3g} per particle "
                     "with the imaginary ones)")
        if self.registry == "centroid":
            lines += [f"  sites: centroids of their atoms (level {n + 1} moved by "
                      f"{' '.join(f'{v:.6g}' for v in self.shift[n])} A)" for n in range(1, self.nlevels)]
        lines += ["  snapped: " + s for s in self.snapped]
        lines += ["  " + w for w in self.warnings]
        return lines

    def commands(self, data=None):
        """The LAMMPS commands of the model (read_data of DATA, if given)."""
        types = self.types()
        boundary = " ".join("p" if p else "s" for p in self.periodic)
        c = [f"# GP model written by tools/gp_build.py: " + self.summary()[0][len("GP model: "):]]
        c += ["units           metal", "atom_style      atomic", "atom_modify     map array",
              f"boundary        {boundary}"]
        if data:
            c.append(f"read_data       {data}")
        levels = " ".join(str(n + 1) for _, n in types)
        pot = self.potential
        if pot.eam:
            c.append(f"pair_style      gp/{pot.style} ratio {self.k}")
            c.append(f"pair_coeff      * * {pot.file} {' '.join([self.element] * len(types))} "
                     f"level {levels}")
        else:
            c.append(f"pair_style      gp/{pot.style} {pot.cutoff:.10g} ratio {self.k}")
            coeffs = " ".join(f"{v:.10g}" for v in pot.coeffs)
            for i, (_, n) in enumerate(types, start=1):
                for j, (_, m) in enumerate(types, start=1):
                    if j >= i and n == m:
                        c.append(f"pair_coeff      {i} {j} {coeffs} level {n + 1}")
            for i, (_, n) in enumerate(types, start=1):
                c.append(f"mass            {i} {self.type_mass(n):.10g}")
        for kind in ("real", "imaginary", "image"):
            ids = [str(i) for i, (k, _) in enumerate(types, start=1) if k == kind]
            if ids:
                c.append(f"group           {'images' if kind == 'image' else kind} type {' '.join(ids)}")
        for n in range(self.nlevels):
            ids = [str(i) for i, (k, m) in enumerate(types, start=1) if m == n and k == "real"]
            c.append(f"group           level{n + 1} type {' '.join(ids)}")
        c.append(f"neighbor        1.0 {self.neighbor}")
        if any(len(i) for i in self.imaginary):
            fit = "" if self.fit == "linear" else f" fit {self.fit}"
            c.append(f"fix             gplink imaginary gp/link real coupling {self.coupling}{fit}")
        if any(len(i) for i in self.images):
            # members of an image up to 2 r_c,n deep: reach a plane off the surface
            reach = self.image_reach()
            c.append(f"fix             gpimages images gp/link real level same cutoff {reach:.6g} "
                     f"coupling {self.coupling}")
            c.append(f"comm_modify     cutoff {reach + 1.0:.6g}")
        c.append("compute         treal real temp")
        c.append("thermo_modify   temp treal")
        return c

    def write(self, prefix):
        """PREFIX.data and in.PREFIX; returns their paths."""
        prefix = pathlib.Path(prefix)
        prefix.parent.mkdir(parents=True, exist_ok=True)
        data = prefix.with_name(prefix.name + ".data")
        script = prefix.with_name("in." + prefix.name)
        x, types = self.particles()
        lo, hi = self.extent()
        ntypes = len(self.types())
        with open(data, "w") as f:
            f.write("# " + "\n# ".join(self.summary()) + "\n\n")
            f.write(f"{len(x)} atoms\n{ntypes} atom types\n\n")
            for d in range(3):
                f.write(f"{lo[d]:.16g} {hi[d]:.16g} {AXES[d]}lo {AXES[d]}hi\n")
            f.write("\nMasses\n\n")
            for t, (_, n) in enumerate(self.types(), start=1):
                f.write(f"{t} {self.type_mass(n):.10g}\n")
            f.write("\nAtoms # atomic\n\n")
            for i in range(len(x)):
                f.write(f"{i + 1} {types[i]} {x[i, 0]:.16g} {x[i, 1]:.16g} {x[i, 2]:.16g}\n")
        script.write_text("\n".join(self.commands(data.name)) + "\n")
        return data, script

    def create(self, lmp):
        """Creates the model in a running LAMMPS instance (the lammps Python module)."""
        x, types = self.particles()
        lo, hi = self.extent()
        commands = self.commands()
        head = [c for c in commands[:5] if not c.startswith("#")]
        lmp.commands_list(head)
        lmp.command(f"region gpbox block {lo[0]:.16g} {hi[0]:.16g} {lo[1]:.16g} {hi[1]:.16g} "
                    f"{lo[2]:.16g} {hi[2]:.16g} units box")
        lmp.command(f"create_box {len(self.types())} gpbox")
        for t, (_, n) in enumerate(self.types(), start=1):
            lmp.command(f"mass {t} {self.type_mass(n):.10g}")
        n = len(x)
        lmp.create_atoms(n, list(range(1, n + 1)), types.tolist(), x.ravel().tolist())
        lmp.commands_list(commands[5:])


def build(spec):
    """A Model from a spec (a dict, or the path of a JSON file)."""
    if not isinstance(spec, dict):
        spec = json.loads(pathlib.Path(spec).read_text())
    return Model(spec)


def main(argv):
    import argparse
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("spec", help="the model's spec, a JSON file")
    parser.add_argument("-o", "--output", help="prefix of the files (default: the spec's name)")
    args = parser.parse_args(argv)
    try:
        model = build(args.spec)
    except (BuildError, KeyError) as e:
        sys.exit(f"gp_build.py: ERROR: {e}")
    prefix = args.output or pathlib.Path(args.spec).with_suffix("").name
    data, script = model.write(prefix)
    print("\n".join(model.summary()))
    print(f"wrote {data} and {script}")


if __name__ == "__main__":
    main(sys.argv[1:])
