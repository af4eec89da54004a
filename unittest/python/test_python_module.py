"""The LAMMPS Python module drives an MCA run and hands MCA fields to numpy.

Runs only with the "current" build, which is built as a shared library with
the Python module (the Python module of LAMMPS 2021 is not built here).
"""

import math

import numpy as np
import pytest

from mca_inputs import lattice_box
from mcatest import build_named

lammps_module = pytest.importorskip("lammps", reason="LAMMPS Python module not on PYTHONPATH")


@pytest.fixture
def lmp():
    if build_named("current") is None:
        pytest.skip("the Python module belongs to the 'current' build")
    instance = lammps_module.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    yield instance
    instance.close()


def test_run_and_read_mca_fields_as_numpy(lmp):
    """Per-automaton MCA data reaches numpy with the values the model defines.

    An fcc block of 4a x 4a x 4a has 256 automata of radius a/(2 sqrt 2) and
    cell volume a^3/4; mca_set density gives m = rho a^3/4 (tolerance 1e-14).
    """
    a = 0.7184
    lmp.commands_string(lattice_box("fcc", a, 4) + """
mca_set         all density 2700
variable        d atom 0.001*id
mca_set         all damage v_d
compute         mca all property/atom volume damage packing
pair_style      zero 1.0
pair_coeff      * *
fix             integrate all nve/mca
velocity        all set 0.1 0.0 0.0 units box
run             10
""")
    assert lmp.get_natoms() == 256
    volume = lmp.numpy.extract_compute("mca", lammps_module.LMP_STYLE_ATOM,
                                       lammps_module.LMP_TYPE_ARRAY)
    assert volume.shape == (256, 3)
    assert np.allclose(volume[:, 0], a**3 / 4, rtol=1e-14, atol=0)
    assert np.all(volume[:, 2] == 12)
    nlocal = lmp.extract_global("nlocal")
    ids = lmp.numpy.extract_atom("id")[:nlocal]
    assert np.allclose(volume[:, 1], 0.001 * ids, rtol=1e-14, atol=0)
    mass = lmp.numpy.extract_atom("rmass")[:nlocal]
    assert np.allclose(mass, 2700 * a**3 / 4, rtol=1e-14, atol=0)
    radius = lmp.numpy.extract_atom("radius")[:nlocal]
    assert np.allclose(radius, a / (2 * math.sqrt(2)), rtol=1e-14, atol=0)
    vx = lmp.numpy.extract_atom("v")[:nlocal, 0]
    assert np.all(vx == 0.1)


def test_errors_raise_python_exceptions(lmp):
    """A bad MCA command raises an exception that carries the LAMMPS message."""
    lmp.commands_string(lattice_box("fcc", 0.7184, 2))
    with pytest.raises(Exception, match="mca_set radius must be > 0"):
        lmp.command("mca_set all radius -1")


def test_time_step_from_the_estimate(lmp):
    """compute mca/timestep asked for before the first run (no links yet):
    an error that says how to get the links; after 'run 0' the script sets
    its time step from it, and the run then stays below the estimate."""
    lmp.commands_string(lattice_box("fcc", 0.7184, 3) + """
comm_modify     vel yes
pair_style      mca
pair_coeff      * * E 70e9 nu 0.3 rho 2700
compute         dt all mca/timestep
fix             integrate all nve/mca
""")
    with pytest.raises(Exception, match=r"Compute mca/timestep: the stable time step is estimated "
                                        r"from the links of pair mca, which are made at the first "
                                        r"run; use 'run 0' before asking for it"):
        lmp.extract_compute("dt", lammps_module.LMP_STYLE_GLOBAL, lammps_module.LMP_TYPE_SCALAR)
    lmp.command("run 0")
    dt = lmp.extract_compute("dt", lammps_module.LMP_STYLE_GLOBAL, lammps_module.LMP_TYPE_SCALAR)
    recommended = lmp.extract_compute("dt", lammps_module.LMP_STYLE_GLOBAL,
                                      lammps_module.LMP_TYPE_VECTOR)[1]
    assert 0.0 < dt < 1.0e-3
    assert recommended == pytest.approx(0.7 * dt, rel=1e-15)
    lmp.command(f"timestep {recommended}")
    lmp.command("run 10")
    ratio = lmp.extract_compute("dt", lammps_module.LMP_STYLE_GLOBAL,
                                lammps_module.LMP_TYPE_VECTOR)[2]
    assert ratio == pytest.approx(0.7, rel=1e-12)
