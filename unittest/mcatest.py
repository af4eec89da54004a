"""Helpers of the MCA package tests: LAMMPS builds, runs and output readers.

The tests run LAMMPS executables as separate processes (serial or with
mpirun), one set for each build made by ``tools/mca``:

* ``current``: LAMMPS 4 Jul 2026, directory in $MCA_BUILD_CURRENT
* ``kokkos``:  LAMMPS 29 Sep 2021 + Kokkos, directory in $MCA_BUILD_KOKKOS
* ``kokkos5``: LAMMPS 4 Jul 2026 + Kokkos 5, directory in $MCA_BUILD_KOKKOS5
  (only where asked for: ``tools/mca test-kokkos5``)

A test that takes a ``build`` argument runs once per build.  Set
MCA_TEST_BUILDS=current (or kokkos) to restrict the runs while developing;
``tools/mca test`` always runs current and kokkos.  The Kokkos tests use the
build named by MCA_TEST_KOKKOS (default kokkos).
"""

import os
import pathlib
import subprocess
import tempfile

import numpy as np
import pytest

UNITTEST = pathlib.Path(__file__).resolve().parent
ROOT = UNITTEST.parent
BUILD_NAMES = ("current", "kokkos", "kokkos5")
DEFAULT_BUILDS = ("current", "kokkos")


class Build:
    """One LAMMPS build: its executable, unit-test programs and source tree."""

    def __init__(self, name, path, tree):
        self.name = name
        self.path = pathlib.Path(path)
        self.tree = pathlib.Path(tree) if tree else None
        self.lmp = self.path / "lmp"
        if not self.lmp.exists():
            raise RuntimeError(f"no lmp executable in {self.path} (build '{name}')")

    def __repr__(self):
        return self.name

    def tester(self, program):
        """Path of a LAMMPS unit-test program (location differs by version)."""
        for candidate in (self.path / program,
                          self.path / "unittest" / "force-styles" / program):
            if candidate.exists():
                return candidate
        raise RuntimeError(f"unit-test program {program} not built in {self.path}")

    def environment(self):
        """mpi_environment, and the potential files of the build's LAMMPS
        tree (LAMMPS looks for a potential file there when it is not in
        the working directory)."""
        env = mpi_environment()
        if self.tree is not None:
            env.setdefault("LAMMPS_POTENTIALS", str(self.tree / "potentials"))
        return env

    def run(self, script, cwd, nprocs=1, variables=None, timeout=600, check=True,
            extra_args=(), name="in.test"):
        """Run an input script (text) in directory cwd; return the completed process.

        The log is written to cwd/log.lammps.  With check=True a non-zero exit
        status fails the test and shows the end of the output.
        """
        cwd = pathlib.Path(cwd)
        cwd.mkdir(parents=True, exist_ok=True)
        (cwd / name).write_text(script)
        cmd = []
        if nprocs > 1:
            cmd += ["mpirun", "-np", str(nprocs)]
        cmd += [str(self.lmp), "-in", name, "-log", "log.lammps", "-nocite"]
        for key, value in (variables or {}).items():
            cmd += ["-var", key, str(value)]
        cmd += list(extra_args)
        result = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True,
                                timeout=timeout, env=self.environment())
        if check and result.returncode != 0:
            tail = (result.stdout + result.stderr)[-4000:]
            raise AssertionError(f"LAMMPS ({self.name}) failed with status "
                                 f"{result.returncode} in {cwd}:\n{tail}")
        return result


def mpi_environment():
    """Environment that lets Open MPI run as root and oversubscribe cores."""
    env = dict(os.environ)
    if os.geteuid() == 0:
        env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
        env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    env.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
    env.setdefault("OMP_NUM_THREADS", "1")
    # a session directory of Open MPI per pytest worker: on a fresh machine
    # the first runs of two workers, started at the same moment, race to
    # make the shared one and one fails ("mkdir ... /tmp/ompi.HOST.UID: File
    # exists", orte_session_dir)
    worker = os.environ.get("PYTEST_XDIST_WORKER", "main")
    session = pathlib.Path(tempfile.gettempdir()) / f"mca-ompi-{worker}"
    session.mkdir(exist_ok=True)
    env.setdefault("OMPI_MCA_orte_tmpdir_base", str(session))
    return env


def available_builds():
    wanted = os.environ.get("MCA_TEST_BUILDS", ",".join(DEFAULT_BUILDS)).split(",")
    builds = []
    for name in wanted:
        name = name.strip()
        if not name:
            continue
        if name not in BUILD_NAMES:
            raise RuntimeError(f"unknown build '{name}' in MCA_TEST_BUILDS")
        path = os.environ.get(f"MCA_BUILD_{name.upper()}")
        if not path:
            raise RuntimeError(f"MCA_BUILD_{name.upper()} is not set: run the tests "
                               "through 'tools/mca test'")
        builds.append(Build(name, path, os.environ.get(f"MCA_TREE_{name.upper()}")))
    return builds


_BUILDS = None


def builds():
    global _BUILDS
    if _BUILDS is None:
        _BUILDS = available_builds()
    return _BUILDS


def build_named(name):
    for b in builds():
        if b.name == name:
            return b
    return None


def kokkos_build():
    """The build whose Kokkos styles the Kokkos tests run (MCA_TEST_KOKKOS,
    default kokkos); skips the calling test if it is not among the tested
    builds."""
    name = os.environ.get("MCA_TEST_KOKKOS", "kokkos")
    if name not in ("kokkos", "kokkos5"):
        raise RuntimeError(f"MCA_TEST_KOKKOS={name}: kokkos or kokkos5")
    build = build_named(name)
    if build is None:
        pytest.skip(f"the {name} build is not among the tested builds")
    return build


def on_gpu():
    """True when the Kokkos tests run with a GPU build (MCA_TEST_GPU=nofma
    or fma, set by tools/mca-gpu check)."""
    return os.environ.get("MCA_TEST_GPU", "") in ("nofma", "fma")


def kokkos_args(threads=2):
    """Command-line switches of a Kokkos run on `threads` host threads, or
    on the GPU with a GPU build.  The GPU stands for the threaded run: its
    sums are in another order than the CPU style's, as on two threads, so
    a test of one thread (the CPU's order, bit for bit) is skipped there."""
    if on_gpu():
        if threads == 1:
            pytest.skip("one thread adds in the CPU style's order; on a GPU the "
                        "two-thread case runs")
        return ("-k", "on", "g", "1", "-sf", "kk")
    return ("-k", "on", "t", str(threads), "-sf", "kk")


def kokkos_thread_counts():
    """The host thread counts a test that loops over Kokkos runs takes:
    (1, 2), or (2,) with a GPU build, whose device run kokkos_args(2)
    makes (kokkos_args(1) would skip the whole test there)."""
    return (2,) if on_gpu() else (1, 2)


# ---------------------------------------------------------------------------
# reading LAMMPS output

def read_dump(path):
    """Read a LAMMPS text dump (custom style).

    Returns a list of snapshots; each is a dict with 'timestep', 'box' and one
    numpy array per column, sorted by atom id when there is an id column.
    """
    snapshots = []
    with open(path) as handle:
        lines = handle.read().splitlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1])
            natoms = int(lines[i + 3])
            bounds = [list(map(float, lines[i + 5 + k].split()[:2])) for k in range(3)]
            columns = lines[i + 8].split()[2:]
            rows = [lines[i + 9 + k].split() for k in range(natoms)]
            data = np.array(rows, dtype=float).reshape(natoms, len(columns))
            snap = {"timestep": step, "box": np.array(bounds)}
            for c, name in enumerate(columns):
                snap[name] = data[:, c]
            if "id" in snap:
                order = np.argsort(snap["id"])
                for name in columns:
                    snap[name] = snap[name][order]
            snapshots.append(snap)
            i += 9 + natoms
        else:
            i += 1
    return snapshots


def read_thermo(log_path):
    """Thermo output of the last run in a log file as a dict of numpy arrays
    (warnings printed between its lines are skipped)."""
    lines = pathlib.Path(log_path).read_text().splitlines()
    header_at = [k for k, line in enumerate(lines) if line.split()[:1] == ["Step"]]
    if not header_at:
        raise AssertionError(f"no thermo output in {log_path}")
    start = header_at[-1]
    names = lines[start].split()
    rows = []
    for line in lines[start + 1:]:
        if line.startswith("WARNING"):
            continue
        words = line.split()
        if len(words) != len(names):
            break
        try:
            rows.append([float(w) for w in words])
        except ValueError:
            break
    data = np.array(rows)
    return {name: data[:, k] for k, name in enumerate(names)}


def relative_difference(a, b):
    """max |a-b| / max(|a|,|b|), 0 for two zero arrays."""
    a = np.asarray(a, dtype=float)
    b = np.asarray(b, dtype=float)
    scale = max(np.max(np.abs(a)), np.max(np.abs(b)))
    return 0.0 if scale == 0.0 else float(np.max(np.abs(a - b)) / scale)


# a 4a fcc cube of 365 automata (R = 0.254 m) written to cube.data: one data
# file gives the same atom IDs on any number of ranks (the consistency tests
# of plasticity and fracture pull it between grips)
FCC_CUBE_DATA = """
units           si
atom_style      mca
atom_modify     map array sort 0 0
boundary        f f f
lattice         fcc 0.7184
region          box block -0.1 4.1 -0.1 4.1 -0.1 4.1 units lattice
create_box      1 box
create_atoms    1 region box
mca_set         all packing fcc radius 0.254
write_data      cube.data
"""


def field_difference(a, b, fields, force_scale):
    """Largest difference of each field of two dumps sorted alike (fields:
    (name, column slice) pairs) over its scale: force_scale for the forces
    ("f"), else the largest magnitude of the field in a."""
    out = {}
    for name, cols in fields:
        scale = force_scale if name == "f" else max(np.abs(a[:, cols]).max(), 1e-300)
        out[name] = np.abs(a[:, cols] - b[:, cols]).max() / scale
    return out
