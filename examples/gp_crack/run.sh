#!/bin/bash
# The K-test of an edge crack in bcc Fe (in.ktest): the full-MD model and
# GP models of the same block with atoms within 16, 32 and 48 A of the
# crack (half width L = 12 level-2 periods, 96.91 A), then the full-MD
# and the 32 A GP model of a block of L = 18 periods (145.37 A); the
# analysis (ktest.txt, ktest.png).  About 6 minutes on one core.
# Fe_mm.eam.fs is read from $LAMMPS_POTENTIALS (tools/mca env sets it);
# MCA_ROOT = the package's checkout (default: two directories up).
set -e
for n in 12 18; do
  L=$(/usr/bin/python3 make_models.py $n $([ $n = 12 ] && echo 16 32 48 || echo 32) | tee /dev/stderr \
      | sed -n 's/^L //p')
  for model in md.$n $(ls in.gp*.$n | sed 's/^in\.//'); do
    lmp -in in.ktest -var model $model -var L $L -log log.ktest.$model -screen none
  done
done
/usr/bin/python3 crack_fields.py md.12 gp16.12 gp32.12 gp48.12 md.18 gp32.18
