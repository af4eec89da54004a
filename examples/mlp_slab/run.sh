#!/bin/bash
# The slab pressed with four forces: two elastic, one on each side of the
# critical pressure, and a plastic flow; then the plot, and the density
# histogram of the run just above the critical pressure
set -e
for p in 0.05 0.5 0.92 0.94 1.5; do
  every=0
  [ "$p" = 0.94 ] && every=100
  lmp -in in.slab -var press $p -var name p$p -var dumpevery $every -log log.p$p -screen none
done
/usr/bin/python3 plot.py
/usr/bin/python3 density.py p0.94
