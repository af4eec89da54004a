"""The bit-for-bit checker of refactorings (bench/bitwise.py) finds what it
must find:

* a build against itself: every output identical (exit status 0), the
  estimate of the stable time step printed to 17 digits on both sides (a
  finite, positive dt_c: the comparison covers it);
* one change of the scene in the "new" run only (the time step 1e-9
  relative larger) is reported as a difference (exit status 1), in the
  thermo lines and in the dump: the velocity along the wave by between
  1e-12 and 1e-6 of its largest value (1.2e-9 measured: a time step larger
  by 1e-9 changes a 20-step wave by about that);
* files that are not text (the examples' pictures) are compared as bytes:
  equal bytes are identical, others "binary files differ".
"""

import re
import subprocess
import sys

import mcatest

sys.path.insert(0, str(mcatest.ROOT / "bench"))
import bitwise  # noqa: E402


def check(build, tmp_path, *args):
    d = str(build.path)
    return subprocess.run([sys.executable, str(mcatest.ROOT / "bench" / "bitwise.py"),
                           "--base", d, "--new", d, "--modes", "cpu", "--scenes", "wave_p",
                           "--nsteps", "20", "--keep", str(tmp_path / "runs"), *args],
                          capture_output=True, text=True, env=build.environment(), timeout=600)


def test_a_build_against_itself_is_identical(build, tmp_path):
    result = check(build, tmp_path)
    assert result.returncode == 0, result.stdout[-2000:] + result.stderr[-2000:]
    assert "all identical" in result.stdout
    for side in ("base", "new"):
        log = (tmp_path / "runs" / "wave_p" / "cpu" / side / "log.lammps").read_text()
        found = re.findall(r"^BITWISE stable time step (\S+) omega (\S+) zeta (\S+)$", log, re.M)
        assert len(found) == 1, log[-2000:]
        dt, omega = float(found[0][0]), float(found[0][1])
        assert 0.0 < dt < 1.0 and omega > 0.0
        digits = found[0][0].split("e")[0].replace(".", "").lstrip("0")
        assert len(digits) >= 12, found[0][0]    # %.17g (%g would give 6)


def test_a_changed_run_is_reported(build, tmp_path):
    wave_input = (mcatest.ROOT / "examples" / "waves" / "in.wave").read_text()
    assert re.search(r"^timestep\s", wave_input, re.M), "in.wave sets its time step"
    result = check(build, tmp_path, "--new-cmd", "timestep $(dt*(1+1e-9))")
    assert result.returncode == 1, result.stdout[-2000:] + result.stderr[-2000:]
    assert "DIFFERENCES" in result.stdout
    assert "thermo:" in result.stdout
    # the velocity along the wave (the columns across it are round-off
    # noise of near-zero values, large relative to their own size)
    vx = re.search(r"bitwise\.dump: .*\bvx \S+ \((\S+)\)", result.stdout)
    assert vx, result.stdout[-2000:]
    assert 1e-12 < float(vx.group(1)) < 1e-6, vx.group(0)[-300:]


def test_binary_outputs():
    png, other = b"\x89PNG\r\n\x1a\n" + bytes(8), b"\x89PNG\r\n\x1a\n" + bytes(7) + b"\x01"
    same, rel, details = bitwise.compare({"a.png": png, "thermo": "1 2"},
                                         {"a.png": png, "thermo": "1 2"})
    assert same and not details
    same, rel, details = bitwise.compare({"a.png": png}, {"a.png": other})
    assert same is False and details == ["a.png: binary files differ"]


def test_read_output(tmp_path):
    (tmp_path / "a.png").write_bytes(b"\x89PNG\x00\xff")
    (tmp_path / "a.dat").write_text("1 2 3\n")
    assert bitwise.read_output(str(tmp_path / "a.png")) == b"\x89PNG\x00\xff"
    assert bitwise.read_output(str(tmp_path / "a.dat")) == "1 2 3\n"


def test_estimate_tolerance():
    """The estimate is an output of its own: a change of it within
    --estimate-rtol is listed but is no difference; one beyond it, or any
    change elsewhere, is."""
    base = {"thermo": "Step Temp\n0 1.5", "estimate": "dt omega zeta\n1e-05 2000 0"}
    moved = dict(base, estimate="dt omega zeta\n1.0000001e-05 2000 0")    # 1e-7 relative
    same, rel, details = bitwise.compare(base, moved, estimate_rtol=1e-6)
    assert same is True and rel == 0.0
    assert len(details) == 1 and "within --estimate-rtol" in details[0], details
    same, rel, details = bitwise.compare(base, moved, estimate_rtol=1e-8)
    assert same is False and 0.9e-7 < rel < 1.1e-7, (rel, details)
    same, rel, details = bitwise.compare(base, moved)
    assert same is False
    other = dict(moved, thermo="Step Temp\n0 1.5000001")
    same, rel, details = bitwise.compare(base, other, estimate_rtol=1e-6)
    assert same is False and any(d.startswith("thermo:") for d in details), details
