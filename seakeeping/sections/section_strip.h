#pragma once
// A strip of water holding one or several identical 2D sections side by side (catamaran demihulls, SWATH
// struts, several hulls in one strip), panelled for the 2D solvers (frequency_domain_section.h and the
// time-domain strip solver). The shared input of `hullopt section`.
#include <string>
#include <vector>

#include "seakeeping/green/panel.h"
#include "seakeeping/sections/section_shapes.h"

namespace hullopt::sk {

enum class SectionShape { kSemicircle, kRectangle, kLewis, kContour };

struct SectionStripSpec {
  SectionShape shape = SectionShape::kSemicircle;
  double radius_m = 1.0;          ///< [m] semicircle radius
  double beam_m = 0.0;            ///< [m] rectangle / Lewis waterline beam
  double draught_m = 0.0;         ///< [m] rectangle / Lewis draught
  double area_coefficient = 0.0;  ///< [-] Lewis A/(B T)
  HalfContour contour;  ///< kContour: half contour keel (y = 0) → waterline (z = 0), e.g. an offsets station
  int count = 1;        ///< sections in the strip
  double spacing_m = 0.0;  ///< [m] centre spacing when count > 1 (sections centred about y = 0)
  int panels = 28;         ///< panels per section, even, >= 4
  /// Checks sizes, counts and that neighbouring sections do not overlap; the error names the field and rule.
  bool IsValid(std::string* error) const;
  /// The half contour of one section (throws std::domain_error for an impossible Lewis form).
  HalfContour Contour() const;
};

/// Panels of every section, port-most first, each port waterline → keel → starboard waterline.
/// Throws std::invalid_argument when !spec.IsValid, std::domain_error for an impossible Lewis form.
std::vector<std::vector<Panel>> PanelSectionStrip(const SectionStripSpec& spec);

/// Waterline beam [m] and submerged area [m²] of one section of the spec (from its contour).
double SectionBeam(const SectionStripSpec& spec);
double SectionArea(const SectionStripSpec& spec);

}  // namespace hullopt::sk
