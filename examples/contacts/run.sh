#!/bin/bash
# the sliding block at mu = 0.3 and 0, the oblique impact; then the plot
set -e
for mu in 0.3 0.0; do
  lmp -in in.sliding_block -var mu $mu -log log.sliding_block.$mu -screen none
done
lmp -in in.impact -log log.impact.0.3 -screen none
/usr/bin/python3 plot.py
