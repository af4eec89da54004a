#!/bin/bash
# the static comparison and the 9 standing waves (3 scalings x 3 levels;
# a few seconds each), then the plot and the table of periods
set -e
for level in 1 2 3; do
  lmp -in in.static -var level $level -log log.static.$level -screen none
done
for scaling in energy pmap pmap_invmap; do
  for level in 1 2 3; do
    lmp -in in.wave -var level $level -var scaling $scaling -log log.wave.$scaling.$level -screen none
  done
done
/usr/bin/python3 plot.py
