#!/usr/bin/env python3
"""Delft 372 link by link: the computed heave-pitch added mass and damping against the forced-oscillation tests.

For each Froude number of the forced tests (0.30, 0.45, 0.60, 0.75) the script writes a `hullopt coefficients`
config from examples/coefficients_delft372.yaml (Cs 0.024, frequencies covering that speed's measured
omega_e sqrt(L/g) range), runs it, and compares A33, B33, A55, B55, A35, B35, A53, B53 with the measured points
of data/delft372 (whole catamaran) inside a near-resonance band (docs/coefficients.md, "Link by link against the
forced tests"):

- band: omega sqrt(L/g) within +-15 % of omega_r sqrt(L/g). At Fn 0.75 omega_r is the encounter frequency of the
  largest measured heave RAO (delft372_tank_rao_fn075.csv: lambda/L -> omega = sqrt(2 pi g / lambda),
  omega_e = omega + omega^2 U / g, U = Fn sqrt(g L), L = 3 m, g = 9.81). At Fn 0.30, 0.45, 0.60 (no RAOs measured)
  it is the undamped heave natural frequency omega_r^2 (M + A33(omega_r)) = C33, M = 87.07 kg, C33 = 10782 N/m,
  A33 measured, interpolated linearly in omega sqrt(L/g) (bisection).
- per speed and link: the computed value interpolated linearly in omega sqrt(L/g) to each measured point in the
  band, relative error (computed - measured) / |measured|, its signed mean and mean absolute value; for the
  couplings a sign check at the points where |measured| > 10 % of the link's largest |measured| at that speed.
- score: the mean absolute relative error of B33, B55, B35 and B53 over all measured points in the bands of all
  four speeds (each point once), Cs 0.024, zero-attitude rows.

Usage:
  python3 scripts/delft372_links.py --out out/links [--hullopt build/app/hullopt] [--solver KEY=VALUE ...]
                                    [--attitude running] [--demihull] [--threads N]

Outputs in --out: links.md (the table), links.csv (one row per speed, link and measured point), links.svg
(computed curves and measured points, 8 links x 4 speeds), runs/<tag>/ (each hullopt run: config.yaml,
coefficients.csv, coefficients.svg).
"""
import argparse
import math
import os
import shutil
import subprocess
import sys
import time

import numpy as np
import pandas as pd
import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, "data", "delft372")
TEMPLATE = os.path.join(ROOT, "examples", "coefficients_delft372.yaml")

L_M = 3.0                 # length between perpendiculars of the model [m]
G = 9.81                  # [m/s^2]
M_MOTION_KG = 87.07       # displacement in the motion tests [kg]
C33_REPORT_N_PER_M = 10782.0
BAND_HALF_WIDTH = 0.15    # the band: |x - x_r| <= 0.15 x_r, x = omega sqrt(L/g)
CLEARLY_NONZERO = 0.10    # sign check where |measured| > 10 % of the link's largest |measured| at that speed
CS = 0.024
SPEEDS = (0.30, 0.45, 0.60, 0.75)
LINKS = ("A33", "B33", "A55", "B55", "A35", "B35", "A53", "B53")
COUPLINGS = ("A35", "B35", "A53", "B53")
SCORED = ("B33", "B55", "B35", "B53")
# Column of each link in the measured files (heave test: A33, B33, A53, B53; pitch test: A55, B55, A35, B35)
# and in hullopt's coefficients.csv (the same names: docs/coefficients.md, "Conventions of the measured data").
MEASURED_COLUMNS = {
    "heave": {"A33": "A33_kg", "B33": "B33_kg_per_s", "A53": "A53_kg_m", "B53": "B53_kg_m_per_s"},
    "pitch": {"A55": "A55_kg_m2", "B55": "B55_kg_m2_per_s", "A35": "A35_kg_m", "B35": "B35_kg_m_per_s"},
}
COMPUTED_COLUMNS = {"A33": "A33_kg", "B33": "B33_kg_per_s", "A55": "A55_kg_m2", "B55": "B55_kg_m2_per_s",
                    "A35": "A35_kg_m", "B35": "B35_kg_m_per_s", "A53": "A53_kg_m", "B53": "B53_kg_m_per_s"}
UNITS = {"A33": "kg", "B33": "kg/s", "A55": "kg m²", "B55": "kg m²/s", "A35": "kg m", "B35": "kg m/s",
         "A53": "kg m", "B53": "kg m/s"}
ZERO = "zero"
RUNNING = "Fn0.75_trim_sinkage"


# ----------------------------------------------------------------------------------------------------------------
# Measured data and the bands (no hullopt needed; tests/verification/test_delft372_links.py).

def load_measured(data_dir=DATA):
    """The forced-oscillation points in long form: Fn, trim_sinkage, test, link, x (omega sqrt(L/g)), measured."""
    rows = []
    for test, name in (("heave", "delft372_forced_heave_coefficients.csv"),
                       ("pitch", "delft372_forced_pitch_coefficients.csv")):
        d = pd.read_csv(os.path.join(data_dir, name))
        for link, col in MEASURED_COLUMNS[test].items():
            for _, r in d.iterrows():
                rows.append({"Fn": round(float(r["Fn"]), 2), "trim_sinkage": r["trim_sinkage"], "test": test,
                             "link": link, "x": float(r["omega_nondim_sqrtLg"]), "measured": float(r[col]),
                             "source_table": r["source_table"]})
    return pd.DataFrame(rows).sort_values(["Fn", "trim_sinkage", "link", "x"]).reset_index(drop=True)


def rao_peak_band_centre(rao_csv=os.path.join(DATA, "delft372_tank_rao_fn075.csv"), Fn=0.75, L=L_M, g=G):
    """x_r = omega_e sqrt(L/g) of the largest measured heave RAO (head seas); returns (x_r, description)."""
    r = pd.read_csv(rao_csv)
    i = int(r["heave_rao"].values.argmax())
    lam = float(r["lambda_over_L"].iloc[i]) * L
    omega = math.sqrt(2.0 * math.pi * g / lam)
    U = Fn * math.sqrt(g * L)
    omega_e = omega + omega * omega * U / g
    x = omega_e * math.sqrt(L / g)
    how = (f"measured heave RAO peak {float(r['heave_rao'].iloc[i]):.3f} at lambda/L {float(r['lambda_over_L'].iloc[i]):.3f} "
           f"(row {i + 1} of {os.path.basename(rao_csv)}): omega {omega:.4f} rad/s, omega_e {omega_e:.4f} rad/s")
    return x, how


def heave_natural_frequency(measured, Fn, trim=ZERO, M=M_MOTION_KG, C33=C33_REPORT_N_PER_M, L=L_M, g=G):
    """x_r with x_r^2 (g/L) (M + A33(x_r)) = C33, A33 measured, linear in x; bisection on the measured range.

    Returns (x_r, description naming the two measured rows that bracket x_r)."""
    d = measured[(measured.Fn == round(Fn, 2)) & (measured.trim_sinkage == trim) & (measured.link == "A33")]
    x, a = d["x"].to_numpy(), d["measured"].to_numpy()
    f = lambda X: X * X * g / L * (M + np.interp(X, x, a)) - C33
    lo, hi = x[0], x[-1]
    if f(lo) * f(hi) > 0:
        raise ValueError(f"Fn {Fn}: no heave natural frequency inside the measured A33 range {lo}-{hi}")
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if f(lo) * f(mid) <= 0:
            hi = mid
        else:
            lo = mid
    xr = 0.5 * (lo + hi)
    j = int(np.searchsorted(x, xr))
    j = min(max(j, 1), len(x) - 1)
    a_r = float(np.interp(xr, x, a))
    how = (f"undamped heave natural frequency, A33 {a_r:.2f} kg interpolated between the measured rows "
           f"x = {x[j - 1]:.3f} (A33 {a[j - 1]:.3f}) and x = {x[j]:.3f} (A33 {a[j]:.3f}), M {M} kg, C33 {C33} N/m")
    return xr, how


def band_centres(measured, data_dir=DATA, speeds=SPEEDS):
    """{Fn: (x_r, description)}: the RAO peak at Fn 0.75, the heave natural frequency at the others (zero rows)."""
    out = {}
    for Fn in speeds:
        if abs(Fn - 0.75) < 1e-9:
            out[Fn] = rao_peak_band_centre(os.path.join(data_dir, "delft372_tank_rao_fn075.csv"), Fn)
        else:
            out[Fn] = heave_natural_frequency(measured, Fn)
    return out


def in_band(x, x_r, half=BAND_HALF_WIDTH):
    return np.abs(np.asarray(x) - x_r) <= half * x_r


def compare_links(measured, computed, centres, trim=ZERO, extra=None):
    """One row per (Fn, link, measured point) of the measured rows `trim` at the speeds of `computed`.

    computed: {Fn: {link: (x array, value array)}} (x = omega_e sqrt(L/g), increasing); extra: the same for a
    second, unscored computation (demihull alone x 2), reported in column computed_extra. Points outside the
    computed range get NaN. Columns: Fn, link, omega_nondim, measured, computed, rel_error, in_band, clear
    (|measured| > 10 % of the link's largest |measured| at that speed), sign_ok (couplings, clear points)."""
    rows = []
    for Fn, curves in sorted(computed.items()):
        x_r = centres[Fn][0]
        for link in LINKS:
            d = measured[(measured.Fn == round(Fn, 2)) & (measured.trim_sinkage == trim) & (measured.link == link)]
            if d.empty or link not in curves:
                continue
            biggest = float(np.abs(d["measured"]).max())
            xc, yc = (np.asarray(v, dtype=float) for v in curves[link])
            for x, m in zip(d["x"], d["measured"]):
                c = float(np.interp(x, xc, yc)) if xc[0] <= x <= xc[-1] else float("nan")
                row = {"Fn": Fn, "link": link, "omega_nondim": x, "measured": m, "computed": c,
                       "rel_error": (c - m) / abs(m), "in_band": bool(in_band(x, x_r)),
                       "clear": abs(m) > CLEARLY_NONZERO * biggest}
                row["sign_ok"] = (bool(np.sign(c) == np.sign(m)) if link in COUPLINGS and row["clear"] else None)
                if extra is not None:
                    xe, ye = (np.asarray(v, dtype=float) for v in extra[Fn][link])
                    ce = float(np.interp(x, xe, ye)) if xe[0] <= x <= xe[-1] else float("nan")
                    row["computed_extra"] = ce
                    row["rel_error_extra"] = (ce - m) / abs(m)
                rows.append(row)
    return pd.DataFrame(rows)


def summarise(rows):
    """Per (Fn, link) over the in-band points: n, mean signed and mean absolute relative error, sign check."""
    out = []
    b = rows[rows.in_band]
    for (Fn, link), d in b.groupby(["Fn", "link"], sort=True):
        r = {"Fn": Fn, "link": link, "n": len(d), "mean_rel": float(d.rel_error.mean()),
             "mean_abs_rel": float(d.rel_error.abs().mean())}
        if link in COUPLINGS:
            s = d[d.clear]
            r["sign_checked"] = len(s)
            r["sign_agree"] = int(s.sign_ok.astype(bool).sum())
        if "rel_error_extra" in d:
            r["mean_rel_extra"] = float(d.rel_error_extra.mean())
            r["mean_abs_rel_extra"] = float(d.rel_error_extra.abs().mean())
        out.append(r)
    return pd.DataFrame(out)


def score(rows, links=SCORED):
    """Mean |relative error| of `links` over all in-band points (each point once); and the number of points."""
    d = rows[rows.in_band & rows.link.isin(links)]
    if d.rel_error.isna().any():
        raise ValueError("a measured point in the band lies outside the computed frequency range")
    return float(d.rel_error.abs().mean()), len(d)


# ----------------------------------------------------------------------------------------------------------------
# Tables and plot.

def _pct(v):
    return "—" if v is None or (isinstance(v, float) and math.isnan(v)) else f"{100 * v:+.0f}"


def markdown_table(summary, extra_label=None):
    """Speed x link: signed mean / mean |rel error| in % (points in the band); couplings: sign agreement."""
    head = "| Fn | " + " | ".join(LINKS) + " |"
    lines = [head, "| --- |" + " --- |" * len(LINKS)]
    for Fn in sorted(summary.Fn.unique()):
        cells = []
        for link in LINKS:
            s = summary[(summary.Fn == Fn) & (summary.link == link)]
            if s.empty:
                cells.append("—")
                continue
            s = s.iloc[0]
            c = f"{_pct(s.mean_rel)} / {100 * s.mean_abs_rel:.0f} ({int(s.n)})"
            if link in COUPLINGS:
                k, a = int(s.sign_checked), int(s.sign_agree)
                c += f", sign {'ok' if a == k else 'WRONG'} {a}/{k}" if k else ", sign —"
            cells.append(c)
        lines.append(f"| {Fn:.2f} | " + " | ".join(cells) + " |")
    if extra_label and "mean_rel_extra" in summary:
        lines += ["", f"{extra_label} (not scored): signed mean / mean |rel error| in %, same points", "",
                  head, "| --- |" + " --- |" * len(LINKS)]
        for Fn in sorted(summary.Fn.unique()):
            cells = []
            for link in LINKS:
                s = summary[(summary.Fn == Fn) & (summary.link == link)]
                cells.append("—" if s.empty else
                             f"{_pct(s.iloc[0].mean_rel_extra)} / {100 * s.iloc[0].mean_abs_rel_extra:.0f}")
            lines.append(f"| {Fn:.2f} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def plot(path, measured, computed, centres, trim, extra=None, extra_label=None, title=""):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    speeds = sorted(computed)
    fig, axes = plt.subplots(len(LINKS), len(speeds), figsize=(3.6 * len(speeds), 2.3 * len(LINKS)),
                             squeeze=False, sharex="col")
    for j, Fn in enumerate(speeds):
        x_r = centres[Fn][0]
        for i, link in enumerate(LINKS):
            ax = axes[i][j]
            ax.axvspan((1 - BAND_HALF_WIDTH) * x_r, (1 + BAND_HALF_WIDTH) * x_r, color="0.9", lw=0)
            ax.axvline(x_r, color="0.6", lw=0.8)
            ax.axhline(0.0, color="0.8", lw=0.6)
            xc, yc = computed[Fn][link]
            ax.plot(xc, yc, "C0-", lw=1.2, label="computed (pair)")
            if extra is not None:
                xe, ye = extra[Fn][link]
                ax.plot(xe, ye, "C2--", lw=1.0, label=extra_label)
            d = measured[(measured.Fn == round(Fn, 2)) & (measured.trim_sinkage == trim) & (measured.link == link)]
            band = in_band(d["x"], x_r)
            ax.plot(d["x"][band], d["measured"][band], "o", color="C3", ms=4, label="measured, in band")
            ax.plot(d["x"][~band], d["measured"][~band], "o", mfc="none", color="C3", ms=4,
                    label="measured, outside")
            if i == 0:
                ax.set_title(f"Fn {Fn:.2f}" + ("" if trim == ZERO else " (running attitude)"), fontsize=10)
            if j == 0:
                ax.set_ylabel(f"{link} [{UNITS[link]}]", fontsize=9)
            if i == len(LINKS) - 1:
                ax.set_xlabel("ω_e √(L/g)", fontsize=9)
            ax.tick_params(labelsize=8)
    axes[0][0].legend(fontsize=7, loc="best")
    fig.suptitle(title, fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.985))
    fig.savefig(path)
    plt.close(fig)


# ----------------------------------------------------------------------------------------------------------------
# hullopt runs.

def set_dotted(d, key, value):
    parts = key.split(".")
    for p in parts[:-1]:
        d = d.setdefault(p, {})
    d[parts[-1]] = value


def running_attitude(data_dir=DATA, Fn=0.75):
    """hull.attitude of the row nearest Fn: sinkage_m + down (file: mm, + up), trim_deg + bow up (file: − bow up)."""
    r = pd.read_csv(os.path.join(data_dir, "delft372_running_attitude.csv"))
    i = int((r["Fn"] - Fn).abs().values.argmin())
    return ({"sinkage_m": -float(r["sinkage_at_CG_mm"].iloc[i]) / 1000.0, "trim_deg": -float(r["trim_deg"].iloc[i])},
            float(r["Fn"].iloc[i]))


def make_config(Fn, x_lo, x_hi, count, solver, attitude=None, demihull=False, trim=ZERO):
    with open(TEMPLATE) as f:
        c = yaml.safe_load(f)
    base = os.path.dirname(TEMPLATE)
    c["hull"]["offsets_csv"] = os.path.normpath(os.path.join(base, c["hull"]["offsets_csv"]))
    for k in ("forced_heave_csv", "forced_pitch_csv", "wave_loads_csv"):
        c["compare"][k] = os.path.normpath(os.path.join(base, c["compare"][k]))
    c["compare"]["trim_sinkage"] = trim
    c["speed"] = {"Fn": Fn}
    c["solver"]["Cs"] = CS
    k = math.sqrt(G / L_M)
    c["solver"]["frequencies"] = {"range": {"quantity": "omega_e_rad_s", "from": round(x_lo * k, 6),
                                            "to": round(x_hi * k, 6), "count": count}}
    for key, value in solver.items():
        set_dotted(c["solver"], key, value)
    if attitude:
        c["hull"]["attitude"] = dict(attitude)
    if demihull:
        c["hull"]["hulls"] = 1
        c["hull"].pop("spacing_m", None)
        c["mass"]["mass_kg"] = c["mass"]["mass_kg"] / 2.0
    return c


def read_curves(csv_path, factor=1.0):
    t = pd.read_csv(csv_path, comment="#")
    t = t.sort_values("omega_e_sqrt_L_over_g")
    x = t["omega_e_sqrt_L_over_g"].to_numpy()
    return {link: (x, factor * t[col].to_numpy()) for link, col in COMPUTED_COLUMNS.items()}


def run_hullopt(binary, config, run_dir, threads):
    os.makedirs(run_dir, exist_ok=True)
    stale = os.path.join(run_dir, "config.resolved.yaml")
    if os.path.exists(stale):  # this script's own run folder: let the new config replace the old results
        os.remove(stale)
    cfg = os.path.join(run_dir, "config.yaml")
    with open(cfg, "w") as f:
        f.write("# written by scripts/delft372_links.py\n")
        yaml.safe_dump(config, f, sort_keys=False)
    env = dict(os.environ)
    env["OMP_NUM_THREADS"] = str(threads)
    t0 = time.time()
    p = subprocess.run([binary, "coefficients", cfg, "--out", run_dir], env=env, capture_output=True, text=True)
    if p.returncode != 0:
        sys.stderr.write(p.stdout + p.stderr)
        raise SystemExit(f"hullopt coefficients failed for {cfg} (exit {p.returncode})")
    for line in p.stderr.splitlines():
        if "warning" in line:
            print(f"  {line}")
    return os.path.join(run_dir, "coefficients.csv"), time.time() - t0


def parse_solver(items):
    out = {}
    for it in items or []:
        if "=" not in it:
            raise SystemExit(f"--solver {it}: expected KEY=VALUE")
        k, v = it.split("=", 1)
        if k.split(".")[0] in ("Cs", "frequencies"):
            raise SystemExit(f"--solver {k}: fixed by the comparison (Cs {CS}, frequencies from the measured range)")
        out[k] = yaml.safe_load(v)
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("--out", required=True, help="output folder (links.md, links.csv, links.svg, runs/)")
    ap.add_argument("--hullopt", default="build/app/hullopt",
                    help="the hullopt binary (default build/app/hullopt, relative to the repository)")
    ap.add_argument("--solver", action="append", metavar="KEY=VALUE",
                    help="dotted key into the config's solver block, repeatable, e.g. sectional_force=pressure")
    ap.add_argument("--attitude", choices=("zero", "running"), default="zero",
                    help="running: Fn 0.75 only, hull at the measured running sinkage and trim, against the "
                         "Fn0.75_trim_sinkage rows")
    ap.add_argument("--demihull", action="store_true",
                    help="also compute one demihull alone (hulls: 1, half the mass) and report 2 x its values "
                         "beside the pair (not scored)")
    ap.add_argument("--threads", type=int, default=1, help="OMP_NUM_THREADS of each hullopt run (default 1)")
    ap.add_argument("--step", type=float, default=0.1, help="frequency step in omega_e sqrt(L/g) (default 0.1)")
    ap.add_argument("--fn", type=float, action="append", help="only these Froude numbers (no score then)")
    a = ap.parse_args(argv)

    binary = a.hullopt if os.path.isabs(a.hullopt) else os.path.join(ROOT, a.hullopt)
    if not os.path.exists(binary):
        binary = os.path.abspath(a.hullopt)
    if not os.path.exists(binary):
        raise SystemExit(f"hullopt binary not found: {a.hullopt} (give --hullopt PATH)")
    solver = parse_solver(a.solver)
    trim = RUNNING if a.attitude == "running" else ZERO
    speeds = (0.75,) if a.attitude == "running" else tuple(sorted(a.fn)) if a.fn else SPEEDS
    for Fn in speeds:
        if Fn not in SPEEDS:
            raise SystemExit(f"--fn {Fn}: the forced tests are at Fn {', '.join(map(str, SPEEDS))}")
    attitude, attitude_fn = running_attitude() if trim == RUNNING else (None, None)

    measured = load_measured()
    centres = band_centres(measured, speeds=speeds)
    os.makedirs(a.out, exist_ok=True)
    t_start = time.time()
    computed, extra = {}, ({} if a.demihull else None)
    for Fn in speeds:
        d = measured[(measured.Fn == Fn) & (measured.trim_sinkage == trim)]
        x_lo = max(0.5, d["x"].min() - 0.1)
        x_hi = d["x"].max() + 0.1
        count = int(math.ceil((x_hi - x_lo) / a.step)) + 1
        tag = f"fn{int(round(Fn * 100)):03d}" + ("_running" if trim == RUNNING else "")
        cfg = make_config(Fn, x_lo, x_hi, count, solver, attitude, False, trim)
        csv, dt = run_hullopt(binary, cfg, os.path.join(a.out, "runs", tag), a.threads)
        print(f"Fn {Fn:.2f}: pair, {count} frequencies, omega_e sqrt(L/g) {x_lo:.2f}-{x_hi:.2f}: {dt:.0f} s")
        computed[Fn] = read_curves(csv)
        if a.demihull:
            cfg = make_config(Fn, x_lo, x_hi, count, solver, attitude, True, trim)
            csv, dt = run_hullopt(binary, cfg, os.path.join(a.out, "runs", tag + "_demihull"), a.threads)
            print(f"Fn {Fn:.2f}: one demihull alone: {dt:.0f} s")
            extra[Fn] = read_curves(csv, 2.0)
    runtime = time.time() - t_start

    rows = compare_links(measured, computed, centres, trim, extra)
    summary = summarise(rows)
    extra_label = "one demihull alone x 2" if a.demihull else None
    method = solver.get("method", make_config(0.3, 3, 4, 2, {})["solver"]["method"])
    desc = (f"method {method}, both demihulls; Cs {CS}; solver overrides: "
            f"{', '.join(f'{k}={v}' for k, v in solver.items()) or 'none (momentum form)'}; "
            + ("zero trim and sinkage" if trim == ZERO else
               f"running attitude of Fn {attitude_fn} (sinkage {attitude['sinkage_m'] * 1000:+.2f} mm + down, "
               f"trim {attitude['trim_deg']:+.2f} deg + bow up), against the {RUNNING} rows"))
    out = [f"# Delft 372 link by link against the forced tests", "", desc, "",
           f"Band: omega sqrt(L/g) within ±{100 * BAND_HALF_WIDTH:.0f} % of omega_r sqrt(L/g):", ""]
    for Fn in speeds:
        x_r, how = centres[Fn]
        out.append(f"- Fn {Fn:.2f}: omega_r sqrt(L/g) = {x_r:.3f}, band {(1 - BAND_HALF_WIDTH) * x_r:.3f}–"
                   f"{(1 + BAND_HALF_WIDTH) * x_r:.3f}; {how}")
    out += ["", "Cells: signed mean / mean |relative error| of (computed − measured)/|measured| in %, over the "
            "measured points in the band (count in brackets); couplings: computed sign = measured sign at the "
            f"band points where |measured| > {100 * CLEARLY_NONZERO:.0f} % of the link's largest |measured| at "
            "that speed (agreeing / checked).", "", markdown_table(summary, extra_label), ""]
    if trim == ZERO and set(speeds) == set(SPEEDS):
        s, n = score(rows)
        line = f"score (B33, B55, B35, B53; near-resonance band; Cs 0.024): {s:.3f}"
        out += [line, f"({n} measured points; runtime of the hullopt runs {runtime:.0f} s)"]
    else:
        s, n = score(rows)
        out += [f"mean |rel error| of B33, B55, B35, B53 in the band(s) of this run: {s:.3f} over {n} points "
                f"(not the score: that is defined at zero attitude over all four speeds)",
                f"(runtime of the hullopt runs {runtime:.0f} s)"]
    if a.demihull:
        b = rows[rows.in_band & rows.link.isin(SCORED)]
        out += [f"one demihull alone x 2, same points (not scored): mean |rel error| {b.rel_error_extra.abs().mean():.3f}"]
    text = "\n".join(out) + "\n"
    print()
    print(text)
    with open(os.path.join(a.out, "links.md"), "w") as f:
        f.write(text)
    cols = ["Fn", "link", "omega_nondim", "measured", "computed", "rel_error", "in_band", "clear", "sign_ok"]
    if a.demihull:
        cols += ["computed_extra", "rel_error_extra"]
    rows[cols].rename(columns={"computed_extra": "computed_demihull_x2",
                               "rel_error_extra": "rel_error_demihull_x2"}).to_csv(
        os.path.join(a.out, "links.csv"), index=False, float_format="%.6g")
    plot(os.path.join(a.out, "links.svg"), measured, computed, centres, trim, extra, extra_label,
         f"Delft 372, Cs {CS}, solver overrides: {', '.join(f'{k}={v}' for k, v in solver.items()) or 'none'}, "
         + ("zero attitude" if trim == ZERO else "running attitude") + ": computed (line), forced tests (points), "
         "near-resonance band shaded")
    print(f"wrote links.md, links.csv, links.svg in {a.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
