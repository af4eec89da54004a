#!/bin/bash
# the static comparison (Cu Morse and Fe EAM) and the standing waves (Cu
# Morse: 3 scalings x 3 levels; Fe EAM: energy-consistent, 3 levels; a few
# seconds each), then the plot and the table of periods.  Fe EAM reads
# Fe_mm.eam.fs from $LAMMPS_POTENTIALS (tools/mca env sets it)
set -e
for level in 1 2 3; do
  lmp -in in.static -var level $level -log log.static.$level -screen none
  lmp -in in.static -var level $level -var potential eam -log log.static.eam.$level -screen none
done
for scaling in energy pmap pmap_invmap; do
  for level in 1 2 3; do
    lmp -in in.wave -var level $level -var scaling $scaling -log log.wave.$scaling.$level -screen none
  done
done
for level in 1 2 3; do
  lmp -in in.wave -var level $level -var potential eam -log log.wave.eam.energy.$level -screen none
done
/usr/bin/python3 plot.py
