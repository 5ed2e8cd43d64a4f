"""scripts/delft372_links.py: the band centres and the score arithmetic (no hullopt binary needed).

A synthetic coefficients.csv per speed equal to the measured points times known factors (on the union of the
heave and pitch tests' frequencies plus points between them, so the measured points are grid points and the
linear interpolation returns factor x measured exactly) goes through the script's reader, comparison and score.
The expected numbers are worked out by hand below from data/delft372.
"""
import importlib.util
import math
import os

import numpy as np
import pandas as pd
import pytest

ROOT = os.environ.get("HULLOPT_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
spec = importlib.util.spec_from_file_location("links", os.path.join(ROOT, "scripts", "delft372_links.py"))
links = importlib.util.module_from_spec(spec)
spec.loader.exec_module(links)
DATA = os.path.join(ROOT, "data", "delft372")

# Factors of the synthetic computation. Scored links: |rel error| = |f - 1| at every point (B53 x -1: 2).
FACTORS = {"A33": 3.0, "B33": 1.5, "A55": 0.1, "B55": 0.8, "A35": 1.0, "B35": 1.1, "A53": -0.5, "B53": -1.0}


def test_band_centre_fn075_is_the_tank_rao_peak():
    # Largest heave_rao in delft372_tank_rao_fn075.csv: 2.532 at lambda/L 1.806. By hand: lambda = 5.418 m,
    # omega = sqrt(2 pi 9.81 / 5.418) = 3.37291 rad/s, U = 0.75 sqrt(9.81 x 3) = 4.06869 m/s,
    # omega_e = 3.37291 + 3.37291^2 x 4.06869 / 9.81 = 3.37291 + 4.71843 = 8.09134 rad/s,
    # omega_e sqrt(3 / 9.81) = 8.09134 x 0.553001 = 4.47452.
    x, how = links.rao_peak_band_centre(os.path.join(DATA, "delft372_tank_rao_fn075.csv"))
    assert x == pytest.approx(4.47452, abs=2e-5)
    assert "1.806" in how


@pytest.mark.parametrize("Fn,lo,hi", [(0.30, 4.718, 5.130), (0.45, 4.898, 5.286), (0.60, 4.712, 5.047)])
def test_heave_natural_frequency_solves_its_equation(Fn, lo, hi):
    m = links.load_measured(DATA)
    x, how = links.heave_natural_frequency(m, Fn)
    # Bracketing rows named in the description, the root between them, and the equation satisfied.
    assert lo < x < hi and f"{lo:.3f}" in how and f"{hi:.3f}" in how
    a = m[(m.Fn == Fn) & (m.trim_sinkage == "zero") & (m.link == "A33")]
    a_lo = float(a[a.x == lo].measured.iloc[0])
    a_hi = float(a[a.x == hi].measured.iloc[0])
    a33 = a_lo + (a_hi - a_lo) * (x - lo) / (hi - lo)
    assert x * x * 9.81 / 3.0 * (87.07 + a33) == pytest.approx(10782.0, rel=1e-9)


def test_natural_frequencies_hand_values():
    # Fn 0.30: between 4.718 (A33 50.533) and 5.130 (53.902): 4.8727; 0.45: 4.9639; 0.60: 4.7854 (docs: 4.87,
    # 4.96, 4.79 as the measured heave resonance).
    m = links.load_measured(DATA)
    for Fn, want in ((0.30, 4.8727), (0.45, 4.9639), (0.60, 4.7854)):
        assert links.heave_natural_frequency(m, Fn)[0] == pytest.approx(want, abs=2e-4)


def synthetic_curves(measured, Fn, tmp_path, trim="zero"):
    d = measured[(measured.Fn == Fn) & (measured.trim_sinkage == trim)]
    xs = np.unique(d.x.to_numpy())
    grid = np.unique(np.concatenate([xs, 0.5 * (xs[1:] + xs[:-1])]))
    cols = {"omega_e_sqrt_L_over_g": grid}
    for link, col in links.COMPUTED_COLUMNS.items():
        e = d[d.link == link]
        cols[col] = FACTORS[link] * np.interp(grid, e.x.to_numpy(), e.measured.to_numpy())
    path = tmp_path / f"coefficients_{int(Fn * 100)}.csv"
    with open(path, "w") as f:
        f.write("# synthetic: measured x factor\n")
        pd.DataFrame(cols).to_csv(f, index=False)
    return links.read_curves(str(path))


def synthetic_rows(tmp_path):
    m = links.load_measured(DATA)
    centres = links.band_centres(m, DATA)
    computed = {Fn: synthetic_curves(m, Fn, tmp_path) for Fn in links.SPEEDS}
    return links.compare_links(m, computed, centres)


def test_score_of_known_factors(tmp_path):
    rows = synthetic_rows(tmp_path)
    # Points in the bands (hand count from the CSVs; band = centre +-15 %):
    #   Fn 0.30 centre 4.873 (4.142-5.604): heave 4.371 4.718 5.130; pitch 4.368 4.725 5.119
    #   Fn 0.45 centre 4.964 (4.219-5.709): heave 4.392 4.582 4.898 5.286; pitch 4.343 4.593 4.920 5.281
    #   Fn 0.60 centre 4.785 (4.068-5.503): heave 4.304 4.524 4.712 5.047 5.408; pitch 4.321 4.651 5.061 5.366
    #   Fn 0.75 centre 4.475 (3.803-5.146): heave 4.103 4.421 4.861 5.097; pitch 4.094 4.464 4.880 5.126
    # B33, B53: 3 + 4 + 5 + 4 = 16 points each; B55, B35: 3 + 4 + 4 + 4 = 15 each; 62 in all.
    # |rel error|: B33 0.5, B55 0.2, B35 0.1, B53 2 -> (16 x 0.5 + 15 x 0.2 + 15 x 0.1 + 16 x 2) / 62 = 44.5 / 62.
    s, n = links.score(rows)
    assert n == 62
    assert s == pytest.approx(44.5 / 62.0, rel=1e-12)
    # Per link and speed: the signed means.
    summ = links.summarise(rows)
    got = {(r.Fn, r.link): r for r in summ.itertuples()}
    assert got[(0.60, "B33")].n == 5 and got[(0.60, "B33")].mean_rel == pytest.approx(0.5)
    assert got[(0.75, "B55")].n == 4 and got[(0.75, "B55")].mean_rel == pytest.approx(-0.2)
    assert got[(0.45, "A33")].mean_abs_rel == pytest.approx(2.0)
    # B53 x -1: rel error -2 sign(measured); Fn 0.30 band points -39.684, -23.362, +40.571 -> +2, +2, -2.
    assert got[(0.30, "B53")].mean_rel == pytest.approx(2.0 / 3.0)
    assert got[(0.30, "B53")].mean_abs_rel == pytest.approx(2.0)


def test_sign_check(tmp_path):
    rows = synthetic_rows(tmp_path)
    summ = links.summarise(rows)
    got = {(r.Fn, r.link): r for r in summ.itertuples()}
    for Fn in links.SPEEDS:
        for link in ("A35", "B35"):  # factors 1.0, 1.1: every clear point agrees
            assert got[(Fn, link)].sign_agree == got[(Fn, link)].sign_checked
        for link in ("A53", "B53"):  # factors -0.5, -1: every clear point is flagged
            assert got[(Fn, link)].sign_agree == 0
    # Fn 0.30 B53: largest |measured| 179.134 -> "clear" above 17.91; all three band points clear.
    assert got[(0.30, "B53")].sign_checked == 3
    # Fn 0.75 A35: largest 15.143 -> 1.514; band points 13.461, 12.224, 11.240, 15.143 clear: 4.
    assert got[(0.75, "A35")].sign_checked == 4


def test_score_refuses_points_outside_the_computed_range(tmp_path):
    m = links.load_measured(DATA)
    centres = links.band_centres(m, DATA)
    computed = {Fn: synthetic_curves(m, Fn, tmp_path) for Fn in links.SPEEDS}
    x, y = computed[0.75]["B33"]
    computed[0.75]["B33"] = (x[x > 4.5], y[x > 4.5])  # the band starts at 3.80
    with pytest.raises(ValueError):
        links.score(links.compare_links(m, computed, centres))


def test_running_attitude_signs():
    # File: Fn 0.748 sinkage +2.57 mm (up), trim -1.35 deg (bow up) -> hull.attitude: sinkage_m + down, trim + bow up.
    a, fn = links.running_attitude(DATA)
    assert fn == pytest.approx(0.748)
    assert a["sinkage_m"] == pytest.approx(-0.00257)
    assert a["trim_deg"] == pytest.approx(1.35)


def test_sign_check_skips_points_near_zero():
    # |measured| 5 is below 10 % of the largest (100): not checked; 12 is above: checked (and flagged).
    m = pd.DataFrame({"Fn": 0.30, "trim_sinkage": "zero", "test": "heave", "link": "B53",
                      "x": [4.6, 4.8, 5.0, 5.2], "measured": [100.0, 5.0, 12.0, -50.0], "source_table": "-"})
    x = np.array([4.0, 6.0])
    computed = {0.30: {"B53": (x, np.array([20.0, 20.0]))}}  # +20 everywhere
    rows = links.compare_links(m, computed, {0.30: (4.9, "test")})
    r = links.summarise(rows).iloc[0]
    assert (r.n, r.sign_checked, r.sign_agree) == (4, 3, 2)
