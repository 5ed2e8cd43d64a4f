"""A campaign run from Python (hullopt.optimize, no YAML text) against the CLI's, and resume from Python.

Run by ctest (python_bindings) with PYTHONPATH=<build>/python and HULLOPT_BIN=<build>/app/hullopt.
"""
import math
import os
import subprocess

import pandas as pd
import pytest
import yaml

import hullopt

BIN = os.environ["HULLOPT_BIN"]
ROOT = os.environ.get("HULLOPT_SOURCE_DIR", os.getcwd())

# Both sides log and compute with the same binary code and the log is written with 17 significant digits
# (read back bit for bit), so they agree exactly; 1e-12 relative is the brief's bound, far above rounding in
# a CSV round trip (0) and far below any change a different design or evaluation would make.
REL_TOL = 1e-12


def small_campaign():
    """The default campaign (configs/optimize-catamaran.yaml) as a dict, cut down: the coarse 20 x 8 strip grid,
    one start of 12 COBYLA evaluations (13 with the base design; about a second on one core)."""
    with open(os.path.join(ROOT, "configs", "optimize-catamaran.yaml")) as f:
        config = yaml.safe_load(f)
    config["solver"].update({"sections": 20, "panels": 8})
    config["optimize"].update({"max_evaluations": 12})
    return config


def write_yaml(config, path):
    with open(path, "w") as f:
        yaml.safe_dump(config, f, sort_keys=False)


def cli_history(path):
    return pd.read_csv(path)


def assert_same_history(a, b):
    """Every column but wall_time_s: numbers within REL_TOL, the rest equal."""
    assert list(a.columns) == list(b.columns)
    assert len(a) == len(b)
    for col in a.columns:
        if col == "wall_time_s":
            continue
        for i, (x, y) in enumerate(zip(a[col], b[col])):
            if isinstance(x, str) or isinstance(y, str) or col == "message":
                xs = "" if (isinstance(x, float) and math.isnan(x)) else str(x)
                ys = "" if (isinstance(y, float) and math.isnan(y)) else str(y)
                assert xs == ys, (col, i, x, y)
            elif math.isnan(float(x)) or math.isnan(float(y)):
                assert math.isnan(float(x)) and math.isnan(float(y)), (col, i, x, y)
            else:
                assert float(x) == pytest.approx(float(y), rel=REL_TOL, abs=0.0), (col, i, x, y)


def test_optimize_from_a_dict_equals_the_cli(tmp_path):
    config = small_campaign()
    write_yaml(config, tmp_path / "campaign.yaml")
    cli = subprocess.run([BIN, "optimize", str(tmp_path / "campaign.yaml"), "--out", str(tmp_path / "cli"),
                          "--threads", "1", "--quiet", "--no-plots"], capture_output=True, text=True)
    assert cli.returncode == 0, cli.stderr
    result = hullopt.optimize(config, out=tmp_path / "py", threads=1, plots=False)
    assert result.complete
    assert len(result.history) == 13  # the base design and 12 evaluations of the one start
    # Same columns under the CSV's names (units in the names, e.g. L_max_m is L_m), same values.
    assert_same_history(result.history, cli_history(tmp_path / "cli" / "history.csv"))
    assert "L_m" in result.history.columns
    # best: the feasible row of lowest objective, as summary.json says.
    feasible = result.history[result.history["feasible"]]
    assert result.best["objective"] == feasible["objective"].min()
    assert result.best["evaluation"] == result.summary["best_evaluation"]
    for name in ("L_over_B", "B_over_T", "Cp", "LCF_pct_L"):
        assert result.best[name] == result.history.loc[result.best["evaluation"], name]
    # The repr reads like the CLI's result lines.
    text = repr(result)
    assert "best objective" in text and "at evaluation" in text
    assert cli.stdout == ""  # --quiet: the CLI printed nothing


def test_optimize_from_a_file_writes_what_the_cli_writes(tmp_path):
    config = small_campaign()
    write_yaml(config, tmp_path / "campaign.yaml")
    result = hullopt.optimize(str(tmp_path / "campaign.yaml"), out=tmp_path / "py", threads=1, plots=False)
    for f in ("history.csv", "summary.json", "best.yaml", "config.resolved.yaml"):
        assert (tmp_path / "py" / f).exists(), f
    assert_same_history(result.history, cli_history(tmp_path / "py" / "history.csv"))


def test_stopped_and_resumed_equals_uninterrupted(tmp_path):
    config = small_campaign()
    whole = hullopt.optimize(config, out=tmp_path / "whole", threads=1, plots=False)
    first = hullopt.optimize(config, out=tmp_path / "part", threads=1, plots=False, max_evaluations=5)
    assert not first.complete
    assert len(first.history) == 5
    assert "stopped at max_evaluations" in repr(first)
    assert not (tmp_path / "part" / "summary.json").exists()
    second = hullopt.optimize(config, out=tmp_path / "part", threads=1, plots=False)
    assert second.complete
    assert second.replayed == 5
    # Nothing evaluated twice: the resumed call computed exactly the evaluations the first did not.
    assert second.summary["replayed_evaluations"] == 5
    assert second.summary["computed_evaluations"] == len(whole.history) - 5
    assert list(second.history["evaluation"]) == list(range(len(whole.history)))
    assert_same_history(second.history, whole.history)
    assert_same_history(second.history, cli_history(tmp_path / "part" / "history.csv"))
    assert second.best == whole.best


def test_resume_off_refuses_a_folder_with_a_log(tmp_path):
    config = small_campaign()
    hullopt.optimize(config, out=tmp_path / "c", threads=1, plots=False, max_evaluations=2)
    with pytest.raises(hullopt.InputError, match="resume is off"):
        hullopt.optimize(config, out=tmp_path / "c", threads=1, plots=False, resume=False)


def test_a_bad_campaign_dict_is_refused_with_the_key(tmp_path):
    config = small_campaign()
    config["optimize"]["max_evaluationz"] = 3
    with pytest.raises(hullopt.InputError, match="max_evaluationz"):
        hullopt.optimize(config, out=tmp_path / "bad", plots=False)


def test_a_pareto_sweep_needs_a_config_file(tmp_path):
    config = small_campaign()
    config["optimize"]["pareto"] = {"quantity": "P_E_kW", "points": 2, "to": 10000}
    with pytest.raises(hullopt.InputError, match="optimize.pareto"):
        hullopt.optimize(config, out=tmp_path / "p", plots=False)
