"""The YAML force-style tests of the package, run with the Kokkos variants.

The tester programs of LAMMPS 29 Sep 2021 have no KOKKOS test (that came
with later versions as PairStyle.kokkos_omp / FixTimestep.kokkos_omp), so
this module does what those tests do, with the lmp executable of the
"kokkos" build: the YAML file's input, styles and coefficients, run with
-k on t 2 -sf kk, newton on and off; forces, energy and virial after
"run 0" and after "run 4" with fix nve, compared with the reference
data of the same YAML file (made by the CPU styles) with the tolerances of
LAMMPS's kokkos_omp tests: every component's relative error (to the
smaller of the two magnitudes) at most 5 epsilon of the file for the
first forces, 25 epsilon after the run, 50 epsilon for the virial.

The YAML test of fix nve/mca is not run this way: its system is an
atom_style hybrid (mca angle, because the fix tester of 2021 issues angle
commands), which has no Kokkos variant; fix nve/mca/kk is compared with
fix nve/mca at every step in test_kokkos.py.
"""

import pathlib
import re

import numpy as np
import pytest
import yaml

from mcatest import UNITTEST, kokkos_build

TESTS = UNITTEST / "force-styles" / "tests"
KOKKOS_ARGS = ("-k", "on", "t", "2", "-sf", "kk")
# pressure x volume per energy in LAMMPS's metal units (bar A^3 / eV)
METAL_NKTV2P = 1.6021765e6


def lines(text):
    return [line for line in (text or "").splitlines() if line.strip()]


def per_atom(text):
    """'id a b c' rows of a YAML block as {id: array}."""
    rows = {}
    for line in lines(text):
        words = line.split()
        rows[int(words[0])] = np.array([float(w) for w in words[1:]])
    return rows


def read_rows(path, columns):
    rows = {}
    for line in pathlib.Path(path).read_text().splitlines()[9:]:
        words = line.split()
        rows[int(words[0])] = np.array([float(w) for w in words[1:1 + columns]])
    return rows


def relative_error(a, b):
    """Largest componentwise |a-b| / min(|a|,|b|) (|a-b| where one is 0),
    the measure of LAMMPS's EXPECT_FP_LE_WITH_EPS."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    diff = np.abs(a - b)
    div = np.minimum(np.abs(a), np.abs(b))
    err = np.where(div == 0.0, diff, diff / np.where(div == 0.0, 1.0, div))
    return float(err.max())


def common_input(config, newton):
    text = [f"variable newton_pair index {newton}", f"variable input_dir index {TESTS}"]
    text += lines(config.get("pre_commands"))
    text.append(f"include {TESTS / config['input_file']}")
    return text


PAIR_STAGE = """
write_dump all custom {name}.dump id fx fy fz modify format float %.17g sort id
print "ENERGY {name} $(evdwl:%.17g)"
print "VIRIAL {name} $(c_vir[1]*vol:%.17g) $(c_vir[2]*vol:%.17g) $(c_vir[3]*vol:%.17g) $(c_vir[4]*vol:%.17g) $(c_vir[5]*vol:%.17g) $(c_vir[6]*vol:%.17g)"
"""


def pair_script(config, newton):
    text = common_input(config, newton)
    text.append(f"pair_style {config['pair_style']}")
    text += [f"pair_coeff {c}" for c in lines(config["pair_coeff"])]
    text += lines(config.get("post_commands"))
    # the pair virial (pressure tensor without kinetic part, times volume);
    # in the thermo output so that it is current after each run
    text.append("compute vir all pressure NULL virial")
    text.append("thermo_style custom step evdwl c_vir[*]")
    text.append("thermo_modify norm no")
    text.append("run 0 post no")
    text.append(PAIR_STAGE.format(name="init"))
    text += ["fix 1 all nve", "run 4 post no"]
    text.append(PAIR_STAGE.format(name="run"))
    text.append("info system")
    return "\n".join(text) + "\n"


def printed(output, key, name):
    for line in output.splitlines():
        words = line.split()
        if words[:2] == [key, name]:
            return np.array([float(w) for w in words[2:]])
    raise AssertionError(f"no '{key} {name}' line in the output")


def stress_vector(text):
    return np.array([float(w) for w in " ".join(lines(text)).split()])


@pytest.mark.parametrize("newton", ["on", "off"])
@pytest.mark.parametrize("name", ["atomic-pair-mca", "atomic-pair-mca_damping",
                                  "atomic-pair-mca_plasticity", "atomic-pair-mca_fracture",
                                  "atomic-pair-mca_contacts"])
def test_pair_mca_kk_yaml(tmp_path, newton, name):
    build = kokkos_build()
    config = yaml.safe_load((TESTS / f"{name}.yaml").read_text())
    eps = float(config["epsilon"])
    result = build.run(pair_script(config, newton), tmp_path, extra_args=KOKKOS_ARGS)
    output = result.stdout
    # the Kokkos styles ran, not the CPU ones
    assert re.search(r"Atom style\s*=\s*mca/kk", output), "atom style is not mca/kk"
    assert "pair mca/kk: link passes as Kokkos kernels" in output, "pair style is not mca/kk"

    for stage, factor in (("init", 5), ("run", 25)):
        reference = per_atom(config[f"{stage}_forces"])
        forces = read_rows(tmp_path / f"{stage}.dump", 3)
        assert sorted(forces) == sorted(reference)
        err = max(relative_error(forces[i], reference[i]) for i in reference)
        print(f"newton {newton} {stage}_forces: largest relative error {err:.2e}")
        assert err <= factor * eps, f"{stage}_forces: {err:.2e} > {factor} x {eps}"

        energy = printed(output, "ENERGY", stage)[0]
        err = relative_error(energy, float(config[f"{stage}_vdwl"]))
        assert err <= 5 * eps, f"{stage}_vdwl: {err:.2e}"

        virial = printed(output, "VIRIAL", stage)
        err = relative_error(virial, stress_vector(config[f"{stage}_stress"]))
        # the pressure compute divides by the volume and the print multiplies
        # again: 2 more roundings on top of the kernel's
        assert err <= 10 * 5 * eps, f"{stage}_stress: {err:.2e}"


def check_pair_kk_yaml(tmp_path, newton, name):
    """A pair style's kk variant against the CPU reference data of its
    YAML file (a style of plain pair forces: no MCA atom style)."""
    build = kokkos_build()
    config = yaml.safe_load((TESTS / f"{name}.yaml").read_text())
    eps = float(config["epsilon"])
    result = build.run(pair_script(config, newton), tmp_path, extra_args=KOKKOS_ARGS)
    output = result.stdout
    style = config["pair_style"].split()[0]
    assert re.search(rf"pair {re.escape(style)}/kk", output), f"pair style is not {style}/kk"
    for stage, factor in (("init", 5), ("run", 25)):
        reference = per_atom(config[f"{stage}_forces"])
        forces = read_rows(tmp_path / f"{stage}.dump", 3)
        assert sorted(forces) == sorted(reference)
        err = max(relative_error(forces[i], reference[i]) for i in reference)
        print(f"newton {newton} {stage}_forces: largest relative error {err:.2e}")
        assert err <= factor * eps, f"{stage}_forces: {err:.2e} > {factor} x {eps}"
        energy = printed(output, "ENERGY", stage)[0]
        assert relative_error(energy, float(config[f"{stage}_vdwl"])) <= 5 * eps
        # (the YAML stores the virial in energy units; the print gives
        # pressure x volume: bar A^3 in metal units)
        virial = printed(output, "VIRIAL", stage) / METAL_NKTV2P
        err = relative_error(virial, stress_vector(config[f"{stage}_stress"]))
        assert err <= 10 * 5 * eps, f"{stage}_stress: {err:.2e}"


@pytest.mark.parametrize("newton", ["on", "off"])
@pytest.mark.parametrize("name", ["atomic-pair-gp_morse", "atomic-pair-gp_lj_cut",
                                  "atomic-pair-gp_eam_alloy", "atomic-pair-gp_eam_fs"])
def test_gp_pair_kk_yaml(tmp_path, newton, name):
    """The GP pair styles' kk variants (the kernels of LAMMPS's kk styles with
    the parameters or the tables of the scale levels) against the CPU
    reference data."""
    check_pair_kk_yaml(tmp_path, newton, name)


@pytest.mark.parametrize("newton", ["on", "off"])
@pytest.mark.parametrize("name", ["atomic-pair-mlp", "atomic-pair-mlp_conservative"])
def test_mlp_pair_kk_yaml(tmp_path, newton, name):
    """pair_style mlp/kk (2-D, both return forces) against the CPU reference data."""
    check_pair_kk_yaml(tmp_path, newton, name)
