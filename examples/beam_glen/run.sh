#!/bin/bash
# Glen's law from melting and re-freezing beams: the sheared layer at five
# shear stresses (a factor 4 in all), then the plot and the fitted exponent
set -e
for tau in 0.05 0.0707 0.1 0.1414 0.2; do
  lmp -in in.glen -var tau $tau -log log.glen$tau -screen none
done
/usr/bin/python3 plot.py log.glen*
