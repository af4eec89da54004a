#!/bin/bash
# the hard cases of issue #14: the notched plate pulled apart at half the
# nominal time step R/c_p and at 0.9 of its measured stable time step
# (1.32 R/c_p, bisected by unittest/python/test_hard_cases.py), and the
# plastic cube compressed by 30 %; reference logs log.25Nov26.<scene>.g++.1
# and the dumps of the plate, then the plot
set -e
cd "$(dirname "$0")"
eval "$(cd ../.. && tools/mca env current)"   # the lmp of the current build
lmp -in in.notched_plate -var factor 0.5 -var nsteps 8000 -var dumps 4 -var name plate \
  -log log.25Nov26.notched_plate.0.5.g++.1 -screen none
lmp -in in.notched_plate -var factor 1.19 -var nsteps 3400 -var every 20 -var dumps 4 -var name plate_fast \
  -log log.25Nov26.notched_plate.1.19.g++.1 -screen none
lmp -in in.compression -log log.25Nov26.compression.g++.1 -screen none
/usr/bin/python3 plot.py
