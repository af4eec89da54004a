"""The kernels of an MCA step on a GPU, profiled with Nsight Compute (ncu):
for each kernel its time, the bytes it moves to and from the device memory
(DRAM) and through the L2 cache, the share of the device's memory bandwidth
and of its compute throughput it reaches, and its double-precision
operations per DRAM byte (its place on the roofline: H100/H200 reach their
FP64 peak above about 7-20 operations per byte, below it a kernel is bound
by the memory).  The same for LAMMPS's pair gran/hooke/history/kk on the
same lattice (in.gran_hooke), the reference of the speed issue.

A run of in.bench is profiled after `--skip` kernel launches (set-up and
the first steps), for `--count` launches; kernels are named by the functor
and tag of their Kokkos parallel_for/parallel_reduce.

Usage (the GPU build's lmp on the PATH, ncu on the PATH or in --ncu):
    python3 gpu_profile.py [--n 40] [--skip 600] [--count 40] [--out results]
Writes <out>/gpu_profile.csv (one row per run and kernel, means over its
launches) and prints the table; the raw ncu output is <out>/ncu.<run>.csv.
"""

import argparse
import csv
import io
import os
import re
import shutil
import subprocess
from collections import defaultdict

from gpu import GRAN_PACKAGE, MODES, gran_mode

HERE = os.path.dirname(os.path.abspath(__file__))
RUNS = {  # name: style and geometry of in.bench, extra command-line arguments
    "mca": MODES["kk_gpu"],
    "gran_hooke": gran_mode(),
}
METRICS = {  # column: ncu metric
    "time": "gpu__time_duration.sum",
    "dram_read": "dram__bytes_read.sum",
    "dram_write": "dram__bytes_write.sum",
    "dram_percent": "dram__throughput.avg.pct_of_peak_sustained_elapsed",
    "l2_bytes": "lts__t_bytes.sum",
    "sm_percent": "sm__throughput.avg.pct_of_peak_sustained_elapsed",
    "dadd": "smsp__sass_thread_inst_executed_op_dadd_pred_on.sum",
    "dmul": "smsp__sass_thread_inst_executed_op_dmul_pred_on.sum",
    "dfma": "smsp__sass_thread_inst_executed_op_dfma_pred_on.sum",
    "registers": "launch__registers_per_thread",
    "occupancy_percent": "sm__warps_active.avg.pct_of_peak_sustained_active",
}
SCALE = {"": 1.0, "byte": 1.0, "ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0, "Kbyte": 1e3, "Mbyte": 1e6, "Gbyte": 1e9, "nsecond": 1e-9,
         "usecond": 1e-6, "msecond": 1e-3, "second": 1.0, "%": 1.0, "inst": 1.0,
         "register/thread": 1.0, "Kinst": 1e3, "Minst": 1e6, "Ginst": 1e9}


def kernel_label(name):
    """Functor (with its template arguments, which make different kernels)
    and tag of a Kokkos kernel's demangled name."""
    for prefix in ("<unnamed>::", "(anonymous namespace)::", "LAMMPS_NS::", "Kokkos::"):
        name = name.replace(prefix, "")
    start = re.search(r"Parallel(?:For|Reduce|Scan)<", name)
    if not start:
        return name[:60]
    depth, end = 0, start.end()
    while end < len(name) and not (depth == 0 and name[end] in ",>"):
        depth += {"<": 1, ">": -1}.get(name[end], 0)
        end += 1
    label = name[start.end():end].replace(" ", "")
    tag = re.search(r"RangePolicy<[^>]*?(Tag\w+)", name)
    return f"{label}/{tag.group(1)}" if tag else label


def number(text, unit):
    text = text.replace(",", "").strip()
    if text in ("", "n/a"):
        return float("nan")
    return float(text) * SCALE.get(unit, 1.0)


def profile(ncu, lmp, run, n, skip, count, outdir):
    style, geometry, extra = RUNS[run]
    raw = os.path.join(outdir, f"ncu.{run}.csv")
    cmd = [ncu, "--csv", "--page", "raw", "--print-units", "base", "--clock-control", "none",
           "--kernel-name-base", "demangled", "--launch-skip", str(skip), "--launch-count",
           str(count), "--metrics", ",".join(METRICS.values()),
           lmp, "-in", "in.bench", "-var", "style", style, "-var", "geometry", geometry,
           "-var", "n", str(n), "-var", "nsteps", "300", "-log", "none", "-screen", "none"]
    cmd += extra
    result = subprocess.run(cmd, cwd=HERE, capture_output=True, text=True, timeout=600)
    if result.returncode != 0 and "print-units" in result.stderr:
        # an older ncu: the units row scales the values instead
        i = cmd.index("--print-units")
        del cmd[i:i + 2]
        result = subprocess.run(cmd, cwd=HERE, capture_output=True, text=True, timeout=600)
    with open(raw, "w") as handle:
        handle.write(result.stdout)
    if result.returncode != 0:
        raise RuntimeError(f"ncu failed ({result.returncode}): {result.stderr[-2000:]}")
    lines = result.stdout.splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith('"ID"'))
    rows = list(csv.reader(io.StringIO("\n".join(lines[start:]))))
    header, units = rows[0], rows[1]
    col = {name: header.index(metric) for name, metric in METRICS.items() if metric in header}
    missing = [metric for metric in METRICS.values() if metric not in header]
    if missing:
        print(f"  ({run}: ncu reported no {', '.join(missing)})")
    kname = header.index("Kernel Name")
    sums = defaultdict(lambda: defaultdict(float))
    launches = defaultdict(int)
    for row in rows[2:]:
        if len(row) != len(header):
            continue
        label = kernel_label(row[kname])
        launches[label] += 1
        for name, i in col.items():
            sums[label][name] += number(row[i], units[i])
    table = []
    for label, total in sums.items():
        k = launches[label]
        mean = {name: total[name] / k if name in col else float("nan") for name in METRICS}
        dram = mean["dram_read"] + mean["dram_write"]
        flops = mean["dadd"] + mean["dmul"] + 2 * mean["dfma"]
        ratio = (lambda a, b: a / b if b > 0 else float("nan"))
        table.append({"run": run, "n": n, "kernel": label, "launches": k,
                      "us": 1e6 * mean["time"], "dram_mb": dram / 1e6,
                      "dram_gb_per_s": ratio(dram, mean["time"]) / 1e9,
                      "dram_percent": mean["dram_percent"], "l2_mb": mean["l2_bytes"] / 1e6,
                      "sm_percent": mean["sm_percent"], "fp64_per_dram_byte": ratio(flops, dram),
                      "registers": mean["registers"],
                      "occupancy_percent": mean["occupancy_percent"]})
    table.sort(key=lambda r: -r["us"] * r["launches"])
    return table


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, default=40, help="edge of the cube (40: 265721 automata)")
    ap.add_argument("--skip", type=int, default=600, help="kernel launches not profiled")
    ap.add_argument("--count", type=int, default=40, help="kernel launches profiled")
    ap.add_argument("--runs", nargs="+", choices=list(RUNS), default=list(RUNS))
    ap.add_argument("--gran-package", default=GRAN_PACKAGE,
                    help="the '-pk kokkos' keywords of gran/hooke/history/kk")
    ap.add_argument("--lmp", default="lmp")
    ap.add_argument("--ncu", default=shutil.which("ncu") or "ncu")
    ap.add_argument("--out", default=os.path.join(HERE, "results"))
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    RUNS["gran_hooke"] = gran_mode(args.gran_package)
    rows = []
    for run in args.runs:
        try:
            table = profile(args.ncu, args.lmp, run, args.n, args.skip, args.count, args.out)
        except (RuntimeError, StopIteration, subprocess.TimeoutExpired) as err:
            print(f"{run}: no profile ({type(err).__name__}: {err})", flush=True)
            continue
        rows += table
        print(f"{run}, n = {args.n}:")
        print(f"  {'kernel':52s} {'launches':>8s} {'us':>9s} {'DRAM MB':>8s} {'GB/s':>7s}"
              f" {'%peak':>6s} {'L2 MB':>8s} {'SM %':>5s} {'FP64/B':>7s} {'regs':>5s} {'occ %':>6s}")
        for r in table:
            print(f"  {r['kernel'][:52]:52s} {r['launches']:8d} {r['us']:9.1f} {r['dram_mb']:8.1f}"
                  f" {r['dram_gb_per_s']:7.0f} {r['dram_percent']:6.1f} {r['l2_mb']:8.1f}"
                  f" {r['sm_percent']:5.1f} {r['fp64_per_dram_byte']:7.2f} {r['registers']:5.0f}"
                  f" {r['occupancy_percent']:6.1f}", flush=True)
    if not rows:
        raise SystemExit("no kernel was profiled")
    path = os.path.join(args.out, "gpu_profile.csv")
    with open(path, "w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
