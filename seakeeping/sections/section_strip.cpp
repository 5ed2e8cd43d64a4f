#include "seakeeping/sections/section_strip.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hullopt::sk {

HalfContour SectionStripSpec::Contour() const {
  switch (shape) {
    case SectionShape::kSemicircle:
      return SemicircleContour(radius_m);
    case SectionShape::kRectangle:
      return RectangleContour(beam_m, draught_m);
    case SectionShape::kLewis:
      return LewisContour(beam_m, draught_m, area_coefficient);
    case SectionShape::kContour:
      return contour;
  }
  return contour;
}

bool SectionStripSpec::IsValid(std::string* error) const {
  std::ostringstream os;
  auto positive = [&](const char* name, double v) {
    if (os.str().empty() && !(v > 0 && std::isfinite(v)))
      os << name << " = " << v << " must be a finite number > 0";
  };
  switch (shape) {
    case SectionShape::kSemicircle:
      positive("radius_m", radius_m);
      break;
    case SectionShape::kRectangle:
      positive("beam_m", beam_m);
      positive("draught_m", draught_m);
      break;
    case SectionShape::kLewis:
      positive("beam_m", beam_m);
      positive("draught_m", draught_m);
      if (os.str().empty() && !(area_coefficient > 0 && area_coefficient <= 1))
        os << "area_coefficient = " << area_coefficient << " must be in (0, 1]";
      break;
    case SectionShape::kContour:
      if (contour.size() < 2) os << "contour needs at least 2 points, got " << contour.size();
      break;
  }
  if (os.str().empty() && (panels < 4 || panels % 2 != 0 || panels > 2000))
    os << "panels = " << panels << " must be even and in 4..2000";
  if (os.str().empty() && (count < 1 || count > 20)) os << "count = " << count << " must be in 1..20";
  if (os.str().empty() && count > 1) {
    double beam = 0.0;
    try {
      beam = SectionBeam(*this);
    } catch (const std::exception& e) {
      os << e.what();
    }
    if (os.str().empty() && !(spacing_m > beam))
      os << "spacing_m = " << spacing_m << " must exceed the section beam " << beam
         << " m so that the sections do not overlap";
  }
  if (os.str().empty()) return true;
  if (error) *error = os.str();
  return false;
}

double SectionBeam(const SectionStripSpec& spec) {
  const HalfContour c = spec.Contour();
  double half = 0.0;
  for (const auto& p : c) half = std::max(half, p[0]);
  return 2.0 * half;
}

double SectionArea(const SectionStripSpec& spec) {
  // Shoelace over the half contour closed along the waterline and the centreline, doubled.
  const HalfContour c = spec.Contour();
  double a = 0.0;
  for (std::size_t i = 0; i + 1 < c.size(); ++i) a += c[i][0] * c[i + 1][1] - c[i + 1][0] * c[i][1];
  a += c.back()[0] * 0.0 - 0.0 * c.back()[1];    // waterline point → (0, 0)
  a += 0.0 * c.front()[1] - c.front()[0] * 0.0;  // (0, 0) → keel
  return std::fabs(a);                           // 2 × (|shoelace| / 2)
}

std::vector<std::vector<Panel>> PanelSectionStrip(const SectionStripSpec& spec) {
  std::string err;
  if (!spec.IsValid(&err)) throw std::invalid_argument("section strip: " + err);
  const HalfContour c = spec.Contour();
  std::vector<std::vector<Panel>> out;
  for (int k = 0; k < spec.count; ++k) {
    const double y_centre = (0.5 * (spec.count - 1) - k) * spec.spacing_m;  // port-most first
    out.push_back(PanelSymmetricSection(c, spec.panels, y_centre));
  }
  return out;
}

}  // namespace hullopt::sk
