// SVG plot writer: the document is well-formed XML with one <svg> root, carries every title, axis label and
// legend text (escaped), has nice tick labels on linear and log axes, and skips non-finite points.
#include <catch2/catch.hpp>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "io/formats/input_error.h"
#include "io/report/svg_plot.h"

namespace io = hullopt::io;

namespace {

// A small independent XML well-formedness check: balanced and properly nested tags, quoted attributes,
// only the five predefined or numeric entities, no raw '<' in text, exactly one root element.
bool WellFormed(const std::string& s, std::string* why) {
  std::vector<std::string> stack;
  int roots = 0;
  size_t i = 0;
  auto fail = [&](const std::string& m) {
    *why = m + " at offset " + std::to_string(i);
    return false;
  };
  auto check_text = [&](const std::string& t) {
    for (size_t k = 0; k < t.size(); ++k) {
      if (t[k] == '<') return false;
      if (t[k] == '&') {
        const size_t semi = t.find(';', k);
        if (semi == std::string::npos) return false;
        const std::string ent = t.substr(k + 1, semi - k - 1);
        if (ent != "amp" && ent != "lt" && ent != "gt" && ent != "quot" && ent != "apos" &&
            (ent.empty() || ent[0] != '#'))
          return false;
      }
    }
    return true;
  };
  while (i < s.size()) {
    if (s[i] != '<') {
      const size_t next = s.find('<', i);
      const std::string text = s.substr(i, next == std::string::npos ? std::string::npos : next - i);
      if (!check_text(text)) return fail("bad character data");
      if (stack.empty() && text.find_first_not_of(" \n\r\t") != std::string::npos)
        return fail("text outside the root");
      if (next == std::string::npos) break;
      i = next;
      continue;
    }
    if (s.compare(i, 2, "<?") == 0) {
      const size_t e = s.find("?>", i);
      if (e == std::string::npos) return fail("unterminated declaration");
      i = e + 2;
      continue;
    }
    if (s.compare(i, 4, "<!--") == 0) {
      const size_t e = s.find("-->", i);
      if (e == std::string::npos) return fail("unterminated comment");
      i = e + 3;
      continue;
    }
    const bool closing = s.compare(i, 2, "</") == 0;
    size_t k = i + (closing ? 2 : 1);
    const size_t name_start = k;
    while (k < s.size() && (std::isalnum(static_cast<unsigned char>(s[k])) || s[k] == '-' || s[k] == ':'))
      ++k;
    const std::string name = s.substr(name_start, k - name_start);
    if (name.empty()) return fail("empty tag name");
    bool self_closing = false;
    // Attributes: name="value".
    while (true) {
      while (k < s.size() && std::isspace(static_cast<unsigned char>(s[k]))) ++k;
      if (k >= s.size()) return fail("unterminated tag");
      if (s[k] == '>') break;
      if (s.compare(k, 2, "/>") == 0) {
        self_closing = true;
        ++k;
        break;
      }
      if (closing) return fail("attribute in closing tag");
      const size_t a0 = k;
      while (k < s.size() && (std::isalnum(static_cast<unsigned char>(s[k])) || s[k] == '-' || s[k] == ':'))
        ++k;
      if (k == a0 || k >= s.size() || s[k] != '=') return fail("bad attribute");
      ++k;
      if (k >= s.size() || s[k] != '"') return fail("unquoted attribute");
      const size_t e = s.find('"', k + 1);
      if (e == std::string::npos) return fail("unterminated attribute");
      if (!check_text(s.substr(k + 1, e - k - 1))) return fail("bad attribute value");
      k = e + 1;
    }
    i = k + 1;
    if (closing) {
      if (stack.empty() || stack.back() != name) return fail("mismatched </" + name + ">");
      stack.pop_back();
    } else if (!self_closing) {
      if (stack.empty()) ++roots;
      stack.push_back(name);
    } else if (stack.empty()) {
      ++roots;
    }
  }
  if (!stack.empty()) return fail("unclosed <" + stack.back() + ">");
  if (roots != 1) return fail("expected one root element, found " + std::to_string(roots));
  return true;
}

int Count(const std::string& hay, const std::string& needle) {
  int n = 0;
  for (size_t p = hay.find(needle); p != std::string::npos; p = hay.find(needle, p + 1)) ++n;
  return n;
}

io::PlotFigure SampleFigure() {
  io::PlotFigure fig;
  fig.title = "Sample figure: spectra & RAOs";
  fig.footnote = "JONSWAP γ = 3.3, head seas, 40 kn";
  std::vector<double> w, s1, s2;
  for (int i = 1; i <= 120; ++i) {
    const double x = 0.05 * i;
    w.push_back(x);
    s1.push_back(std::exp(-std::pow(x - 1.6, 2) / 0.1));
    s2.push_back(0.6 * std::exp(-std::pow(x - 2.9, 2) / 0.2));
  }
  auto& p1 = fig.AddPanel("Encounter spectra", "ω_e [rad/s]", "S(ω_e) [m²s/rad]");
  p1.series.push_back(io::PlotSeries::Line("Hs 3 m, Tz 7.5 s", w, s1));
  p1.series.push_back(io::PlotSeries::Line("Hs 0.5 m, Tz 5 s", w, s2));
  p1.series.back().dash = "6 3";
  auto& p2 = fig.AddPanel("Heave RAO <measured vs computed>", "λ/L [-]", "|x3|/A [m/m]");
  p2.series.push_back(io::PlotSeries::LineMarkers("computed", {0.5, 1.0, 1.5, 2.0, 3.0, 4.0},
                                                  {0.1, 0.6, 1.3, 1.1, 1.02, 1.0}));
  auto measured = io::PlotSeries::Markers("tank (Delft 372)", {0.6, 1.2, 1.8, 2.4}, {0.2, 0.9, 1.25, 1.05});
  measured.hollow_markers = true;
  measured.marker = io::MarkerShape::kSquare;
  p2.series.push_back(measured);
  p2.bands.push_back({"paper range", 0.9, 1.2, "#2ca02c"});
  p2.y_include_zero = true;
  auto& p3 = fig.AddPanel("Log-log with a NaN gap", "f [Hz]", "a [m/s²]");
  p3.x_scale = io::AxisScale::kLog;
  p3.y_scale = io::AxisScale::kLog;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  p3.series.push_back(io::PlotSeries::LineMarkers("with gap", {0.01, 0.1, 0.3, 1.0, 3.0, 10.0},
                                                  {0.02, 0.1, nan, 1.5, 4.0, 30.0}));
  p3.series.back().point_labels = {"a", "b", "c", "d", "e", "f"};
  return fig;
}

}  // namespace

TEST_CASE("nice linear ticks are 1, 2, 2.5 or 5 times a power of ten and cover the range", "[plot]") {
  auto t = io::NiceLinearTicks(0.13, 2.87);
  REQUIRE(t.size() >= 4);
  CHECK(t.front() <= 0.13);
  CHECK(t.back() >= 2.87);
  CHECK(t[1] - t[0] == Approx(0.5));
  auto u = io::NiceLinearTicks(42.0, 72.0);
  CHECK(u.front() == Approx(40.0));
  CHECK(u.back() == Approx(75.0));
  CHECK(io::FormatTick(0.5, 0.5) == "0.5");
  CHECK(io::FormatTick(1.0, 0.25) == "1.00");
  CHECK(io::FormatTick(40.0, 5.0) == "40");
  CHECK(io::FormatTick(-0.2, 0.1) == "−0.2");
  CHECK(io::FormatTick(1e-17, 0.1) == "0.0");
}

TEST_CASE("a multi-panel figure is well-formed SVG with all labels", "[plot]") {
  const auto fig = SampleFigure();
  const std::string svg = io::RenderSvg(fig);
  std::string why;
  INFO(why);
  REQUIRE(WellFormed(svg, &why));
  CHECK(svg.find("<svg xmlns=\"http://www.w3.org/2000/svg\"") != std::string::npos);
  for (const char* text :
       {"Sample figure: spectra &amp; RAOs", "Encounter spectra", "ω_e [rad/s]", "S(ω_e) [m²s/rad]",
        "Hs 3 m, Tz 7.5 s", "Hs 0.5 m, Tz 5 s", "Heave RAO &lt;measured vs computed&gt;", "λ/L [-]",
        "tank (Delft 372)", "paper range", "f [Hz]", "a [m/s²]", "JONSWAP γ = 3.3"}) {
    INFO(text);
    CHECK(svg.find(text) != std::string::npos);
  }
  // Three panels, each with its two clip paths (lines to the plot area, markers a little wider); log axes
  // label their decades.
  CHECK(Count(svg, "<g class=\"panel\">") == 3);
  CHECK(Count(svg, "<clipPath") == 6);
  CHECK(svg.find(">0.01</text>") != std::string::npos);
  CHECK(svg.find(">10</text>") != std::string::npos);
  // The NaN splits the log-log line into two subpaths and draws no "nan" coordinate.
  CHECK(svg.find("nan") == std::string::npos);
  CHECK(svg.find("inf") == std::string::npos);
  // Hollow square markers for the measured points.
  CHECK(Count(svg, "fill=\"#ffffff\" stroke=\"#ff7f0e\"") >= 4);

  const std::string path = std::string(HULLOPT_BINARY_DIR) + "/test_svg_plot_sample.svg";
  io::WriteSvg(fig, path);
  std::ifstream f(path);
  std::stringstream back;
  back << f.rdbuf();
  CHECK(back.str() == svg);
}

TEST_CASE("empty and degenerate panels still render", "[plot]") {
  io::PlotFigure fig;
  fig.AddPanel("empty", "x [m]", "y [m]");
  auto& p = fig.AddPanel("one point", "x [m]", "y [m]");
  p.series.push_back(io::PlotSeries::Markers("single", {2.0}, {3.0}));
  p.legend = io::LegendPlace::kOutsideRight;
  std::string why;
  INFO(why);
  CHECK(WellFormed(io::RenderSvg(fig), &why));
}

TEST_CASE("an unwritable plot path is an InputError", "[plot][bad-input]") {
  CHECK_THROWS_AS(io::WriteSvg(SampleFigure(), "/nonexistent-dir/x.svg"), io::InputError);
}
