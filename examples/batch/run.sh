#!/bin/bash
# the batch scene run directly on 2 ranks (no Slurm needed), then the plot of
# its energies; the Slurm scripts are submitted with sbatch (README.md)
set -e
rm -f energies.dat batch.*.restart
mpirun -np 2 lmp -in in.batch -log log.batch -screen none
grep "^BATCH" log.batch
/usr/bin/python3 plot.py .
