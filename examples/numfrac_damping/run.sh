#!/bin/bash
# growth factor per step of damped oscillators, both schemes, four damping
# ratios; then the plot
set -e
for xi in 0 0.5 1 3; do
  for scheme in centred lagged; do
    lmp -in in.oscillators -var xi $xi -var scheme $scheme -log log.$scheme.$xi -screen none
  done
done
/usr/bin/python3 plot.py
