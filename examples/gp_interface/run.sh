#!/bin/bash
# the patch test (both couplings, both potentials), NVE from 100 K (both
# couplings, about a minute each), wave packets of 6 to 24 atomic cells
# (both couplings; 1 to 12 minutes each on one core), the surface images
# (a level-2 slab: periodic, free, with images; static strained and at
# 300 K), then the plot.
# Fe EAM reads Fe_mm.eam.fs from $LAMMPS_POTENTIALS (tools/mca env sets it)
set -e
for potential in eam morse; do
  for coupling in force energy; do
    lmp -in in.patch -var potential $potential -var coupling $coupling \
      -log log.patch.$potential.$coupling -screen none
  done
done
lmp -in in.patch -var potential eam -var fit quadratic -log log.patch.eam.force.quadratic -screen none
for coupling in force energy; do
  lmp -in in.nve -var coupling $coupling -log log.nve.$coupling -screen none
done
for lambda in 6 8 12 16 24; do
  nx=$(( lambda * 21 / 2 > 84 ? lambda * 21 / 2 : 84 ))
  for coupling in force energy; do
    lmp -in in.wave -var lambda $lambda -var nx $nx -var coupling $coupling \
      -log log.wave.$coupling.$lambda -screen none
  done
done
for potential in morse eam; do
  for case in bulk free images; do
    lmp -in in.images -var potential $potential -var case $case -var T 0 -var steps 20 \
      -var strain 0.01 -log log.images.$potential.$case.static -screen none
    lmp -in in.images -var potential $potential -var case $case -var T 300 \
      -log log.images.$potential.$case.300 -screen none
  done
done
grep -h "^IMAGES" log.images.* > images.txt
/usr/bin/python3 plot.py
