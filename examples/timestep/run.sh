#!/bin/bash
# the block at 0.5, 0.7 (recommended) and 0.9 of the stable time step,
# 20000 steps each (about 15 s each on one core), elastic, plastic and
# with fracture; then the plot and the table
set -e
for model in elastic plastic fracture; do
  for f in 0.5 0.7 0.9; do
    lmp -in in.timestep -var f $f -var model $model -log log.timestep.$model.$f -screen none
  done
done
/usr/bin/python3 plot.py
