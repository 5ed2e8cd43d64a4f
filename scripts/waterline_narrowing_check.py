#!/usr/bin/env python3
"""Which change of a hull's sections along its length makes the strip results converge slowly in panels.

Builds a hull with `hullopt hull`, then writes three variants of its offsets in which the sections aft of a
station x_split are replaced by (a) the section at x_split (prismatic run), (b) that section scaled in breadth
to each station's waterline half-breadth (only the waterline narrows), (c) that section scaled in depth to
each station's draught (only the keel rises); the body forward of x_split is kept. Each hull (one body, the
generated hull's draught) goes through scripts/panel_convergence.sh at the given panel counts, which prints
A33, A53, B33, B55 from `hullopt coefficients` at one wave frequency.

Usage: scripts/waterline_narrowing_check.py HULL_CONFIG X_SPLIT_M OMEGA_RAD_S SECTIONS PANELS...
  e.g. scripts/waterline_narrowing_check.py configs/davis-holloway-2003/hull05_S64.yaml 32.5 0.7 40 14 28 56
Binary: $HULLOPT (default build/app/hullopt).
"""
import os
import subprocess
import sys
import tempfile

from generated_hull import first_body_stations

def main():
    if len(sys.argv) < 6:
        print(__doc__)
        return 2
    cfg, x_split, omega, sections = sys.argv[1], float(sys.argv[2]), sys.argv[3], sys.argv[4]
    panels = sys.argv[5:]
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    hullopt = os.path.abspath(os.environ.get("HULLOPT", os.path.join(root, "build/app/hullopt")))
    work = tempfile.mkdtemp(prefix="wl_narrowing_")
    T, stations = first_body_stations(hullopt, cfg, work)
    xs = sorted(stations)
    xm = min(xs, key=lambda x: abs(x - x_split))
    mid = stations[xm]

    def waterline_half_breadth(sec):
        for (y1, z1), (y2, z2) in zip(sec, sec[1:]):
            if z1 <= T <= z2:
                return y1 + (y2 - y1) * (T - z1) / (z2 - z1) if z2 > z1 else y2
        return sec[-1][0]

    def draught(sec):
        return T - sec[0][1]

    bm, dm = waterline_half_breadth(mid), draught(mid)
    variants = {
        "as generated": lambda x: stations[x],
        "prismatic aft of x_split": lambda x: stations[x] if x >= xm else mid,
        "only the waterline narrows aft": lambda x: stations[x] if x >= xm else
            [(y * waterline_half_breadth(stations[x]) / bm, z) for y, z in mid],
        "only the keel rises aft": lambda x: stations[x] if x >= xm else
            [(y, T - (T - z) * draught(stations[x]) / dm) for y, z in mid],
    }
    for i, (name, section) in enumerate(variants.items()):
        path = os.path.join(work, f"v{i}")
        with open(path + ".csv", "w") as f:
            f.write("x_m,y_m,z_m\n")
            for x in xs:
                for y, z in section(x):
                    f.write(f"{x:.9g},{y:.9g},{z:.9g}\n")
        with open(path + ".yaml", "w") as f:
            f.write(f"hull: {{ offsets_csv: {path}.csv, draught_m: {T!r}, hulls: 1 }}\n")
            with open(cfg) as c:
                for line in c:
                    if line.startswith(("water:", "speed:")):
                        f.write(line)
        print(f"\n{name} (one body, sections aft of x = {xm:.2f} m):")
        sys.stdout.flush()
        subprocess.run(["bash", os.path.join(root, "scripts/panel_convergence.sh"), path + ".yaml", omega,
                        sections] + panels, check=True, env=dict(os.environ, HULLOPT=hullopt))
    return 0

if __name__ == "__main__":
    sys.exit(main())
