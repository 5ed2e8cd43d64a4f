#!/usr/bin/python3
"""The user manual against the code.

(a) Every key a command reads is in that command's page: each command is run on its example configs (coarse
    solver settings in temporary copies, to keep the check under a minute) and the key paths of the written
    config.resolved.yaml, which records every key read with its default, must each appear in the key tables of
    docs/commands/<command>.md or of the shared blocks that page names (docs/commands/common-blocks.md).
(b) No documented key is rejected: every documented key of a command appears in some config.resolved.yaml of
    that command, or in READ_WHEN_PRESENT below (keys read only when given, which the runs here do not reach),
    whose last component must be a string literal of the readers in io/formats/, io/config/, io/report/ and app/.
(c) No page refers to a file outside the repository, and every relative link of docs/ and README.md points to
    an existing file.

Usage: check_doc_keys.py HULLOPT_BINARY   (run from the repository root)
"""
import copy
import os
import re
import subprocess
import sys
import tempfile

import yaml

ROOT = os.path.abspath(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
COMMANDS = ["hull", "section", "rao", "coefficients", "evaluate", "optimize", "explore", "calibrate", "resistance", "design"]

# Keys that hold file paths: made absolute in the temporary copies so they read the same files wherever the
# copy lives (tried beside the original config, then from the repository root).
PATH_KEYS = {"offsets_csv", "stl", "data", "forced_heave_csv", "forced_pitch_csv", "wave_loads_csv", "rao_csv",
             "config", "scatter_csv", "tank_rao_csv"}

# Mappings whose keys are names the user chooses (variables, constraints, parameters): one placeholder.
USER_NAMED = {"variables", "start", "constraints", "parameters"}
PLACEHOLDER = "<name>"

COARSE = {"sections": 6, "panels": 4}
FEW_FREQUENCIES = {"range": {"quantity": "lambda_over_L", "from": 1.0, "to": 3.0, "count": 3}}

# Keys read only when present on paths the runs below do not take (alternative inputs, Pareto sweeps, the
# cost-estimate override...). Each must also be documented; its last component is checked against the source.
READ_WHEN_PRESENT = {
    "optimize": ["optimize.pareto.quantity", "optimize.pareto.points", "optimize.pareto.from", "optimize.pareto.to",
                 "optimize.pareto.starts", "solver.time_scheme",
                 # the objective over headings (tests/cli/campaign_headings.sh runs it)
                 "optimize.objective.headings_deg", "optimize.objective.heading_weights"],
    # read with `solver.path: time_marching` only
    "explore": ["solver.time_scheme", "explore.objective.headings_deg", "explore.objective.heading_weights"],
    "calibrate": ["solver.time_scheme", "mass.kyy_over_L", "mass.kg_over_T"],
    # the campaigns' ratio keys, accepted instead of mass.kyy_m / mass.kg_m (a campaign's best.yaml)
    **{c: ["solver.time_scheme", "mass.kyy_over_L", "mass.kg_over_T"] for c in ("rao", "coefficients", "evaluate")},
    "hull": ["mass.kyy_over_L", "mass.kg_over_T"],
    "design": ["solver.time_scheme", "mass.kyy_over_L", "mass.kg_over_T"],
}
# solver.panel_spacing, solver.section_formulation, solver.body_potential, solver.steady_flow and
# solver.adaptive_grid* are read only when given, by every command with a solver block.
for _c in ("rao", "coefficients", "evaluate", "optimize", "explore", "calibrate", "design"):
    READ_WHEN_PRESENT[_c] = READ_WHEN_PRESENT.get(_c, []) + ["solver.panel_spacing.end_spacing",
                                                              "solver.panel_spacing.grading",
                                                              "solver.section_formulation",
                                                              "solver.body_potential",
                                                              "solver.steady_flow",
                                                              "solver.adaptive_grid",
                                                              "solver.adaptive_grid_max_passes",
                                                              "solver.adaptive_grid_max_frequencies"]
# rao's oblique-sea keys, read only with solver.headings_deg.
READ_WHEN_PRESENT["rao"] += ["solver.headings_deg", "mass.kxx_m", "solver.roll_damping", "solver.roll_amplitude_deg"]


# Keys that once appeared in the documentation and that every command refuses.
REFUSED_KEYS = ["heading_deg"]


def fail(msg):
    print("FAIL " + msg)
    return 1


def absolutise(node, base_dir):
    """Path values of node made absolute (beside the config first, then from the repository root)."""
    def fix(v):
        if not isinstance(v, str) or os.path.isabs(v):
            return v
        for d in (base_dir, ROOT):
            p = os.path.normpath(os.path.join(d, v))
            if os.path.exists(p):
                return p
        return v
    if isinstance(node, dict):
        for k, v in node.items():
            if k in PATH_KEYS:
                node[k] = [fix(x) for x in v] if isinstance(v, list) else fix(v)
            else:
                absolutise(v, base_dir)
    elif isinstance(node, list):
        for v in node:
            absolutise(v, base_dir)


def merge(base, over):
    for k, v in over.items():
        if v is None:
            base.pop(k, None)
        elif isinstance(v, dict) and isinstance(base.get(k), dict) and k != "frequencies":
            merge(base[k], v)
        else:
            base[k] = copy.deepcopy(v)
    return base


def key_paths(node, prefix=""):
    """Dotted key paths of the leaves of a resolved config ('[]' for list elements that are mappings)."""
    out = set()
    if isinstance(node, dict):
        user_named = prefix.split(".")[-1].replace("[]", "") in USER_NAMED
        for k, v in node.items():
            name = PLACEHOLDER if user_named else str(k)
            p = prefix + "." + name if prefix else name
            if isinstance(v, dict):
                out |= key_paths(v, p)  # an empty mapping holds no key
            elif isinstance(v, list) and v and all(isinstance(x, dict) for x in v):
                for x in v:
                    out |= key_paths(x, p + "[]")
            else:
                out.add(p)
    return out


# Each run: (command, config relative to the repository, overrides merged into a copy, or a whole config).
HULL_P = {"type": "catamaran", "displacement_t": 1000, "L_over_B": 11, "B_over_T": 2, "Cb": 0.4, "Cp": 0.69,
          "Cwp": 0.76, "LCB_pct_L": -6.4, "LCF_pct_L": -8.3}
RUNS = [
    ("design", "configs/davis-holloway-2003/hull02_NPL5b.yaml", {"solver": dict(COARSE)}),
    ("design", "configs/delft372_offsets.yaml",
     {"solver": dict(COARSE), "positions": {"points": [{"name": "bridge", "x_from_cg_m": 0.5}]},
      "resolution_check": {"enabled": True, "factor": 2, "msi_tolerance_pct": 1.0, "peak_tolerance_pct": 3.0}}),
    ("hull", "examples/hull_catamaran.yaml", {}),
    ("hull", "configs/delft372_offsets.yaml", {"hull": {"stations": 21}}),
    ("hull", "examples/rao_delft372_running_attitude.yaml", {"speed": {"Fn": None, "m_s": 2.0}}),
    ("hull", None, {"hull": {"stl": "tests/fuzz/corpus/stl/box_ascii.stl", "draught_m": 0.2}}),
    ("section", "examples/section_semicircle.yaml", {"section": {"frequencies": {"omega_rad_s": [1.0, 2.0]}}}),
    ("section", "examples/section_delft372_station.yaml", {"section": {"method": None}}),
    ("section", None, {"section": {"shape": "lewis", "beam_m": 2.0, "draught_m": 1.0, "area_coefficient": 0.8,
                                   "frequencies": {"omega_min_rad_s": 1.0, "omega_max_rad_s": 2.0, "count": 2}}}),
    ("section", None, {"section": {"shape": "rectangle", "beam_m": 2.0, "draught_m": 1.0,
                                   "frequencies": {"omega_min_rad_s": 1.0, "omega_max_rad_s": 2.0, "count": 2}}}),
    ("rao", "examples/rao_delft372.yaml", {"solver": dict(COARSE, frequencies=FEW_FREQUENCIES)}),
    ("rao", "examples/rao_delft372_running_attitude.yaml",
     {"solver": dict(COARSE, kernel="impulsive", frequencies={"omega_rad_s": [4.0, 5.0]})}),
    ("rao", "examples/hull_catamaran.yaml",
     {"hull": {"parametric": {"stations": 11, "section_points": 8}},
      "solver": dict(COARSE, method="strip_theory_stf", frequencies={"lambda_over_L": [1.0, 2.0]})}),
    ("rao", "examples/rao_delft372.yaml",
     {"solver": dict(COARSE, sectional_force="pressure", frequencies={"omega_e_rad_s": [8.0, 9.0]})}),
    ("coefficients", "examples/coefficients_delft372.yaml",
     {"solver": dict(COARSE, frequencies={"range": {"quantity": "omega_e_rad_s", "from": 5, "to": 6.5, "count": 3}})}),
    ("evaluate", "examples/evaluate_from_rao_csv.yaml", {"report": {"plots": False}}),
    ("evaluate", "configs/davis-holloway-2003.yaml", {"designs": "FIRST", "report": {"plots": False}}),
    ("evaluate", None, {
        "designs": [{"name": "a", "group": "g", "rao_csv": "examples/data/synthetic_catamaran_rao.csv",
                     "cg_to_transom_m": 18.0, "cg_to_bow_m": 24.0, "parameters": {"Fr": 0.8}}],
        "water": {"g_m_s2": 9.81, "rho_kg_m3": 1025},
        "seas": [{"spectrum": "bretschneider", "Hs_m": 1.0, "Tp_s": 7.0},
                 {"spectrum": "jonswap", "Hs_m": 2.0, "Tz_s": 6.0, "gamma": 3.3}],
        "report": {"plots": False}}),
    ("evaluate", "examples/hull_catamaran.yaml", {
        "hull": {"parametric": {"stations": 11, "section_points": 8}},
        "solver": dict(COARSE, frequencies={"lambda_over_L": [0.8, 1.2, 1.6, 2.0, 2.5, 3.0]}),
        "seas": [{"Hs_m": 1.0, "Tz_s": 5.5}], "msi": {"model": "lloyd"},
        "resolution_check": {"enabled": True, "factor": 2},
        "operability": {"scatter_csv": "SCATTER", "probabilities": "percent",
                        "criteria": [{"msi_max_pct": 20, "name": "msi20"}, {"rms_accel_max_g": 0.1},
                                     {"nordforsk": "transit_passengers", "position": "lcg"}],
                        "polar": {"speeds_kn": [0, 20], "headings_deg": [0, 90, 180],
                                  "criteria": [{"rms_vertical_accel_max_g": 0.275, "position": "forward"},
                                               {"rms_lateral_accel_max_g": 0.1, "position": "lcg", "y_m": 1.0,
                                                "z_m": 3.0, "name": "lateral", "source": "NORDFORSK 1987"},
                                               {"roll_rms_max_deg": 4.0}, {"msi_max_pct": 10}]}},
        "mass": {"kg_m": 3.0, "kxx_m": 5.0},
        "report": {"plots": False}}),
    ("optimize", "examples/optimize_analytic_demo.yaml",
     {"optimize": {"max_evaluations": 5, "starts": 1, "polish": {"algorithm": "LN_NELDERMEAD", "max_evaluations": 3},
                   "objective": {"analytic": "rosenbrock", "eval_delay_ms": 0}}}),
    ("optimize", "configs/optimize-catamaran.yaml",
     {"hull": {"parametric": {"stations": 11, "section_points": 8}},
      "solver": dict(COARSE, frequencies={"lambda_over_L": [1.0, 2.0, 3.0]}),
      "mass": {"kyy_over_L": 0.25, "kg_over_T": 1.0},
      "optimize": {"max_evaluations": 2, "start": {"L_over_B": 11.0}}}),
    ("optimize", "configs/optimize-catamaran.yaml",
     {"hull": {"parametric": {"stations": 11, "section_points": 8}},
      "solver": dict(COARSE, frequencies={"lambda_over_L": [1.0, 2.0, 3.0]}),
      "operability": {"scatter_csv": "SCATTER", "probabilities": "percent", "spectrum": "jonswap", "gamma": 3.3,
                      "criteria": [{"msi_max_pct": 20, "name": "msi20", "position": "mean"}, {"rms_accel_max_g": 0.1},
                                   {"nordforsk": "transit_passengers", "position": "lcg"}]},
      "optimize": {"max_evaluations": 2, "objective": {"measure": "downtime_pct", "criterion": "msi20",
                                                       "sea_weights": None}}}),
    ("explore", "examples/explore_analytic_demo.yaml", {"explore": {"samples": 4}}),
    ("explore", "configs/optimize-catamaran.yaml",
     {"hull": {"parametric": {"stations": 11, "section_points": 8}},
      "solver": dict(COARSE, frequencies={"lambda_over_L": [1.0, 2.0, 3.0]}),
      "operability": {"scatter_csv": "SCATTER", "probabilities": "percent",
                      "criteria": [{"msi_max_pct": 20}, {"rms_accel_max_g": 0.1}, {"nordforsk": "cruise_liner"}]},
      "optimize": {"samples": 2, "objective": {"measure": "downtime_pct", "sea_weights": None}}}),
    ("explore", "configs/optimize-catamaran.yaml",
     {"hull": {"parametric": {"stations": 11, "section_points": 8}},
      "solver": dict(COARSE, frequencies={"lambda_over_L": [1.0, 2.0, 3.0]}),
      "optimize": {"samples": 2, "method": "lhs"}}),
    ("calibrate", "examples/calibrate_synthetic.yaml", {}),
    ("calibrate", "examples/calibrate_delft372.yaml", {"solver": COARSE}),
    ("calibrate", None, {"calibrate": {"mode": "linear_in_parameter", "parameter_name": "q", "hulls": [
        {"name": "A", "parameter": 1.0, "data": ["data/delft372/delft372_tank_rao_fn075.csv"],
         "model": {"synthetic_oscillator": {"length_m": 3.0}}},
        {"name": "B", "parameter": 2.0, "data": ["data/delft372/delft372_tank_rao_fn075.csv"],
         "model": {"synthetic_oscillator": {"length_m": 3.0}}}]}, "speed": {"Fn": 0.75}}),
    ("calibrate", None, {"calibrate": {"speeds_Fn": [0.75], "data": ["data/delft372/delft372_tank_rao_fn075.csv"],
                                       "model": {"synthetic_oscillator": {"length_m": 3.0}}}}),
    ("resistance", "examples/resistance_catamaran.yaml", {}),
    ("resistance", "examples/resistance_delft372.yaml",
     {"resistance": {"speeds_Fn": None, "speeds_kn": [4.0, 5.0], "kinematic_viscosity_m2_s": 1.14e-6}}),
    ("resistance", "examples/hull_catamaran.yaml", {}),
    ("resistance", "examples/resistance_delft372.yaml", {}),
]


def anchor(heading):
    """The anchor of a Markdown heading, as GitHub makes it."""
    return re.sub(r" ", "-", re.sub(r"[^\w\s-]", "", heading.strip().lower()))


def tables(path):
    """{section anchor: [key]} of the key tables of a page (the section is the nearest heading above)."""
    out, section, in_table = {}, "", False
    for line in open(path, encoding="utf-8"):
        s = line.strip()
        h = re.match(r"^#+\s+(.*)$", s)
        if h:
            section = anchor(h.group(1))
        if re.match(r"^\|\s*key\s*\|\s*unit\s*\|\s*default\s*\|\s*rule\s*\|$", s):
            in_table = True
            continue
        if in_table and s.startswith("|"):
            m = re.match(r"^\|\s*`([^`]+)`", s)
            if m:
                out.setdefault(section, []).append(m.group(1))
            continue
        in_table = False
    return out


def documented_keys():
    """{command: (own keys, {shared section: keys})} from docs/commands; None for a missing page."""
    cpath = os.path.join(ROOT, "docs/commands/common-blocks.md")
    common = tables(cpath) if os.path.exists(cpath) else {}
    out = {}
    for c in COMMANDS:
        page = os.path.join(ROOT, "docs/commands", c + ".md")
        if not os.path.exists(page):
            out[c] = None
            continue
        own = {k for keys in tables(page).values() for k in keys}
        text = open(page, encoding="utf-8").read()
        m = re.search(r"^Shared blocks:(.*?)(?:\n\s*\n|\Z)", text, re.M | re.S)
        shared = {}
        for section in re.findall(r"common-blocks\.md#([\w-]+)", m.group(1) if m else ""):
            if section not in common:
                print("FAIL docs/commands/%s.md: common-blocks.md has no key table under #%s" % (c, section))
                shared[section] = {"<missing section %s>" % section}
            else:
                shared[section] = set(common[section])
        out[c] = (own, shared)
    return out


def run_commands(binary, tmp):
    accepted = {c: set() for c in COMMANDS}
    errors = 0
    scatter = os.path.join(tmp, "scatter.csv")
    with open(scatter, "w") as f:
        f.write("Hs_m\\Tz_s,5.5\n1.0,100\n")
    for i, (command, config, over) in enumerate(RUNS):
        base_dir = os.path.dirname(os.path.join(ROOT, config)) if config else ROOT
        data = yaml.safe_load(open(os.path.join(ROOT, config))) if config else {}
        over = copy.deepcopy(over)
        if over.get("designs") == "FIRST":
            over["designs"] = data["designs"][:1]
        if "operability" in over:
            over["operability"]["scatter_csv"] = scatter
        merge(data, over)
        absolutise(data, base_dir)
        cfg = os.path.join(tmp, "run%02d.yaml" % i)
        with open(cfg, "w") as f:
            yaml.safe_dump(data, f, sort_keys=False)
        out = os.path.join(tmp, "out%02d" % i)
        args = [binary, command, cfg, "--out", out]
        if command in ("optimize", "explore"):
            args += ["--quiet", "--threads", "1"]
        p = subprocess.run(args, cwd=ROOT, capture_output=True, text=True)
        if p.returncode != 0:
            errors += fail("%s on %s (run %d): exit %d: %s" % (command, config or "generated config", i,
                                                               p.returncode, (p.stderr or p.stdout).strip()[:400]))
            continue
        resolved = yaml.safe_load(open(os.path.join(out, "config.resolved.yaml")))
        keys = key_paths(resolved)
        if command == "explore":  # explore reads `optimize:` when there is no `explore:` block
            keys = {"explore" + k[len("optimize"):] if k.split(".")[0] == "optimize" else k for k in keys}
        accepted[command] |= keys
    return accepted, errors


def check_present_only():
    errors = 0
    sources = ""
    for d in ("io/formats", "io/config", "io/report", "app"):
        for name in sorted(os.listdir(os.path.join(ROOT, d))):
            if name.endswith(".cpp"):
                sources += open(os.path.join(ROOT, d, name), encoding="utf-8").read()
    for command, keys in READ_WHEN_PRESENT.items():
        for k in keys:
            last = re.split(r"[.\[\]]+", k.rstrip("]"))[-1]
            if '"%s"' % last not in sources:
                errors += fail("%s: READ_WHEN_PRESENT key %s: no reader names \"%s\"" % (command, k, last))
    return errors


def check_links():
    errors = 0
    pages = [os.path.join(ROOT, "README.md"), os.path.join(ROOT, "CHANGELOG.md")]
    for dirpath, _, files in os.walk(os.path.join(ROOT, "docs")):
        pages += [os.path.join(dirpath, f) for f in files if f.endswith(".md")]
    for page in pages:
        text = open(page, encoding="utf-8").read()
        rel = os.path.relpath(page, ROOT)
        for bad in ("ARCHITECTURE", "../shared", "/work/", "theory-notes", "theory notes"):
            if bad in text:
                errors += fail("%s refers to '%s', outside the repository" % (rel, bad))
        for key in REFUSED_KEYS:
            if key in text:
                errors += fail("%s documents `%s`, a key every command refuses" % (rel, key))
        for target in re.findall(r"\]\(([^)\s]+)\)", text):
            if re.match(r"^[a-z]+:", target) or target.startswith("#"):
                continue
            path, _, fragment = target.partition("#")
            full = os.path.normpath(os.path.join(os.path.dirname(page), path))
            if not os.path.exists(full):
                errors += fail("%s: link to %s: no such file" % (rel, target))
            elif fragment and full.endswith(".md"):
                anchors = {anchor(h) for h in re.findall(r"^#+\s+(.*)$", open(full, encoding="utf-8").read(), re.M)}
                if fragment not in anchors:
                    errors += fail("%s: link to %s: no such heading" % (rel, target))
    return errors


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    binary = os.path.abspath(sys.argv[1])
    errors = check_links() + check_present_only()
    documented = documented_keys()
    with tempfile.TemporaryDirectory() as tmp:
        accepted, run_errors = run_commands(binary, tmp)
    errors += run_errors
    if os.environ.get("DOC_KEYS_DUMP"):
        with open(os.environ["DOC_KEYS_DUMP"], "w") as f:
            for c in COMMANDS:
                for k in sorted(accepted[c]):
                    f.write("%s %s\n" % (c, k))
    # A shared section is read by one reader in every command that names it: a key of it read by one of them
    # is accepted by all (the runs need not repeat every alternative of, say, speed for every command).
    shared_read = {}
    for c in COMMANDS:
        if documented[c] is not None:
            for section, keys in documented[c][1].items():
                shared_read.setdefault(section, set()).update(keys & accepted[c])
    for c in COMMANDS:
        if documented[c] is None:
            errors += fail("docs/commands/%s.md is missing" % c)
            continue
        own, shared = documented[c]
        doc = own.union(*shared.values())
        read = accepted[c] | set(READ_WHEN_PRESENT.get(c, []))
        for k in sorted(read - doc):
            errors += fail("%s: key `%s` is read but not documented in docs/commands/%s.md" % (c, k, c))
        if run_errors == 0:
            seen = read.union(*(shared_read[s] for s in shared))
            for k in sorted(doc - seen):
                errors += fail("%s: documented key `%s` is not read by the command (no config.resolved.yaml "
                               "of its runs has it)" % (c, k))
        print("%-12s %3d keys read, %3d documented" % (c, len(read), len(doc)))
    if errors == 0:
        print("doc keys: all checks passed")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
