#!/usr/bin/env python3
"""Delft 372: the forced-oscillation tests simulated as run, with the strips on the instantaneous hull.

For each Froude number of the tests (0.30, 0.45, 0.60, 0.75) and each measured point inside the near-resonance
band of scripts/delft372_links.py, the catamaran is forced in heave (15 mm) and in pitch (1.718 deg about the
LCG) at that frequency with hullopt.forced_oscillation (docs/ship-motions.md, "Forced oscillation on the
instantaneous hull"): the water line of every strip follows the hull, the transom comes and goes, and the force
is reduced as the tank reduced it (first harmonic, only the static restoring at rest removed). Cs 0.024. The
links are scored with the same band, points and score as scripts/delft372_links.py.

Usage:
  PYTHONPATH=build/python /usr/bin/python3 scripts/delft372_forced.py --out out/forced
      [--force momentum|pressure] [--amplitude-scale 1|0.1] [--attitude zero|running] [--demihull]
      [--test heave|pitch|both] [--fn 0.75 ...] [--sections 40] [--panels 14]

Outputs in --out: forced.md (the table and the score), forced.csv (one row per speed, link and measured point).
"""
import argparse
import math
import os
import sys
import time

import numpy as np
import pandas as pd

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import delft372_links as links  # noqa: E402

import hullopt  # noqa: E402

HEAVE_AMPLITUDE_M = 0.015                 # the tests' heave amplitude
PITCH_AMPLITUDE_RAD = math.radians(1.718)  # the tests' pitch amplitude
LCG_M = 1.41                               # oscillation axis assumed at the LCG (data/delft372/SOURCE.md)
TEST_LINKS = {"heave": ("A33", "B33", "A53", "B53"), "pitch": ("A55", "B55", "A35", "B35")}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("--out", required=True)
    ap.add_argument("--force", choices=("momentum", "pressure"), default="momentum")
    ap.add_argument("--amplitude-scale", type=float, default=1.0, help="times the tests' amplitudes (default 1)")
    ap.add_argument("--attitude", choices=("zero", "running"), default="zero")
    ap.add_argument("--demihull", action="store_true", help="one demihull alone, values x 2 (not the pair)")
    ap.add_argument("--test", choices=("heave", "pitch", "both"), default="both", help="which forced tests")
    ap.add_argument("--fn", type=float, action="append")
    ap.add_argument("--sections", type=int, default=40)
    ap.add_argument("--panels", type=int, default=14)
    a = ap.parse_args(argv)

    trim = links.RUNNING if a.attitude == "running" else links.ZERO
    speeds = (0.75,) if trim == links.RUNNING else tuple(sorted(a.fn)) if a.fn else links.SPEEDS
    attitude = links.running_attitude()[0] if trim == links.RUNNING else {"sinkage_m": 0.0, "trim_deg": 0.0}
    hull = hullopt.load_hull(links.TEMPLATE)
    mass = hullopt.MassProperties()
    mass.mass_kg, mass.lcg_m_from_ap, mass.kyy_m, mass.kg_m = 87.07, LCG_M, 0.782, 0.34
    measured = links.load_measured()
    centres = links.band_centres(measured, speeds=speeds)
    os.makedirs(a.out, exist_ok=True)
    computed, notes, t0 = {}, [], time.time()
    for Fn in speeds:
        U = Fn * math.sqrt(links.G * links.L_M)
        x_r = centres[Fn][0]
        computed[Fn] = {}
        for test, names in TEST_LINKS.items():
            if a.test not in ("both", test):
                continue
            d = measured[(measured.Fn == Fn) & (measured.trim_sinkage == trim) & (measured.link == names[0])]
            xs = sorted(x for x in d["x"] if links.in_band(x, x_r))
            values = {name: [] for name in names}
            for x in xs:
                omega_e = x * math.sqrt(links.G / links.L_M)
                amp = (HEAVE_AMPLITUDE_M if test == "heave" else PITCH_AMPLITUDE_RAD) * a.amplitude_scale
                r = hullopt.forced_oscillation(hull, mass, U, test, amp, omega_e, sectional_force=a.force,
                                               sections=a.sections, panels=a.panels, body=0 if a.demihull else -1,
                                               sinkage_m=attitude["sinkage_m"], trim_deg=attitude["trim_deg"],
                                               Cs=links.CS)
                for name in names:
                    values[name].append((2.0 if a.demihull else 1.0) * r[name])
                notes.append(f"Fn {Fn:.2f} {test} x {x:.3f}: strips {r['strips']}, second harmonic "
                             f"{r['second_harmonic_ratio'][0]:.3f} / {r['second_harmonic_ratio'][1]:.3f}")
                print(notes[-1], flush=True)
            for name in names:
                computed[Fn][name] = (np.array(xs), np.array(values[name]))
    runtime = time.time() - t0
    rows = links.compare_links(measured, computed, centres, trim)
    summary = links.summarise(rows)
    s, n = links.score(rows)
    desc = (f"strips on the instantaneous hull, {a.force} form, {a.sections} x {a.panels}, "
            f"{'one demihull alone x 2' if a.demihull else 'both demihulls'}, Cs {links.CS}, amplitudes "
            f"{1000 * HEAVE_AMPLITUDE_M * a.amplitude_scale:.2f} mm / "
            f"{math.degrees(PITCH_AMPLITUDE_RAD) * a.amplitude_scale:.3f} deg, "
            + ("zero trim and sinkage" if trim == links.ZERO else "running attitude of Fn 0.75"))
    label = ("score (B33, B55, B35, B53; near-resonance band; Cs 0.024)" if trim == links.ZERO and
             set(speeds) == set(links.SPEEDS) else "mean |rel error| of B33, B55, B35, B53 in the band(s)")
    out = ["# Delft 372 forced tests simulated as run", "", desc, "", links.markdown_table(summary), "",
           f"{label}: {s:.3f} ({n} points; {runtime:.0f} s)", "", "Second-harmonic ratios (force / moment):", ""]
    out += [f"- {line}" for line in notes]
    with open(os.path.join(a.out, "forced.md"), "w") as f:
        f.write("\n".join(out) + "\n")
    rows.to_csv(os.path.join(a.out, "forced.csv"), index=False)
    print("\n".join(out[:8]))


if __name__ == "__main__":
    main()
