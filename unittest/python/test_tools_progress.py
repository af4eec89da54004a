"""tools/mca shows how far a long build is: with_progress runs a command with
its output in a log and prints, every MCA_PROGRESS_EVERY seconds, the time so
far and the last step cmake announced (what it builds, with its percentage);
the command's exit status is kept (a failed build must still fail)."""

import re
import subprocess

import mcatest

TOOL = mcatest.ROOT / "tools" / "mca"


def run_with_progress(tmp_path, status):
    function = re.search(r"^with_progress\(\) \{.*?^\}", TOOL.read_text(), re.M | re.S).group(0)
    script = f"""set -euo pipefail
log() {{ echo "[mca] $*" >&2; }}
{function}
fake() {{ for p in 10 40 80; do echo "[ $p%] Building CXX object x.o"; sleep 1.2; done; return {status}; }}
MCA_PROGRESS_EVERY=1 with_progress "building fake" {tmp_path}/build.log fake
"""
    return subprocess.run(["bash", "-c", script], capture_output=True, text=True, timeout=60)


def test_progress_lines_and_exit_status(tmp_path):
    ok = run_with_progress(tmp_path, 0)
    assert ok.returncode == 0, ok.stderr
    lines = re.findall(r"\[mca\] building fake, (\d+) s: \[ (\d+)%\] Building CXX object x\.o",
                       ok.stderr)
    assert len(lines) >= 2, ok.stderr
    percents = [int(p) for _, p in lines]
    assert percents == sorted(percents) and set(percents) <= {10, 40, 80}, ok.stderr
    seconds = [int(t) for t, _ in lines]
    assert seconds == sorted(seconds) and seconds[-1] <= 5, ok.stderr
    assert "[ 80%]" in (tmp_path / "build.log").read_text()
    failed = run_with_progress(tmp_path, 3)
    assert failed.returncode == 3, failed.stderr
