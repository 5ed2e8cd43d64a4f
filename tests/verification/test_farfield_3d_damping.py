"""scripts/farfield_3d_damping.py against closed forms (no hullopt binary needed).

Radiated-power integrals of a line source q(x) at encounter frequency w (docs/coefficients.md, Findings):
- zero speed, 2D+t dispersion: B = integral q^2 dx (Parseval), for q = sin(pi x / L);
- zero speed, two lines at spacing s: B_pair / (2 B_single) = 2 cos^2(k0 s / 2), k0 = w^2/g (steady 2D);
- zero speed, 3D dispersion, a line much shorter than a wave: the point source's B = Q^2 k0 / 2, Q = integral q dx
  (the integrand's inverse-square-root ends at |k_x| = k0 are where the quadrature can go wrong);
- a line many waves long: B_3D / B_2D+t -> 1 (the 3D spreading vanishes for a slender source).
Tolerances: 2e-3 relative, set by the 4001-point trapezoidal spectrum of the piecewise-linear q (its error is
O(dx^2 k^2), below 1e-3 for these lines) and 400 Gauss nodes per wavenumber interval.
"""
import importlib.util
import math
import os

import numpy as np
import pytest

ROOT = os.environ.get("HULLOPT_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
spec = importlib.util.spec_from_file_location("farfield", os.path.join(ROOT, "scripts", "farfield_3d_damping.py"))
ff = importlib.util.module_from_spec(spec)
spec.loader.exec_module(ff)

G = 9.81
REL = 2e-3


def sine_line(L, n=201):
    x = np.linspace(0.0, L, n)
    return x, np.sin(np.pi * x / L)


def test_zero_speed_2dt_is_parseval():
    x, q = sine_line(3.0)
    b2, _ = ff.damping(x, q, 8.6, 0.0, 400.0)
    assert b2 == pytest.approx(1.5, rel=REL)  # integral of sin^2 over [0, 3]


@pytest.mark.parametrize("omega", [5.0, 6.5, 8.6, 11.0])
def test_zero_speed_pair_is_steady_2d_interference(omega):
    x, q = sine_line(3.0)
    s = 0.70
    b2, _ = ff.damping(x, q, omega, 0.0, 400.0)
    p2, _ = ff.damping(x, q, omega, 0.0, 400.0, s)
    want = 2.0 * math.cos(0.5 * omega * omega / G * s) ** 2
    assert p2 / (2.0 * b2) == pytest.approx(want, rel=REL, abs=1e-4)


def test_zero_speed_3d_short_line_is_point_source():
    omega = 3.0  # k0 = 0.917 rad/m: a 0.05 m line is 0.007 of a wavelength
    L = 0.05
    x, q = sine_line(L)
    _, b3 = ff.damping(x, q, omega, 0.0, 400.0)
    Q = 2.0 * L / math.pi
    assert b3 == pytest.approx(Q * Q * (omega * omega / G) / 2.0, rel=REL)


def test_long_line_3d_equals_2dt():
    x, q = sine_line(60.0, 2001)  # k0 L = 450 at 8.6 rad/s
    for U in (0.0, 4.07):
        b2, b3 = ff.damping(x, q, 8.6, U, 400.0)
        assert b3 / b2 == pytest.approx(1.0, rel=REL)
