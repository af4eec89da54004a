#!/bin/bash
# The slab pressed with four forces: two elastic, one on each side of the
# critical pressure, and a plastic flow; then the plot
set -e
for p in 0.05 0.5 0.92 0.94 1.5; do
  lmp -in in.slab -var press $p -var name p$p -log log.p$p -screen none
done
/usr/bin/python3 plot.py
