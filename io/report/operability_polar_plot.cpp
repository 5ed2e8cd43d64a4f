#include "io/report/operability_polar_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "io/formats/atomic_file.h"
#include "io/report/html_report.h"

namespace hullopt::io {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kKnot = 1852.0 / 3600.0;  // [m/s]
constexpr double kPolarWidth = 900.0, kCx = 450.0, kCy = 330.0, kRadius = 250.0;

std::string F(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f", v);
  return b;
}

// Screen angle, clockwise from the top, of the direction the waves come from: 180° − β.
double ScreenAngle(double beta_deg) { return (180.0 - beta_deg) * kPi / 180.0; }

double Px(double r, double theta) { return kCx + r * std::sin(theta); }
double Py(double r, double theta) { return kCy - r * std::cos(theta); }

// Red (0) → yellow (0.5) → green (1).
std::string Colour(double v) {
  v = std::clamp(v, 0.0, 1.0);
  const double lo[3] = {215, 48, 39}, mid[3] = {254, 224, 139}, hi[3] = {26, 152, 80};
  const double* a = v < 0.5 ? lo : mid;
  const double* b = v < 0.5 ? mid : hi;
  const double t = v < 0.5 ? v / 0.5 : (v - 0.5) / 0.5;
  char buf[16];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", int(a[0] + t * (b[0] - a[0]) + 0.5),
                int(a[1] + t * (b[1] - a[1]) + 0.5), int(a[2] + t * (b[2] - a[2]) + 0.5));
  return buf;
}

std::string Sector(double r0, double r1, double t0, double t1) {
  std::ostringstream p;
  const int large = (t1 - t0) > kPi ? 1 : 0;
  p << "M" << F(Px(r1, t0)) << "," << F(Py(r1, t0)) << " A" << F(r1) << "," << F(r1) << " 0 " << large
    << " 1 " << F(Px(r1, t1)) << "," << F(Py(r1, t1)) << " L" << F(Px(r0, t1)) << "," << F(Py(r0, t1));
  if (r0 > 0.0)
    p << " A" << F(r0) << "," << F(r0) << " 0 " << large << " 0 " << F(Px(r0, t0)) << "," << F(Py(r0, t0));
  p << " Z";
  return p.str();
}

std::vector<double> Distinct(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

// Band edges around sorted values: half-way between neighbours, the ends as far out as the nearest half gap.
std::vector<std::pair<double, double>> Bands(const std::vector<double>& v, double default_half) {
  std::vector<std::pair<double, double>> out;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double left = i > 0 ? 0.5 * (v[i] - v[i - 1]) : (v.size() > 1 ? 0.5 * (v[1] - v[0]) : default_half);
    const double right = i + 1 < v.size() ? 0.5 * (v[i + 1] - v[i]) : left;
    out.push_back({v[i] - (i > 0 ? left : std::min(left, right)), v[i] + right});
  }
  return out;
}

// The notes and the mirror line, each wrapped at spaces to lines of at most kNoteChars characters (11 px sans
// serif in the figure's width), continuation lines indented.
constexpr std::size_t kNoteChars = 140;
std::vector<std::string> NoteLines(const std::vector<std::string>& notes, bool mirror) {
  std::vector<std::string> in = notes, out;
  if (mirror) in.push_back("Headings 0–180° computed; the port side (180–360°) mirrors them (port–starboard symmetric hull).");
  for (const std::string& n : in) {
    std::string rest = n, indent;
    while (rest.size() + indent.size() > kNoteChars) {
      std::size_t cut = rest.rfind(' ', kNoteChars - indent.size());
      if (cut == std::string::npos || cut == 0) break;
      out.push_back(indent + rest.substr(0, cut));
      rest = rest.substr(cut + 1);
      indent = "    ";
    }
    out.push_back(indent + rest);
  }
  return out;
}

}  // namespace

std::string RenderOperabilityPolarSvg(const eval::OperabilityPolar& polar, const std::string& title,
                                      const std::vector<std::string>& notes) {
  std::vector<double> speeds, headings;
  for (const auto& c : polar.cells) {
    speeds.push_back(c.speed_m_s / kKnot);
    headings.push_back(c.heading_deg);
  }
  speeds = Distinct(speeds);
  headings = Distinct(headings);
  const bool mirror = !headings.empty() && headings.back() <= 180.0;
  // Radial bands of the speeds [kn], from 0 or half a step below the first.
  auto speed_bands = Bands(speeds, std::max(speeds.empty() ? 1.0 : speeds.front(), 1.0) * 0.5);
  if (!speed_bands.empty()) speed_bands.front().first = std::max(0.0, speed_bands.front().first);
  const double outer_kn = speed_bands.empty() ? 1.0 : speed_bands.back().second;
  auto R = [&](double kn) { return kRadius * kn / outer_kn; };
  // Angular half-width of a heading's sector: half the smallest gap between headings (15° for one heading).
  double half = 15.0;
  for (std::size_t i = 1; i < headings.size(); ++i) half = std::min(half, 0.5 * (headings[i] - headings[i - 1]));
  bool any_missing = false;
  for (const auto& c : polar.cells) any_missing = any_missing || !c.computed;
  const std::vector<std::string> lines = NoteLines(notes, mirror);
  const double notes_h = 18.0 * (lines.size() + 1);
  const double height = kCy + kRadius + 110.0 + notes_h;

  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kPolarWidth << "\" height=\"" << F(height)
      << "\" viewBox=\"0 0 " << kPolarWidth << " " << F(height) << "\" font-family=\"sans-serif\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<defs><pattern id=\"hatch\" width=\"8\" height=\"8\" patternUnits=\"userSpaceOnUse\" "
         "patternTransform=\"rotate(45)\"><rect width=\"8\" height=\"8\" fill=\"#e0e0e0\"/><line x1=\"0\" y1=\"0\" "
         "x2=\"0\" y2=\"8\" stroke=\"#9e9e9e\" stroke-width=\"2\"/></pattern></defs>\n";
  svg << "<text x=\"" << kCx << "\" y=\"30\" font-size=\"17\" font-weight=\"bold\" text-anchor=\"middle\">"
      << HtmlEscape(title) << "</text>\n";
  // The cells.
  svg << "<g class=\"cells\">\n";
  for (const auto& c : polar.cells) {
    const double kn = c.speed_m_s / kKnot;
    const auto si = std::lower_bound(speeds.begin(), speeds.end(), kn - 1e-9) - speeds.begin();
    const double r0 = R(speed_bands[si].first), r1 = R(speed_bands[si].second);
    std::vector<double> betas = {c.heading_deg};
    if (mirror && c.heading_deg > 0.0 && c.heading_deg < 180.0) betas.push_back(360.0 - c.heading_deg);
    for (double b : betas) {
      // Clockwise on screen from t0 to t1.
      const double t0 = ScreenAngle(b) - half * kPi / 180.0, t1 = ScreenAngle(b) + half * kPi / 180.0;
      const std::string fill = c.computed ? Colour(c.operability) : "url(#hatch)";
      svg << "<path d=\"" << Sector(r0, r1, t0, t1) << "\" fill=\"" << fill
          << "\" stroke=\"white\" stroke-width=\"1\"><title>" << F(kn) << " kn, heading " << c.heading_deg
          << " deg: "
          << (c.computed ? F(100.0 * c.operability) + " %" : HtmlEscape("not computed: " + c.note))
          << "</title></path>\n";
      if (c.computed && r1 - r0 > 14.0) {
        const double rm = 0.5 * (r0 + r1), tm = ScreenAngle(b);
        char buf[16];
        std::snprintf(buf, sizeof buf, "%.0f", 100.0 * c.operability);
        svg << "<text x=\"" << F(Px(rm, tm)) << "\" y=\"" << F(Py(rm, tm) + 4)
            << "\" font-size=\"11\" text-anchor=\"middle\" fill=\"#111\">" << buf << "</text>\n";
      }
    }
  }
  svg << "</g>\n";
  // Speed rings and labels (along the head-sea direction's left edge), heading spokes and labels.
  svg << "<g class=\"axes\" fill=\"none\" stroke=\"#555\" stroke-width=\"0.8\">\n";
  for (std::size_t i = 0; i < speeds.size(); ++i)
    svg << "<circle cx=\"" << kCx << "\" cy=\"" << kCy << "\" r=\"" << F(R(speed_bands[i].second))
        << "\" stroke-dasharray=\"3 3\"/>\n";
  svg << "</g>\n<g class=\"labels\" font-size=\"12\" fill=\"#222\">\n";
  // Speed labels down the following-seas axis (where a polar of 90–270° has no cells), on a white ground.
  // A speed at which the method raised a warning of its own (its validity range) is starred: its cells'
  // motions are outside the method's assumptions.
  bool any_starred = false;
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const double r = R(speeds[i]), t = ScreenAngle(0.0);
    bool starred = false;
    for (const auto& f : polar.flags)
      for (double u : f.speeds_m_s) starred = starred || (f.method && std::fabs(u / kKnot - speeds[i]) < 1e-9);
    any_starred = any_starred || starred;
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g kn%s", speeds[i], starred ? " *" : "");
    const double w = starred ? 54.0 : 44.0;
    svg << "<rect x=\"" << F(Px(r, t) - 0.5 * w) << "\" y=\"" << F(Py(r, t) - 9) << "\" width=\"" << F(w)
        << "\" height=\"15\" rx=\"3\" "
        << "fill=\"white\" fill-opacity=\"0.85\"/><text x=\"" << F(Px(r, t)) << "\" y=\"" << F(Py(r, t) + 3)
        << "\" text-anchor=\"middle\">" << buf << "</text>\n";
  }
  svg << "<text x=\"" << F(kCx + 30) << "\" y=\"" << F(kCy + 0.5 * kRadius) << "\" font-size=\"11\" fill=\"#555\">"
      << "speed (radius)</text>\n";
  if (any_starred)
    svg << "<text x=\"" << F(kCx + 30) << "\" y=\"" << F(kCy + 0.5 * kRadius + 15) << "\" font-size=\"11\" fill=\"#555\">"
        << "* outside the method's validity range (notes)</text>\n";
  for (double b : {0.0, 45.0, 90.0, 135.0, 180.0, 225.0, 270.0, 315.0}) {
    const double t = ScreenAngle(b), r = kRadius + 22.0;
    std::string text = std::to_string(int(b)) + "°";
    if (b == 180.0) text += " head seas";
    if (b == 0.0) text += " following seas";
    if (b == 90.0) text += " beam, from stbd";
    if (b == 270.0) text += " beam, from port";
    const char* anchor = std::fabs(std::sin(t)) < 0.2 ? "middle" : (std::sin(t) > 0 ? "start" : "end");
    svg << "<text x=\"" << F(Px(r, t)) << "\" y=\"" << F(Py(r, t) + 4) << "\" text-anchor=\"" << anchor << "\">"
        << text << "</text>\n";
  }
  // A ship outline at the centre, bow up.
  svg << "<path d=\"M" << kCx << "," << kCy - 18 << " L" << kCx + 6 << "," << kCy - 4 << " L" << kCx + 6 << ","
      << kCy + 16 << " L" << kCx - 6 << "," << kCy + 16 << " L" << kCx - 6 << "," << kCy - 4
      << " Z\" fill=\"#333\"/>\n";
  svg << "</g>\n";
  // Colour bar and legend.
  const double by = kCy + kRadius + 50.0, bx = 150.0, bw = 400.0;
  svg << "<defs><linearGradient id=\"opbar\">";
  for (int i = 0; i <= 10; ++i) svg << "<stop offset=\"" << i * 10 << "%\" stop-color=\"" << Colour(i / 10.0) << "\"/>";
  svg << "</linearGradient></defs>\n";
  svg << "<rect x=\"" << bx << "\" y=\"" << by << "\" width=\"" << bw << "\" height=\"14\" fill=\"url(#opbar)\"/>\n";
  for (int i = 0; i <= 4; ++i)
    svg << "<text x=\"" << bx + bw * i / 4 << "\" y=\"" << by + 28 << "\" font-size=\"11\" text-anchor=\"middle\">"
        << 25 * i << " %</text>\n";
  svg << "<text x=\"" << bx + bw + 10 << "\" y=\"" << by + 12 << "\" font-size=\"12\">operability</text>\n";
  if (any_missing)
    svg << "<rect x=\"" << bx + bw + 90 << "\" y=\"" << by << "\" width=\"18\" height=\"14\" fill=\"url(#hatch)\"/>"
        << "<text x=\"" << bx + bw + 112 << "\" y=\"" << by + 12
        << "\" font-size=\"11\">not computed (notes)</text>\n";
  double y = by + 52.0;
  for (const auto& n : lines) {
    svg << "<text x=\"20\" y=\"" << F(y) << "\" font-size=\"11\" fill=\"#444\">" << HtmlEscape(n) << "</text>\n";
    y += 18.0;
  }
  svg << "</svg>\n";
  return svg.str();
}

void WriteOperabilityPolarSvg(const std::string& path, const eval::OperabilityPolar& polar,
                              const std::string& title, const std::vector<std::string>& notes) {
  WriteFileAtomically(path, RenderOperabilityPolarSvg(polar, title, notes));
}

}  // namespace hullopt::io
