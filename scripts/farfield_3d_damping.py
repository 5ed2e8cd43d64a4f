#!/usr/bin/env python3
"""How much a 3D far field changes the wave damping of a slender hull in heave, against the 2D+t far field.

A diagnostic of the strip method's heave damping B33 at forward speed. Each station of one hull is replaced by
a line source whose strength per metre q(x) is that of its 2D section heaving at the encounter frequency:
the far field of a 2D section is that of a surface source, so q(x)^2 = b33(x) (from `hullopt section`,
frequency-domain solver, up to a constant common to every station). With the same sources, the radiated
power of a source distribution translating at U and oscillating at w_e (time factor exp(i w_e t)) is, in
wavenumber space (k_x along the hull, k_y across it, Omega = w_e - U k_x the frequency seen in a fixed strip),

    B = 1/(4 pi w_e) * integral |q^(k_x)|^2 * 2 |Omega| * S(k_x) dk_x

with S = 1 for the 2D+t dispersion Omega^2 = g |k_y| (the strips of the time-domain method), and, for the
3D dispersion Omega^2 = g sqrt(k_x^2 + k_y^2) = g K,

    S = K / sqrt(K^2 - k_x^2) where K > |k_x|,  0 where K < |k_x|  (no free wave with that k_x).

Every wave component adds to B, those with Omega < 0 as well: with w_e = 0 the same radiated power is U times
Havelock's wave resistance of the sources, in which both signs of Omega count alike. The constant makes
B = integral b33 dx at U = 0 (Parseval), which the script prints as a check. The ratio
B_3D / B_2D+t is the 3D far-field effect on the damping for given sources; it does not include the change of
the sources themselves (near field, interaction between hulls).

With --pair SPACING_M a second, identical line at that lateral spacing is added (a catamaran; heave, so both
in phase): the lateral factor |2 cos(k_y s/2)|^2 then multiplies the integrand, k_y = Omega^2/g for 2D+t and
sqrt(K^2 - k_x^2) for 3D, and the script prints B_pair / (2 B_single) for each. The sources stay those of the
demihull alone, so this is the far-field interference only: in a steady 2D catamaran section the sources
themselves change with the gap, which this does not model.

Usage: scripts/farfield_3d_damping.py [--pair SPACING_M] SECTION_CONFIG X_AFT_M X_FWD_M STATIONS PANELS U_M_S
                                     OMEGA_E_RAD_S...
  SECTION_CONFIG: a `hullopt section` config of one section (shape: offsets, count: 1); its x_m, panels,
  method and frequencies are replaced. e.g.
  scripts/farfield_3d_damping.py examples/section_delft372_station.yaml 0 3.0 45 28 4.07 5.0 6.5 8.6 11.0
Binary: $HULLOPT (default build/app/hullopt). Needs python3-numpy and python3-yaml.
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile

import numpy as np
import yaml

G = 9.81


def section_b33(hullopt, template, x, panels, omegas, work):
    """b33 [kg/(m s)] of the section at x for each omega; 0 where the solver refuses the section (an end)."""
    cfg = dict(template)
    sec = dict(cfg["section"])
    sec.update({"x_m": float(x), "panels": int(panels), "count": 1, "method": ["frequency_domain"],
                "frequencies": {"omega_rad_s": [float(w) for w in omegas]}})
    sec.pop("spacing_m", None)
    cfg["section"] = sec
    path = os.path.join(work, "station.yaml")
    with open(path, "w") as f:
        yaml.safe_dump(cfg, f)
    out = os.path.join(work, f"station_{x:.6f}")
    run = subprocess.run([hullopt, "section", path, "--out", out], capture_output=True, text=True)
    if run.returncode != 0:
        return None
    with open(os.path.join(out, "section.csv")) as f:
        rows = list(csv.DictReader(f))
    return np.array([float(r["b33_kg_per_m_s"]) for r in rows])


def line_spectrum(x, q, kx):
    """Fourier transform of the piecewise-linear q(x) (zero outside [x0, xn]) at the wavenumbers kx."""
    xf = np.linspace(x[0], x[-1], 4001)
    qf = np.interp(xf, x, q)
    w = np.full(xf.size, xf[1] - xf[0])
    w[0] = w[-1] = 0.5 * w[0]
    return np.exp(-1j * np.outer(kx, xf)) @ (qf * w)


def cosine_nodes(a, b, n):
    """Nodes and weights on [a, b] that make an inverse-square-root singularity at either end integrable."""
    u, wu = np.polynomial.legendre.leggauss(n)
    u = 0.5 * (u + 1.0)
    wu = 0.5 * wu
    x = a + (b - a) * 0.5 * (1.0 - np.cos(np.pi * u))
    return x, wu * (b - a) * 0.5 * np.pi * np.sin(np.pi * u)


def damping(x, q, omega, U, kmax, spacing=None, n_per_interval=400):
    """(B_2D+t, B_3D) in kg/s for the line source q(x) at encounter frequency omega and speed U; with spacing
    [m], for two such lines that far apart."""
    # Ends of the 3D wave-free band (Omega^2 = g |k_x|), where S is singular.
    cuts = [-kmax, kmax]
    for sign in (+1.0, -1.0):  # k_x > 0: (omega - U k)^2 = g k; k_x < 0 with k = |k_x|: (omega + U k)^2 = g k
        a, b, c = U * U, -(2.0 * omega * U * sign + G), omega * omega
        disc = b * b - 4.0 * a * c
        if U > 0 and disc > 0:
            for r in ((-b - np.sqrt(disc)) / (2 * a), (-b + np.sqrt(disc)) / (2 * a)):
                if 0 < r < kmax:
                    cuts.append(sign * r)
    if U == 0 and omega * omega / G < kmax:
        cuts += [omega * omega / G, -omega * omega / G]
    cuts = sorted(set(cuts))
    b2, b3 = 0.0, 0.0
    for lo, hi in zip(cuts, cuts[1:]):
        k, w = cosine_nodes(lo, hi, n_per_interval)
        Q2 = np.abs(line_spectrum(x, q, k)) ** 2
        Om = omega - U * k
        K = Om * Om / G
        ky3 = np.sqrt(np.maximum(K * K - k * k, 0.0))
        s3 = np.where(K > np.abs(k), K / np.maximum(ky3, 1e-300), 0.0)
        f2 = f3 = 1.0
        if spacing is not None:  # both lines in phase: |exp(i k_y s/2) + exp(-i k_y s/2)|^2
            f2 = 4.0 * np.cos(0.5 * K * spacing) ** 2
            f3 = 4.0 * np.cos(0.5 * ky3 * spacing) ** 2
        b2 += np.sum(w * Q2 * 2.0 * np.abs(Om) * f2)
        b3 += np.sum(w * Q2 * 2.0 * np.abs(Om) * s3 * f3)
    return b2 / (4 * np.pi * omega), b3 / (4 * np.pi * omega)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--pair", type=float, metavar="SPACING_M", help="add a second line at this spacing")
    ap.add_argument("config")
    ap.add_argument("x_aft", type=float)
    ap.add_argument("x_fwd", type=float)
    ap.add_argument("stations", type=int)
    ap.add_argument("panels", type=int)
    ap.add_argument("U", type=float, help="speed [m/s]")
    ap.add_argument("omegas", type=float, nargs="+", help="encounter frequencies [rad/s]")
    a = ap.parse_args()
    cfg_path, x_aft, x_fwd, stations, panels, U, omegas = (a.config, a.x_aft, a.x_fwd, a.stations, a.panels,
                                                           a.U, a.omegas)
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    hullopt = os.path.abspath(os.environ.get("HULLOPT", os.path.join(root, "build/app/hullopt")))
    with open(cfg_path) as f:
        template = yaml.safe_load(f)
    offsets = template["section"].get("offsets_csv")
    if offsets and not os.path.isabs(offsets):  # relative to the config's folder, as hullopt reads it
        template["section"]["offsets_csv"] = os.path.abspath(os.path.join(os.path.dirname(cfg_path), offsets))
    work = tempfile.mkdtemp(prefix="farfield_3d_")
    dx = (x_fwd - x_aft) / stations
    xs, b33 = [x_aft], [np.zeros(len(omegas))]  # the source line ends at zero strength
    for i in range(stations):
        x = x_aft + (i + 0.5) * dx
        b = section_b33(hullopt, template, x, panels, omegas, work)
        xs.append(x)
        b33.append(b if b is not None else np.zeros(len(omegas)))
    xs.append(x_fwd)
    b33.append(np.zeros(len(omegas)))
    xs, b33 = np.array(xs), np.array(b33)
    print(f"# {stations} stations x {panels} panels over x = {x_aft}..{x_fwd} m, U = {U} m/s; "
          f"{int(np.sum(b33[:, 0] > 0))} sections solved")
    pair_head = ",pair_over_2single_2Dt,pair_over_2single_3D" if a.pair is not None else ""
    print("omega_e_rad_s,tau,int_b33_dx_kg_s,B_2Dt_U0_kg_s,B_2Dt_kg_s,B_3D_kg_s,B_3D_over_B_2Dt,"
          "B_3D_over_B_2Dt_kmax_doubled" + pair_head)
    for j, w in enumerate(omegas):
        q = np.sqrt(b33[:, j])
        int_b = np.trapz(b33[:, j], xs)
        b0, _ = damping(xs, q, w, 0.0, 400.0)
        b2, b3 = damping(xs, q, w, U, 400.0)
        b2d, b3d = damping(xs, q, w, U, 800.0)
        row = f"{w:g},{U * w / G:.3f},{int_b:.2f},{b0:.2f},{b2:.2f},{b3:.2f},{b3 / b2:.4f},{b3d / b2d:.4f}"
        if a.pair is not None:
            p2, p3 = damping(xs, q, w, U, 400.0, a.pair)
            row += f",{p2 / (2 * b2):.4f},{p3 / (2 * b3):.4f}"
        print(row)
    return 0


if __name__ == "__main__":
    sys.exit(main())
