#!/usr/bin/env python3
"""Delft 372 at Fn 0.75: computed heave and pitch RAOs, amplitude and phase, beside the tank at each measured λ/L.

Runs `hullopt rao` on the catamaran of data/delft372 (both demihulls in the strips, 40 sections x 14 panels, the
time-domain strip method, Cs fixed in advance at 0.024, the paper's value for this hull) at the tank's own λ/L
values (no adaptive grid, no interpolation), for each sectional force form (momentum, pressure) and with the
strips on the hull at rest (steady_flow off) or at the solved running attitude (steady_flow on).

Both the tank file and rao.csv give phases as leads over the wave crest at the CG in degrees, heave positive up;
pitch in rao.csv is positive bow-down and the tank's pitch phases follow the same convention (at λ/L 2.0 both are
near 180 deg, the long-wave limit of a bow-down pitch lagging the slope is -90 deg, reached only above λ/L 3).
The phase error is wrapped into (-180, 180].

Usage:
  /usr/bin/python3 scripts/delft372_rao_phases.py [--hullopt build/app/hullopt] [--Cs 0.024]
Prints one markdown table per configuration and a summary table (rms amplitude error relative to the tank's peak,
rms and largest phase error).
"""
import argparse
import csv
import math
import os
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, "data", "delft372")

CONFIG = """hull:
  offsets_csv: {data}/delft372_offsets.csv
  draught_m: 0.15
  hulls: 2
  spacing_m: 0.70
  length_m: 3.0
mass: {{ mass_kg: 87.07, lcg_m_from_ap: 1.41, kyy_m: 0.782, kg_m: 0.34 }}
water: {{ rho_kg_m3: 1000, g_m_s2: 9.81 }}
speed: {{ Fn: 0.75 }}
solver:
  sections: 40
  panels: 14
  Cs: {cs}
  sectional_force: {force}
  steady_flow: {steady}
  adaptive_grid: off
  frequencies: {{ lambda_over_L: [{lams}] }}
"""


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def wrap(deg):
    d = (deg + 180.0) % 360.0 - 180.0
    return 180.0 if d == -180.0 else d


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--hullopt", default=os.path.join(ROOT, "build", "app", "hullopt"))
    ap.add_argument("--Cs", type=float, default=0.024)
    a = ap.parse_args(argv)
    tank = read_csv(os.path.join(DATA, "delft372_tank_rao_fn075.csv"))
    lams = sorted({float(r["lambda_over_L"]) for r in tank})
    peak = {"heave": max(float(r["heave_rao"]) for r in tank), "pitch": max(float(r["pitch_rao"]) for r in tank)}
    summary = []
    with tempfile.TemporaryDirectory() as tmp:
        for force in ("momentum", "pressure"):
            for steady in ("off", "on"):
                cfg = os.path.join(tmp, f"{force}_{steady}.yaml")
                with open(cfg, "w") as f:
                    f.write(CONFIG.format(data=DATA, cs=a.Cs, force=force, steady=steady,
                                          lams=", ".join(f"{x:.3f}" for x in lams)))
                out = os.path.join(tmp, f"{force}_{steady}")
                subprocess.run([a.hullopt, "rao", cfg, "--out", out, "--quiet", "--no-plots"], check=True)
                calc = {round(float(r["lambda_over_L"]), 3): r for r in read_csv(os.path.join(out, "rao.csv"))}
                print(f"\n### sectional_force {force}, steady_flow {steady}, Cs {a.Cs}\n")
                print("| λ/L | heave tank | heave calc | heave phase tank | calc | pitch tank | pitch calc "
                      "| pitch phase tank | calc |")
                print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
                err = {"heave": [], "pitch": [], "heave_ph": [], "pitch_ph": []}
                for r in tank:
                    c = calc[round(float(r["lambda_over_L"]), 3)]
                    cells = [r["lambda_over_L"]]
                    for m in ("heave", "pitch"):
                        ta, ca = float(r[f"{m}_rao"]), float(c[f"{m}_amp"])
                        tp, cp = float(r[f"{m}_phase_deg"]), float(c[f"{m}_phase_deg"])
                        err[m].append((ca - ta) / peak[m])
                        err[m + "_ph"].append(wrap(cp - tp))
                        cells += [f"{ta:.3f}", f"{ca:.3f}", f"{tp:.1f}", f"{cp:.1f}"]
                    print("| " + " | ".join(cells) + " |")

                def rms(v):
                    return math.sqrt(sum(x * x for x in v) / len(v))
                summary.append((force, steady, rms(err["heave"]), rms(err["heave_ph"]),
                                max(err["heave_ph"], key=abs), rms(err["pitch"]), rms(err["pitch_ph"]),
                                max(err["pitch_ph"], key=abs)))
    print(f"\n### Summary over the {len(tank)} tank runs (amplitude error relative to the tank's peak)\n")
    print("| force form | steady_flow | heave amp rms | heave phase rms [deg] | largest [deg] | pitch amp rms "
          "| pitch phase rms [deg] | largest [deg] |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- |")
    for s in summary:
        print(f"| {s[0]} | {s[1]} | {100 * s[2]:.1f} % | {s[3]:.1f} | {s[4]:+.1f} | {100 * s[5]:.1f} % | "
              f"{s[6]:.1f} | {s[7]:+.1f} |")


if __name__ == "__main__":
    main()
