#!/usr/bin/env python3
"""Oblique seas at low forward speed: hullopt's STF strip theory beside PDStrip on the same monohull.

The Delft 372 demihull alone as a monohull (data/delft372 offsets, 40 sections; 14 panels in hullopt, 15 offset
points per whole section in PDStrip, scripts/pdstrip_input.py), Fn 0.25, headings 120 and 150 deg (180 head
seas in both programs' conventions), 37 wavelengths lambda/L 0.5-3.0. Mass 43.535 kg, LCG 1.41 m, k_yy 0.782 m;
KG 0.10 m (above the base: the demihull alone needs a low centre of gravity to be stable in roll; GM about
0.05 m) and k_xx 0.084 m (0.35 B). Neither program has viscous roll damping here (PDStrip's nonlinear
resistance terms are off with steepness 0), so roll is potential-flow on both sides.

Amplitudes: heave |x3|/A, pitch and roll |x|/(kA), sway |x2|/A (PDStrip's "Translation" and "Rotation/k" rows,
hullopt's rao.csv). PDStrip gives the motions at its origin, which is put at the centre of gravity (x) so that
both heaves are the CG's. Phases are not compared: the programs' axes differ (PDStrip's results are forward,
starboard, down).

Usage:
  /usr/bin/python3 scripts/pdstrip_oblique_compare.py --pdstrip /path/to/pdstrip [--hullopt build/app/hullopt]
Prints, per heading, the amplitudes side by side and the rms difference relative to the larger peak.
"""
import argparse
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
L, T, FN = 3.0, 0.15, 0.25
MASS_KG, XG, ZG, KYY, KXX = 43.535, 1.41, 0.10, 0.782, 0.084
HEADINGS = (120.0, 150.0)


def parse_pdstrip(path):
    """{(wave angle, wave length): {mode: amplitude}} from pdstrip.out."""
    out, key = {}, None
    head = re.compile(r"wave length\s+([0-9.]+)\s+wave number\s+[0-9.]+\s+wave angle\s+([-0-9.]+)")
    with open(path) as f:
        for line in f:
            m = head.search(line)
            if m:
                key = (round(float(m.group(2)), 3), round(float(m.group(1)), 2))
                continue
            if key and line.startswith(" Translation"):
                v = line.split()[1:]
                out.setdefault(key, {}).update(surge=float(v[2]), sway=float(v[5]), heave=float(v[8]))
            elif key and line.startswith(" Rotation/k"):
                v = line.split()[1:]
                out.setdefault(key, {}).update(roll=float(v[2]), pitch=float(v[5]), yaw=float(v[8]))
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--pdstrip", required=True)
    ap.add_argument("--hullopt", default=os.path.join(ROOT, "build", "app", "hullopt"))
    a = ap.parse_args(argv)
    U = FN * math.sqrt(9.81 * L)
    lams = [0.5 + 2.5 * i / 36 for i in range(37)]
    with tempfile.TemporaryDirectory() as tmp:
        pd = os.path.join(tmp, "pd")
        subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "pdstrip_input.py"),
                        os.path.join(ROOT, "data", "delft372", "delft372_offsets.csv"), pd, "--draught", str(T),
                        "--sections", "40", "--points", "8", "--speed", f"{U:.6f}", "--mass-t", str(MASS_KG / 1000),
                        "--xg", str(XG), "--x-origin", str(XG), "--zg", str(ZG), "--kyy", str(KYY), "--kxx", str(KXX), "--rho", "1.0",
                        "--headings", *[f"{180 - h:g}" for h in HEADINGS],
                        "--wavelengths", *[f"{L * x:.6f}" for x in lams]], check=True)
        subprocess.run([os.path.abspath(a.pdstrip), "pdstrip.inp"], cwd=pd, check=True, capture_output=True)
        p = parse_pdstrip(os.path.join(pd, "pdstrip.out"))
        cfg = os.path.join(tmp, "h.yaml")
        with open(cfg, "w") as f:
            f.write(f"""hull:
  offsets_csv: {os.path.join(ROOT, 'data', 'delft372', 'delft372_offsets.csv')}
  draught_m: {T}
  length_m: {L}
mass: {{ mass_kg: {MASS_KG}, lcg_m_from_ap: {XG}, kyy_m: {KYY}, kg_m: {ZG}, kxx_m: {KXX} }}
water: {{ rho_kg_m3: 1000, g_m_s2: 9.81 }}
speed: {{ Fn: {FN} }}
solver:
  method: strip_theory_stf
  sections: 40
  panels: 14
  headings_deg: [{', '.join(f'{h:g}' for h in HEADINGS)}]
  roll_damping: none
  frequencies: {{ lambda_over_L: [{', '.join(f'{x:.6f}' for x in lams)}] }}
""")
        out = os.path.join(tmp, "h")
        subprocess.run([a.hullopt, "rao", cfg, "--out", out, "--quiet", "--no-plots"], check=True)
        with open(os.path.join(out, "rao.csv")) as f:
            rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    print(f"Delft 372 demihull as a monohull, Fn {FN}, 40 sections, KG {ZG} m, k_xx {KXX} m")
    for beta in HEADINGS:
        print(f"\n### heading {beta:g} deg\n")
        print("| λ/L | heave PDStrip | heave hullopt | pitch PDStrip | pitch hullopt | roll PDStrip | roll hullopt |")
        print("| --- | --- | --- | --- | --- | --- | --- |")
        series = {m: ([], [], []) for m in ("heave", "pitch", "roll")}
        for r in rows:
            if abs(float(r["wave_direction_deg"]) - beta) > 1e-6:
                continue
            lam = float(r["lambda_over_L"])
            q = p.get((beta, round(lam * L, 2)))
            if q is None:
                continue
            cells = [f"{lam:.3f}"]
            for m in ("heave", "pitch", "roll"):
                series[m][0].append(q[m]), series[m][1].append(float(r[f"{m}_amp"])), series[m][2].append(lam)
                cells += [f"{q[m]:.3f}", f"{float(r[m + '_amp']):.3f}"]
            print("| " + " | ".join(cells) + " |")
        for m, (ps, hs, ls) in series.items():
            if not ps:
                continue
            peak = max(max(ps), max(hs))
            rms = math.sqrt(sum((x - y) ** 2 for x, y in zip(ps, hs)) / len(ps)) / peak
            ip, ih = ps.index(max(ps)), hs.index(max(hs))
            print(f"- {m}: rms difference {100 * rms:.1f} % of the peak; peaks PDStrip {max(ps):.3f} at λ/L "
                  f"{ls[ip]:.2f}, hullopt {max(hs):.3f} at λ/L {ls[ih]:.2f}")


if __name__ == "__main__":
    main()
