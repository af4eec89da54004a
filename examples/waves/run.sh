#!/bin/bash
# P and S waves at 4, 6, 10, 20, 40 automata per wavelength (nu = 0.3), and
# the P wave for nu = 0 (no mean-stress term: a chain of planes); then the
# dispersion plot (needs lmp on the PATH; tools/mca run waves does that)
set -e
for m in 4 6 10 20 40; do
  lmp -in in.wave -var pol p -var m $m -log log.wave.p.$m -screen none
  lmp -in in.wave -var pol s -var m $m -log log.wave.s.$m -screen none
  lmp -in in.wave -var pol p -var m $m -var nu 0.0 -var label p0 -log log.wave.p0.$m -screen none
done
/usr/bin/python3 plot.py
