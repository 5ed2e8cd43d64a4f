// Plots read back from the written SVG: lines stay inside the axes, a phase curve never jumps across the panel
// at its ±180° wrap, a legend covers no drawn point or line, the body plan's waterline label is clear of the
// sections and its scale bar measures what the drawing shows, axis labels carry units (the pitch RAO's the
// one of docs/conventions.md), design variables read as names with units, and measured RAOs of a rao
// config's `compare:` block arrive on rao.svg at the run's speed.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "io/report/campaign_plots.h"
#include "io/report/bodyplan_svg.h"
#include "io/report/design_variable_label.h"
#include "io/formats/input_error.h"
#include "io/report/rao_axis_labels.h"
#include "io/report/rao_comparison.h"
#include "io/report/rao_plot.h"
#include "io/report/seakeeping_plots.h"
#include "io/report/svg_plot.h"
#include "io/config/yaml_map.h"
#include "parametric_hull/hull_generator.h"

namespace io = hullopt::io;
namespace fs = std::filesystem;

namespace {

// Pixel coordinates are written with 2 decimals: a point on an edge may sit this far outside it.
constexpr double kPixelRoundOff = 0.011;

struct Rect {
  double x0, y0, x1, y1;
  bool Contains(double x, double y, double tol) const {
    return x >= x0 - tol && x <= x1 + tol && y >= y0 - tol && y <= y1 + tol;
  }
};
struct Pt {
  double x, y;
};

std::string ReadText(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// Every "<name ...>" start tag (with its attributes) in document order.
std::vector<std::string> Tags(const std::string& svg, const std::string& name) {
  std::vector<std::string> tags;
  const std::string open = "<" + name + " ";
  for (size_t p = svg.find(open); p != std::string::npos; p = svg.find(open, p + 1))
    tags.push_back(svg.substr(p, svg.find('>', p) - p + 1));
  return tags;
}

std::string AttrText(const std::string& tag, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const size_t p = tag.find(key);
  if (p == std::string::npos) return "";
  const size_t b = p + key.size();
  return tag.substr(b, tag.find('"', b) - b);
}

double Attr(const std::string& tag, const std::string& name) {
  const std::string t = AttrText(tag, name);
  return t.empty() ? NAN : std::atof(t.c_str());
}

Rect RectOf(const std::string& tag) {
  const double x = Attr(tag, "x"), y = Attr(tag, "y");
  return {x, y, x + Attr(tag, "width"), y + Attr(tag, "height")};
}

// The subpaths of a path's "M x yL x y..." data.
std::vector<std::vector<Pt>> Subpaths(const std::string& d) {
  std::vector<std::vector<Pt>> runs;
  size_t i = 0;
  while (i < d.size()) {
    const char c = d[i++];
    char* end = nullptr;
    const double x = std::strtod(d.c_str() + i, &end);
    const double y = std::strtod(end, &end);
    i = static_cast<size_t>(end - d.c_str());
    if (c == 'M') runs.push_back({});
    runs.back().push_back({x, y});
  }
  return runs;
}

// "x1,y1 x2,y2 ..." of a polyline.
std::vector<Pt> PolylinePoints(const std::string& points) {
  std::vector<Pt> pts;
  std::istringstream s(points);
  std::string pair;
  while (s >> pair) {
    const size_t comma = pair.find(',');
    pts.push_back({std::atof(pair.substr(0, comma).c_str()), std::atof(pair.substr(comma + 1).c_str())});
  }
  return pts;
}

// Whether the segment a–b meets the rectangle (sampled finely: the segments here are a few pixels to a few
// hundred long, the boxes at least 10 px).
bool SegmentMeets(const Pt& a, const Pt& b, const Rect& r) {
  for (int k = 0; k <= 200; ++k) {
    const double t = k / 200.0;
    if (r.Contains(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), 0.0)) return true;
  }
  return false;
}

// One panel's pieces: frame, data paths and markers, legend box.
struct PanelSvg {
  Rect frame{};
  std::vector<std::vector<Pt>> lines;
  std::vector<std::pair<Pt, double>> circles;  // centre, radius
  bool has_legend = false;
  Rect legend{};
  std::string line_clip;  // the id of the clip path around the lines
  std::string text;
};

std::vector<PanelSvg> Panels(const std::string& svg) {
  std::vector<PanelSvg> panels;
  const std::string mark = "<g class=\"panel\">";
  for (size_t p = svg.find(mark); p != std::string::npos;) {
    const size_t next = svg.find(mark, p + 1);
    PanelSvg ps;
    ps.text = svg.substr(p, next == std::string::npos ? std::string::npos : next - p);
    for (const auto& t : Tags(ps.text, "rect"))
      if (AttrText(t, "class") == "frame") ps.frame = RectOf(t);
    for (const auto& t : Tags(ps.text, "path"))
      if (AttrText(t, "fill") == "none" && AttrText(t, "stroke-linejoin") == "round")
        for (auto& run : Subpaths(AttrText(t, "d"))) ps.lines.push_back(run);
    // Markers of the data (not the legend's samples): between the data group and the frame.
    const size_t data0 = ps.text.find("<g class=\"data\">"), data1 = ps.text.find("class=\"frame\"");
    if (data0 != std::string::npos && data1 != std::string::npos)
      for (const auto& t : Tags(ps.text.substr(data0, data1 - data0), "circle"))
        ps.circles.push_back({{Attr(t, "cx"), Attr(t, "cy")}, Attr(t, "r")});
    const size_t legend = ps.text.find("<g class=\"legend\">");
    if (legend != std::string::npos) {
      ps.has_legend = true;
      ps.legend = RectOf(Tags(ps.text.substr(legend), "rect").front());
    }
    const size_t data = ps.text.find("<g class=\"data\">");
    if (data != std::string::npos) {
      const std::string g = Tags(ps.text.substr(data + 1), "g").front();
      const std::string url = AttrText(g, "clip-path");  // url(#id)
      ps.line_clip = url.substr(5, url.size() - 6);
    }
    panels.push_back(ps);
    p = next;
  }
  return panels;
}

Rect ClipRect(const std::string& svg, const std::string& id) {
  const size_t p = svg.find("<clipPath id=\"" + id + "\">");
  REQUIRE(p != std::string::npos);
  return RectOf(Tags(svg.substr(p), "rect").front());
}

// Deterministic scatter filling the unit square (a linear congruential sequence, no library generator).
std::vector<double> Scatter(int n, unsigned seed) {
  std::vector<double> v;
  unsigned s = seed;
  for (int i = 0; i < n; ++i) {
    s = s * 1103515245u + 12345u;
    v.push_back(((s >> 8) & 0xFFFF) / 65535.0);
  }
  return v;
}

void CheckLegendCoversNothing(const PanelSvg& p) {
  REQUIRE(p.has_legend);
  for (const auto& [c, r] : p.circles) {
    INFO("marker at " << c.x << ", " << c.y);
    const Rect grown{p.legend.x0 - r, p.legend.y0 - r, p.legend.x1 + r, p.legend.y1 + r};
    CHECK_FALSE(grown.Contains(c.x, c.y, 0.0));
  }
  for (const auto& run : p.lines)
    for (size_t i = 1; i < run.size(); ++i) CHECK_FALSE(SegmentMeets(run[i - 1], run[i], p.legend));
}

}  // namespace

TEST_CASE("lines are cut at the axes and clipped to the plot area", "[plot]") {
  io::PlotFigure fig;
  auto& p = fig.AddPanel("fixed ranges narrower than the data", "x [m]", "y [m]");
  std::vector<double> x, y;
  for (int i = 0; i <= 200; ++i) x.push_back(0.05 * i), y.push_back(0.6 * std::sin(0.065 * i));  // x to 10
  p.series.push_back(io::PlotSeries::Line("sine", x, y));
  p.series.push_back(io::PlotSeries::Markers("every tenth", {1, 2, 4, 6, 8}, {0.1, 0.2, 0.3, 0.4, 0.45}));
  p.x_min = 0.0, p.x_max = 5.0, p.y_min = -0.5, p.y_max = 0.5;
  const std::string svg = io::RenderSvg(fig);
  const auto panels = Panels(svg);
  REQUIRE(panels.size() == 1);
  const PanelSvg& ps = panels[0];
  REQUIRE_FALSE(ps.lines.empty());
  bool reaches_right = false, reaches_top = false;
  for (const auto& run : ps.lines)
    for (const auto& pt : run) {
      INFO("point " << pt.x << ", " << pt.y);
      CHECK(ps.frame.Contains(pt.x, pt.y, kPixelRoundOff));
      reaches_right = reaches_right || std::abs(pt.x - ps.frame.x1) < kPixelRoundOff;
      reaches_top = reaches_top || std::abs(pt.y - ps.frame.y0) < kPixelRoundOff;
    }
  // Cut where it leaves (at y = 0.5 near the peak, and at x = 5, y ≈ 0.13), not stopped short.
  CHECK(reaches_right);
  CHECK(reaches_top);
  // The lines' clip path is the plot area itself.
  const Rect clip = ClipRect(svg, ps.line_clip);
  CHECK(clip.x0 == Approx(ps.frame.x0).margin(kPixelRoundOff));
  CHECK(clip.x1 == Approx(ps.frame.x1).margin(kPixelRoundOff));
  CHECK(clip.y0 == Approx(ps.frame.y0).margin(kPixelRoundOff));
  CHECK(clip.y1 == Approx(ps.frame.y1).margin(kPixelRoundOff));
  // Markers beyond x = 5 are not drawn: 1, 2 and 4 are.
  CHECK(ps.circles.size() == 3);
}

TEST_CASE("a phase curve breaks at its wrap instead of crossing the panel", "[plot]") {
  // Phase falling 37° per point through several wraps, given in (−180°, 180°].
  std::vector<double> x, phase;
  int wraps = 0;
  for (int i = 0; i <= 40; ++i) {
    double v = std::remainder(-10.0 - 37.0 * i, 360.0);
    if (v <= -180.0) v += 360.0;
    if (i > 0 && v > phase.back()) ++wraps;  // falling curve: each rise is a wrap
    x.push_back(i), phase.push_back(v);
  }
  REQUIRE(wraps == 4);
  auto render = [&](double period) {
    io::PlotFigure fig;
    auto& p = fig.AddPanel("phase", "ω_e [rad/s]", "phase [deg]");
    p.y_min = -180, p.y_max = 180;
    p.series.push_back(io::PlotSeries::Line("phase", x, phase));
    p.series.back().wrap_period = period;
    return Panels(io::RenderSvg(fig)).at(0);
  };
  const PanelSvg wrapped = render(360.0);
  const double px_per_deg = (wrapped.frame.y1 - wrapped.frame.y0) / 360.0;
  // No segment rises or falls more than the 37° step (far below 180°); out at one edge, in at the other.
  for (const auto& run : wrapped.lines)
    for (size_t i = 1; i < run.size(); ++i) CHECK(std::abs(run[i].y - run[i - 1].y) <= 37.0 * px_per_deg + 0.05);
  CHECK(wrapped.lines.size() == static_cast<size_t>(wraps + 1));
  // Without the period the same data do draw the vertical strokes (the check above can fail).
  const PanelSvg plain = render(0.0);
  double largest = 0.0;
  for (const auto& run : plain.lines)
    for (size_t i = 1; i < run.size(); ++i) largest = std::max(largest, std::abs(run[i].y - run[i - 1].y));
  CHECK(largest > 180.0 * px_per_deg);
}

TEST_CASE("a legend covers no point or line; with no free corner it goes outside", "[plot]") {
  SECTION("scatter with an empty region") {
    // Points fill the panel except its lower right quarter.
    const auto u = Scatter(120, 7), v = Scatter(120, 99);
    std::vector<double> x, y;
    for (size_t i = 0; i < u.size(); ++i)
      if (!(u[i] > 0.5 && v[i] < 0.5)) x.push_back(u[i]), y.push_back(v[i]);
    io::PlotFigure fig;
    auto& p = fig.AddPanel("samples", "Cp [-]", "mean MSI [%]");
    p.pad_fraction = 0.06;
    p.series.push_back(io::PlotSeries::Markers("samples", x, y));
    p.series.push_back(io::PlotSeries::Line("trend", {0.0, 0.5, 1.0}, {0.9, 0.8, 0.7}));
    p.legend = io::LegendPlace::kTopLeft;  // asked for a corner that is full
    const PanelSvg ps = Panels(io::RenderSvg(fig)).at(0);
    CheckLegendCoversNothing(ps);
    CHECK(ps.legend.x1 <= ps.frame.x1);  // inside: the free quarter has room
  }
  SECTION("data everywhere") {
    const auto u = Scatter(400, 3), v = Scatter(400, 11);
    io::PlotFigure fig;
    auto& p = fig.AddPanel("samples", "L/B [-]", "mean MSI [%]");
    p.series.push_back(io::PlotSeries::Markers("samples", u, v));
    const PanelSvg ps = Panels(io::RenderSvg(fig)).at(0);
    CheckLegendCoversNothing(ps);
    CHECK(ps.legend.x0 >= ps.frame.x1);  // outside on the right
  }
}

TEST_CASE("body plan: DWL label clear of the sections, station numbers, a true scale bar", "[plot][bodyplan]") {
  hullopt::hull::DesignVariables dv;  // the default catamaran
  const auto hull = hullopt::hull::GenerateHull(dv);
  const std::string path = std::string(HULLOPT_BINARY_DIR) + "/test_plot_faults_bodyplan.svg";
  io::WriteBodyPlanSvg(path, hull, "default catamaran");
  const std::string svg = ReadText(path);

  std::vector<std::vector<Pt>> sections;
  for (const auto& t : Tags(svg, "polyline"))
    if (AttrText(t, "class") == "section") sections.push_back(PolylinePoints(AttrText(t, "points")));
  REQUIRE(sections.size() > 10);

  // The DWL label (anchored at its end): an upper bound of its box, 0.7 em per glyph, 12 px font.
  std::string dwl;
  for (const auto& t : Tags(svg, "text"))
    if (AttrText(t, "class") == "dwl-label") dwl = t;
  REQUIRE_FALSE(dwl.empty());
  const size_t text0 = svg.find(dwl) + dwl.size();
  const std::string label = svg.substr(text0, svg.find('<', text0) - text0);
  CHECK(label.find("DWL") == 0);
  const double lx = Attr(dwl, "x"), ly = Attr(dwl, "y");
  const Rect box{lx - 0.7 * 12.0 * label.size(), ly - 12.0, lx, ly + 3.0};
  for (const auto& s : sections)
    for (size_t i = 1; i < s.size(); ++i) CHECK_FALSE(SegmentMeets(s[i - 1], s[i], box));

  // Station numbers: one per drawn section of a demihull (a catamaran draws both sides of each), AP and
  // midships among them.
  std::vector<std::string> numbers;
  for (size_t p = svg.find("class=\"station-number\""); p != std::string::npos;
       p = svg.find("class=\"station-number\"", p + 1)) {
    const size_t b = svg.find('>', p) + 1;
    numbers.push_back(svg.substr(b, svg.find('<', b) - b));
  }
  CHECK(numbers.size() * 2 == sections.size());
  CHECK(std::find(numbers.begin(), numbers.end(), "0") != numbers.end());
  CHECK(std::find(numbers.begin(), numbers.end(), "5") != numbers.end());

  // Scale bar: its length in pixels per metre equals the drawing's, the distance from the baseline to the
  // design waterline over the draught.
  const size_t bar = svg.find("<g class=\"scale-bar\">");
  REQUIRE(bar != std::string::npos);
  const std::string bar_svg = svg.substr(bar, svg.find("</g>", bar) - bar);
  const std::string bar_line = Tags(bar_svg, "line").front();
  const double bar_px = Attr(bar_line, "x2") - Attr(bar_line, "x1");
  const size_t m = bar_svg.rfind(" m</text>");
  REQUIRE(m != std::string::npos);
  const double bar_m = std::atof(bar_svg.substr(bar_svg.rfind('>', m) + 1).c_str());
  double bl_y = NAN, dwl_y = NAN;
  for (const auto& t : Tags(svg, "line")) {
    if (AttrText(t, "stroke") == "#888" && AttrText(t, "stroke-dasharray").empty()) bl_y = Attr(t, "y1");
    if (AttrText(t, "stroke") == "#0a8a3a") dwl_y = Attr(t, "y1");
  }
  REQUIRE(std::isfinite(bl_y));
  REQUIRE(std::isfinite(dwl_y));
  const double px_per_m = (bl_y - dwl_y) / hull.draught_m;
  CHECK(bar_px / bar_m == Approx(px_per_m).epsilon(1e-3));  // coordinates written to 6 digits
}

TEST_CASE("axis labels carry units; the pitch RAO label is the one of the conventions", "[plot][labels]") {
  // docs/conventions.md states the RAO units; every plot uses exactly those.
  const std::string conventions = ReadText(std::string(HULLOPT_SOURCE_DIR) + "/docs/conventions.md");
  CHECK(conventions.find(std::string("pitch ") + io::kPitchRaoLabel) != std::string::npos);
  CHECK(conventions.find(std::string("heave ") + io::kHeaveRaoLabel) != std::string::npos);

  hullopt::sk::RaoTable t;
  for (int i = 1; i <= 20; ++i) {
    const double w = 0.2 * i;
    t.omega_rad_s.push_back(w);
    t.omega_e_rad_s.push_back(w + w * w * 10.0 / 9.81);
    t.heave.push_back(std::polar(1.0 / (1.0 + 0.1 * i), -0.3 * i));
    t.pitch.push_back(std::polar(1.0 / (1.0 + 0.2 * i), 2.5 - 0.4 * i));  // wraps past −180°
  }
  t.speed_m_s = 10.0;
  const io::PlotFigure rao = io::RaoFigure({t}, {"computed"}, 30.0, "RAOs");
  REQUIRE(rao.panels.size() == 8);
  for (const auto& p : rao.panels) {
    INFO(p.title);
    CHECK(p.x_label.find('[') != std::string::npos);
    CHECK(p.y_label.find(']') != std::string::npos);
    if (p.title == "Pitch magnitude") CHECK(p.y_label == io::kPitchRaoLabel);
  }
  io::EvaluatedDesign d;
  d.name = "one";
  d.rao = t;
  const io::PlotFigure raos = io::RaoFigure(std::vector<io::EvaluatedDesign>{d});
  REQUIRE(raos.panels.size() == 2);
  CHECK(raos.panels[0].y_label == io::kHeaveRaoLabel);
  CHECK(raos.panels[1].y_label == io::kPitchRaoLabel);
  // The pitch phase of rao.svg breaks at the wrap: no drawn segment spans half the panel.
  const auto panels = Panels(io::RenderSvg(rao));
  for (size_t k : {3, 7}) {
    const auto& ps = panels.at(k);
    for (const auto& run : ps.lines)
      for (size_t i = 1; i < run.size(); ++i)
        CHECK(std::abs(run[i].y - run[i - 1].y) < 0.5 * (ps.frame.y1 - ps.frame.y0));
  }
}

TEST_CASE("design variables read as names with units in the campaign plots", "[plot][labels]") {
  CHECK(io::DesignVariableAxisLabel("LCF_pct_L") == "LCF [% L]");
  CHECK(io::DesignVariableAxisLabel("L_over_B") == "L/B [-]");
  CHECK(io::DesignVariableAxisLabel("spacing_m") == "spacing [m]");
  CHECK(io::DesignVariableAxisLabel("transom_immersion") == "transom immersion [-]");
  CHECK(io::DesignVariableName("LCB_pct_L") == "LCB");
  CHECK(io::DesignVariableAxisLabel("x1") == "x1");  // not a hull variable: as given

  std::vector<hullopt::opt::EvaluationRecord> records;
  const auto u = Scatter(12, 5);
  for (int i = 0; i < 12; ++i) {
    hullopt::opt::EvaluationRecord r;
    r.x = {-8.0 + 4.0 * u[i], 9.0 + 5.0 * u[(i + 3) % 12]};
    r.result.produced = true;
    r.result.objective = 20.0 + 10.0 * u[(i + 5) % 12];
    r.feasible = i % 4 != 0;
    records.push_back(r);
  }
  const fs::path dir = fs::path(HULLOPT_BINARY_DIR) / "test_plot_faults_campaign";
  fs::create_directories(dir);
  io::WriteExplorePlots(dir.string(), records, {"LCF_pct_L", "L_over_B"}, "mean MSI over 2 seas [%]");
  io::WriteOptimizePlots(dir.string(), records, {"LCF_pct_L", "L_over_B"}, {-10, 8}, {-3, 16},
                         "mean MSI over 2 seas [%]");
  for (const char* file : {"scatter.svg", "variables.svg"}) {
    INFO(file);
    const std::string svg = ReadText((dir / file).string());
    CHECK(svg.find("LCF [% L]") != std::string::npos);
    CHECK(svg.find("L/B [-]") != std::string::npos);
    CHECK(svg.find("LCF_pct_L") == std::string::npos);
    CHECK(svg.find("L_over_B") == std::string::npos);
  }
  CHECK(ReadText((dir / "convergence.svg").string()).find("mean MSI over 2 seas [%]") != std::string::npos);
  // Every legend of the scatter covers no sample.
  for (const auto& ps : Panels(ReadText((dir / "scatter.svg").string())))
    if (ps.has_legend) CheckLegendCoversNothing(ps);
}

TEST_CASE("compare.tank_rao_csv: measured RAOs at the run's speed, on both frequency axes", "[plot][compare]") {
  const fs::path dir = fs::path(HULLOPT_BINARY_DIR) / "test_plot_faults_compare";
  fs::create_directories(dir / "data");
  {
    std::ofstream csv(dir / "data" / "tank.csv");
    csv << "Fn,lambda_over_L,heave_rao,heave_phase_deg,pitch_rao,pitch_phase_deg\n"
        << "0.75,1.0,0.2,-145,0.17,113\n0.75,2.0,2.4,-20,1.5,-173\n0.50,1.5,1.1,-60,0.9,150\n";
  }
  auto write_config = [&](const std::string& body) {
    std::ofstream y(dir / "rao.yaml");
    y << body;
  };
  // Relative to the config's folder (the test runs in the source folder).
  write_config("compare: { tank_rao_csv: data/tank.csv, label: tank }\n");
  const double L = 3.0, g = 9.81, Fn = 0.75;
  io::YamlMap root = io::YamlMap::LoadFile((dir / "rao.yaml").string());
  const auto m = io::ReadRaoComparison(root, Fn, L, g);
  root.Finish();
  REQUIRE(m.has_value());
  CHECK(m->label == "tank");
  REQUIRE(m->lambda_over_L.size() == 2);  // the Fn 0.5 row is another speed
  CHECK(m->lambda_over_L[1] == Approx(2.0).epsilon(1e-12));
  // ω from λ = 2πg/ω², ω_e = ω + ω²U/g in head seas, U = Fn √(gL).
  const double omega = std::sqrt(2 * M_PI * g / (2.0 * L)), U = Fn * std::sqrt(g * L);
  CHECK(m->omega_e_rad_s[1] == Approx(omega + omega * omega * U / g).epsilon(1e-12));
  CHECK(m->pitch_phase_deg[1] == -173.0);

  // Drawn as markers in all 8 panels of rao.svg (both rows: ω_e and λ/L).
  hullopt::sk::RaoTable t;
  for (int i = 1; i <= 30; ++i) {
    const double w = 2.0 + 0.3 * i;
    t.omega_rad_s.push_back(w);
    t.omega_e_rad_s.push_back(w + w * w * U / g);
    t.heave.push_back(std::polar(1.0, -0.1 * i));
    t.pitch.push_back(std::polar(1.0, 0.1 * i));
  }
  const std::string svg = io::RenderSvg(io::RaoFigure({t}, {"computed"}, L, "RAOs", &*m));
  size_t hollow = 0;
  for (const auto& c : Tags(svg, "circle")) hollow += AttrText(c, "fill") == "#ffffff";
  CHECK(hollow == 8 * 2 + 2);  // 2 points in each panel, plus each row's legend sample

  // No row at the run's speed: the error names the key and the speeds the file has.
  io::YamlMap again = io::YamlMap::LoadFile((dir / "rao.yaml").string());
  try {
    io::ReadRaoComparison(again, 0.6, L, g);
    FAIL("no error");
  } catch (const io::InputError& e) {
    const std::string what = e.what();
    CHECK(what.find("compare.tank_rao_csv") != std::string::npos);
    CHECK(what.find("0.5, 0.75") != std::string::npos);
  }
  write_config("compare: { tank_rao_csv: data/tank.csv, colour: red }\n");
  io::YamlMap bad = io::YamlMap::LoadFile((dir / "rao.yaml").string());
  CHECK_THROWS_AS(io::ReadRaoComparison(bad, Fn, L, g), io::InputError);
  write_config("water: { g_m_s2: 9.81 }\n");
  io::YamlMap absent = io::YamlMap::LoadFile((dir / "rao.yaml").string());
  CHECK_FALSE(io::ReadRaoComparison(absent, Fn, L, g).has_value());
}
