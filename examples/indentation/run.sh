#!/bin/bash
# The indentation scenes (README.md): Hertz and the first yield (lens of
# radius 500 d), the thesis's materials I1-I3 loaded to a fully plastic
# contact and unloaded (lens of radius 25 d), the scratch at mu = 0 and 0.3;
# then the plot.  Two runs at a time (about 25 minutes on 2 cores).
set -e
big="-var Rs 20 -var Hs 16 -var rlens 13 -var rref 10"
lmp -in in.indent -var mat elastic -var Rind 500 $big -var depth 0.11 -log log.hertz -screen none &
lmp -in in.indent -var mat AR -var Rind 500 $big -var depth 0.07 -var label onset -log log.onset -screen none
wait
for mat in AR T274; do
  lmp -in in.indent -var mat $mat -var Rind 25 $big -var depth 1.4 -var back 0.15 -var v 4 \
      -log log.$mat -screen none &
done
wait
small="-var Rind 25 -var Rs 14 -var Hs 12 -var rlens 9 -var rref 7 -var depth 0.25 -var slide 3 -var v 4"
lmp -in in.indent -var mat T413 -var Rind 25 $big -var depth 1.4 -var back 0.15 -var v 4 \
    -log log.T413 -screen none &
lmp -in in.indent -var mat AR $small -var mu 0.0 -var label scratch.0.0 -log log.scratch.0.0 -screen none
lmp -in in.indent -var mat AR $small -var mu 0.3 -var label scratch.0.3 -log log.scratch.0.3 -screen none
wait
/usr/bin/python3 plot.py
