#!/bin/bash
# the vibrating block without damping and with two viscosities; then the plot
set -e
for eta in 0 2e5 1e6; do
  lmp -in in.damping -var eta $eta -log log.damping.$eta -screen none
done
/usr/bin/python3 plot.py
