#!/bin/bash
# The polydisperse packing: made (in.pack), bonded by distance (bond.py),
# checked at 1 to 1.3 times the stable time step, pulled to fracture
set -e
lmp -in in.pack -log log.pack -screen none
/usr/bin/python3 bond.py pack.data bonded.data 0.02
for f in 1.0 1.1 1.2 1.26 1.27 1.3; do
    lmp -in in.tension -var mode check -var factor $f -log log.check$f -screen none
done
lmp -in in.tension -log log.tension -screen none
/usr/bin/python3 plot.py .
