#!/bin/bash
# the block pressed onto the plane and pulled off: with a healing pressure
# of 3.5 MPa (half the press: the 16 contacts weld, the pull breaks the
# welds) and 28 MPa (never reached: the block comes off); then the plot
set -e
for heal in 3.5e6 28e6; do
  lmp -in in.weld -var heal $heal -log log.weld.$heal -screen none
done
/usr/bin/python3 plot.py
