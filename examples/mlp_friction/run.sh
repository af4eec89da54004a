#!/bin/bash
# Two MLP bars pressed and sheared (the profile of |F_return| across the
# contact) and pressed only; then the plot.  Needs fix pair (LAMMPS 2022
# and later: the "current" build)
set -e
lmp -in in.bars -var name bars -log log.bars -screen none
lmp -in in.bars -var name pressed -var shear 0.0 -log log.pressed -screen none
/usr/bin/python3 plot.py
