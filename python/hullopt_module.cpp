// The Python module `hullopt` (extension `hullopt._hullopt`): hull generation and reading, hydrostatics,
// heave and pitch RAOs, seas and MSI, and the command line in-process (campaigns). `design()` turns keyword
// arguments and dicts straight into the typed eval::DesignSpec and builds it with eval::BuildDesign, as the
// commands do; the older calls' option dicts go through the CLI's YAML block readers, so defaults, rules and
// error messages are the CLI's. Arrays are NumPy arrays; units are SI and named in every docstring.
#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <complex>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "app/campaign_report.h"
#include "app/commands.h"
#include "campaign/run_campaign.h"
#include "evaluation/adaptive_frequency_grid.h"
#include "evaluation/design_spec.h"
#include "evaluation/hull_plausibility.h"
#include "evaluation/strip_attitude.h"
#include "evaluation/validity_envelope.h"
#include "hullopt/hullopt.h"
#include "io/config/design_config.h"
#include "io/config/hull_config.h"
#include "io/config/motion_config.h"
#include "io/config/seas_config.h"
#include "io/config/water_config.h"
#include "io/config/yaml_map.h"
#include "io/formats/input_error.h"
#include "io/formats/output_lock.h"
#include "io/formats/utf8_text.h"
#include "optimizer/rao_peak.h"
#include "seakeeping/motions/calm_water.h"
#include "seakeeping/motions/forced_oscillation.h"

namespace py = pybind11;
using namespace hullopt;

namespace {

constexpr const char* kPythonSource = "<python>";

// A Python value (dict, list, str, bool, int, float) as a YAML node, for the config readers.
YAML::Node ToYaml(const py::handle& v) {
  if (py::isinstance<py::dict>(v)) {
    YAML::Node n(YAML::NodeType::Map);
    for (const auto& kv : py::reinterpret_borrow<py::dict>(v)) n[py::str(kv.first).cast<std::string>()] = ToYaml(kv.second);
    return n;
  }
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v) || py::isinstance<py::array>(v)) {
    YAML::Node n(YAML::NodeType::Sequence);
    for (const auto& x : py::iter(v)) n.push_back(ToYaml(x));
    return n;
  }
  if (v.is_none()) return YAML::Node();
  if (py::isinstance<py::bool_>(v)) return YAML::Node(v.cast<bool>() ? "true" : "false");
  if (py::isinstance<py::int_>(v)) return YAML::Node(std::to_string(v.cast<long long>()));
  if (py::isinstance<py::float_>(v)) {
    std::ostringstream os;
    os.precision(17);
    os << v.cast<double>();
    return YAML::Node(os.str());
  }
  return YAML::Node(py::str(v).cast<std::string>());
}

// A root mapping {key: value} read by the CLI's readers.
io::YamlMap RootOf(const std::string& key, const py::object& value) {
  YAML::Node root(YAML::NodeType::Map);
  if (!value.is_none()) root[key] = ToYaml(value);
  return io::YamlMap(root, "", kPythonSource, YAML::Node(YAML::NodeType::Map));
}

py::array_t<double> Array(const std::vector<double>& v) { return py::array_t<double>(v.size(), v.data()); }
py::array_t<std::complex<double>> Array(const std::vector<std::complex<double>>& v) {
  return py::array_t<std::complex<double>>(v.size(), v.data());
}

py::dict HydrostaticsDict(const hull::Hydrostatics& h) {
  py::dict d;
  d["L_m"] = h.L_m; d["B_m"] = h.B_m; d["T_m"] = h.T_m; d["reference_hulls"] = h.reference_hulls;
  d["volume_m3"] = h.volume_m3; d["displacement_kg"] = h.displacement_kg; d["displacement_t"] = h.displacement_t;
  d["lcb_m_from_ap"] = h.lcb_m_from_ap; d["vcb_m"] = h.vcb_m; d["awp_m2"] = h.awp_m2;
  d["lcf_m_from_ap"] = h.lcf_m_from_ap; d["midship_area_m2"] = h.midship_area_m2; d["i_l_m4"] = h.i_l_m4;
  d["i_t_m4"] = h.i_t_m4; d["bm_l_m"] = h.bm_l_m; d["bm_t_m"] = h.bm_t_m; d["kg_m"] = h.kg_m;
  d["gm_l_m"] = h.gm_l_m; d["gm_t_m"] = h.gm_t_m; d["wetted_surface_m2"] = h.wetted_surface_m2;
  d["x_ap_m"] = h.x_ap_m; d["Cb"] = h.Cb; d["Cp"] = h.Cp; d["Cm"] = h.Cm; d["Cwp"] = h.Cwp; d["Cvp"] = h.Cvp;
  d["LCB_pct_L"] = h.LCB_pct_L; d["LCF_pct_L"] = h.LCF_pct_L;
  return d;
}

py::dict RaoDict(const sk::RaoTable& t) {
  py::dict d;
  d["speed_m_s"] = t.speed_m_s;
  d["g_m_s2"] = t.g_m_s2;
  d["omega_rad_s"] = Array(t.omega_rad_s);
  d["omega_e_rad_s"] = Array(t.omega_e_rad_s);
  d["heave"] = Array(t.heave);
  d["pitch"] = Array(t.pitch);
  d["warnings"] = t.warnings;
  return d;
}

sk::RaoTable RaoFromDict(const py::dict& d) {
  sk::RaoTable t;
  t.speed_m_s = d["speed_m_s"].cast<double>();
  t.g_m_s2 = d["g_m_s2"].cast<double>();
  t.omega_rad_s = d["omega_rad_s"].cast<std::vector<double>>();
  t.omega_e_rad_s = d["omega_e_rad_s"].cast<std::vector<double>>();
  t.heave = d["heave"].cast<std::vector<std::complex<double>>>();
  t.pitch = d["pitch"].cast<std::vector<std::complex<double>>>();
  if (d.contains("warnings")) t.warnings = d["warnings"].cast<std::vector<std::string>>();
  return t;
}

py::dict PositionDict(const sk::PositionResult& p) {
  py::dict d;
  d["position"] = p.position; d["x_from_cg_m"] = p.x_from_cg_m; d["rms_accel_m_s2"] = p.rms_accel_m_s2;
  d["rms_accel_g"] = p.rms_accel_g; d["rms_displacement_m"] = p.rms_displacement_m;
  d["omega_char_rad_s"] = p.omega_char_rad_s; d["msi_pct"] = p.msi_pct;
  return d;
}

sk::HullExtent ExtentOf(const hull::Hydrostatics& hs, const hull::MassProperties& m) {
  return {m.lcg_m_from_ap - hs.x_ap_m, hs.x_ap_m + hs.L_m - m.lcg_m_from_ap};
}

io::WaterOptions WaterOf(const py::object& water) {
  io::YamlMap root = RootOf("water", water);
  return io::ParseWater(root);
}

// ---- A design from Python objects: keyword arguments and dicts straight into eval::DesignSpec (no YAML).
// ----

[[noreturn]] void Refuse(const std::string& what) {
  throw io::InputError(std::string(kPythonSource) + ": " + what);
}

std::string Known(const std::vector<std::string>& keys) {
  std::string s;
  for (const auto& k : keys) s += (s.empty() ? "" : ", ") + k;
  return s;
}

// The dict's keys, each checked against the known ones (a misspelt key is named, as a config's would be).
std::vector<std::pair<std::string, py::handle>> Items(const py::object& d, const std::string& block,
                                                      const std::vector<std::string>& known) {
  std::vector<std::pair<std::string, py::handle>> out;
  if (d.is_none()) return out;
  if (!py::isinstance<py::dict>(d)) Refuse(block + ": must be a dict");
  for (const auto& kv : py::reinterpret_borrow<py::dict>(d)) {
    const std::string key = py::str(kv.first);
    if (std::find(known.begin(), known.end(), key) == known.end())
      Refuse(block + ": unknown key '" + key + "' (known: " + Known(known) + ")");
    out.emplace_back(key, kv.second);
  }
  return out;
}

double NumberOf(const py::handle& v, const std::string& key) {
  if (py::isinstance<py::bool_>(v) || !(py::isinstance<py::float_>(v) || py::isinstance<py::int_>(v)))
    Refuse("key '" + key + "': must be a number");
  const double x = v.cast<double>();
  if (!std::isfinite(x)) Refuse("key '" + key + "': must be a finite number");
  return x;
}

int IntegerOf(const py::handle& v, const std::string& key) {
  if (py::isinstance<py::bool_>(v) || !py::isinstance<py::int_>(v))
    Refuse("key '" + key + "': must be a whole number");
  return v.cast<int>();
}

bool SwitchOf(const py::handle& v, const std::string& key) {
  if (py::isinstance<py::bool_>(v)) return v.cast<bool>();
  if (py::isinstance<py::str>(v)) {
    const std::string s = py::str(v);
    if (s == "on") return true;
    if (s == "off") return false;
  }
  Refuse("key '" + key + "': must be True/False (or 'on'/'off')");
}

std::string ChoiceOf(const py::handle& v, const std::string& key, const std::vector<std::string>& choices) {
  const std::string s = py::isinstance<py::str>(v) ? std::string(py::str(v)) : std::string();
  if (std::find(choices.begin(), choices.end(), s) == choices.end())
    Refuse("key '" + key + "': must be one of " + Known(choices));
  return s;
}

eval::WaterOptions TypedWater(const py::object& water) {
  eval::WaterOptions w;
  for (const auto& [k, v] : Items(water, "water", {"rho_kg_m3", "g_m_s2"}))
    (k == "rho_kg_m3" ? w.rho_kg_m3 : w.g_m_s2) = NumberOf(v, "water." + k);
  if (std::string e; !w.IsValid(&e)) Refuse("water: " + e);
  return w;
}

eval::MassSpec TypedMass(const py::object& mass) {
  eval::MassSpec m;
  const std::vector<std::string> known = {"mass_kg",   "lcg_m_from_ap",       "kyy_m", "kyy_over_L", "kg_m",
                                          "kg_over_T", "accept_mass_mismatch"};
  for (const auto& [k, v] : Items(mass, "mass", known)) {
    if (k == "accept_mass_mismatch") {
      m.accept_mass_mismatch = SwitchOf(v, "mass." + k);
      continue;
    }
    const double x = NumberOf(v, "mass." + k);
    if (k == "mass_kg") m.mass_kg = x;
    if (k == "lcg_m_from_ap") m.lcg_m_from_ap = x;
    if (k == "kyy_m") m.kyy_m = x;
    if (k == "kyy_over_L") m.kyy_over_L = x;
    if (k == "kg_m") m.kg_m = x;
    if (k == "kg_over_T") m.kg_over_T = x;
  }
  if (std::string e; !m.IsValid(&e)) Refuse(e);
  return m;
}

// The solver settings a Python design may set; the others keep the defaults of a config without them.
eval::SolverSettings TypedSolver(const py::object& solver) {
  eval::SolverSettings s;
  const std::vector<std::string> known = {"method",      "sections",      "panels",
                                          "Cs",          "path",          "sectional_force",
                                          "steady_flow", "adaptive_grid", "interaction"};
  for (const auto& [k, v] : Items(solver, "solver", known)) {
    const std::string key = "solver." + k;
    if (k == "method")
      s.rao.method = ChoiceOf(v, key, {"time_domain_strip", "strip_theory_stf"}) == "strip_theory_stf"
                         ? sk::RaoSolverOptions::Method::kStripTheory
                         : sk::RaoSolverOptions::Method::kTimeDomainStrip;
    if (k == "sections") s.rao.sections = IntegerOf(v, key);
    if (k == "panels") s.rao.panels = IntegerOf(v, key);
    if (k == "Cs") s.rao.motion.damping_cs = NumberOf(v, key);
    if (k == "path")
      s.rao.path = ChoiceOf(v, key, {"periodic", "time_marching"}) == "periodic"
                       ? sk::RaoSolverOptions::Path::kPeriodic
                       : sk::RaoSolverOptions::Path::kTimeMarching;
    if (k == "sectional_force")
      s.sectional_force = ChoiceOf(v, key, {"momentum", "pressure"}) == "pressure"
                              ? sk::SectionalForce::kPressure
                              : sk::SectionalForce::kMomentum;
    if (k == "steady_flow") s.steady_flow = SwitchOf(v, key);
    if (k == "adaptive_grid") s.grid.enabled = SwitchOf(v, key);
    if (k == "interaction") s.rao.interaction = SwitchOf(v, key);
  }
  if (std::string e; !s.rao.IsValid(&e) || !s.grid.IsValid(&e)) Refuse("solver: " + e);
  if (s.cs() < 0.0) Refuse("key 'solver.Cs': must be >= 0 (the paper's values are 0 to 0.15)");
  return s;
}

// speed_kn= or speed_m_s=, exactly one.
eval::SpeedOptions TypedSpeed(const py::object& kn, const py::object& m_s) {
  if (kn.is_none() == m_s.is_none())
    throw py::type_error(kn.is_none() ? "give the speed: speed_kn= [kn] or speed_m_s= [m/s]"
                                      : "give speed_kn= or speed_m_s=, not both");
  eval::SpeedOptions s;
  s.unit = kn.is_none() ? eval::SpeedOptions::Unit::kMetresPerSecond : eval::SpeedOptions::Unit::kKnots;
  s.value = NumberOf(kn.is_none() ? m_s : kn, kn.is_none() ? "speed_m_s" : "speed_kn");
  if (std::string e; !s.IsValid(&e)) Refuse(e);
  return s;
}

}  // namespace

PYBIND11_MODULE(_hullopt, m) {
  m.doc() = "hullopt: hull-form optimisation of high-speed vessels for seakeeping in head seas";
  m.attr("__version__") = kVersion;
  py::register_exception<io::InputError>(m, "InputError", PyExc_ValueError);

  py::class_<hull::DesignVariables>(m, "DesignVariables",
                                    "Design variables of the parametric hull (Table 1 of Davis & Holloway 2003). "
                                    "Coefficients of one demihull for catamarans and SWATHs, of the whole for the "
                                    "trihull; L, B, T of the main hull / demihull.")
      .def(py::init([](const py::kwargs& kw) {
             hull::DesignVariables dv;
             py::object self = py::cast(dv);
             for (const auto& kv : kw) {
               const std::string key = py::str(kv.first);
               if (!py::hasattr(self, key.c_str()))
                 throw py::type_error("DesignVariables: unknown variable '" + key + "'");
               py::setattr(self, key.c_str(), kv.second);
             }
             return self.cast<hull::DesignVariables>();
           }),
           "DesignVariables(**variables): defaults overridden by keyword, e.g. DesignVariables(L_over_B=12)")
      .def_property(
          "type", [](const hull::DesignVariables& d) { return hull::ToString(d.type); },
          [](hull::DesignVariables& d, const std::string& s) { d.type = hull::ParseHullType(s); },
          "monohull | catamaran | swath | trihull")
      .def_property(
          "section_style", [](const hull::DesignVariables& d) { return hull::ToString(d.section_style); },
          [](hull::DesignVariables& d, const std::string& s) { d.section_style = hull::ParseSectionStyle(s); },
          "round_bilge | hard_chine | swath_bulb")
      .def_readwrite("displacement_t", &hull::DesignVariables::displacement_t, "[t] whole vessel")
      .def_readwrite("rho_kg_m3", &hull::DesignVariables::rho_kg_m3, "[kg/m^3] water density")
      .def_readwrite("L_over_B", &hull::DesignVariables::L_over_B)
      .def_readwrite("B_over_T", &hull::DesignVariables::B_over_T)
      .def_readwrite("Cb", &hull::DesignVariables::Cb)
      .def_readwrite("Cp", &hull::DesignVariables::Cp)
      .def_readwrite("Cwp", &hull::DesignVariables::Cwp)
      .def_readwrite("LCB_pct_L", &hull::DesignVariables::LCB_pct_L, "[% L from midships, + forward]")
      .def_readwrite("LCF_pct_L", &hull::DesignVariables::LCF_pct_L, "[% L from midships, + forward]")
      .def_readwrite("transom_immersion", &hull::DesignVariables::transom_immersion, "transom draught / T")
      .def_readwrite("transom_beam_ratio", &hull::DesignVariables::transom_beam_ratio)
      .def_readwrite("keel_rise", &hull::DesignVariables::keel_rise)
      .def_readwrite("spacing_over_L", &hull::DesignVariables::spacing_over_L)
      .def_readwrite("spacing_m", &hull::DesignVariables::spacing_m, "[m] wins over spacing_over_L if > 0")
      .def_readwrite("strut_ratio", &hull::DesignVariables::strut_ratio)
      .def_readwrite("bulb_height_ratio", &hull::DesignVariables::bulb_height_ratio,
                     "SWATH bulb height at midships / T (0: elliptic bulb scaled to the ends)")
      .def_readwrite("outrigger_length_ratio", &hull::DesignVariables::outrigger_length_ratio)
      .def_readwrite("outrigger_L_over_B", &hull::DesignVariables::outrigger_L_over_B)
      .def_readwrite("outrigger_B_over_T", &hull::DesignVariables::outrigger_B_over_T)
      .def_readwrite("outrigger_offset_over_L", &hull::DesignVariables::outrigger_offset_over_L)
      .def_readwrite("freeboard_over_T", &hull::DesignVariables::freeboard_over_T)
      .def_readwrite("stations", &hull::DesignVariables::stations)
      .def_readwrite("section_points", &hull::DesignVariables::section_points)
      .def("validate",
           [](const hull::DesignVariables& d) {
             std::string error;
             if (!d.IsValid(&error)) throw std::invalid_argument(error);
           },
           "Raises ValueError naming the first variable out of range and its rule.");

  py::class_<hull::HullForm>(m, "Hull", "A hull: bodies of stations (x from AP, y half-breadth, z above base, m).")
      .def_readonly("type", &hull::HullForm::type)
      .def_readonly("draught_m", &hull::HullForm::draught_m, "[m] design waterline above the baseline")
      .def_readonly("length_m", &hull::HullForm::length_m, "[m] waterline length of the main body")
      .def_readonly("adjustments", &hull::HullForm::adjustments,
                    "what the generator changed to build it (on_infeasible: nearest), one line each")
      .def_property_readonly("body_count", [](const hull::HullForm& h) { return h.bodies.size(); })
      .def(
          "stations",
          [](const hull::HullForm& h, std::size_t body) {
            if (body >= h.bodies.size()) throw py::index_error("body index out of range");
            py::list out;
            for (const auto& s : h.bodies[body].stations) {
              py::dict d;
              d["x_m"] = s.x_m;
              d["y_m"] = Array(s.y_m);
              d["z_m"] = Array(s.z_m);
              out.append(d);
            }
            return out;
          },
          py::arg("body") = 0,
          "Stations of one body aft to forward: dicts of x_m [m from AP], y_m [m half-breadth], z_m [m above base]")
      .def_property_readonly("body_y_centre_m", [](const hull::HullForm& h) {
        std::vector<double> y;
        for (const auto& b : h.bodies) y.push_back(b.y_centre_m);
        return Array(y);
      });

  py::class_<hull::MassProperties>(m, "MassProperties", "Mass properties of the whole vessel.")
      .def(py::init<>())
      .def_readwrite("mass_kg", &hull::MassProperties::mass_kg, "[kg]")
      .def_readwrite("lcg_m_from_ap", &hull::MassProperties::lcg_m_from_ap, "[m] from AP")
      .def_readwrite("kyy_m", &hull::MassProperties::kyy_m, "[m] pitch radius of gyration")
      .def_readwrite("kg_m", &hull::MassProperties::kg_m, "[m] above the baseline");

  m.def("generate_hull", &hull::GenerateHull, py::arg("variables"),
        "The parametric hull at the requested displacement. ValueError for variables out of range or a "
        "combination the section families cannot meet (the rule and the numbers).");

  m.def(
      "load_hull",
      [](const std::string& config_file) {
        io::YamlMap root = io::YamlMap::LoadFile(config_file);
        const io::WaterOptions water = io::ParseWater(root);
        return io::LoadHull(io::ParseHullConfig(root, water), config_file);
      },
      py::arg("config_file"),
      "The hull of a config file's hull: block (parametric, offsets_csv or stl), as `hullopt hull` reads it.");

  m.def(
      "hydrostatics",
      [](const hull::HullForm& h, double rho, double kg) { return HydrostaticsDict(hull::ComputeHydrostatics(h, rho, kg)); },
      py::arg("hull"), py::arg("rho_kg_m3") = 1025.0, py::arg("kg_m") = 0.0,
      "Hydrostatics at the design draught in water of density rho_kg_m3 [kg/m^3]; kg_m [m] for GM. A dict "
      "with SI units in the key names (L_m, displacement_t, lcb_m_from_ap, gm_l_m, Cb, ...).");

  m.def(
      "mass_properties",
      [](const hull::HullForm& h, const py::object& mass, const py::object& water) {
        const io::WaterOptions w = WaterOf(water);
        const hull::Hydrostatics hs = hull::ComputeHydrostatics(h, w.rho_kg_m3);
        io::YamlMap root = RootOf("mass", mass);
        io::YamlMap mm = root.MapOrEmpty("mass");
        return io::ParseMassConfig(mm, hs);
      },
      py::arg("hull"), py::arg("mass") = py::none(), py::arg("water") = py::none(),
      "Mass properties as a config's mass: block gives them (dict with mass_kg, lcg_m_from_ap, kyy_m, kg_m; "
      "defaults: the displacement, LCB, 0.25 L, the draught).");

  m.def(
      "compute_raos",
      [](const hull::HullForm& h, const hull::MassProperties& mass, double speed_m_s,
         const std::vector<double>& omega, const py::object& solver, const py::object& water,
         const std::string& name) {
        const io::WaterOptions w = WaterOf(water);
        io::YamlMap root = RootOf("solver", solver.is_none() ? py::object(py::dict()) : solver);
        io::YamlMap sm = root.Map("solver");
        const io::SolverConfig sc = io::ParseSolverConfig(sm, /*frequencies_required=*/false);
        sm.Finish();
        const sk::RaoSolverOptions o = eval::RaoOptions(sc, name, sc.cs());
        // The method's validity envelope, as the commands apply it: refused beyond a hard limit (ValueError),
        // flagged in the returned warnings (a speed in knots given as m/s is flagged or refused here).
        const hull::Hydrostatics hs = hull::ComputeHydrostatics(h, w.rho_kg_m3);
        const std::vector<std::string> flags =
            eval::ApplyDesignEnvelope(w, speed_m_s, sc.cs(), h, hs, &mass, "hull '" + name + "'");
        sk::RaoTable t;
        hull::RunningAttitude attitude;
        {
          py::gil_scoped_release release;
          // solver.steady_flow: on solves the running attitude in calm water first (the hull as given floats at rest).
          attitude = eval::StripAttitude(h, mass, speed_m_s, w, sc, {}, "hull '" + name + "'");
          // solver.adaptive_grid (on by default): the peaks refined from omega, as `hullopt rao` does.
          const sk::RaoSweeper sweeper(sc.steady_flow ? hull::ApplyRunningAttitude(h, attitude) : h, mass, speed_m_s,
                                       w.rho_kg_m3, w.g_m_s2, o,
                                       sk::TransientGreenKernelBuilder(sc.sectional_force, sc.body_potential));
          t = eval::SweepAdaptively(sweeper, omega, sc.grid);
        }
        t.warnings.insert(t.warnings.begin(), flags.begin(), flags.end());
        py::dict d = RaoDict(t);
        if (sc.steady_flow) d["sinkage_m"] = attitude.sinkage_m, d["trim_deg"] = attitude.trim_deg;
        return d;
      },
      py::arg("hull"), py::arg("mass"), py::arg("speed_m_s"), py::arg("omega_rad_s"),
      py::arg("solver") = py::none(), py::arg("water") = py::none(), py::arg("name") = "hull",
      "Heave X3/A [m/m] and pitch X5/(kA) [rad/rad] RAOs (complex, phase lead positive relative to the wave "
      "crest at the CG) at wave frequencies omega_rad_s [rad/s] (increasing) and speed speed_m_s [m/s]. "
      "solver: a dict as a config's solver: block (sections, panels, Cs, method, path, steady_flow, adaptive_grid, "
      "...): with adaptive_grid on (the default) omega_rad_s is refined around the RAO peaks. Returns a "
      "dict of NumPy arrays omega_rad_s, omega_e_rad_s, heave, pitch and a list of warnings (with steady_flow "
      "'on' also the solved sinkage_m, + down, and trim_deg, + bow up).");

  m.def(
      "calm_water",
      [](const hull::HullForm& h, const hull::MassProperties& mass, double speed_m_s, const std::string& sectional_force,
         int sections, int panels, int body, const py::object& attitude, bool elevation, bool wave_resistance,
         const py::object& water) {
        const io::WaterOptions w = WaterOf(water);
        sk::CalmWaterOptions o;
        o.elevation = elevation;
        o.wave_resistance = wave_resistance;
        if (sectional_force != "momentum" && sectional_force != "pressure")
          throw std::invalid_argument("sectional_force must be 'momentum' or 'pressure', got '" + sectional_force + "'");
        o.sectional_force = sectional_force == "pressure" ? sk::SectionalForce::kPressure : sk::SectionalForce::kMomentum;
        o.geometry.sections = sections, o.geometry.panels = panels, o.geometry.body = body;
        py::dict d;
        auto force_dict = [&](const sk::SteadyForce& f) {
          d["heave_N"] = f.heave_N, d["moment_N_m"] = f.moment_N_m;
          d["hydrodynamic_heave_N"] = f.hydrodynamic_heave_N, d["hydrodynamic_moment_N_m"] = f.hydrodynamic_moment_N_m;
          d["x_m"] = Array(f.x_m), d["force_N_per_m"] = Array(f.force_N_per_m),
          d["buoyancy_N_per_m"] = Array(f.buoyancy_N_per_m);
          if (elevation) d["elevation_outer_m"] = Array(f.elevation_outer_m), d["elevation_inner_m"] = Array(f.elevation_inner_m);
          if (wave_resistance) d["power_W_per_m"] = Array(f.power_W_per_m), d["wave_resistance_N"] = f.wave_resistance_N;
        };
        if (!attitude.is_none()) {  // the force at a given (sinkage_m + down, trim_deg + bow up)
          const auto a = attitude.cast<std::pair<double, double>>();
          hull::RunningAttitude ra;
          ra.sinkage_m = a.first, ra.trim_deg = a.second, ra.pivot_x_m = mass.lcg_m_from_ap;
          sk::SteadyForce f;
          {
            py::gil_scoped_release release;
            f = sk::CalmWaterForce(h, mass, ra, speed_m_s, w.rho_kg_m3, w.g_m_s2, o);
          }
          force_dict(f);
          d["sinkage_m"] = ra.sinkage_m, d["trim_deg"] = ra.trim_deg;
          return d;
        }
        sk::CalmWaterResult r;
        {
          py::gil_scoped_release release;
          r = sk::SolveRunningAttitude(h, mass, speed_m_s, w.rho_kg_m3, w.g_m_s2, o);
        }
        force_dict(r.force);
        d["sinkage_m"] = r.attitude.sinkage_m, d["trim_deg"] = r.attitude.trim_deg;
        d["converged"] = r.converged, d["iterations"] = r.iterations, d["note"] = r.note;
        return d;
      },
      py::arg("hull"), py::arg("mass"), py::arg("speed_m_s"), py::arg("sectional_force") = "momentum",
      py::arg("sections") = 40, py::arg("panels") = 14, py::arg("body") = -1, py::arg("attitude") = py::none(),
      py::arg("elevation") = false, py::arg("wave_resistance") = false, py::arg("water") = py::none(),
      "Calm water on the strips of the instantaneous hull at speed_m_s [m/s]: the running sinkage_m (+ down, at "
      "the LCG) and trim_deg (+ bow up) where the steady force and moment vanish, with the steady sectional force "
      "force_N_per_m along x_m (bow first). attitude=(sinkage_m, trim_deg) gives the steady force at that "
      "attitude instead of iterating. elevation=True adds elevation_outer_m and elevation_inner_m, the steady "
      "free-surface elevation at the water line beside each station (+ up; inner: multihulls only). "
      "wave_resistance=True adds wave_resistance_N, the linear 2D+t wave resistance, and power_W_per_m, the "
      "power each station's strip contour delivers to the water (docs/ship-motions.md). The hull as "
      "given floats at rest (its weight is its buoyancy at rest).");

  m.def(
      "forced_oscillation",
      [](const hull::HullForm& h, const hull::MassProperties& mass, double speed_m_s, const std::string& mode,
         double amplitude, double omega_e_rad_s, const std::string& sectional_force, int sections, int panels,
         int body, double sinkage_m, double trim_deg, int analysed_periods, double cs, const py::object& water) {
        const io::WaterOptions w = WaterOf(water);
        sk::ForcedOscillationOptions o;
        if (mode != "heave" && mode != "pitch") throw std::invalid_argument("mode must be 'heave' or 'pitch', got '" + mode + "'");
        if (sectional_force != "momentum" && sectional_force != "pressure")
          throw std::invalid_argument("sectional_force must be 'momentum' or 'pressure', got '" + sectional_force + "'");
        o.mode = mode == "heave" ? sk::ForcedMode::kHeave : sk::ForcedMode::kPitch;
        o.sectional_force = sectional_force == "pressure" ? sk::SectionalForce::kPressure : sk::SectionalForce::kMomentum;
        o.amplitude = amplitude, o.omega_e_rad_s = omega_e_rad_s, o.analysed_periods = analysed_periods;
        o.damping_cs = cs;
        o.geometry.sections = sections, o.geometry.panels = panels, o.geometry.body = body;
        o.attitude.sinkage_m = sinkage_m, o.attitude.trim_deg = trim_deg, o.attitude.pivot_x_m = mass.lcg_m_from_ap;
        sk::ForcedOscillationResult r;
        {
          py::gil_scoped_release release;
          r = sk::SimulateForcedOscillation(h, mass, speed_m_s, w.rho_kg_m3, w.g_m_s2, o);
        }
        py::dict d;
        const bool heave = o.mode == sk::ForcedMode::kHeave;
        d[heave ? "A33" : "A35"] = r.added_mass[0], d[heave ? "A53" : "A55"] = r.added_mass[1];
        d[heave ? "B33" : "B35"] = r.damping[0], d[heave ? "B53" : "B55"] = r.damping[1];
        d["static_restoring"] = py::make_tuple(r.static_restoring[0], r.static_restoring[1]);
        d["mean_force_N"] = r.mean[0], d["mean_moment_N_m"] = r.mean[1];
        d["second_harmonic_ratio"] = py::make_tuple(r.second_harmonic_ratio[0], r.second_harmonic_ratio[1]);
        d["strips"] = r.strips;
        d["time_s"] = Array(r.time_s), d["motion"] = Array(r.motion), d["force_N"] = Array(r.force_N),
        d["moment_N_m"] = Array(r.moment_N_m);
        return d;
      },
      py::arg("hull"), py::arg("mass"), py::arg("speed_m_s"), py::arg("mode"), py::arg("amplitude"),
      py::arg("omega_e_rad_s"), py::arg("sectional_force") = "momentum", py::arg("sections") = 40,
      py::arg("panels") = 14, py::arg("body") = -1, py::arg("sinkage_m") = 0.0, py::arg("trim_deg") = 0.0,
      py::arg("analysed_periods") = 2, py::arg("Cs") = 0.0, py::arg("water") = py::none(),
      "A forced heave ('heave', amplitude [m]) or pitch ('pitch', amplitude [rad], about the LCG) test at "
      "omega_e_rad_s [rad/s] and speed_m_s [m/s], simulated with the strips on the instantaneous hull and "
      "reduced as a tank reduces it (first harmonic, the static restoring at rest removed). sinkage_m (+ down) "
      "and trim_deg (+ bow up) give the running attitude about the LCG; body -1 all bodies, else that body "
      "alone; Cs the sectional damping coefficient. Returns a dict with the added mass and damping links [kg, kg m, kg m^2; per s], the mean force, "
      "the second-harmonic ratio and the analysed record (NumPy arrays).");

  m.def(
      "evaluate",
      [](const py::dict& rao, const hull::HullForm& h, const hull::MassProperties& mass, const py::object& seas,
         const py::object& msi, const py::object& water) {
        const io::WaterOptions w = WaterOf(water);
        const hull::Hydrostatics hs = hull::ComputeHydrostatics(h, w.rho_kg_m3);
        YAML::Node root(YAML::NodeType::Map);
        root["seas"] = ToYaml(seas);
        if (!msi.is_none()) root["msi"] = ToYaml(msi);
        io::YamlMap rm(root, "", kPythonSource, YAML::Node(YAML::NodeType::Map));
        const std::vector<sk::SeaState> sea_list = io::ReadSeas(rm);
        sk::EvaluationOptions options;
        options.msi = io::ReadMsiOptions(rm);
        rm.Finish();
        const sk::DesignEvaluation ev = sk::EvaluateDesign(RaoFromDict(rao), ExtentOf(hs, mass), sea_list, {}, options);
        const std::vector<std::string> flags = eval::ResponseEnvelopeWarnings(ev, w.g_m_s2);
        py::list out;
        for (std::size_t i = 0; i < ev.seas.size(); ++i) {
          const auto& s = ev.seas[i];
          py::dict d;
          // The validity-envelope flags of this sea (steepness, rms acceleration above 1 g).
          std::vector<std::string> sea_flags;
          const std::string tag = "(sea " + std::to_string(i + 1) + " (";
          for (const auto& f : flags)
            if (f.find(tag) != std::string::npos) sea_flags.push_back(f);
          d["warnings"] = sea_flags;
          d["Hs_m"] = s.sea.Hs_m;
          d["Tz_s"] = s.Tz_s;
          d["Tp_s"] = s.Tp_s;
          d["peak_omega_e_rad_s"] = s.peak_omega_e_rad_s;
          d["truncated_wave_energy_fraction"] = s.truncated_wave_energy_fraction;
          py::list pos;
          for (const auto& p : s.positions) pos.append(PositionDict(p));
          d["positions"] = pos;
          d["mean"] = PositionDict(s.mean);
          out.append(d);
        }
        return out;
      },
      py::arg("rao"), py::arg("hull"), py::arg("mass"), py::arg("seas"), py::arg("msi") = py::none(),
      py::arg("water") = py::none(),
      "rms vertical accelerations and MSI per head sea at the forward, LCG and transom positions and their "
      "mean. seas: a list of dicts as a config's seas: list (Hs_m [m], Tz_s or Tp_s [s], spectrum, gamma); "
      "msi: a dict as the msi: block. Returns one dict per sea with positions (rms_accel_g [g], msi_pct [%], "
      "...), mean and warnings (the validity envelope's flags of that sea: steepness, rms acceleration above 1 g).");

  m.def(
      "rao_peak",
      [](const std::vector<double>& x, const std::vector<double>& y) {
        const opt::RaoPeak p = opt::InterpolatedPeak(x, y);
        return py::make_tuple(p.value, p.x, p.at_edge);
      },
      py::arg("x"), py::arg("y"),
      "(value, x, at_edge): the peak of samples y(x) by a parabola through the largest sample and its "
      "neighbours, "
      "as the commands' summaries find it; at_edge when the largest sample is the first or last.");

  m.def(
      "evaluation_frequencies", [](int count) { return Array(eval::EvaluationFrequencies(count)); },
      py::arg("count") = 60, "The wave-frequency grid [rad/s] `hullopt evaluate` uses (uniform 0.2–3 rad/s).");

  py::class_<eval::DesignCase>(
      m, "Design",
      "One design as `hullopt evaluate` and the campaigns read it from a config: hull, "
      "hydrostatics, mass, water, speed and solver.")
      .def_readonly("name", &eval::DesignCase::name)
      .def_readonly("hull", &eval::DesignCase::hull)
      .def_readonly("mass", &eval::DesignCase::mass)
      .def_readonly("speed_m_s", &eval::DesignCase::speed_m_s, "[m/s]")
      .def_readonly("warnings", &eval::DesignCase::input_warnings,
                    "plausibility and validity-envelope flags of the inputs (carried into every result)")
      .def_property_readonly(
          "sinkage_m", [](const eval::DesignCase& d) { return d.attitude.sinkage_m; },
          "[m] running sinkage at the LCG (+ down): given, or solved with steady_flow")
      .def_property_readonly(
          "trim_deg", [](const eval::DesignCase& d) { return d.attitude.trim_deg; },
          "[deg] running trim (+ bow up)")
      .def_property_readonly("hydrostatics",
                             [](const eval::DesignCase& d) { return HydrostaticsDict(d.hydrostatics); })
      .def(
          "raos",
          [](const eval::DesignCase& d, const py::object& omega) {
            const std::vector<double> w =
                omega.is_none() ? eval::SeaFrequencies(d) : omega.cast<std::vector<double>>();
            sk::RaoTable t;
            {
              py::gil_scoped_release release;
              t = eval::ComputeDesignRaos(d, w);
            }
            return RaoDict(t);
          },
          py::arg("omega_rad_s") = py::none(),
          "RAOs (as compute_raos) at omega_rad_s [rad/s], by default the grid of `hullopt evaluate`: the "
          "config's solver.frequencies, else the evaluation grid; with solver.adaptive_grid on (the default) "
          "that grid refined around the RAO peaks.");

  m.def(
      "design",
      [](const py::object& hull, const py::object& speed_kn, const py::object& speed_m_s,
         const py::object& mass, const py::object& water, const py::object& solver,
         const py::object& attitude, const std::string& name) {
        eval::DesignSpec spec;
        spec.name = name;
        spec.source = kPythonSource;
        spec.water = TypedWater(water);
        if (py::isinstance<hull::HullForm>(hull)) {
          spec.hull.parametric = false;
          spec.hull.given = hull.cast<hull::HullForm>();
        } else {
          spec.hull.variables = py::isinstance<py::dict>(hull)
                                    ? py::module_::import("hullopt")
                                          .attr("DesignVariables")(**py::reinterpret_borrow<py::dict>(hull))
                                          .cast<hull::DesignVariables>()
                                    : hull.cast<hull::DesignVariables>();
          spec.hull.variables.rho_kg_m3 = spec.water.rho_kg_m3;  // as a config's water: gives it
        }
        spec.speed = TypedSpeed(speed_kn, speed_m_s);
        spec.mass = TypedMass(mass);
        spec.solver = TypedSolver(solver);
        if (!attitude.is_none()) {
          for (const auto& [k, v] : Items(attitude, "attitude", {"sinkage_m", "trim_deg"}))
            (k == "sinkage_m" ? spec.hull.attitude.sinkage_m : spec.hull.attitude.trim_deg) =
                NumberOf(v, "hull.attitude." + k);
        }
        py::gil_scoped_release release;
        return eval::BuildDesign(spec);
      },
      py::arg("hull"), py::kw_only(), py::arg("speed_kn") = py::none(), py::arg("speed_m_s") = py::none(),
      py::arg("mass") = py::none(), py::arg("water") = py::none(), py::arg("solver") = py::none(),
      py::arg("attitude") = py::none(), py::arg("name") = "design",
      "One design from Python values, built as the commands build a config's design (same rules, defaults "
      "and "
      "results): hull a DesignVariables, a dict of its fields or a Hull (e.g. from load_hull); the speed by "
      "keyword, speed_kn= [kn] or speed_m_s= [m/s] (exactly one); mass a dict as a config's mass: block "
      "(mass_kg, lcg_m_from_ap, kyy_m or kyy_over_L, kg_m or kg_over_T, accept_mass_mismatch; the rest from "
      "the "
      "hull); water {rho_kg_m3, g_m_s2}; solver {method, sections, panels, Cs, path, sectional_force, "
      "steady_flow, adaptive_grid, interaction}; attitude {sinkage_m, trim_deg}. hullopt.InputError (a "
      "ValueError) names the key and rule; TypeError for no speed or both.");

  m.def(
      "load_design",
      [](const std::string& config_file, const std::string& name) {
        io::YamlMap root = io::YamlMap::LoadFile(config_file);
        return io::LoadDesignCase(root, config_file, name);
      },
      py::arg("config_file"), py::arg("name") = "design",
      "The design of a hull config (hull, water, speed, solver, mass), read as `hullopt evaluate` reads it.");

  m.def(
      "_run_campaign",
      [](const std::string& command, const py::object& spec, const std::string& out, bool resume,
         long max_evaluations, int threads, bool plots) {
        const io::CampaignCommand kind =
            command == "explore" ? io::CampaignCommand::kExplore : io::CampaignCommand::kOptimize;
        campaign::CampaignSpec s = py::isinstance<py::str>(spec) || py::hasattr(spec, "__fspath__")
                                       ? campaign::CampaignSpec::FromFile(kind, py::str(spec).cast<std::string>())
                                       : campaign::CampaignSpec::FromTree(kind, ToYaml(spec), kPythonSource);
        campaign::CampaignRunOptions o;
        o.out = out;
        o.resume = resume;
        o.max_evaluations = max_evaluations;
        o.threads = threads;
        o.plots = plots;
        std::vector<std::string> messages;
        o.message = [&messages](const std::string& line) { messages.push_back(line); };
        o.write_report = [](const campaign::CampaignReportRequest& r) {
          app::WriteCampaignReport(r.out, r.command, r.config_file, r.campaign_warnings, r.active_set);
        };
        for (const std::string& path : {out, s.Name()})
          if (!io::IsValidUtf8(path)) throw io::InputError(path + ": not valid UTF-8 (paths are written to JSON outputs)");
        campaign::CampaignResult r;
        {
          py::gil_scoped_release release;
          io::OutputFolderLock lock(out, command);
          r = campaign::RunCampaign(s, o);
        }
        // The log's columns (io::HistoryLayout::Header(), as history.csv has them), one list each.
        py::dict columns;
        const io::HistoryLayout& L = r.layout;
        const std::size_t n = r.history.size();
        auto numbers = [&](const std::function<double(std::size_t)>& f) {
          py::array_t<double> a(static_cast<py::ssize_t>(n));
          for (std::size_t i = 0; i < n; ++i) a.mutable_at(i) = f(i);
          return a;
        };
        std::vector<long> evaluation(n), run(n), step(n);
        std::vector<bool> feasible(n);
        std::vector<std::string> message(n);
        for (std::size_t i = 0; i < n; ++i) {
          const opt::EvaluationRecord& rec = r.history[i];
          evaluation[i] = static_cast<long>(i);
          run[i] = rec.run;
          step[i] = rec.step;
          feasible[i] = rec.feasible;
          message[i] = rec.result.produced ? (rec.result.warning.empty() ? "" : io::kWarningPrefix + rec.result.warning)
                                           : rec.result.error;
        }
        columns["evaluation"] = evaluation;
        for (std::size_t v = 0; v < L.variables.size(); ++v)
          columns[py::str(L.variables[v])] = numbers([&](std::size_t i) { return r.history[i].x[v]; });
        columns["objective"] = numbers([&](std::size_t i) {
          return r.history[i].result.produced ? r.history[i].result.objective : NAN;
        });
        columns["feasible"] = feasible;
        for (std::size_t k = 0; k < L.seas.size(); ++k)
          columns[py::str(L.seas[k])] = numbers([&](std::size_t i) {
            const auto& res = r.history[i].result;
            return res.produced && k < res.sea_values.size() ? res.sea_values[k] : NAN;
          });
        for (std::size_t q = 0; q < L.quantities.size(); ++q)
          columns[py::str(L.quantities[q])] = numbers([&](std::size_t i) { return r.reported[i][q]; });
        columns["wall_time_s"] = numbers([&](std::size_t i) { return r.history[i].wall_time_s; });
        columns["run"] = run;
        columns["step"] = step;
        columns["message"] = message;
        py::dict d;
        d["complete"] = r.complete;
        d["command"] = r.command;
        d["log_path"] = r.log_path;
        d["columns"] = columns;
        d["column_order"] = L.Header();
        d["variables"] = L.variables;
        d["replayed"] = r.replayed;
        d["best"] = r.best;
        d["summary"] = r.summary.is_null() ? std::string() : r.summary.dump();
        d["text"] = r.text + r.sweep;
        d["messages"] = messages;
        return d;
      },
      py::arg("command"), py::arg("spec"), py::arg("out"), py::arg("resume") = true,
      py::arg("max_evaluations") = 0, py::arg("threads") = 0, py::arg("plots") = true,
      "The campaign library (campaign::RunCampaign) for hullopt.optimize/explore: a dict of columns and the "
      "summary; use hullopt.optimize().");

  m.def(
      "run",
      [](std::vector<std::string> args) {
        CLI::App app{"hullopt"};
        app.require_subcommand(1);
        app::AddAllCommands(app);
        std::reverse(args.begin(), args.end());  // CLI11 takes the arguments last-first
        try {
          py::gil_scoped_release release;
          app.parse(args);
        } catch (const CLI::ParseError& e) {
          throw io::InputError(std::string("command line: ") + e.what());
        }
      },
      py::arg("args"),
      "Runs a hullopt command in-process, e.g. run(['optimize', 'campaign.yaml', '--out', 'out/c']). "
      "Raises hullopt.InputError with the CLI's message for bad input.");
}
