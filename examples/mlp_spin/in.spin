# A free disc of movable lattice particles set spinning (pair_style mlp;
# the surface effect of the reference notes, Part B.3-B.4).  The return
# force ties the bonds to axes fixed in space: a body turned as a whole
# feels the torque -N_bonds f0 c sin(6 beta) through its surface, and a
# free disc rocks about the axes instead of turning.  With the axes of
# fix mlp/frame (pair_style mlp ... frame fr) they turn with the disc,
# which spins on.  fix mlp/frame measures the disc's angle in both runs;
# only the pair style decides whether the axes follow it.
#
#   -var frame fr|none   axes that turn with the disc, or fixed axes
#   -var every N         measure the angle every N steps (1)
#   -var nsteps N        steps (3927: 90 degrees at the initial rate)
#   -var visevery N      snapshots every N steps (0: none)

variable        frame index fr
variable        every index 1
variable        nsteps index 3927
variable        omega index 0.02
variable        radius index 10.2
variable        name index spin

units           lj
dimension       2
atom_style      atomic
atom_modify     map array
boundary        f f p
# hexagonal lattice of spacing 1 (lattice custom: the scale is a number
# density in lj units), bonds along 0, 60, 120 degrees, a site at 0 0
lattice         custom 1.1547005383792515 a1 1 0 0 a2 0 1.7320508075688772 0 &
                a3 0 0 1 basis 0 0 0 basis 0.5 0.5 0
region          box block -16 16 -16 16 -0.5 0.5 units box
create_box      1 box
region          disc cylinder z 0 0 ${radius} -0.5 0.5 units box
create_atoms    1 region disc
mass            1 1.0

# Morse bonds (U'' = 8) and the return force of order 6 (f0 = 0.2:
# k1 = 1.2, k2 = 6.8, nu_2D = 0.079), the energy-conserving variant
pair_style      mlp 1.3 return conservative taper 0.2 frame ${frame}
pair_coeff      1 1 morse 1.0 2.0 1.0 0.2 6 0.0
neighbor        0.3 bin

fix             fr all mlp/frame ${every}

# a rigid spin omega about the centre (the centre of mass is at 0 0)
variable        vx atom -${omega}*y
variable        vy atom ${omega}*x
velocity        all set v_vx v_vy 0.0
variable        lz atom mass*(x*vy-y*vx)
compute         lz all reduce sum v_lz
fix             1 all nve
fix             2 all enforce2d
timestep        0.02

thermo_style    custom step time f_fr[1] c_lz ke pe etotal
thermo_modify   norm no format float %.12g
thermo          50

variable        visevery index 0
compute         vispe all pe/atom
if "${visevery} > 0" then &
  "dump vis all custom ${visevery} ${name}.*.dump id type x y z vx vy vz c_vispe" &
  "dump_modify vis sort id"
run             ${nsteps}

# the final state, and a picture where the build writes PNG
dump            visfinal all custom 1 ${name}.final.dump id type x y z vx vy vz c_vispe
dump_modify     visfinal sort id format float %.10g
run             0 post no
undump          visfinal
if "$(is_available(feature,png))" then &
  "write_dump all image ${name}.png c_vispe type view 0 0 zoom 1.4 size 600 600"
