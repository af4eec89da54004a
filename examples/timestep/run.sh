#!/bin/bash
# the block at 0.5, 0.7 (recommended) and 0.9 of the stable time step,
# 20000 steps each (about a minute each on one core), then the plot
set -e
for f in 0.5 0.7 0.9; do
  lmp -in in.timestep -var f $f -log log.timestep.$f -screen none
done
/usr/bin/python3 plot.py
