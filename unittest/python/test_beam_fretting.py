"""The example examples/beam_fretting (NUMFRAC's fretting, reference case
17) at reduced size: a substrate of 32 x 10 cells of breakable beams
under a pad of 10 columns, pressed and slid along it for one period.
The source gives no numbers, only the morphology ("bent cracks and
platelet formation", qualitatively like fretting damage in magnesium);
the test asserts what makes it fretting damage and not something else,
with the figures measured here (same input, both builds):

* nothing breaks while the pad is pressed (the contact pressure alone is
  below the strength): the bonds at the end of the ramp are those of the
  start;
* sliding breaks bonds (91 of 896 measured with LAMMPS 2026, 77 with
  2021: the breaks follow chaotic contact dynamics, so the two versions'
  round-off leads to other bonds; at least 20);
* the damage is at the contact: at least 75 % of the broken bonds lie
  under the pad or within 3 spacings of its edges (measured 88 % and
  83 %; the rest are cracks that run on from its edges);
* the surface under the pad comes off as a layer: at least half of the
  substrate's top-row bonds under the pad broken (measured 9 of 10 on both);
* cracks run below the surface (deepest more than 3 rows; measured 8.5 and 7.5).
"""

import importlib.util

import numpy as np

import mcatest

EXAMPLE = mcatest.ROOT / "examples" / "beam_fretting"
PADX = 10


def load_plot():
    spec = importlib.util.spec_from_file_location("fretting_plot", EXAMPLE / "plot.py")
    plot = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(plot)
    return plot


def test_fretting_breaks_the_surface_under_the_pad(build, tmp_path):
    plot = load_plot()
    build.run((EXAMPLE / "in.fretting").read_text(), tmp_path, name="in.fretting",
              variables={"nx": 32, "ny": 10, "padx": PADX, "cycles": 1})
    start = plot.read_data(tmp_path / "fretting.start.data")
    end = plot.read_data(tmp_path / "fretting.end.data")
    broken = plot.broken_bonds(start, end)
    pos, lx = start[0], start[2][1] - start[2][0]
    substrate = start[1][1]
    top = max(pos[a][1] for bond in substrate for a in bond)
    centre = 0.5 * lx
    mids = np.array([(0.5 * (pos[a][0] + pos[b][0]), 0.5 * (pos[a][1] + pos[b][1]))
                     for a, b in broken if abs(pos[a][0] - pos[b][0]) < 0.5 * lx])
    near = np.mean(np.abs(mids[:, 0] - centre) <= 0.5 * PADX + 3.0)
    surface = [(a, b) for a, b in substrate
               if abs(pos[a][1] - top) < 0.01 and abs(pos[b][1] - top) < 0.01
               and abs(0.5 * (pos[a][0] + pos[b][0]) - centre) < 0.5 * PADX]
    stripped = len(set(surface) & set(broken))
    deepest = (top - mids[:, 1]).max() / (np.sqrt(3.0) / 2.0)
    thermo = plot.thermo(tmp_path / "log.lammps")
    pressed = thermo[thermo[:, 1] <= 50.0]
    print(f"{len(broken)} of {len(substrate)} substrate bonds broken, {100 * near:.0f} % at the "
          f"contact, {stripped} of {len(surface)} surface bonds under the pad, deepest "
          f"{deepest:.1f} rows; bonds {pressed[0, 4]:.0f} at the start, {pressed[-1, 4]:.0f} "
          "at the end of the pressing")
    assert pressed[-1, 4] == pressed[0, 4]
    assert len(broken) >= 20
    assert near >= 0.75
    assert 2 * stripped >= len(surface)
    assert deepest > 3.0
    # fragments (R11): compute fragment/atom's clusters are those of the
    # intact bonds of the end's data file (union-find here): the substrate
    # and the pad, and debris if any
    frag = plot.read_fragments(tmp_path / "fretting.fragments.dump")
    mine = plot.clusters(end)
    canon = lambda of: sorted(sorted(a for a in of if of[a] == f) for f in set(of.values()))
    sizes = plot.fragment_sizes(frag)
    print(f"fragments {len(sizes)}: sizes {sizes[:2]} and debris {sizes[2:]}")
    assert canon(frag) == canon(mine)
    assert len(sizes) >= 2 and sizes[1] >= PADX
