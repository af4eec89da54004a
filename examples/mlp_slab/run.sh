#!/bin/bash
# The slab pressed with four forces: two elastic, one on each side of the
# critical pressure, and a plastic flow; then the plot, and the density
# histogram of the run just above the critical pressure; then the slabs
# with compensated surfaces (traction.py)
set -e
for p in 0.05 0.5 0.92 0.94 1.5; do
  every=0
  [ "$p" = 0.94 ] && every=100
  lmp -in in.slab -var press $p -var name p$p -var dumpevery $every -log log.p$p -screen none
done
/usr/bin/python3 plot.py
/usr/bin/python3 density.py p0.94
# the compensated surfaces (fix mlp/traction): the interior strains per unit
# load at P = 0.01 and 0.02 (for P -> 0) at three sizes, the pressed
# columns loaded as the uniform stress -P (ends half), with the fix and
# without; and with the fix, every pressed particle loaded by P (ends full)
for size in "12 20" "24 40" "48 80"; do
  set -- $size
  for t in yes no; do
    for p in 0.01 0.02; do
      lmp -in in.slab -var press $p -var nx $1 -var ny $2 -var relax 0 -var traction $t \
          -var ends half -var name tr.$t.$1.p$p -log log.tr.$t.$1.p$p -screen none &
    done
    wait
  done
  lmp -in in.slab -var press 0.01 -var nx $1 -var ny $2 -var relax 0 -var traction yes \
      -var ends full -var name tr.full.$1.p0.01 -log log.tr.full.$1.p0.01 -screen none
done
/usr/bin/python3 traction.py
