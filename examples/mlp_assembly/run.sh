#!/bin/bash
# MLP lattice assembly with the return force (axes 0 and 10 degrees) and
# without it (f0 = 0); then the plot
set -e
lmp -in in.assembly -var name aligned -log log.aligned -screen none
lmp -in in.assembly -var name turned -var theta0 10 -log log.turned -screen none
lmp -in in.assembly -var name free -var f0 0.0 -log log.free -screen none
/usr/bin/python3 plot.py
