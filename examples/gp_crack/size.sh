#!/bin/bash
# The size study (in.tension, make_tension.py, crack_size.py): edge-cracked Fe
# plates 387.7 A wide, half heights 8, 16, 32 level-2 periods (64.6, 129.2,
# 258.4 A), GP and, for the two smaller, full MD, pulled by grips to 1 %
# strain.  About 15 minutes on one core: size.txt, size.png.
set -e
models=""
for m in tgp.8 tmd.8 tgp.16 tmd.16 tgp.32; do
  n=${m#*.}
  out=$(/usr/bin/python3 make_tension.py $n $([ ${m%%.*} = tmd ] && echo md))
  W=$(echo "$out" | sed -n 's/^W //p'); H=$(echo "$out" | sed -n 's/^H //p')
  lmp -in in.tension -var model $m -var W $W -var H $H -log log.tension.$m -screen none
  models="$models $m"
done
/usr/bin/python3 crack_size.py $models
