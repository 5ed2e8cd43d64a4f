#!/usr/bin/python3
"""RAOs of all five modes over headings 90-180 deg at 1000 t and 40 kn, from `hullopt rao` with
solver.headings_deg, by the time-domain strip method (default) or, with --method strip_theory_stf, the
oblique-sea strip theory with the STF speed terms, for
- mona (default): the Table 1 monohull MONa (Davis & Holloway 2003, configs/davis-holloway-2003/hull14_MONa.yaml),
  roll with potential damping only: docs/figures/oblique_rao_mona_40kn.svg;
- dut372: the Delft 372 catamaran form of Table 1 at ship scale (the hull of configs/polar-dut372-40kn.yaml),
  roll with the viscous roll damping of solver.roll_damping: ikeda (for a catamaran the demihulls' Cs heave
  damping at their offsets, Cs 0.024): docs/figures/oblique_rao_dut372_40kn.svg.
Prints the peak of each mode per heading.
Usage: scripts/oblique_rao_figure.py [--hull mona|dut372] [--method time_domain_strip|strip_theory_stf]
       [HULLOPT_BINARY]   (from the repository root; default build/app/hullopt). The STF figure is written with
       the suffix _stf.
The mass blocks are assumed (Table 1 gives none): MONa KG 4.0 m (GM_T about 2 m); DUT372 KG 6.0 m; kyy 0.25 L,
kxx 0.35 × the overall beam (defaults).
"""
import csv
import os
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ARGS = sys.argv[1:]
HULL, METHOD = "mona", "time_domain_strip"
while len(ARGS) >= 2 and ARGS[0] in ("--hull", "--method"):
    if ARGS[0] == "--hull":
        HULL = ARGS[1]
    else:
        METHOD = ARGS[1]
    ARGS = ARGS[2:]
if HULL not in ("mona", "dut372"):
    sys.exit("oblique_rao_figure.py: --hull must be mona or dut372")
if METHOD not in ("time_domain_strip", "strip_theory_stf"):
    sys.exit("oblique_rao_figure.py: --method must be time_domain_strip or strip_theory_stf")
METHOD_TITLE = {"time_domain_strip": "time-domain strip method", "strip_theory_stf": "oblique-sea strip theory (STF)"}[METHOD]
BIN = ARGS[0] if ARGS else os.path.join(ROOT, "build", "app", "hullopt")
TITLE = {"mona": "MONa (Table 1 monohull), 1000 t, 40 kn (Fn 0.60): RAOs over headings, %s, "
                 "no viscous roll damping",
         "dut372": "DUT372 (Table 1 Delft 372 catamaran form), 1000 t, 40 kn (Fn 0.80): RAOs over headings, "
                   "%s, Cs 0.024"}[HULL] % METHOD_TITLE
ROLL_LABEL = {"mona": "roll |x4|/kA (potential damping only)",
              "dut372": "roll |x4|/kA (potential + demihulls' Cs damping)"}[HULL]
HEADINGS = [180, 165, 150, 135, 120, 105, 90]
MODES = [("heave_amp", "heave |x3|/A"), ("pitch_amp", "pitch |x5|/kA"), ("sway_amp", "sway |x2|/A"),
         ("roll_amp", ROLL_LABEL), ("yaw_amp", "yaw |x6|/kA")]
COLOURS = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#17becf"]


def config():
    if HULL == "dut372":
        hull = open(os.path.join(ROOT, "configs", "polar-dut372-40kn.yaml")).read()
        hull = "hull:" + hull.split("hull:", 1)[1].split("water:")[0]
        return hull + """water: { rho_kg_m3: 1025, g_m_s2: 9.81 }
speed: { kn: 40 }
mass: { kg_m: 6.0 }
solver:
  method: %s
  Cs: 0.024
  sections: 24
  panels: 8
  headings_deg: [%s]
  roll_damping: ikeda
  frequencies: { range: { quantity: lambda_over_L, from: 0.4, to: 4.0, count: 60 } }
""" % (METHOD, ", ".join(str(h) for h in HEADINGS))
    hull = open(os.path.join(ROOT, "configs", "davis-holloway-2003", "hull14_MONa.yaml")).read()
    hull = hull.split("water:")[0]  # the hull block; water and speed below
    return hull + """water: { rho_kg_m3: 1025, g_m_s2: 9.81 }
speed: { kn: 40 }
mass: { kg_m: 4.0 }
solver:
  method: %s
  headings_deg: [%s]
  roll_damping: none
  frequencies: { range: { quantity: lambda_over_L, from: 0.4, to: 4.0, count: 60 } }
""" % (METHOD, ", ".join(str(h) for h in HEADINGS))


def run():
    cfg = config()
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, HULL + ".yaml")
        open(path, "w").write(cfg)
        subprocess.run([BIN, "rao", path, "--out", os.path.join(tmp, "out"), "--quiet"], check=True)
        lines = [l for l in open(os.path.join(tmp, "out", "rao.csv")) if not l.startswith("#")]
        notes = [l[2:].strip() for l in open(os.path.join(tmp, "out", "rao.csv")) if l.startswith("# ")]
    return list(csv.DictReader(lines)), notes


def svg(rows, notes):
    w, h, pw, ph, left, top = 1180, 760, 330, 260, 60, 50
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="11">'
           % (w, h), '<rect width="100%" height="100%" fill="white"/>',
           '<text x="%d" y="22" font-size="14">%s</text>' % (left, TITLE)]
    for m, (key, label) in enumerate(MODES):
        x0 = left + (m % 3) * (pw + 40)
        y0 = top + (m // 3) * (ph + 70)
        ymax = max(float(r[key]) for r in rows) * 1.05 or 1.0
        xmin, xmax = 0.4, 4.0
        out.append('<rect x="%d" y="%d" width="%d" height="%d" fill="none" stroke="black"/>' % (x0, y0, pw, ph))
        out.append('<text x="%d" y="%d">%s</text>' % (x0, y0 - 6, label))
        for t in range(5):
            yv = ymax * t / 4
            yy = y0 + ph - ph * t / 4
            out.append('<text x="%d" y="%.1f" text-anchor="end">%.3g</text>' % (x0 - 4, yy + 4, yv))
        for xv in [0.5, 1, 1.5, 2, 2.5, 3, 3.5, 4]:
            xx = x0 + pw * (xv - xmin) / (xmax - xmin)
            out.append('<text x="%.1f" y="%d" text-anchor="middle">%g</text>' % (xx, y0 + ph + 14, xv))
        out.append('<text x="%d" y="%d" text-anchor="middle">wavelength / L</text>' % (x0 + pw / 2, y0 + ph + 28))
        for i, hd in enumerate(HEADINGS):
            pts = sorted((float(r["lambda_over_L"]), float(r[key])) for r in rows
                         if abs(float(r["wave_direction_deg"]) - hd) < 1e-9)
            path = " ".join("%.1f,%.1f" % (x0 + pw * (x - xmin) / (xmax - xmin), y0 + ph - ph * y / ymax)
                            for x, y in pts if xmin <= x <= xmax)
            out.append('<polyline fill="none" stroke="%s" stroke-width="1.5" points="%s"/>' % (COLOURS[i], path))
    lx, ly = left + 2 * (pw + 40), top + ph + 70
    for i, hd in enumerate(HEADINGS):
        out.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="%s" stroke-width="2"/>'
                   % (lx, ly + 18 * i, lx + 25, ly + 18 * i, COLOURS[i]))
        out.append('<text x="%d" y="%d">%d deg%s</text>' % (lx + 30, ly + 18 * i + 4, hd,
                                                          " (head seas)" if hd == 180 else " (beam seas)" if hd == 90 else ""))
    for i, n in enumerate(notes[-3:]):
        out.append('<text x="%d" y="%d" font-size="9">%s</text>' % (left, h - 40 + 12 * i,
                                                                  n.replace("&", "&amp;").replace("<", "&lt;")))
    out.append("</svg>")
    return "\n".join(out)


def main():
    rows, notes = run()
    suffix = "" if METHOD == "time_domain_strip" else "_stf"
    dst = os.path.join(ROOT, "docs", "figures", "oblique_rao_%s_40kn%s.svg" % (HULL, suffix))
    open(dst, "w").write(svg(rows, notes))
    print("wrote", os.path.relpath(dst, ROOT))
    for hd in HEADINGS:
        sel = [r for r in rows if abs(float(r["wave_direction_deg"]) - hd) < 1e-9]
        peaks = []
        for key, _ in MODES:
            best = max(sel, key=lambda r: float(r[key]))
            peaks.append("%s %.3g at lambda/L %.2f" % (key.split("_")[0], float(best[key]), float(best["lambda_over_L"])))
        print("%3d deg: %s" % (hd, "; ".join(peaks)))


if __name__ == "__main__":
    main()
