# Shell functions of the MCA batch scripts (sourced by *.sbatch, bash).
#
# Settings (environment variables, all optional):
#   LMP          the LAMMPS executable (default: lmp on the PATH)
#   MCA_MPIRUN   the MPI launcher and its options (default: mpirun);
#                e.g. "srun --mpi=pmix" where Slurm and MPI are built for it
#   MCA_KK_THREADS  Kokkos threads per rank; must equal --cpus-per-task
#
# Every check fails with a line "mca-job: ERROR: ..." and exit status 2,
# before anything runs.

mca_die() {
  echo "mca-job: ERROR: $*" >&2
  exit 2
}

mca_log() {
  echo "mca-job: $*" >&2
}

# the job runs inside a Slurm allocation, in the directory it was submitted from
mca_require_slurm() {
  [ -n "${SLURM_JOB_ID:-}" ] || mca_die "not inside a Slurm job: submit with sbatch $(basename "$0")"
  [ -n "${SLURM_NTASKS:-}" ] || mca_die "the job has no task count: give #SBATCH --ntasks"
  cd "${SLURM_SUBMIT_DIR:?}" || mca_die "cannot enter the submit directory $SLURM_SUBMIT_DIR"
  LMP=${LMP:-lmp}
  command -v "$LMP" >/dev/null || mca_die "the LAMMPS executable '$LMP' is not found (set LMP or the PATH)"
  mca_log "job $SLURM_JOB_ID on ${SLURM_JOB_NODELIST:-?}: $SLURM_NTASKS ranks, ${SLURM_CPUS_PER_TASK:-1} CPUs each, $LMP"
}

# set KK_THREADS, the Kokkos threads of a rank: --cpus-per-task, which
# MCA_KK_THREADS and OMP_NUM_THREADS (where set) must agree with
mca_kk_threads() {
  local cpus=${SLURM_CPUS_PER_TASK:-}
  [ -n "$cpus" ] || mca_die "a threaded job needs #SBATCH --cpus-per-task (the threads of each rank)"
  if [ -n "${MCA_KK_THREADS:-}" ] && [ "$MCA_KK_THREADS" != "$cpus" ]; then
    mca_die "MCA_KK_THREADS=$MCA_KK_THREADS asks for '-k on t $MCA_KK_THREADS' but the job has" \
      "--cpus-per-task=$cpus: submit with --cpus-per-task=$MCA_KK_THREADS or unset MCA_KK_THREADS"
  fi
  if [ -n "${OMP_NUM_THREADS:-}" ] && [ "$OMP_NUM_THREADS" != "$cpus" ]; then
    mca_die "OMP_NUM_THREADS=$OMP_NUM_THREADS does not match --cpus-per-task=$cpus ('-k on t $cpus'):" \
      "unset OMP_NUM_THREADS or submit with --cpus-per-task=$OMP_NUM_THREADS"
  fi
  # shellcheck disable=SC2034  # read by the scripts that source this file
  KK_THREADS=$cpus
  # no OMP_PROC_BIND here: with ranks not bound to their own cores (the
  # default launcher below) it would put thread k of every rank on core k
  export OMP_NUM_THREADS=$cpus
}

# the executable has the KOKKOS package (and, with "gpu", a GPU back end)
mca_require_kokkos() {
  local api
  api=$("$LMP" -h 2>/dev/null | grep "KOKKOS package API:" || true)
  [ -n "$api" ] || mca_die "$LMP has no KOKKOS package: build it with -D PKG_KOKKOS=on (doc/src/Build_mca.rst)"
  if [ "${1:-}" = gpu ] && ! echo "$api" | grep -qE "CUDA|HIP|SYCL"; then
    mca_die "$LMP has Kokkos without a GPU back end (${api#*: }): build it with Kokkos_ENABLE_CUDA" \
      "(or HIP, SYCL) for '-k on g N'"
  fi
}

# mca_run ARGS...: the job's ranks run LAMMPS with ARGS.  The ranks are not
# bound to cores by default (Open MPI would bind every rank to one core, its
# threads included); on a cluster "mpirun --map-by slot:PE=N --bind-to core"
# with OMP_PROC_BIND=close gives each rank its own N cores
mca_run() {
  ${MCA_MPIRUN:-mpirun -np $SLURM_NTASKS --bind-to none} "$LMP" "$@"
}
