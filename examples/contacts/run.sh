#!/bin/bash
# the sliding block at mu = 0.3 and 0, the oblique impact, and the hard
# cases: a projectile perforating a plate, a packing compressed by 50 % at
# 0.15 R/c_p and at 0.9 of its stable time step (1.52 R/c_p, bisected by
# unittest/python/test_contacts.py); then the plot
set -e
for mu in 0.3 0.0; do
  lmp -in in.sliding_block -var mu $mu -log log.sliding_block.$mu -screen none
done
lmp -in in.impact -log log.impact.0.3 -screen none
lmp -in in.impact_plate -log log.impact_plate -screen none
lmp -in in.packing -var n 10 -var h 12 -var factor 0.15 -log log.packing.0.15 -screen none
lmp -in in.packing -var n 10 -var h 12 -var factor 1.36 -log log.packing.1.36 -screen none
/usr/bin/python3 plot.py
