#!/usr/bin/env python3
"""Writes a PDStrip case (pdstrip.inp and its section offset file) for a monohull given as a hullopt offsets CSV.

PDStrip (Söding and Bertram, public domain; github.com/eriove/pdstrip) is a frequency-domain strip method for
monohulls. This writer serves the side-by-side runs of bench/pdstrip_ratio.sh: the same hull, the same number of
sections, the same wavelengths and speed as a `hullopt rao` run.

Geometry: each station of the offsets file (x from the AP, y half-breadth, z above base; metres) is cut at the
draught and resampled by arc length to `points` offset points from the keel (y = 0) to the water line (then mirrored: a
whole section has 2 points - 1 offset points, 2 (points - 1) segments); sections
between stations are interpolated linearly in x at equal arc-length fractions. PDStrip's input axes are x forward,
y to port, z up, the same as the offsets file. Sections run from the aft end to the bow, as PDStrip requires.

The case: deep water, no pressure points, no fins, sails, external forces or suspended weight, no motion points,
no resistance coefficients (steepness 0: linear), one speed with the transom dry, head and following seas
(PDStrip computes 180 - mu for every angle mu it is given; mu = 0 gives both).

Usage:
  scripts/pdstrip_input.py OFFSETS_CSV OUT_DIR --draught 0.15 --sections 40 --points 8 --speed 4.0687
      --mass-t 0.043535 --xg 1.41 --zg 0.34 --kyy 0.782 --kxx 0.1 --rho 1.0 --wavelengths 1.5 2.0 ...
Units are PDStrip's: metres, seconds, tonnes (rho in t/m^3, mass in t).
"""
import argparse
import csv
import math
import os


def read_stations(path):
    stations = {}
    with open(path) as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#"))]
    for r in rows[1:]:
        x, y, z = (float(v) for v in r[:3])
        stations.setdefault(x, []).append((y, z))
    return [(x, pts) for x, pts in sorted(stations.items())]


def cut_and_resample(pts, draught, n):
    """The contour from the keel to the water line, n points equally spaced in arc length."""
    below = []
    for i, (y, z) in enumerate(pts):
        if z <= draught:
            below.append((y, z))
            continue
        if i > 0 and pts[i - 1][1] < draught:  # crossing of the water line
            (y0, z0) = pts[i - 1]
            t = (draught - z0) / (z - z0)
            below.append((y0 + t * (y - y0), draught))
        break
    if len(below) < 2 or below[-1][1] < draught - 1e-12:
        return None  # the station does not reach the water line in a way we can cut: left out
    s = [0.0]
    for (y0, z0), (y1, z1) in zip(below, below[1:]):
        s.append(s[-1] + math.hypot(y1 - y0, z1 - z0))
    out = []
    for k in range(n):
        target = s[-1] * k / (n - 1)
        j = max(i for i in range(len(s)) if s[i] <= target + 1e-15)
        j = min(j, len(s) - 2)
        t = 0.0 if s[j + 1] == s[j] else (target - s[j]) / (s[j + 1] - s[j])
        out.append((below[j][0] + t * (below[j + 1][0] - below[j][0]),
                    below[j][1] + t * (below[j + 1][1] - below[j][1])))
    out[0] = (0.0, out[0][1])
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("offsets")
    ap.add_argument("out_dir")
    ap.add_argument("--draught", type=float, required=True)
    ap.add_argument("--sections", type=int, default=40)
    ap.add_argument("--points", type=int, default=8, help="offset points per half section (keel to water line)")
    ap.add_argument("--speed", type=float, required=True, help="[m/s]")
    ap.add_argument("--mass-t", type=float, required=True)
    ap.add_argument("--xg", type=float, required=True, help="[m from AP]")
    ap.add_argument("--zg", type=float, required=True, help="[m above base]")
    ap.add_argument("--kyy", type=float, required=True, help="[m] pitch radius of gyration")
    ap.add_argument("--kxx", type=float, required=True, help="[m] roll radius of gyration")
    ap.add_argument("--rho", type=float, default=1.0, help="[t/m^3]")
    ap.add_argument("--g", type=float, default=9.81)
    ap.add_argument("--headings", type=float, nargs="+", default=[0.0],
                    help="PDStrip encounter angles in [-90, 90] (0: following; 180 - mu is added)")
    ap.add_argument("--wavelengths", type=float, nargs="+", required=True, help="[m]")
    ap.add_argument("--x-origin", type=float, default=0.0,
                    help="[m from AP] where PDStrip's x = 0 is put: its motions are given at its origin, so the CG "
                         "(the --xg value) makes its heave the heave at the centre of gravity")
    a = ap.parse_args(argv)

    stations = []
    for x, pts in read_stations(a.offsets):
        c = cut_and_resample(pts, a.draught, a.points)
        if c is not None:
            stations.append((x, c))
    x0, x1 = stations[0][0], stations[-1][0]
    sections = []
    for i in range(a.sections):
        x = x0 + (x1 - x0) * i / (a.sections - 1)
        j = max(k for k in range(len(stations)) if stations[k][0] <= x + 1e-12)
        j = min(j, len(stations) - 2)
        (xa, ca), (xb, cb) = stations[j], stations[j + 1]
        t = (x - xa) / (xb - xa)
        sections.append((x, [(p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])) for p, q in zip(ca, cb)]))

    os.makedirs(a.out_dir, exist_ok=True)
    with open(os.path.join(a.out_dir, "geometry"), "w") as f:
        # Whole sections (sym = f), starboard water line -> keel -> port water line: the symmetric input
        # (half sections from the keel) stops in PDStrip's own check of closed contours.
        f.write(f"{len(sections)} f {a.draught:.6f}\n")
        for x, c in sections:
            whole = [(-p[0], p[1]) for p in reversed(c[1:])] + c
            f.write(f"{x - a.x_origin:.6f} {len(whole)} 0\n")
            f.write(" ".join(f"{p[0]:.6f}" for p in whole) + "\n")
            f.write(" ".join(f"{p[1]:.6f}" for p in whole) + "\n")
    with open(os.path.join(a.out_dir, "pdstrip.inp"), "w") as f:
        f.write("0 t t f\n")
        f.write("'hullopt side-by-side case'\n")
        f.write(f"{a.g} {a.rho} {a.draught:.6f} -1e6 999.\n")
        f.write(f"{len(a.headings)} " + " ".join(f"{h:g}" for h in a.headings) + "\n")
        f.write("geometry\n")
        f.write("f\n")
        f.write(f"{a.mass_t:.6g} {a.xg - a.x_origin:.6f} 0.0 {a.zg:.6f} {a.kxx ** 2:.6g} {a.kyy ** 2:.6g} {a.kyy ** 2:.6g} "
                "0.0 0.0 0.0\n")
        f.write(" ".join("0" for _ in sections) + "\n")
        f.write("0.0 1.0\n")        # steepness 0: linear, no resistance coefficients
        f.write("0\n")              # fins
        f.write("0\n")              # sails
        f.write("0\n")              # forces depending on motions
        f.write("0.0 0.0 0.0 0.0 0.0\n")  # no suspended weight
        f.write("0\n")              # motion points
        f.write(f"{len(a.wavelengths)}\n" + " ".join(f"{w:.6f}" for w in a.wavelengths) + "\n")
        f.write(f"1\n{a.speed:.6f} f\n")


if __name__ == "__main__":
    main()
