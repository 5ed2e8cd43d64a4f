#include "io/config/section_config.h"

#include <cmath>
#include <sstream>

#include "io/config/config_path.h"
#include "io/formats/offsets_csv.h"
#include "parametric_hull/section_geometry.h"

namespace hullopt::io {
namespace {

double Positive(YamlMap& m, const std::string& key) {
  const double v = m.Number(key);
  if (!(v > 0)) m.Fail(key, "must be > 0");
  return v;
}

// The section of an offsets CSV (docs/file-formats.md; a relative path is relative to the config's folder)
// at x_m [m from AP], cut at draught_m [m above baseline] and shifted so that the
// waterline is z = 0, as a half contour keel → waterline.
sk::HalfContour OffsetsSection(YamlMap& s) {
  const std::string file = ConfigFilePath(s, "offsets_csv");
  const double x = s.Number("x_m");
  const double T = Positive(s, "draught_m");
  const hull::Demihull body = ReadOffsetsCsv(file, T);
  const double x_aft = body.stations.front().x_m, x_fwd = body.stations.back().x_m;
  if (!(x >= x_aft && x <= x_fwd)) {
    std::ostringstream os;
    os << "is outside the stations of " << file << " (x from " << x_aft << " to " << x_fwd
       << " m from the AP)";
    s.Fail("x_m", os.str());
  }
  const auto wetted = hull::WettedContour(hull::InterpolateStation(body, x), T);
  sk::HalfContour c;
  for (const auto& q : wetted) c.push_back({q[0], q[1] - T});
  if (c.size() < 2 || c.back()[1] < -1e-9 * T) {
    std::ostringstream os;
    os << "the section at x = " << x << " m does not cross the waterline z = " << T
       << " m (dry, or its deck edge is below the waterline)";
    s.Fail("x_m", os.str());
  }
  if (!(c.front()[1] < 0.0) || c.back()[0] <= 0.0) {
    std::ostringstream os;
    os << "the section at x = " << x << " m has no wetted area at draught " << T << " m";
    s.Fail("x_m", os.str());
  }
  c.back()[1] = 0.0;  // the waterline crossing, exactly on z = 0
  return c;
}

}  // namespace

SectionRunConfig ReadSectionConfig(YamlMap& root) {
  // Blocks owned by other commands may share the file (one campaign config for the whole tool).
  for (const char* other : {"hull", "mass", "speed", "solver", "seas", "optimize", "calibrate", "explore"})
    if (root.Has(other)) root.Skip(other);
  SectionRunConfig cfg;
  YamlMap s = root.Map("section");
  cfg.shape_name = s.Choice("shape", {"semicircle", "rectangle", "lewis", "offsets"});
  sk::SectionStripSpec& strip = cfg.strip;
  if (cfg.shape_name == "semicircle") {
    strip.shape = sk::SectionShape::kSemicircle;
    strip.radius_m = Positive(s, "radius_m");
  } else if (cfg.shape_name == "rectangle") {
    strip.shape = sk::SectionShape::kRectangle;
    strip.beam_m = Positive(s, "beam_m");
    strip.draught_m = Positive(s, "draught_m");
  } else if (cfg.shape_name == "lewis") {
    strip.shape = sk::SectionShape::kLewis;
    strip.beam_m = Positive(s, "beam_m");
    strip.draught_m = Positive(s, "draught_m");
    strip.area_coefficient = s.Number("area_coefficient");
    if (!(strip.area_coefficient > 0 && strip.area_coefficient <= 1))
      s.Fail("area_coefficient", "must be in (0, 1] (section area / (beam × draught))");
    try {
      (void)strip.Contour();
    } catch (const std::exception& e) {
      s.Fail("area_coefficient", e.what());
    }
  } else {  // offsets: the wetted section of an offsets file at x_m (interpolated between its stations)
    strip.shape = sk::SectionShape::kContour;
    strip.contour = OffsetsSection(s);
  }
  strip.count = s.Integer("count", 1);
  if (strip.count < 1 || strip.count > 20) s.Fail("count", "must be an integer in 1..20");
  if (strip.count > 1) {
    strip.spacing_m = Positive(s, "spacing_m");
    const double beam = sk::SectionBeam(strip);
    if (!(strip.spacing_m > beam)) {
      std::ostringstream os;
      os << "must exceed the section beam " << beam << " m (the sections would overlap)";
      s.Fail("spacing_m", os.str());
    }
  } else if (s.Has("spacing_m")) {
    strip.spacing_m = s.Number("spacing_m");  // accepted and unused with one section
  }
  strip.panels = s.Integer("panels", 28);
  if (strip.panels < 4 || strip.panels % 2 != 0 || strip.panels > 2000)
    s.Fail("panels", "must be an even integer in 4..2000");

  if (s.Has("method")) {
    cfg.methods = s.Strings("method");
    const char* kMethods = "frequency_domain, frequency_domain_direct, time_domain, time_domain_green_identity";
    if (cfg.methods.empty()) s.Fail("method", std::string("must list at least one of: ") + kMethods);
    for (const auto& m : cfg.methods)
      if (m != "frequency_domain" && m != "frequency_domain_direct" && m != "time_domain" &&
          m != "time_domain_green_identity")
        s.Fail("method", "'" + m + "' is not a method; use one or more of: " + kMethods);
  } else {
    cfg.methods = {"frequency_domain"};
    s.Skip("method");
    s.resolved()["method"] = std::vector<std::string>{"frequency_domain"};
  }

  YamlMap f = s.Map("frequencies");
  if (f.Has("omega_rad_s")) {
    if (f.Has("omega_min_rad_s") || f.Has("omega_max_rad_s") || f.Has("count"))
      f.Fail("omega_rad_s",
             "give either a list omega_rad_s or a range omega_min_rad_s/omega_max_rad_s/count");
    cfg.omegas_rad_s = f.Numbers("omega_rad_s");
    for (double w : cfg.omegas_rad_s)
      if (!(w > 0)) f.Fail("omega_rad_s", "every frequency must be > 0 rad/s");
  } else {
    const double lo = Positive(f, "omega_min_rad_s");
    const double hi = Positive(f, "omega_max_rad_s");
    const int n = f.Integer("count");
    if (n < 1 || n > 10000) f.Fail("count", "must be an integer in 1..10000");
    if (n == 1 && hi != lo) f.Fail("count", "must be >= 2 when omega_max_rad_s differs from omega_min_rad_s");
    if (hi < lo) f.Fail("omega_max_rad_s", "must be >= omega_min_rad_s");
    for (int i = 0; i < n; ++i) cfg.omegas_rad_s.push_back(n == 1 ? lo : lo + (hi - lo) * i / (n - 1));
  }
  f.Finish();
  s.Finish();

  YamlMap w = root.MapOrEmpty("water");
  cfg.rho_kg_m3 = w.Number("rho_kg_m3", 1025.0);
  if (!(cfg.rho_kg_m3 > 0)) w.Fail("rho_kg_m3", "must be > 0");
  cfg.g_m_s2 = w.Number("g_m_s2", 9.81);
  if (!(cfg.g_m_s2 > 0)) w.Fail("g_m_s2", "must be > 0");
  w.Finish();
  root.Finish();
  return cfg;
}

}  // namespace hullopt::io
