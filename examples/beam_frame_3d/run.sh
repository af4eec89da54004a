#!/bin/bash
# The 3-D cantilever for 4 and 10 elements, then the plot
set -e
for n in 4 10; do
  lmp -in in.frame3d -var N $n -log log.frame$n -screen none
done
/usr/bin/python3 plot.py
