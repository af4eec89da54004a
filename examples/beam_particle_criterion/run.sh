#!/bin/bash
# Uniaxial strain of a hexagonal beam lattice to failure, by the bond
# criterion and by the particle criterion; then the plot
set -e
for criterion in bond particle; do
  lmp -in in.uniaxial -var criterion $criterion -log log.$criterion -screen none
done
/usr/bin/python3 plot.py
