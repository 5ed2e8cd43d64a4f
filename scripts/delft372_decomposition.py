#!/usr/bin/env python3
"""Delft 372 at Fn 0.75: the heave peak decomposed link by link, with the links of the instantaneous hull.

The added mass and damping links (A33, B33, A55, B55 and the couplings A35, A53, B35, B53) come from the forced
tests simulated as run (hullopt.forced_oscillation: the strips on the instantaneous hull, the tests' amplitudes
15 mm and 1.718 deg, Cs 0.024, zero attitude, both demihulls), at the encounter frequencies of --points
wavelengths lambda/L in [1.2, 1.98] (inside every measured range); the wave loads F3, F5 and the static restoring
from the linear strips (`hullopt coefficients`, the same stations). Each measured link (zero attitude,
interpolated linearly in omega_e sqrt(L/g)) then replaces the computed one in
    sum_j [-omega_e^2 (M_ij + A_ij) + i omega_e B_ij + C_ij] X_j = F_i
(M = 87.07 kg, I55 = M k_yy^2, k_yy 0.782 m) and the heave peak over lambda/L is read (parabola through the
largest sample). Tank: 2.53 at lambda/L 1.80.

Usage:
  PYTHONPATH=build/python /usr/bin/python3 scripts/delft372_decomposition.py --out out/decomposition
      [--force momentum|pressure] [--points 16] [--hullopt build/app/hullopt]
Writes decomposition.md and links.csv (the computed links per frequency) in --out.
"""
import argparse
import math
import os
import subprocess
import sys

import numpy as np
import pandas as pd
import yaml

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import delft372_links as links  # noqa: E402

import hullopt  # noqa: E402

FN = 0.75
M_KG, KYY_M, LCG_M = 87.07, 0.782, 1.41
HEAVE_AMPLITUDE_M, PITCH_AMPLITUDE_RAD = 0.015, math.radians(1.718)
CS = 0.024
LINKS = ("A33", "B33", "A55", "B55", "A35", "B35", "A53", "B53")


def peak(lam, values):
    """Largest value and its lambda/L, refined by the parabola through it and its neighbours."""
    i = int(np.argmax(values))
    if 0 < i < len(values) - 1:
        x, y = lam[i - 1:i + 2], values[i - 1:i + 2]
        c = np.polyfit(x, y, 2)
        if c[0] < 0:
            xv = -c[1] / (2 * c[0])
            return float(np.polyval(c, xv)), float(xv), ""
    return float(values[i]), float(lam[i]), " (edge)"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--force", choices=("momentum", "pressure"), default="momentum")
    ap.add_argument("--points", type=int, default=16)
    ap.add_argument("--hullopt", default="build/app/hullopt")
    a = ap.parse_args(argv)
    os.makedirs(a.out, exist_ok=True)
    g, L = links.G, links.L_M
    U = FN * math.sqrt(g * L)
    lam = np.linspace(1.2, 1.98, a.points)
    omega = np.sqrt(2 * math.pi * g / (lam * L))
    omega_e = omega + omega ** 2 * U / g
    x = omega_e * math.sqrt(L / g)

    # Loads and static restoring from the linear strips at the same encounter frequencies.
    with open(links.TEMPLATE) as f:
        c = yaml.safe_load(f)
    base = os.path.dirname(links.TEMPLATE)
    c["hull"]["offsets_csv"] = os.path.normpath(os.path.join(base, c["hull"]["offsets_csv"]))
    c.pop("compare", None)
    c["solver"]["sectional_force"] = a.force
    c["solver"]["frequencies"] = {"omega_e_rad_s": [float(w) for w in sorted(omega_e)]}
    cfg = os.path.join(a.out, "coefficients.yaml")
    with open(cfg, "w") as f:
        yaml.safe_dump(c, f)
    subprocess.run([a.hullopt, "coefficients", cfg, "--out", os.path.join(a.out, "linear"), "--force"], check=True,
                   stdout=subprocess.DEVNULL)
    lin = pd.read_csv(os.path.join(a.out, "linear", "coefficients.csv"), comment="#").sort_values("omega_e_rad_s")
    at = (lambda col: np.interp(omega_e, lin.omega_e_rad_s.values, lin[col].values))  # the same frequencies
    C = {k: at(col) for k, col in (("33", "C33_N_per_m"), ("35", "C35_N_per_rad"), ("53", "C53_N"),
                                   ("55", "C55_N_m_per_rad"))}
    F3 = at("F3_amp_N_per_m") * np.exp(1j * np.radians(at("F3_phase_deg")))
    F5 = at("F5_amp_N_m_per_m") * np.exp(1j * np.radians(at("F5_phase_deg")))

    hull = hullopt.load_hull(links.TEMPLATE)
    mass = hullopt.MassProperties()
    mass.mass_kg, mass.lcg_m_from_ap, mass.kyy_m, mass.kg_m = M_KG, LCG_M, KYY_M, 0.34
    rows = []
    for we in omega_e:
        r = {"omega_e_rad_s": we}
        for test, amp in (("heave", HEAVE_AMPLITUDE_M), ("pitch", PITCH_AMPLITUDE_RAD)):
            d = hullopt.forced_oscillation(hull, mass, U, test, amp, float(we), sectional_force=a.force, Cs=CS,
                                           water={"rho_kg_m3": 1000.0, "g_m_s2": g})
            r.update({k: v for k, v in d.items() if k in LINKS})
        rows.append(r)
        print(f"omega_e {we:.3f}: " + ", ".join(f"{k} {r[k]:.1f}" for k in LINKS), flush=True)
    comp = pd.DataFrame(rows)
    comp.to_csv(os.path.join(a.out, "links.csv"), index=False)

    measured = links.load_measured()
    meas = {}
    for link in LINKS:
        m = measured[(measured.Fn == FN) & (measured.trim_sinkage == links.ZERO) & (measured.link == link)]
        meas[link] = np.interp(x, m.x.values, m.measured.values)

    def heave_peak(sub):
        h = []
        for i, we in enumerate(omega_e):
            v = {k: (meas[k][i] if k in sub else comp[k].iloc[i]) for k in LINKS}
            w2 = we * we
            K = np.array([[-w2 * (M_KG + v["A33"]) + 1j * we * v["B33"] + C["33"][i],
                           -w2 * v["A35"] + 1j * we * v["B35"] + C["35"][i]],
                          [-w2 * v["A53"] + 1j * we * v["B53"] + C["53"][i],
                           -w2 * (M_KG * KYY_M ** 2 + v["A55"]) + 1j * we * v["B55"] + C["55"][i]]])
            h.append(abs(np.linalg.solve(K, np.array([F3[i], F5[i]]))[0]))
        return peak(lam, np.array(h))

    cases = [("none (instantaneous-hull links)", ()), ("A33", ("A33",)), ("B33", ("B33",)), ("A55", ("A55",)),
             ("B55", ("B55",)), ("A35, A53, B35, B53", ("A35", "A53", "B35", "B53")),
             ("B33 + B55", ("B33", "B55")), ("all links", LINKS)]
    out = [f"Delft 372, Fn {FN}: heave peak with measured links substituted into the links of the instantaneous "
           f"hull ({a.force} form, tests' amplitudes, Cs {CS}; loads and C from the linear strips). Tank 2.53 at "
           f"lambda/L 1.80.", "", "| substituted | heave peak (λ/L) | change |", "| --- | --- | --- |"]
    base_peak = None
    for label, sub in cases:
        p, at, edge = heave_peak(sub)
        base_peak = p if base_peak is None else base_peak
        out.append(f"| {label} | {p:.3f} ({at:.2f}{edge}) | {p - base_peak:+.3f} |")
    with open(os.path.join(a.out, "decomposition.md"), "w") as f:
        f.write("\n".join(out) + "\n")
    print("\n".join(out))


if __name__ == "__main__":
    main()
