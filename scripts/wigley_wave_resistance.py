#!/usr/bin/env python3
"""The 2D+t wave resistance of the Wigley model C2 beside Michell's integral and Insel's (1990) measured C_T.

Insel's model C2-FX (data/insel1990/SOURCE.md): y = ±(B/2)(1 − (2x/L)²)(1 − (z/T)²), L = 1.8 m, L/B = 10,
B/T = 1.6, fixed in trim and sinkage (the attitude at rest both predictions assume), monohull and catamarans at
S/L 0.2-0.5, fresh water at 15 °C. For each measured Fn:
  C_T = C_F + C_W,   C_F the ITTC-1957 line at Re = U L / ν (ν 1.1386e-6 m²/s, 1 + k = 1, as the resistance
  command's default), C_W = R_W / (½ ρ S U²) on the static wetted surface (0.482 m² per hull, Table 1),
with R_W from the strips (hullopt.calm_water(..., wave_resistance=True): the power of the strips' dynamic
pressure, seakeeping/strip/strip_power.h) and from Michell's thin-ship integral (hullopt resistance). Nothing is
fitted. 2D+t is a high-speed theory: the strip assumption needs the hull's own wave longer than the hull,
roughly Fn >= 0.5.

Usage:
  PYTHONPATH=build/python /usr/bin/python3 scripts/wigley_wave_resistance.py [--sections 40] [--panels 14]
      [--hullopt build/app/hullopt]
Prints a markdown table per configuration and the mean |ΔC_T|/C_T over Fn >= 0.5 for each method.
"""
import argparse
import csv
import math
import os
import subprocess
import tempfile

import hullopt

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
L, B, T = 1.8, 0.18, 0.1125
S_HULL = 0.482          # m², per hull (Insel Table 1)
RHO, G, NU = 1000.0, 9.81, 1.1386e-6


def read(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def write_offsets(path, stations=41, depths=16):
    """The Wigley offsets (x from the AP, half-breadth y, z above the base), a deck 0.05 m above the water line."""
    with open(path, "w") as f:
        f.write("x_m,y_m,z_m\n")
        for i in range(stations):
            x = L * i / (stations - 1)
            xi = 2.0 * x / L - 1.0
            for k in range(depths + 1):
                z = T * k / depths
                d = T - z
                y = 0.5 * B * (1.0 - xi * xi) * (1.0 - (d / T) ** 2)
                f.write(f"{x:.6f},{y:.8f},{z:.6f}\n")
            f.write(f"{x:.6f},{0.5 * B * (1.0 - xi * xi):.8f},{T + 0.05:.6f}\n")


def c_f(U):
    return 0.075 / (math.log10(U * L / NU) - 2.0) ** 2


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sections", type=int, default=40)
    ap.add_argument("--panels", type=int, default=14)
    ap.add_argument("--hullopt", default=os.path.join(ROOT, "build", "app", "hullopt"))
    a = ap.parse_args(argv)
    data = os.path.join(ROOT, "data", "insel1990")
    cases = [("monohull", None, read(os.path.join(data, "wigley_c2fx_monohull_ct.csv")))]
    cat = read(os.path.join(data, "wigley_c2fx_catamaran_ct.csv"))
    for s in ("0.2", "0.3", "0.4", "0.5"):
        cases.append((f"catamaran S/L {s}", float(s), [r for r in cat if abs(float(r["S_over_L"]) - float(s)) < 1e-9]))
    with tempfile.TemporaryDirectory() as tmp:
        offsets = os.path.join(tmp, "wigley.csv")
        write_offsets(offsets)
        summary = []
        for name, s_over_l, rows in cases:
            hulls = 1 if s_over_l is None else 2
            cfg = os.path.join(tmp, "hull.yaml")
            with open(cfg, "w") as f:
                f.write(f"hull:\n  offsets_csv: {offsets}\n  draught_m: {T}\n  length_m: {L}\n")
                if hulls == 2:
                    f.write(f"  hulls: 2\n  spacing_m: {s_over_l * L}\n")
                f.write(f"water: {{ rho_kg_m3: {RHO}, g_m_s2: {G} }}\n")
            h = hullopt.load_hull(cfg)
            mass = hullopt.mass_properties(h, water={"rho_kg_m3": RHO, "g_m_s2": G})  # floats at rest
            S = hulls * S_HULL
            fns = [float(r["Fn"]) for r in rows]
            # Michell from the resistance command at the same speeds (its R_W_kN column).
            rcfg = os.path.join(tmp, "res.yaml")
            speeds = ", ".join(f"{fn:.4f}" for fn in fns)
            with open(rcfg, "w") as f:
                f.write(open(cfg).read())
                f.write(f"resistance:\n  speeds_Fn: [{speeds}]\n")
            out = os.path.join(tmp, "res_" + str(hulls) + str(s_over_l))
            subprocess.run([a.hullopt, "resistance", rcfg, "--out", out, "--quiet"], check=True,
                           capture_output=True)
            michell = [float(r["R_W_kN"]) * 1e3 for r in read(os.path.join(out, "resistance.csv"))]
            print(f"\n### {name} (strips {a.sections} x {a.panels})\n")
            print("| Fn | C_T measured × 10³ | C_F × 10³ | C_W 2D+t × 10³ | C_T 2D+t | error | C_W Michell × 10³ "
                  "| C_T Michell | error |")
            print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
            errs_t, errs_m = [], []
            for r, fn, rm in zip(rows, fns, michell):
                U = fn * math.sqrt(G * L)
                q = 0.5 * RHO * S * U * U
                w = hullopt.calm_water(h, mass, U, sections=a.sections, panels=a.panels, attitude=(0.0, 0.0),
                                       wave_resistance=True, water={"rho_kg_m3": RHO, "g_m_s2": G})
                ct, cf = float(r["C_T"]), c_f(U)
                cw_t, cw_m = w["wave_resistance_N"] / q, rm / q
                et, em = (cf + cw_t) / ct - 1.0, (cf + cw_m) / ct - 1.0
                if fn >= 0.5:
                    errs_t.append(abs(et)), errs_m.append(abs(em))
                print(f"| {fn:.3f} | {1e3 * ct:.2f} | {1e3 * cf:.2f} | {1e3 * cw_t:.2f} | {1e3 * (cf + cw_t):.2f} | "
                      f"{100 * et:+.1f} % | {1e3 * cw_m:.2f} | {1e3 * (cf + cw_m):.2f} | {100 * em:+.1f} % |")
            if errs_t:
                summary.append((name, len(errs_t), sum(errs_t) / len(errs_t), max(errs_t), sum(errs_m) / len(errs_m),
                                max(errs_m)))
    print("\n### Mean and largest |ΔC_T|/C_T at Fn >= 0.5\n")
    print("| configuration | points | 2D+t mean | 2D+t largest | Michell mean | Michell largest |")
    print("| --- | --- | --- | --- | --- | --- |")
    for s in summary:
        print(f"| {s[0]} | {s[1]} | {100 * s[2]:.1f} % | {100 * s[3]:.1f} % | {100 * s[4]:.1f} % | {100 * s[5]:.1f} % |")


if __name__ == "__main__":
    main()
