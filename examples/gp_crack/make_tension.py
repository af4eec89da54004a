#!/usr/bin/python3
"""The models of the size study (in.tension), made with tools/gp_build.py.

Bcc Fe (Fe_mm.eam.fs), X = [110], Y = [-110], Z = [001] (22.8 A, periodic,
plane strain): a plate x in [0, W), y in [-H, H), W = 48 level-2 periods
(387.6 A), H = n periods, with an edge crack from the xlo face to x = 81 A
(a/W = 0.21; a slit of three removed (110) planes).

  tgp.n   atoms within 32 A of the crack (x < 113 A, |y| < 32 A; the crack
          faces atomic all along), level-2 particles (k = 2) elsewhere
  tmd.n   all atoms

  make_tension.py n [md] [--width periods] [--tip x]   (prints W and H;
                          the tests use a narrower plate)
"""
from make_models import PERIOD, cracked_plate, gp_build  # (make_models finds the builder)


def main(n, md, width, tip):
    W, H = width * PERIOD, n * PERIOD
    print(f"W {W:.6f}\nH {H:.6f}")
    name = f"{'tmd' if md else 'tgp'}.{n}"
    # the size study was measured with the linear fit (size.txt): the trend
    # across plates is the result, GP within 3.1 % of full MD
    model = gp_build.build(cracked_plate(0.0, W, -H, H, tip, None if md else (tip + 32, 32),
                                         fit="linear"))
    model.write(name)
    print(f"{name}: " + "; ".join(line.strip() for line in model.summary()[1:]))


if __name__ == "__main__":
    import argparse
    parser = argparse.ArgumentParser()
    parser.add_argument("n", type=int)
    parser.add_argument("md", nargs="?", default="")
    parser.add_argument("--width", type=int, default=48)
    parser.add_argument("--tip", type=float, default=81.0)
    args = parser.parse_args()
    main(args.n, args.md == "md", args.width, args.tip)
