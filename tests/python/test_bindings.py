"""The Python module against the CLI: the same numbers to the last digit written, the same error messages.

Run by ctest (python_bindings) with PYTHONPATH=<build>/python and HULLOPT_BIN=<build>/app/hullopt.
"""
import csv
import os
import subprocess
import textwrap

import numpy as np
import pytest

import hullopt

BIN = os.environ["HULLOPT_BIN"]
ROOT = os.environ.get("HULLOPT_SOURCE_DIR", os.getcwd())

# The NPL 5b-like catamaran of Table 1 (configs/davis-holloway-2003/hull02_NPL5b.yaml).
NPL5B = dict(type="catamaran", section_style="round_bilge", displacement_t=1000, L_over_B=11.0, B_over_T=2.0,
             Cb=0.40, Cp=0.69, Cwp=0.76, LCB_pct_L=-6.4, LCF_pct_L=-8.3, transom_immersion=0.3,
             transom_beam_ratio=0.6, keel_rise=0.3, spacing_over_L=0.25)
SPEED_M_S = 40 * (1852.0 / 3600.0)  # 40 kn, as io/config/speed_config converts it
OMEGA = [0.4, 0.6, 0.8, 1.0, 1.2, 1.5, 2.0]
# The comparisons below are of fixed grids, digit for digit: refinement off (solver.adaptive_grid) everywhere.
SOLVER = {"sections": 20, "panels": 8, "Cs": 0.065, "adaptive_grid": False}


def hull_yaml(extra=""):
    params = "\n".join(f"    {k}: {v}" for k, v in NPL5B.items())
    return f"hull:\n  parametric:\n{params}\nwater: {{ rho_kg_m3: 1025, g_m_s2: 9.81 }}\nspeed: {{ kn: 40 }}\n{extra}"


def run_cli(*args):
    return subprocess.run([BIN, *args], capture_output=True, text=True, cwd=ROOT)


def csv_rows(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def g10(x):
    """A number as rao.csv writes it (ostream, precision 10)."""
    return f"{x:.10g}"


def g6(x):
    """A number as msi.csv writes it (ostream, default precision 6)."""
    return f"{x:.6g}"


def test_npl5b_raos_match_the_cli_to_the_last_digit(tmp_path):
    freqs = ", ".join(str(w) for w in OMEGA)
    cfg = tmp_path / "npl5b.yaml"
    cfg.write_text(hull_yaml(textwrap.dedent(f"""\
        solver:
          sections: {SOLVER['sections']}
          panels: {SOLVER['panels']}
          Cs: {SOLVER['Cs']}
          adaptive_grid: off
          frequencies: {{ omega_rad_s: [{freqs}] }}
        """)))
    r = run_cli("rao", str(cfg), "--out", str(tmp_path / "rao"))
    assert r.returncode == 0, r.stderr
    rows = csv_rows(tmp_path / "rao" / "rao.csv")

    hull = hullopt.generate_hull(hullopt.DesignVariables(**NPL5B))
    mass = hullopt.mass_properties(hull)
    rao = hullopt.compute_raos(hull, mass, SPEED_M_S, OMEGA, solver=SOLVER)
    assert isinstance(rao["heave"], np.ndarray) and rao["heave"].dtype == np.complex128
    assert len(rows) == len(OMEGA)
    for i, row in enumerate(rows):
        assert row["omega_e_rad_s"] == g10(rao["omega_e_rad_s"][i])
        assert row["heave_amp"] == g10(abs(rao["heave"][i]))
        assert row["heave_phase_deg"] == g10(np.degrees(np.angle(rao["heave"][i])))
        assert row["pitch_amp"] == g10(abs(rao["pitch"][i]))
        assert row["pitch_phase_deg"] == g10(np.degrees(np.angle(rao["pitch"][i])))


def test_npl5b_msi_matches_evaluate(tmp_path):
    hull_cfg = tmp_path / "npl5b.yaml"
    hull_cfg.write_text(hull_yaml(f"solver: {{ sections: {SOLVER['sections']}, panels: {SOLVER['panels']}, "
                                  "adaptive_grid: off }\n"))
    ev_cfg = tmp_path / "evaluate.yaml"
    ev_cfg.write_text(textwrap.dedent(f"""\
        designs:
          - {{ config: {hull_cfg}, name: npl5b, Cs: {SOLVER['Cs']} }}
        seas:
          - {{ Hs_m: 3.0, Tz_s: 7.5 }}
          - {{ Hs_m: 1.5, Tz_s: 6.25 }}
        """))
    r = run_cli("evaluate", str(ev_cfg), "--out", str(tmp_path / "ev"))
    assert r.returncode == 0, r.stderr
    rows = [row for row in csv_rows(tmp_path / "ev" / "msi.csv") if row["design"] == "npl5b"]
    assert rows, "no msi.csv rows for the design"

    hull = hullopt.generate_hull(hullopt.DesignVariables(**NPL5B))
    mass = hullopt.mass_properties(hull)
    rao = hullopt.compute_raos(hull, mass, SPEED_M_S, hullopt.evaluation_frequencies(), solver=SOLVER)
    seas = hullopt.evaluate(rao, hull, mass, seas=[{"Hs_m": 3.0, "Tz_s": 7.5}, {"Hs_m": 1.5, "Tz_s": 6.25}])
    checked = 0
    for row in rows:
        sea = next(s for s in seas if g6(s["Hs_m"]) == row["Hs_m"])
        pos = sea["mean"] if row["position"] == "mean" else next(
            p for p in sea["positions"] if p["position"] == row["position"])
        assert row["msi_pct"] == g6(pos["msi_pct"]), row
        assert row["rms_accel_g"] == g6(pos["rms_accel_g"]), row
        checked += 1
    assert checked >= 8  # 2 seas x (3 positions + mean)


def test_design_from_a_config_matches_the_physics_calls(tmp_path):
    cfg = tmp_path / "npl5b.yaml"
    cfg.write_text(hull_yaml(f"solver: {{ sections: 20, panels: 8, Cs: 0.065, adaptive_grid: off }}\n"))
    d = hullopt.load_design(str(cfg), "npl5b")
    assert d.speed_m_s == SPEED_M_S
    a = d.raos(OMEGA)
    hull = hullopt.generate_hull(hullopt.DesignVariables(**NPL5B))
    b = hullopt.compute_raos(hull, hullopt.mass_properties(hull), SPEED_M_S, OMEGA, solver=SOLVER)
    np.testing.assert_array_equal(a["heave"], b["heave"])
    np.testing.assert_array_equal(a["pitch"], b["pitch"])


def test_hydrostatics_meets_the_displacement():
    hull = hullopt.generate_hull(hullopt.DesignVariables(**NPL5B))
    hs = hullopt.hydrostatics(hull)
    # The generator scales to the target displacement to round-off (docs/hull-generator.md).
    assert hs["displacement_t"] == pytest.approx(1000.0, rel=1e-9)
    assert hs["L_m"] / hs["B_m"] == pytest.approx(11.0, rel=0.02)  # Table 1 tolerance of the generator


def test_bad_variable_raises_with_the_cli_message(tmp_path):
    bad = dict(NPL5B, Cp=1.0)
    with pytest.raises(ValueError) as py_err:
        hullopt.generate_hull(hullopt.DesignVariables(**bad))
    cfg = tmp_path / "bad.yaml"
    cfg.write_text(hull_yaml().replace("Cp: 0.69", "Cp: 1.0"))
    r = run_cli("hull", str(cfg), "--out", str(tmp_path / "h"))
    assert r.returncode == 1
    # The library names the variable ("Cp = 1: rule"), the CLI the key and line; the rule is the same text.
    variable, rule = str(py_err.value).split(": ", 1)
    assert variable == "Cp = 1"
    assert "key 'hull.parametric.Cp' = 1.0: " + rule in r.stderr, (str(py_err.value), r.stderr)
    # Read through the config readers, the message is the CLI's line itself.
    with pytest.raises(hullopt.InputError) as cfg_err:
        hullopt.load_hull(str(cfg))
    assert r.stderr.strip() == "hullopt: error: " + str(cfg_err.value)


def test_unknown_solver_key_is_named():
    hull = hullopt.generate_hull(hullopt.DesignVariables(**NPL5B))
    with pytest.raises(hullopt.InputError, match="sectoins"):
        hullopt.compute_raos(hull, hullopt.mass_properties(hull), SPEED_M_S, OMEGA, solver={"sectoins": 20})


def test_run_a_command_in_process(tmp_path):
    cfg = tmp_path / "npl5b.yaml"
    cfg.write_text(hull_yaml())
    hullopt.run(["hull", str(cfg), "--out", str(tmp_path / "h")])
    assert (tmp_path / "h" / "hydrostatics.json").exists()
    with pytest.raises(hullopt.InputError):
        hullopt.run(["hull", str(tmp_path / "missing.yaml"), "--out", str(tmp_path / "h2")])


def test_knots_given_as_metres_per_second_are_flagged_and_absurd_speeds_refused():
    """The validity envelope applies to the module as to the commands: 40 (knots) passed as m/s is Fn 1.5 and
    Fn_vol 4.1 on the NPL 5b-like catamaran (flagged: planing), 74 m/s is Fn_vol 7.5 (refused)."""
    hull = hullopt.generate_hull(hullopt.DesignVariables(**NPL5B))
    mass = hullopt.mass_properties(hull)
    rao = hullopt.compute_raos(hull, mass, 40.0, [0.6, 1.0], solver={"sections": 10, "panels": 6})
    assert any(w.startswith("Fn_vol = 4.") for w in rao["warnings"]), rao["warnings"]
    with pytest.raises(hullopt.InputError, match=r"key 'speed': .* validity envelope"):
        hullopt.compute_raos(hull, mass, 74.0, [0.6, 1.0], solver={"sections": 10, "panels": 6})


def test_a_steep_sea_is_flagged_in_the_evaluation():
    hull = hullopt.generate_hull(hullopt.DesignVariables(**NPL5B))
    mass = hullopt.mass_properties(hull)
    rao = hullopt.compute_raos(hull, mass, SPEED_M_S, hullopt.evaluation_frequencies(), solver={"sections": 10, "panels": 6})
    seas = hullopt.evaluate(rao, hull, mass, [{"Hs_m": 1.0, "Tz_s": 5.0}, {"Hs_m": 6.0, "Tz_s": 5.0}])
    assert seas[0]["warnings"] == []
    assert any(w.startswith("Hs/lambda_p = ") for w in seas[1]["warnings"]), seas[1]["warnings"]


# A design from Python values (no YAML anywhere) against the CLI's on the same design. The in-process reference
# is load_design (the CLI's config reader and builder); the binary's files hold 10 (rao.csv) and 6 (msi.csv)
# significant digits, compared digit for digit.
# Round-off allowance: both routes run the same operations in the same order, so they agree to the bit; 1e-12
# of the largest RAO amplitude leaves room only for a difference in the last bits, none for a different design.
RAO_TOLERANCE = 1e-12
MASS = {"kyy_over_L": 0.26, "kg_m": 4.0}


def design_yaml(solver_line):
    return hull_yaml(f"solver: {solver_line}\nmass: {{ kyy_over_L: 0.26, kg_m: 4.0 }}\n")


def assert_raos_close(a, b):
    scale = max(np.max(np.abs(b["heave"])), np.max(np.abs(b["pitch"])))
    np.testing.assert_array_equal(a["omega_rad_s"], b["omega_rad_s"])
    assert np.max(np.abs(a["heave"] - b["heave"])) <= RAO_TOLERANCE * scale
    assert np.max(np.abs(a["pitch"] - b["pitch"])) <= RAO_TOLERANCE * scale


def test_a_design_from_python_values_matches_the_cli(tmp_path):
    solver = dict(SOLVER, steady_flow=True)  # the running attitude solved in calm water, once
    d = hullopt.design(NPL5B, speed_kn=40, mass=MASS, solver=solver, water={"rho_kg_m3": 1025, "g_m_s2": 9.81},
                       name="npl5b")
    freqs = ", ".join(str(w) for w in OMEGA)
    cfg = tmp_path / "npl5b.yaml"
    cfg.write_text(design_yaml(f"{{ sections: {SOLVER['sections']}, panels: {SOLVER['panels']}, Cs: {SOLVER['Cs']}, "
                               f"adaptive_grid: off, steady_flow: on, frequencies: {{ omega_rad_s: [{freqs}] }} }}"))
    ref = hullopt.load_design(str(cfg), "npl5b")
    assert d.speed_m_s == ref.speed_m_s == SPEED_M_S
    assert (d.sinkage_m, d.trim_deg) == (ref.sinkage_m, ref.trim_deg)
    assert d.trim_deg != 0.0  # the attitude was solved, not left at even keel
    assert (d.mass.kyy_m, d.mass.kg_m, d.mass.lcg_m_from_ap) == (ref.mass.kyy_m, ref.mass.kg_m, ref.mass.lcg_m_from_ap)
    rao = d.raos(OMEGA)
    assert_raos_close(rao, ref.raos(OMEGA))

    r = run_cli("rao", str(cfg), "--out", str(tmp_path / "rao"))
    assert r.returncode == 0, r.stderr
    rows = csv_rows(tmp_path / "rao" / "rao.csv")
    assert len(rows) == len(OMEGA)
    for i, row in enumerate(rows):
        assert row["heave_amp"] == g10(abs(rao["heave"][i]))
        assert row["pitch_amp"] == g10(abs(rao["pitch"][i]))
        assert row["pitch_phase_deg"] == g10(np.degrees(np.angle(rao["pitch"][i])))


def test_a_design_from_python_values_has_the_cli_msi(tmp_path):
    d = hullopt.design(hullopt.DesignVariables(**NPL5B), speed_m_s=SPEED_M_S, mass=MASS, solver=SOLVER)
    cfg = tmp_path / "npl5b.yaml"
    cfg.write_text(design_yaml(f"{{ sections: {SOLVER['sections']}, panels: {SOLVER['panels']}, Cs: {SOLVER['Cs']}, "
                               "adaptive_grid: off }"))
    seas = [{"Hs_m": 3.0, "Tz_s": 7.5}, {"Hs_m": 1.5, "Tz_s": 6.25}]
    ev_cfg = tmp_path / "evaluate.yaml"
    ev_cfg.write_text("designs:\n  - { config: %s, name: npl5b }\nseas:\n  - { Hs_m: 3.0, Tz_s: 7.5 }\n"
                      "  - { Hs_m: 1.5, Tz_s: 6.25 }\n" % cfg)
    r = run_cli("evaluate", str(ev_cfg), "--out", str(tmp_path / "ev"))
    assert r.returncode == 0, r.stderr
    rows = [row for row in csv_rows(tmp_path / "ev" / "msi.csv") if row["design"] == "npl5b"]

    rao = d.raos()  # the evaluation grid, as `hullopt evaluate` takes it
    ref = hullopt.load_design(str(cfg), "npl5b").raos()
    assert_raos_close(rao, ref)
    ours = hullopt.evaluate(rao, d.hull, d.mass, seas=seas)
    theirs = hullopt.evaluate(ref, d.hull, d.mass, seas=seas)
    checked = 0
    for row in rows:
        i = next(k for k, s in enumerate(ours) if g6(s["Hs_m"]) == row["Hs_m"])
        pick = (lambda s: s["mean"]) if row["position"] == "mean" else (
            lambda s: next(p for p in s["positions"] if p["position"] == row["position"]))
        a, b = pick(ours[i]), pick(theirs[i])
        assert a["msi_pct"] == pytest.approx(b["msi_pct"], rel=RAO_TOLERANCE, abs=1e-300)
        assert row["msi_pct"] == g6(a["msi_pct"]), row
        assert row["rms_accel_g"] == g6(a["rms_accel_g"]), row
        checked += 1
    assert checked >= 8  # 2 seas x (3 positions + mean)


def test_a_python_design_takes_its_speed_in_knots_or_metres_per_second():
    kn = hullopt.design(NPL5B, speed_kn=40, solver={"sections": 10, "panels": 6})
    m_s = hullopt.design(NPL5B, speed_m_s=SPEED_M_S, solver={"sections": 10, "panels": 6})
    assert kn.speed_m_s == m_s.speed_m_s == SPEED_M_S
    with pytest.raises(TypeError, match="not both"):
        hullopt.design(NPL5B, speed_kn=40, speed_m_s=SPEED_M_S)
    with pytest.raises(TypeError, match="speed_kn= .* or speed_m_s="):
        hullopt.design(NPL5B)


def test_a_python_design_names_a_bad_key_and_a_bad_value():
    with pytest.raises(hullopt.InputError, match="unknown key 'sectoins'"):
        hullopt.design(NPL5B, speed_kn=40, solver={"sectoins": 20})
    with pytest.raises(hullopt.InputError, match="kyy_over_L"):
        hullopt.design(NPL5B, speed_kn=40, mass={"kyy_over_L": 0.9})
    # A rule that needs the hull: the LCG must lie on the generated hull's waterline length.
    with pytest.raises(hullopt.InputError, match="mass.lcg_m_from_ap"):
        hullopt.design(NPL5B, speed_kn=40, mass={"lcg_m_from_ap": 1.0e6})


def test_raos_as_a_labelled_dataset_whose_summary_is_the_cli_line(tmp_path):
    d = hullopt.design(NPL5B, speed_kn=40, solver=SOLVER, name="npl5b")
    ds = d.rao_dataset(OMEGA)
    assert ds["heave"].dims == ("omega",) and ds["pitch"].dims == ("omega",)
    assert ds["omega"].attrs["units"] == "rad/s" and ds["omega_e"].attrs["units"] == "rad/s"
    assert ds["lambda_over_L"].attrs["units"] == "1"
    assert ds["heave"].attrs["units"] == "m/m" and ds["pitch"].attrs["units"] == "rad/rad"
    rao = d.raos(OMEGA)
    np.testing.assert_array_equal(ds["heave"].values, rao["heave"])
    np.testing.assert_array_equal(ds["omega"].values, rao["omega_rad_s"])
    assert ds.attrs["speed_m_s"] == SPEED_M_S

    freqs = ", ".join(str(w) for w in OMEGA)
    cfg = tmp_path / "npl5b.yaml"
    cfg.write_text(hull_yaml(f"solver: {{ sections: {SOLVER['sections']}, panels: {SOLVER['panels']}, "
                             f"Cs: {SOLVER['Cs']}, adaptive_grid: off, frequencies: {{ omega_rad_s: [{freqs}] }} }}\n"))
    r = run_cli("rao", str(cfg), "--out", str(tmp_path / "rao"))
    assert r.returncode == 0, r.stderr
    assert r.stdout.startswith(ds.attrs["summary"] + ";"), (r.stdout, ds.attrs["summary"])
    assert "summary:      hull 'npl5b': heave peak" in repr(ds)  # the repr shows it (cut at the display width)


def test_flags_come_through_pythons_warnings():
    hull = hullopt.generate_hull(hullopt.DesignVariables(**NPL5B))
    mass = hullopt.mass_properties(hull)
    rao = hullopt.compute_raos(hull, mass, 40.0, [0.6, 1.0], solver={"sections": 10, "panels": 6})  # 40 "m/s"
    with pytest.warns(hullopt.HulloptWarning, match=r"Fn_vol = 4\."):
        ds = hullopt.rao_dataset(rao, hullopt.hydrostatics(hull)["L_m"])
    assert "Fn_vol = 4." in ds.attrs["warnings"]


def test_an_evaluation_as_a_labelled_dataset():
    d = hullopt.design(NPL5B, speed_kn=40, solver={"sections": 10, "panels": 6})
    seas = hullopt.evaluate(d.raos(), d.hull, d.mass, seas=[{"Hs_m": 3.0, "Tz_s": 7.5}, {"Hs_m": 1.5, "Tz_s": 6.25}])
    ds = hullopt.evaluation_dataset(seas, "npl5b")
    assert ds["msi_pct"].dims == ("sea", "position")
    assert list(ds["position"].values) == ["forward", "lcg", "transom", "mean"]
    assert ds["msi_pct"].attrs["units"] == "%" and ds["rms_accel_g"].attrs["units"] == "g"
    assert ds["Hs_m"].attrs["units"] == "m" and list(ds["Hs_m"].values) == [3.0, 1.5]
    assert ds["msi_pct"].sel(position="mean").values[0] == seas[0]["mean"]["msi_pct"]
    assert ds["rms_accel_g"].sel(position="lcg").values[1] == seas[1]["positions"][1]["rms_accel_g"]
