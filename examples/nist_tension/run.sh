#!/bin/bash
# the three NIST samples with linear hardening, T413 also with the table
# (flat beyond sigma_u); about 5 minutes each on one core; then the plot
set -e
for sample in AR T274 T413; do
  lmp -in in.nist -var sample $sample -log log.nist.$sample.linear -screen none
done
lmp -in in.nist -var sample T413 -var hardening table -log log.nist.T413.table -screen none
/usr/bin/python3 plot.py
