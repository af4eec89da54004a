#!/bin/bash
# the thesis verification cube: frictionless-grip tension (uniaxial stress),
# the thesis' clamped grips in tension and shear, a shear layer and a
# periodically sheared box;
# then the stress-strain plot (needs lmp on the PATH; tools/mca run does that)
set -e
for case in "free tension" "clamped tension" "clamped shear"; do
  set -- $case
  lmp -in in.tension_cube -var grips $1 -var load $2 -log log.cube.$1.$2 -screen none
  grep "^CUBE" log.cube.$1.$2
done
lmp -in in.shear_layer -log log.layer.shear -screen none
grep "^LAYER" log.layer.shear
lmp -in in.shear_box -log log.box.shear -screen none
grep "^BOX" log.box.shear
/usr/bin/python3 plot.py
