#!/bin/bash
# Viscous flow to large strains: the sheared layer with new bonds
# (fix beam/freeze) at three shear stresses (run times for a shear strain
# of about 2.5), and without them at the largest; then the plot and the
# fitted rates
set -e
lmp -in in.flow -var tau 0.2 -var time 1200 -log log.flow0.2 -screen none
lmp -in in.flow -var tau 0.1414 -var time 2500 -log log.flow0.1414 -screen none
lmp -in in.flow -var tau 0.1 -var time 5600 -log log.flow0.1 -screen none
lmp -in in.flow -var tau 0.2 -var time 800 -var freeze 0 -log log.nofreeze0.2 -screen none
/usr/bin/python3 plot.py log.flow* log.nofreeze*
