"""Input-script building blocks shared by the MCA tests."""

import math

# every per-automaton quantity that compute property/atom can report for
# atom_style mca, in the order of the dump columns written by DUMP_ALL
MCA_PROPERTIES = ["packing", "volume", "inertia", "smean", "sxx", "syy", "szz", "sxy", "sxz",
                  "syz", "seq", "eeq", "epsp", "damage", "orientw", "orienti", "orientj",
                  "orientk"]
CORE_COLUMNS = ["id", "type", "mol", "x", "y", "z", "vx", "vy", "vz", "radius", "mass",
                "omegax", "omegay", "omegaz"]
ALL_COLUMNS = CORE_COLUMNS + [f"c_mca[{k + 1}]" for k in range(len(MCA_PROPERTIES))]


def lattice_box(lattice="fcc", a=0.7184, n=3, ntypes=2, boundary="p p p", units="si"):
    """A periodic box filled with automata on a lattice (lattice units)."""
    return f"""
units           {units}
atom_style      mca
atom_modify     map array
boundary        {boundary}
lattice         {lattice} {a}
region          box block 0 {n} 0 {n} 0 {n}
create_box      {ntypes} box
create_atoms    1 box
"""


def lattice_data_file(build, directory, lattice="fcc", a=0.7184, n=3, ntypes=2, units="si"):
    """Write a data file of a lattice box with a serial run and return its path.

    create_atoms numbers the atoms by MPI rank, so runs on different numbers
    of ranks that must be compared atom by atom read the same data file.
    """
    script = lattice_box(lattice, a, n, ntypes, units=units) + "write_data lattice.data\n"
    build.run(script, directory)
    return directory / "lattice.data"


def read_lattice(data_file, units="si"):
    return f"""
units           {units}
atom_style      mca
atom_modify     map array
read_data       {data_file}
"""


def dump_all(filename, every=1, name="all_fields"):
    """Dump every field of every automaton with full double precision."""
    return f"""
compute         mca all property/atom {' '.join(MCA_PROPERTIES)}
dump            {name} all custom {every} {filename} {' '.join(ALL_COLUMNS)}
dump_modify     {name} sort id format float %.17g
"""


# non-trivial, distinct per-automaton values for every settable field, as
# atom-style variables of the atom ID (shared by the round-trip tests)
VARIED_STATE = """
variable        r_var atom 0.25+0.002*(id%7)
variable        rho_var atom 2000+10*(id%5)
variable        smean_var atom -1.0e6*sin(id)
variable        seq_var atom 2.0e6*(1+cos(id))
variable        eeq_var atom 1.0e-4*id
variable        epsp_var atom 1.0e-5*(id%3)
variable        damage_var atom 0.01*(id%11)
variable        vx_var atom 12.0*sin(1.7*id)
variable        vy_var atom 9.0*cos(0.9*id)
variable        vz_var atom 10.0*sin(0.4*id+1)
variable        wx_var atom 3.0*sin(id)
variable        wy_var atom -2.0*cos(2*id)
variable        wz_var atom 1.5*sin(0.3*id)
group           sc_group id 1:10
mca_set         all radius v_r_var density v_rho_var smean v_smean_var seq v_seq_var &
                eeq v_eeq_var epsp v_epsp_var damage v_damage_var
mca_set         sc_group packing sc stress 1.0e5 -2.0e5 3.0e5 4.0e4 -5.0e4 6.0e4
set             type 1 mol 3
velocity        all set v_vx_var v_vy_var v_vz_var units box
set             group all omega v_wx_var v_wy_var v_wz_var
"""


def fcc_radius(a):
    return a / (2.0 * math.sqrt(2.0))


def two_bodies(box, first, second, atom_modify="map array"):
    """The start of a scene of two bodies of an sc packing: the automata of
    the region first = (name, 'xlo xhi ylo yhi zlo zhi') of type 1, in the
    group of that name, and those of second of type 2 (regions in lattice
    units), not linked unless the pair style says so.  The text keeps the
    fields {spacing} (lattice spacing 2R) and {radius} for the caller's
    format(); CONTACT_NEIGHBOR follows the caller's own set-up."""
    (name1, region1), (name2, region2) = first, second
    return f"""
units           si
atom_style      mca
atom_modify     {atom_modify}
boundary        f f f
lattice         sc {{spacing}}
region          box block {box}
create_box      2 box
region          {name1} block {region1}
region          {name2} block {region2}
create_atoms    1 region {name1}
create_atoms    2 region {name2}
mca_set         all packing sc radius {{radius}}
group           {name1} type 1
group           {name2} type 2
"""


# ghost velocities and the neighbor settings contacts need (the field
# {skin} for the caller's format())
CONTACT_NEIGHBOR = """comm_modify     vel yes
neighbor        {skin} bin
neigh_modify    delay 0 every 1 check yes
"""


def block_on_plane(box, plane, block, top, atom_modify="map array"):
    """two_bodies: a plane (type 1, group plane) and a block (type 2, group
    block) on it, the block's layers above z = top (lattice units) in
    group top, and CONTACT_NEIGHBOR."""
    return (two_bodies(box, ("plane", plane), ("block", block), atom_modify)
            + f"region          top block INF INF INF INF {top} INF\n"
            "group           top region top\n" + CONTACT_NEIGHBOR)
