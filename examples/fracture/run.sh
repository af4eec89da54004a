#!/bin/bash
# the periodic box of in.box under the Drucker-Prager criterion in uniaxial
# tension and compression, and under the elliptic criterion at five load
# angles; reference logs log.25Nov26.<scene>.g++.1, then the plot
set -e
cd "$(dirname "$0")"
eval "$(cd ../.. && tools/mca env current)"   # the lmp of the current build
dp="-var crit drucker_prager -var p1 2.0e6 -var p2 6.0e6"
lmp -in in.box $dp -var angle 0 -var nsteps 2000 \
  -log log.25Nov26.box.drucker_prager.0.g++.1 -screen none
lmp -in in.box $dp -var angle 180 -var nsteps 4600 \
  -log log.25Nov26.box.drucker_prager.180.g++.1 -screen none
for angle in 0 45 90 135 180; do
  lmp -in in.box -var crit elliptic -var p1 2.0e6 -var p2 1.5e6 -var angle $angle \
    -var nsteps 3000 -log log.25Nov26.box.elliptic.$angle.g++.1 -screen none
done
/usr/bin/python3 plot.py
