#!/bin/bash
# The grounded terminus: the force balance at water depths D/H = 0 ... 10/12
# (every half row),
# the flotation of a terminus in water as deep as the ice is thick, and
# calving as the water is drawn down; then the figures
set -e
for w in $(seq 0 0.5 10); do
    lmp -in in.terminus -var wrows $w -log log.static$w -screen none
    mv bonds.dump bonds.static$w.dump
done
lmp -in in.terminus -var wrows 12 -var steps 60000 -log log.float -screen none
rm -f bonds.dump
lmp -in in.terminus -var wrows 9 -var mode calve -log log.calve -screen none
/usr/bin/python3 plot.py .
