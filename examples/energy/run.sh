#!/bin/bash
# energy of a vibrating bar at half and a quarter of the stability limit,
# and a rigidly moving and spinning cluster; then the plot
set -e
for factor in 1 2; do
  lmp -in in.energy -var factor $factor -log log.energy.$factor -screen none
done
lmp -in in.rigid -log log.rigid -screen none
/usr/bin/python3 plot.py
