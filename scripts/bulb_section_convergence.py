#!/usr/bin/env python3
"""2D heave added mass of bulb-under-strut sections against the panel count (`hullopt section`).

Two kinds of section, each written as a two-station prismatic offsets file and run through
`hullopt section` (frequency-domain solver, one section, deep water, sea water):
  stations HULL_CONFIG X_M... : the stations of a generated hull (built with `hullopt hull`) nearest each X_M
                                 [m from the AP], at the hull's draught;
  bulb R_M DEPTH_M STRUT_M [FILLET_M]: a circular bulb of radius R centred DEPTH below the waterline under a
                                 straight strut of half-width STRUT, optionally with a fillet of radius FILLET
                                 at the strut-bulb junction.
Prints a33 [kg/m] at OMEGA (default 0.9 rad/s) for 14, 28, 56, 112, 224 panels.

Usage:
  scripts/bulb_section_convergence.py stations configs/davis-holloway-2003/hull11_SW3.yaml 42 65.2 77.8 82
  scripts/bulb_section_convergence.py bulb 1.0 1.8 0.25
  scripts/bulb_section_convergence.py bulb 1.491 2.11 0.373 0.5
Options (environment): OMEGA (rad/s), PANELS (space-separated), HULLOPT (binary, default build/app/hullopt),
METHOD (the `hullopt section` method: frequency_domain, the default, frequency_domain_direct, time_domain or
time_domain_green_identity).
"""
import csv
import math
import os
import subprocess
import sys
import tempfile

from generated_hull import first_body_stations

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run_section(offsets, x, draught, panels, omega, hullopt, work, method):
    cfg = os.path.join(work, f"s{panels}.yaml")
    with open(cfg, "w") as f:
        f.write(f"section: {{ shape: offsets, offsets_csv: {offsets}, x_m: {x!r}, draught_m: {draught!r}, "
                f"panels: {panels}, method: [{method}], frequencies: {{ omega_rad_s: [{omega}] }} }}\n"
                "water: { rho_kg_m3: 1025, g_m_s2: 9.81 }\n")
    out = tempfile.mkdtemp(prefix=f"o{panels}_", dir=work)
    subprocess.run([hullopt, "section", cfg, "--out", out], check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "section.csv")) as f:
        rows = list(csv.DictReader(l for l in f if not l.startswith("#")))
    return float(rows[0]["a33_kg_per_m"])


def write_prismatic(path, contour):
    """contour: (y, z above the keel) from the keel up to above the waterline."""
    with open(path, "w") as f:
        f.write("x_m,y_m,z_m\n")
        for x in (0.0, 1.0):
            for y, z in contour:
                f.write(f"{x},{y:.12g},{z:.12g}\n")


def bulb_contour(R, depth, strut, fillet):
    """Circle (centre `depth` below the waterline) from its keel round to the strut, then the strut to 1 m
    above the waterline; z from the keel. With a fillet: a concave arc tangent to circle and strut."""
    keel = depth + R
    pts = []
    if fillet <= 0:
        end = math.pi - math.asin(strut / R)
        pts = [(R * math.sin(end * i / 400), R - R * math.cos(end * i / 400)) for i in range(401)]
    else:
        # Fillet centre (strut + fillet, zc) at R + fillet from the circle's centre (0, R): externally tangent.
        cy = strut + fillet
        zc = R + math.sqrt((R + fillet) ** 2 - cy ** 2)
        end = math.atan2(cy, R - zc)  # polar angle (from the keel) of the tangent point
        pts = [(R * math.sin(end * i / 400), R - R * math.cos(end * i / 400)) for i in range(401)]
        a0 = math.atan2(R - zc, -cy)  # from the fillet centre to the tangent point, in (-pi, -pi/2)
        for i in range(1, 101):
            a = a0 + (-math.pi - a0) * i / 100
            pts.append((cy + fillet * math.cos(a), zc + fillet * math.sin(a)))
    top = pts[-1][1]
    for z in (top + 0.5 * (keel - top), keel + 1.0):
        pts.append((strut, z))
    return pts, keel


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    hullopt = os.path.abspath(os.environ.get("HULLOPT", os.path.join(ROOT, "build/app/hullopt")))
    omega = float(os.environ.get("OMEGA", "0.9"))
    method = os.environ.get("METHOD", "frequency_domain")
    panels = [int(p) for p in os.environ.get("PANELS", "14 28 56 112 224").split()]
    work = tempfile.mkdtemp(prefix="bulb_sections_")
    cases = []  # (label, offsets, x, draught)
    if sys.argv[1] == "stations":
        T, stations = first_body_stations(hullopt, sys.argv[2], work)
        xs = sorted(stations)
        body = os.path.join(work, "body.csv")
        with open(body, "w") as f:
            f.write("x_m,y_m,z_m\n")
            for x, points in stations.items():
                for y, z in points:
                    f.write(f"{x!r},{y!r},{z!r}\n")
        for want in sys.argv[3:]:
            x = min(xs, key=lambda v: abs(v - float(want)))
            cases.append((f"station x = {x:.2f} m", body, x, T))
    elif sys.argv[1] == "bulb":
        R, depth, strut = (float(v) for v in sys.argv[2:5])
        fillet = float(sys.argv[5]) if len(sys.argv) > 5 else 0.0
        contour, keel = bulb_contour(R, depth, strut, fillet)
        path = os.path.join(work, "bulb.csv")
        write_prismatic(path, contour)
        cases.append((f"bulb R {R} m, centre {depth} m deep, strut half-width {strut} m, fillet {fillet} m",
                      path, 0.5, keel))
    else:
        print(__doc__)
        return 2
    print(f"{method}: a33 [kg/m] at omega {omega} rad/s, panels {' / '.join(map(str, panels))}")
    for label, offsets, x, T in cases:
        a = [run_section(offsets, x, T, p, omega, hullopt, work, method) for p in panels]
        print(f"{label}: " + " / ".join(f"{v:.1f}" for v in a) +
              f"  ({100 * (a[0] / a[-1] - 1):+.1f} % at {panels[0]} against {panels[-1]})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
