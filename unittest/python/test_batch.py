"""The batch scripts of examples/batch under a real Slurm.

A single-node cluster private to the test session (tools/mca-slurm: munged,
slurmctld and slurmd of Debian's packages, a generated slurm.conf with 2
CPUs and one gres "gpu" without a device) runs the scripts with sbatch as a
user would.  The scene is the example's standing wave, small: m = 12 (864
automata) or 16 (2048).  If the daemons cannot start on this machine, every
test here is skipped with the reason (the daemons' logs).

What is asserted:
* a job of MPI ranks and a job of MPI ranks x Kokkos threads give the final
  state of the same mpirun command run directly, bit for bit (same
  executable, same ranks and threads: the same arithmetic);
* a chained run whose first job is cancelled mid-way, one whose jobs
  stop at their time limit, and one whose newest restart file a kill cut
  short, finish from their restart files with the final
  state of an uninterrupted run to 1e-5 of the wave's amplitudes (a run
  continued from a restart file recomputes the forces of its first step
  from the stored link history with other round-off: test_pair_mca's
  restart test; the differences then travel with the waves);
* bad input stops a job before it runs, with a message and a non-zero
  exit status: threads that do not match -k, an executable without a GPU
  back end, a chain without a restart file or state, a restart file of
  another link layout, a finished or failed chain.
"""

import os
import pathlib
import re
import shutil
import struct
import subprocess
import time

import numpy as np
import pytest

import mcatest
from mcatest import read_dump

BATCH = mcatest.ROOT / "examples" / "batch"
SLURM = mcatest.ROOT / "tools" / "mca-slurm"
SMALL = ["-var", "m", "12", "-var", "periods", "20"]    # 864 automata, 367 steps
CHAIN = ["-var", "m", "16", "-var", "periods", "120", "-var", "every", "250"]    # 2932 steps

pytestmark = pytest.mark.mpi


@pytest.fixture(scope="module")
def slurm(tmp_path_factory):
    """The private cluster; its environment (SLURM_CONF) for the commands."""
    d = tmp_path_factory.mktemp("slurm")
    result = subprocess.run([str(SLURM), "start", str(d), "--cpus", "2", "--gpu"],
                            capture_output=True, text=True, timeout=300)
    if result.returncode != 0:
        print(result.stderr)
        pytest.skip("the Slurm daemons cannot start on this machine: "
                    + result.stderr.strip().splitlines()[0][:300])
    env = mcatest.mpi_environment()
    env["SLURM_CONF"] = str(d / "slurm.conf")
    if mcatest.build_named("current"):
        env["PATH"] = str(mcatest.build_named("current").path) + os.pathsep + env["PATH"]
    yield env
    # nothing of a test may be left in the queue when the cluster stops
    subprocess.run(["scancel", "--user", str(os.getuid())], env=env, capture_output=True)
    subprocess.run([str(SLURM), "stop", str(d)], capture_output=True, timeout=60)


def current():
    build = mcatest.build_named("current")
    if build is None:
        pytest.skip("the current build is not among the tested builds")
    return build


def job_dir(tmp_path, name):
    d = tmp_path / name
    shutil.copytree(BATCH, d)
    return d


def sbatch(env, cwd, args, wait=True, extra_env=None):
    """Submit; return (exit status of sbatch, with wait that of the job; the
    job id; the job's output and sbatch's errors)."""
    cmd = ["sbatch", "--parsable"] + (["--wait"] if wait else []) + ["-o", "slurm-%j.out"] + args
    result = subprocess.run(cmd, cwd=cwd, env={**env, **(extra_env or {})}, capture_output=True,
                            text=True, timeout=600)
    job = result.stdout.strip().splitlines()[0] if result.stdout.strip() else ""
    out = pathlib.Path(cwd) / f"slurm-{job}.out"
    text = out.read_text() if job and out.exists() else ""
    return result.returncode, job, text + result.stderr


def direct(env, cwd, launcher, lmp, args, name="log.direct"):
    """The same run without Slurm, in its own directory."""
    cwd.mkdir(parents=True, exist_ok=True)
    for f in ("in.batch", "in.batch_run", "in.batch_continue"):
        shutil.copy(BATCH / f, cwd)
    subprocess.run(launcher + [str(lmp)] + args + ["-log", name, "-screen", "none"], cwd=cwd,
                   env=env, check=True, capture_output=True, timeout=600)
    return read_dump(cwd / "final.dump")[-1]


def assert_identical(a, b):
    assert a["timestep"] == b["timestep"]
    for name in ("xu", "yu", "zu", "vx", "vy", "vz", "omegax", "omegay", "omegaz"):
        assert np.array_equal(a[name], b[name]), name


def test_mpi_job_equals_direct_mpirun(slurm, tmp_path):
    """sbatch mpi.sbatch on 2 ranks: the final state of mpirun -np 2 run directly."""
    d = job_dir(tmp_path, "job")
    rc, job, out = sbatch(slurm, d, ["--ntasks=2", "mpi.sbatch"] + SMALL)
    assert rc == 0, out[-3000:]
    assert f"job {job} on" in out and "2 ranks, 1 CPUs each" in out
    assert re.search(r"^BATCH done step 367 of 367", (d / "log.mpi").read_text(), re.M)
    ref = direct(slurm, tmp_path / "direct", ["mpirun", "-np", "2"], current().lmp,
                 ["-in", "in.batch"] + SMALL)
    assert_identical(read_dump(d / "final.dump")[-1], ref)


def test_hybrid_kk_job_equals_direct_mpirun(slurm, tmp_path):
    """sbatch hybrid_kk.sbatch: 2 ranks x 1 thread and 1 rank x 2 threads
    (the node has 2 CPUs) give the states of the direct runs with the same
    -k on t N -sf kk; the job takes N from --cpus-per-task."""
    kk = mcatest.kokkos_build()
    for ntasks, cpus in ((2, 1), (1, 2)):
        d = job_dir(tmp_path, f"job{ntasks}x{cpus}")
        env = {**slurm, "LMP": str(kk.lmp)}
        env.pop("OMP_NUM_THREADS", None)
        rc, job, out = sbatch(env, d, [f"--ntasks={ntasks}", f"--cpus-per-task={cpus}",
                                       "hybrid_kk.sbatch"] + SMALL)
        assert rc == 0, out[-3000:]
        log = (d / "log.hybrid_kk").read_text()
        assert f"using {cpus} OpenMP thread(s) per MPI task" in log, log[:3000]
        assert f"CPU use with {ntasks} MPI tasks x {cpus} OpenMP threads" in log, log[-3000:]
        ref = direct({**slurm, "OMP_NUM_THREADS": str(cpus)}, tmp_path / f"direct{ntasks}x{cpus}",
                     ["mpirun", "-np", str(ntasks), "--bind-to", "none"], kk.lmp,
                     ["-k", "on", "t", str(cpus), "-sf", "kk", "-in", "in.batch"] + SMALL)
        assert_identical(read_dump(d / "final.dump")[-1], ref)


@pytest.mark.parametrize("case", ["omp", "kk_threads"])
def test_hybrid_job_with_mismatched_threads_stops(slurm, tmp_path, case):
    """A thread count that does not match -k on t N stops the job before
    LAMMPS starts, naming both numbers; exit status 2."""
    kk = mcatest.kokkos_build()
    d = job_dir(tmp_path, "job")
    env = {**slurm, "LMP": str(kk.lmp)}
    env.pop("OMP_NUM_THREADS", None)
    opts = ["--ntasks=1", "--cpus-per-task=2"]
    if case == "omp":
        env["OMP_NUM_THREADS"] = "4"
        expect = r"OMP_NUM_THREADS=4 does not match --cpus-per-task=2 \('-k on t 2'\)"
    else:
        env["MCA_KK_THREADS"] = "1"
        expect = r"MCA_KK_THREADS=1 asks for '-k on t 1' but the job has --cpus-per-task=2"
    rc, _, out = sbatch(env, d, opts + ["hybrid_kk.sbatch"] + SMALL)
    assert rc == 2, out[-2000:]
    assert re.search("mca-job: ERROR: " + expect, out), out[-2000:]
    assert not (d / "log.hybrid_kk").exists()


def test_gpu_job_refuses_an_executable_without_gpu_backend(slurm, tmp_path):
    """gpu_kk.sbatch is scheduled on the node's gres gpu and stops, before
    LAMMPS runs, because this machine's Kokkos executable has only host back
    ends; an executable without KOKKOS is refused too."""
    kk = mcatest.kokkos_build()
    d = job_dir(tmp_path, "job")
    rc, _, out = sbatch({**slurm, "LMP": str(kk.lmp)}, d, ["gpu_kk.sbatch"] + SMALL)
    assert rc == 2, out[-2000:]
    assert re.search(r"has Kokkos without a GPU back end \(OpenMP Serial\): build it with "
                     r"Kokkos_ENABLE_CUDA", out), out
    assert not (d / "log.gpu_kk").exists()
    rc, _, out = sbatch({**slurm, "LMP": str(current().lmp)}, d, ["gpu_kk.sbatch"] + SMALL)
    assert rc == 2 and "has no KOKKOS package" in out, out


# ---------------------------------------------------------------------------
# chained runs

def chain_state(d):
    f = d / "chain.state"
    if not f.exists():
        return {}
    return dict(line.split("=", 1) for line in f.read_text().splitlines() if "=" in line)


def wait_for(predicate, timeout, what):
    end = time.time() + timeout
    while time.time() < end:
        if predicate():
            return
        time.sleep(0.2)
    raise AssertionError(f"timed out after {timeout} s waiting for {what}")


def queue(env):
    r = subprocess.run(["squeue", "-h", "-o", "%i %j %T"], env=env, capture_output=True,
                       text=True)
    return r.stdout.strip()


@pytest.fixture(scope="module")
def uninterrupted_dir(slurm, tmp_path_factory):
    """The chain's run in one piece (mpirun -np 2, no Slurm): its directory,
    with its restart files of every 250 steps."""
    d = tmp_path_factory.mktemp("whole")
    direct(slurm, d, ["mpirun", "-np", "2"], current().lmp, ["-in", "in.batch"] + CHAIN)
    return d


@pytest.fixture(scope="module")
def uninterrupted(uninterrupted_dir):
    """The final state of the uninterrupted run."""
    return read_dump(uninterrupted_dir / "final.dump")[-1]


def assert_same_final_state(d, ref):
    """Positions and velocities against the uninterrupted run, relative to
    the wave's amplitudes u0 = 1 um and omega u0 (omega = 2 pi c_p /
    lambda; not the values at the last step, which may lie near a node of
    the oscillation).  Measured (restart at step 500-750, 2200-2400 steps
    on): velocities 4e-8 of omega u0 in every direction, positions
    2e-8 - 2e-6 of u0 (2e-12 m, 6e-13 of the box): tolerances 1e-6 and
    1e-5, a wrong or lost segment would differ by the order of 1."""
    final = read_dump(d / "final.dump")[-1]
    assert final["timestep"] == ref["timestep"] == 2932
    u0 = 1.0e-6
    c_p = np.sqrt(70.0e9 * 0.7 / (1.3 * 0.4 * 2700.0))
    v0 = 2.0 * np.pi * c_p / 3.592 * u0
    for names, scale, tolerance in ((("xu", "yu", "zu"), u0, 1.0e-5),
                                    (("vx", "vy", "vz"), v0, 1.0e-6)):
        for name in names:
            error = np.max(np.abs(final[name] - ref[name])) / scale
            print(f"{d.parent.name}: {name} differs by {error:.3e} of the amplitude")
            assert error < tolerance, name


def test_chain_cancelled_midway_finishes_from_its_restart_file(slurm, tmp_path, uninterrupted):
    """The first job of a chain is cancelled (scancel) after its second
    restart file; its successor continues from the newest restart file and
    finishes the run with the uninterrupted run's final state."""
    d = job_dir(tmp_path, "chain")
    current()
    rc, first, out = sbatch(slurm, d, ["--ntasks=2", "chain.sbatch", "start"] + CHAIN, wait=False)
    assert rc == 0, out
    wait_for(lambda: (d / "batch.500.restart").exists(), 120, "the restart file of step 500")
    time.sleep(0.3)
    subprocess.run(["scancel", first], env=slurm, check=True)
    wait_for(lambda: chain_state(d).get("status") in ("done", "failed"), 300,
             "the chain to end: " + queue(slurm))
    state = chain_state(d)
    assert state["status"] == "done", (d / f"slurm-{state['job']}.out").read_text()[-3000:]
    # the first segment never finished; the second continued from a restart file
    assert not re.search(r"^BATCH", (d / "log.chain.1").read_text(), re.M)
    outputs = [f.read_text() for f in d.glob("slurm-*.out")]
    second = next(text for text in outputs if "mca-job: link 2:" in text)
    step = int(re.search(r"-var restart batch\.(\d+)\.restart", second).group(1))
    assert 500 <= step < 2932 and step % 250 == 0
    assert "ended before its segment did (cancelled or killed)" in second
    assert_same_final_state(d, uninterrupted)
    wait_for(lambda: queue(slurm) == "", 60, "an empty queue")


def test_chain_continues_past_a_restart_file_cut_short(slurm, tmp_path, uninterrupted_dir,
                                                       uninterrupted):
    """A job killed while LAMMPS wrote its newest restart file leaves that
    file cut short (a cancel of the test above once landed there, and the
    successor stopped with "Invalid LAMMPS restart file").  The state of
    such a chain, made here: the run's files of steps 250, 500 and 750,
    the last cut to half its length, and a chain.state of a job that ended
    while running.  The successor sets the cut file aside, continues from
    step 500 and finishes with the uninterrupted run's final state.  With
    the cut file alone (nothing reads) it continues from it and fails with
    LAMMPS's message, as for any unreadable file."""
    data = (uninterrupted_dir / "batch.750.restart").read_bytes()
    running = "link=1\nstatus=running\njob=1\nlog=log.chain.1\n"

    alone = job_dir(tmp_path, "alone")
    (alone / "batch.750.restart").write_bytes(data[:len(data) // 2])
    (alone / "chain.state").write_text(running)
    rc, _, out = sbatch(slurm, alone, ["--ntasks=2", "chain.sbatch", "continue"] + CHAIN)
    assert rc != 0 and re.search(r"link 2 failed \(exit status \d+\): ERROR", out), out[-3000:]
    assert "-var restart batch.750.restart" in out and "set aside" not in out, out[-3000:]
    assert chain_state(alone)["status"] == "failed"
    wait_for(lambda: queue(slurm) == "", 60, "the successor to be cancelled")

    d = job_dir(tmp_path, "chain")
    for step in (250, 500):
        shutil.copy(uninterrupted_dir / f"batch.{step}.restart", d)
    (d / "batch.750.restart").write_bytes(data[:len(data) // 2])
    (d / "chain.state").write_text(running)
    rc, _, out = sbatch(slurm, d, ["--ntasks=2", "chain.sbatch", "continue"] + CHAIN)
    assert rc == 0, out[-3000:]
    assert ("batch.750.restart does not read (written when the job was killed?): set aside as "
            "batch.750.restart.incomplete") in out, out[-3000:]
    assert "-var restart batch.500.restart" in out, out[-3000:]
    assert (d / "batch.750.restart.incomplete").stat().st_size == len(data) // 2
    assert not (d / "chain.probe.in").exists()
    wait_for(lambda: chain_state(d).get("status") in ("done", "failed"), 60, "the chain to end")
    assert chain_state(d)["status"] == "done"
    assert_same_final_state(d, uninterrupted)
    wait_for(lambda: queue(slurm) == "", 60, "an empty queue")


def test_chain_stopped_by_its_time_limit_continues_job_by_job(slurm, tmp_path, uninterrupted):
    """Jobs of 3 minutes with a margin of 177 s: each segment stops cleanly
    after about 3 s (LAMMPS's timer timeout, computed from the job's time
    left in squeue), writes a restart file, and the next job continues;
    the last one finishes with the uninterrupted run's final state.  The
    jobs run on one rank: the whole run must take longer than a segment,
    and on 2 ranks of the 2-core test machine it takes 2.9 s since the
    batched link pass (8 Dec 2026; 4 s before), 5.5 s on one."""
    d = job_dir(tmp_path, "chain")
    current()
    rc, _, out = sbatch(slurm, d, ["--ntasks=1", "--time=3", "chain.sbatch", "start"] + CHAIN,
                        wait=False, extra_env={"MCA_CHAIN_MARGIN": "177"})
    assert rc == 0, out
    wait_for(lambda: chain_state(d).get("status") in ("done", "failed"), 300,
             "the chain to end: " + queue(slurm))
    state = chain_state(d)
    assert state["status"] == "done", (d / f"slurm-{state['job']}.out").read_text()[-3000:]
    links = int(state["link"])
    assert links >= 2
    for k in range(1, links):
        text = (d / f"log.chain.{k}").read_text()
        assert re.search(r"^BATCH stopped at step \d+ of 2932 \(timeout [1-3] s\)", text, re.M), k
    assert_same_final_state(d, uninterrupted)
    wait_for(lambda: queue(slurm) == "", 60, "an empty queue")


def test_chain_bad_input(slurm, tmp_path):
    """Continue without a chain, without a restart file, after a failure or
    the end; a restart file of another link layout; start over an old chain:
    a message, a non-zero exit status (0 for a finished run), never a fresh
    start."""
    current()
    d = job_dir(tmp_path, "chain")
    rc, _, out = sbatch(slurm, d, ["--ntasks=2", "chain.sbatch", "continue"] + SMALL)
    assert rc == 2 and "no chain.state here: start the chain with 'sbatch chain.sbatch start'" \
        in out, out
    rc, _, out = sbatch(slurm, d, ["--ntasks=2", "chain.sbatch"] + SMALL)
    assert rc == 2 and "the first argument must be 'start'" in out, out

    # a chain whose restart files are gone
    (d / "chain.state").write_text("link=1\nstatus=stopped\njob=1\nlog=log.chain.1\n")
    rc, _, out = sbatch(slurm, d, ["--ntasks=2", "chain.sbatch", "continue"] + SMALL)
    assert rc == 2 and re.search(r"no restart file batch\.\*\.restart in .*: the chain cannot "
                                 r"continue \(it never starts afresh by itself", out), out
    assert not list(d.glob("log.chain.*")) and not (d / "final.dump").exists()
    rc, _, out = sbatch(slurm, d, ["--ntasks=2", "chain.sbatch", "start"] + SMALL)
    assert rc == 2 and "a chain was run here (chain.state: status stopped)" in out, out

    # a restart file of another link layout (the layout record patched to the
    # unnumbered layout of files written before it was recorded)
    subprocess.run(["mpirun", "-np", "2", str(current().lmp), "-in", "in.batch", "-var", "every",
                    "100", "-var", "timeout", "0"] + SMALL + ["-screen", "none", "-log", "none"],
                   cwd=d, env=slurm, check=True, timeout=300)
    for f in d.glob("batch.*.restart"):
        if f.name != "batch.300.restart":
            f.unlink()
    restart = d / "batch.300.restart"
    data = restart.read_bytes()
    record = struct.pack("<d", 2024.0)
    assert data.count(record) == 1
    restart.write_bytes(data.replace(record, struct.pack("<d", 27.0)))
    (d / "final.dump").unlink()
    rc, job, out = sbatch(slurm, d, ["--ntasks=2", "chain.sbatch", "continue"] + SMALL)
    assert rc != 0, out
    assert re.search(r"link 2 failed \(exit status \d+\): ERROR: Restart file holds MCA links in "
                     r"history layout 0 with 27 values each; this version reads layout 2", out), out
    assert chain_state(d)["status"] == "failed"
    wait_for(lambda: queue(slurm) == "", 60, "the successor to be cancelled")
    rc, _, out = sbatch(slurm, d, ["--ntasks=2", "chain.sbatch", "continue"] + SMALL)
    assert rc == 2 and f"the previous job {job} failed (see log.chain.2): not continuing" in out
    assert not (d / "final.dump").exists()

    # a finished run is not continued
    (d / "chain.state").write_text("link=4\nstatus=done\njob=7\nlog=log.chain.4\n")
    rc, _, out = sbatch(slurm, d, ["--ntasks=2", "chain.sbatch", "continue"] + SMALL)
    assert rc == 0 and "the run is complete (job 7); nothing to continue" in out, out
