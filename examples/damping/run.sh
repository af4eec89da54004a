#!/bin/bash
# the vibrating block without damping, with two link viscosities and with
# global damping; then the plot
set -e
for eta in 0 2e5 1e6; do
  lmp -in in.damping -var eta $eta -log log.damping.$eta -screen none
done
lmp -in in.damping -var eta 0 -var gamma 50 -log log.damping.global -screen none
/usr/bin/python3 plot.py
