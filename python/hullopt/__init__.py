"""hullopt: hull-form optimisation of high-speed vessels for seakeeping in head seas.

One import names the public objects:

    DesignVariables, generate_hull, load_hull      parametric or read hulls
    hydrostatics, mass_properties                  displacement, coefficients, GM; mass properties
    compute_raos, evaluation_frequencies           heave and pitch RAOs (time-domain strip method or STF)
    forced_oscillation                             a forced heave or pitch test on the instantaneous hull
    calm_water                                     the steady force and running sinkage and trim in calm water
    evaluate                                       rms vertical accelerations and MSI in head seas
    design, Design                                 a design from Python values (speed_kn= or speed_m_s=), built
                                                   as the commands build a config's
    load_design                                    a design config as `hullopt evaluate` reads it
    optimize, explore, CampaignResult              a campaign (config file or dict) in an output folder,
                                                   resumed from its log; history as a pandas DataFrame
    run                                            any hullopt command in-process
    rao_dataset, evaluation_dataset                results as labelled xarray Datasets (units in attrs), their
                                                   warnings through Python's warnings (HulloptWarning)
    InputError                                     bad input; the message is the CLI's

SI units everywhere; axes and phases as in docs/conventions.md.
"""
from ._hullopt import (  # noqa: F401
    Design,
    DesignVariables,
    Hull,
    InputError,
    MassProperties,
    __version__,
    _run_campaign,
    compute_raos,
    design,
    evaluate,
    evaluation_frequencies,
    forced_oscillation,
    calm_water,
    generate_hull,
    hydrostatics,
    load_design,
    load_hull,
    mass_properties,
    rao_peak,
    run,
)

import math as _math
import warnings as _warnings


class HulloptWarning(UserWarning):
    """A flag of hullopt's inputs or results: plausibility, validity envelope, frequency grid, resonance."""


def _warn(messages, stacklevel=3):
    for m in messages:
        _warnings.warn(m, HulloptWarning, stacklevel=stacklevel)


def rao_dataset(rao, length_m, name="hull"):
    """An RAO dict (compute_raos, Design.raos) as an xarray Dataset: dimension omega (wave frequency), the
    coordinates omega [rad/s], omega_e [rad/s] and lambda_over_L [-] (wavelength over the length length_m [m]),
    the complex variables heave X3/A [m/m] and pitch X5/(kA) [rad/rad]; units in each variable's attrs. The
    Dataset's attrs hold speed_m_s, g_m_s2, the warnings (also issued as HulloptWarning) and summary, the line
    `hullopt rao` prints: the heave and pitch peaks and the lambda/L where they stand."""
    import numpy as np
    import xarray as xr

    omega = np.asarray(rao["omega_rad_s"], dtype=float)
    g = rao["g_m_s2"]
    lam = np.array([2 * _math.pi * g / (w * w) / length_m for w in omega])
    heave, pitch = np.asarray(rao["heave"]), np.asarray(rao["pitch"])
    h, p = rao_peak(lam, np.abs(heave)), rao_peak(lam, np.abs(pitch))
    edge = lambda peak: " (at the end of the range)" if peak[2] else ""  # noqa: E731
    summary = (f"hull '{name}': heave peak {h[0]:.4g} m/m at lambda/L {h[1]:.3g}{edge(h)}, "
               f"pitch peak {p[0]:.4g} rad/rad at lambda/L {p[1]:.3g}{edge(p)}")
    ds = xr.Dataset(
        {
            "heave": ("omega", heave, {"units": "m/m", "long_name": "heave RAO X3/A (phase lead + vs the crest at the CG)"}),
            "pitch": ("omega", pitch, {"units": "rad/rad", "long_name": "pitch RAO X5/(kA)"}),
        },
        coords={
            "omega": ("omega", omega, {"units": "rad/s", "long_name": "wave frequency"}),
            "omega_e": ("omega", np.asarray(rao["omega_e_rad_s"], dtype=float),
                        {"units": "rad/s", "long_name": "encounter frequency"}),
            "lambda_over_L": ("omega", lam, {"units": "1", "long_name": "wavelength / L"}),
        },
        attrs={"summary": summary, "name": name, "speed_m_s": rao["speed_m_s"], "speed_units": "m/s", "g_m_s2": g,
               "L_m": length_m, "warnings": "\n".join(rao["warnings"])},
    )
    _warn(rao["warnings"])
    return ds


def evaluation_dataset(seas, name="design"):
    """The list evaluate() returns as an xarray Dataset: dimensions sea and position (forward, lcg, transom or the
    named points, then mean), coordinates Hs_m [m], Tz_s [s], Tp_s [s] per sea and x_from_cg_m [m] per position,
    variables msi_pct [%], rms_accel_g [g], rms_accel_m_s2 [m/s^2], rms_displacement_m [m] and omega_char_rad_s
    [rad/s]; units in attrs. Each sea's warnings are issued as HulloptWarning and kept in attrs; attrs summary
    has one line per sea (Hs, Tz, the mean MSI)."""
    import numpy as np
    import xarray as xr

    positions = [q["position"] for q in seas[0]["positions"]] + ["mean"]
    rows = [s["positions"] + [s["mean"]] for s in seas]
    units = {"msi_pct": "%", "rms_accel_g": "g", "rms_accel_m_s2": "m/s^2", "rms_displacement_m": "m",
             "omega_char_rad_s": "rad/s"}
    data = {k: (("sea", "position"), np.array([[q[k] for q in r] for r in rows], dtype=float), {"units": u})
            for k, u in units.items()}
    x = [q["x_from_cg_m"] for q in seas[0]["positions"]] + [float("nan")]
    warned = [w for s in seas for w in s["warnings"]]
    summary = "\n".join(f"design '{name}': Hs {s['Hs_m']:.3g} m, Tz {s['Tz_s']:.3g} s: mean MSI "
                         f"{s['mean']['msi_pct']:.3g} %, rms acceleration {s['mean']['rms_accel_g']:.3g} g"
                         for s in seas)
    ds = xr.Dataset(
        data,
        coords={
            "sea": ("sea", np.arange(len(seas))),
            "position": ("position", positions),
            "Hs_m": ("sea", [s["Hs_m"] for s in seas], {"units": "m"}),
            "Tz_s": ("sea", [s["Tz_s"] for s in seas], {"units": "s"}),
            "Tp_s": ("sea", [s["Tp_s"] for s in seas], {"units": "s"}),
            "x_from_cg_m": ("position", x, {"units": "m", "long_name": "position forward of the CG"}),
        },
        attrs={"summary": summary, "name": name, "warnings": "\n".join(warned)},
    )
    _warn(warned)
    return ds


def _design_rao_dataset(self, omega_rad_s=None):
    """The design's RAOs (as raos()) as a labelled Dataset (rao_dataset), over its length L."""
    return rao_dataset(self.raos(omega_rad_s), self.hydrostatics["L_m"], self.name)


Design.rao_dataset = _design_rao_dataset


class CampaignResult:
    """What optimize() and explore() return.

    history: a pandas DataFrame, one row per evaluation in log order, with the columns of the campaign's log
        (history.csv / samples.csv) under the same names (units in the names as the CSV headers have them):
        evaluation, the design variables, objective, feasible, the per-sea values, the constrained quantities,
        wall_time_s, run, step, message (a refusal, or "warning: ..." for a design with a warning).
    best: a dict of the best feasible design: evaluation, objective and its variables by name; None when no
        evaluation is feasible.
    complete: False when the call stopped at max_evaluations (run it again to resume).
    summary: summary.json as a dict (empty when not complete); text: the result lines the command line prints;
    messages: the notes and warnings the command line prints on stderr; out: the output folder.
    """

    def __init__(self, raw, out):
        import json
        import pandas as pd

        self.out = out
        self.command = raw["command"]
        self.complete = raw["complete"]
        self.log_path = raw["log_path"]
        self.replayed = raw["replayed"]
        self.text = raw["text"]
        self.messages = list(raw["messages"])
        self.summary = json.loads(raw["summary"]) if raw["summary"] else {}
        columns = raw["columns"]
        order = raw["column_order"].split(",")
        self.history = pd.DataFrame({k: columns[k] for k in order}, columns=order)
        self.variables = list(raw["variables"])
        b = raw["best"]
        if b < 0:
            self.best = None
        else:
            row = self.history.iloc[b]
            self.best = {"evaluation": int(b), "objective": float(row["objective"])}
            self.best.update({v: float(row[v]) for v in self.variables})

    def __repr__(self):
        n = len(self.history)
        head = f"hullopt {self.command}: {n} evaluations in {self.out}"
        if self.replayed:
            head += f" ({self.replayed} replayed from the log)"
        if not self.complete:
            head += "; stopped at max_evaluations (call again to resume)"
            if self.best is not None:
                head += (f"\nbest objective so far {self.best['objective']:.10g} at evaluation "
                         f"{self.best['evaluation']}")
            return head
        return head + "\n" + self.text.rstrip("\n")


def _campaign(command, spec, out, resume, max_evaluations, threads, plots):
    import os

    if isinstance(spec, os.PathLike):
        spec = os.fspath(spec)
    if not isinstance(spec, (str, dict)):
        raise TypeError("spec: a campaign config file (str or path) or a dict of its blocks")
    if max_evaluations is not None and max_evaluations < 1:
        raise ValueError(f"max_evaluations = {max_evaluations}: must be >= 1 (None = no limit)")
    raw = _run_campaign(command, spec, os.fspath(out), bool(resume), int(max_evaluations or 0), int(threads),
                        bool(plots))
    result = CampaignResult(raw, os.fspath(out))
    _warn([m for m in result.messages if m.startswith("hullopt: warning: ")], stacklevel=4)
    return result


def optimize(spec, out, resume=True, max_evaluations=None, threads=0, plots=True):
    """Runs an optimize campaign, as `hullopt optimize CONFIG --out OUT` does, and returns a CampaignResult.

    spec: the campaign config file (str or path), or a dict of its blocks (hull, mass, speed, solver, seas,
    optimize, ...; the values as a config file has them, no YAML text). out: the output folder (the command's
    files: history.csv, summary.json, best.yaml, figures; report.html for a config file when plots is true).
    resume: a folder holding this campaign's log is continued (its evaluations replayed, not recomputed); with
    resume=False such a folder is refused. max_evaluations: stop after this many computed evaluations (the log
    keeps them; call again to continue). threads: OpenMP threads (0 = the default). Warnings of the campaign
    arrive as HulloptWarning; bad input raises InputError with the CLI's message.
    """
    return _campaign("optimize", spec, out, resume, max_evaluations, threads, plots)


def explore(spec, out, resume=True, max_evaluations=None, threads=0, plots=True):
    """Runs an explore campaign (samples.csv), as optimize() does for `hullopt optimize`."""
    return _campaign("explore", spec, out, resume, max_evaluations, threads, plots)
