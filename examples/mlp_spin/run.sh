#!/bin/bash
# A spinning MLP disc with axes that turn with it (measured every step and
# every 20 steps) and with fixed axes; then the plot
set -e
lmp -in in.spin -var frame fr -var name frame -log log.frame -screen none
lmp -in in.spin -var frame fr -var every 20 -var name frame20 -log log.frame20 -screen none
lmp -in in.spin -var frame none -var name fixed -log log.fixed -screen none
/usr/bin/python3 plot.py
