#!/bin/bash
# the Poisson's-ratio study through the LAMMPS Python module (tools/mca run
# sets PYTHONPATH and LD_LIBRARY_PATH to the current build)
set -e
/usr/bin/python3 poisson_study.py --out . | tee log.poisson_study
