#!/bin/bash
# The cantilever: static deflection for 1, 4 and 10 elements, then ringing
# for 5, 10 and 20 elements, and ringing down with the bond damping
# (5 elements, beta 0.001 and 0.002); then the plot
set -e
for n in 1 4 10; do
  lmp -in in.cantilever -var N $n -var mode static -log log.static$n -screen none
done
for n in 5 10 20; do
  lmp -in in.cantilever -var N $n -var mode ring -log log.ring$n -screen none
done
for beta in 0.001 0.002; do
  lmp -in in.cantilever -var N 5 -var mode ringdown -var beta $beta -log log.ringdown$beta -screen none
done
/usr/bin/python3 plot.py
