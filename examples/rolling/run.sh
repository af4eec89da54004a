#!/bin/bash
# run the three packings and draw the plot (needs lmp on PATH; tools/mca run does that)
set -e
for packing in none sc fcc; do
  lmp -in in.rolling -var packing $packing -log log.rolling.$packing -screen none
  grep "^ROLLING" log.rolling.$packing
done
/usr/bin/python3 plot.py
