#!/bin/bash
# Tidal flexure at a grounding line: the tide falls at three rates
# (elements of 0.5) and at the slowest rate with elements of 0.25; then the plot
set -e
for rate in 0.002 0.001 0.0005; do
  lmp -in in.tide -var rate $rate -var name r$rate -log log.r$rate -screen none
done
lmp -in in.tide -var rate 0.0005 -var L0 0.25 -var dt 0.0005 -var name fine -log log.fine -screen none
/usr/bin/python3 plot.py
