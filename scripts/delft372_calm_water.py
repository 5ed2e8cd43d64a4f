#!/usr/bin/env python3
"""Delft 372: running sinkage and trim in calm water on the strips, beside the measured table.

For each Froude number of data/delft372/delft372_running_attitude.csv from 0.30 up, the catamaran's running
attitude is solved with hullopt.calm_water (seakeeping/motions/calm_water.h; docs/ship-motions.md, "Calm water
and the running attitude"): the steady force of the hull passing through strips fixed in space, both demihulls
in the strips, 40 sections x 14 panels, fresh water. The goal (fixed before the results were seen): within
3 mm and 0.3 deg of the measured at Fn >= 0.6; below Fn 0.5 the steady 2D+t is diagnostic only.

Usage:
  PYTHONPATH=build/python /usr/bin/python3 scripts/delft372_calm_water.py [--force momentum|pressure] [--demihull]
      [--elevation-plot FILE.svg]
Prints a markdown table: Fn, the tank's depth Froude number, computed and measured rise at the CG [mm, + up]
and trim [deg, + bow up], and the errors. --elevation-plot draws the steady elevation at the water line along
the hull (outer and inner side of a demihull) at Fn 0.45 and 0.75 at the computed running attitude.
"""
import argparse
import math
import os
import sys

import pandas as pd

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import delft372_links as links  # noqa: E402

import hullopt  # noqa: E402

TANK_DEPTH_M = 2.35   # Delft tank no. 1 (data/delft372/SOURCE.md)
GOAL_RISE_MM, GOAL_TRIM_DEG, GOAL_FROM_FN = 3.0, 0.3, 0.6


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--force", choices=("momentum", "pressure"), default="momentum")
    ap.add_argument("--demihull", action="store_true", help="one demihull alone in the strips")
    ap.add_argument("--sections", type=int, default=40)
    ap.add_argument("--panels", type=int, default=14)
    ap.add_argument("--elevation-plot", metavar="FILE", help="SVG of the steady elevation at Fn 0.45 and 0.75")
    a = ap.parse_args(argv)
    hull = hullopt.load_hull(links.TEMPLATE)
    mass = hullopt.MassProperties()
    mass.mass_kg, mass.lcg_m_from_ap, mass.kyy_m, mass.kg_m = 87.07, 1.41, 0.782, 0.34
    measured = pd.read_csv(os.path.join(links.DATA, "delft372_running_attitude.csv"))
    print(f"sectional force: {a.force}; {'one demihull' if a.demihull else 'both demihulls'}; "
          f"{a.sections} x {a.panels}\n")
    print("| Fn | Fn_h | rise computed [mm] | rise measured [mm] | error [mm] | trim computed [deg] | "
          "trim measured [deg] | error [deg] |")
    print("|---|---|---|---|---|---|---|---|")
    for _, row in measured.iterrows():
        Fn = row["Fn"]
        if Fn < 0.29:
            continue
        U = Fn * math.sqrt(links.G * links.L_M)
        r = hullopt.calm_water(hull, mass, U, sectional_force=a.force, sections=a.sections, panels=a.panels,
                               body=0 if a.demihull else -1, water={"rho_kg_m3": 1000.0, "g_m_s2": links.G})
        if not r["converged"]:
            print(f"| {Fn:.3f} | - | {r['note']} |")
            continue
        rise, trim = -1000.0 * r["sinkage_m"], r["trim_deg"]
        rise_m, trim_m = row["sinkage_at_CG_mm"], -row["trim_deg"]   # file: + up; - = bow up
        goal = Fn >= GOAL_FROM_FN
        mark = (lambda e, g: f"{e:+.2f}" + ("" if not goal else (" ok" if abs(e) <= g else " miss")))
        print(f"| {Fn:.3f} | {U / math.sqrt(links.G * TANK_DEPTH_M):.2f} | {rise:.2f} | {rise_m:.2f} | "
              f"{mark(rise - rise_m, GOAL_RISE_MM)} | {trim:.2f} | {trim_m:.2f} | {mark(trim - trim_m, GOAL_TRIM_DEG)} |")
    if a.elevation_plot:
        plot_elevation(a, hull, mass)


def plot_elevation(a, hull, mass):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(8, 4.2))
    for Fn, colour in ((0.45, "tab:blue"), (0.75, "tab:red")):
        U = Fn * math.sqrt(links.G * links.L_M)
        r = hullopt.calm_water(hull, mass, U, sectional_force=a.force, sections=a.sections, panels=a.panels,
                               body=0 if a.demihull else -1, elevation=True,
                               water={"rho_kg_m3": 1000.0, "g_m_s2": links.G})
        note = f" (rise {-1000 * r['sinkage_m']:.1f} mm, trim {r['trim_deg']:.2f} deg bow up)"
        ax.plot(r["x_m"], [1000 * e for e in r["elevation_outer_m"]], color=colour, label=f"Fn {Fn}, outer side" + note)
        if len(r["elevation_inner_m"]):
            ax.plot(r["x_m"], [1000 * e for e in r["elevation_inner_m"]], color=colour, ls="--",
                    label=f"Fn {Fn}, inner side")
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.set_xlabel("x from the transom [m] (bow at 2.85-3.0 m)")
    ax.set_ylabel("steady elevation at the hull [mm, + up]")
    ax.set_title(f"Delft 372, calm water on the strips ({a.force} form, {a.sections} x {a.panels})", fontsize=11)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(a.elevation_plot)
    print(f"\nwrote {a.elevation_plot}")


if __name__ == "__main__":
    main()
