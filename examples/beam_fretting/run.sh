#!/bin/bash
# Fretting of a brittle beam lattice: the pad pressed and slid for three
# periods, then the picture of the broken bonds
set -e
lmp -in in.fretting -log log.fretting -screen none
/usr/bin/python3 plot.py log.fretting
