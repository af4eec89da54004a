#!/bin/bash
# the sheared box with linear and with tabulated hardening, the thesis cube
# in tension (V3) and shear (V4); then the plot
set -e
for hardening in linear table; do
  lmp -in in.plastic_box -var hardening $hardening -log log.box.$hardening -screen none
done
lmp -in in.load_unload -log log.cube.free.tension -screen none
lmp -in in.load_unload -var grips clamped -var load shear -log log.cube.clamped.shear -screen none
/usr/bin/python3 plot.py
