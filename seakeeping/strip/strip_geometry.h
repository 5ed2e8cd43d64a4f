#pragma once
// From a HullForm to the panelled sections a strip of water passes through (the geometry half of a
// StripKernel). The strip advances Δx = L_span/sections per step; step n holds the hull at the cell midpoint
// x_n = x_fwd − (n + ½)Δx [m from AP], from the bow (n = 0) to the stern (n = sections − 1), or with
// StationLayout::kCellFaces at the cell faces x_n = x_fwd − nΔx, n = 0 .. sections (bow and transom
// included), where x_fwd and x_aft are the extreme stations of all bodies of the hull (also when only one
// body is panelled). Each body's
// section at x_n (hull::InterpolateStation) is cut at the design draught (hull::WettedContour), shifted to z
// = 0 at the waterline and panelled (PanelSymmetricSection) at its centreline; mirror pairs (y_centre > 0)
// get one panelled section each side.
#include <string>
#include <vector>

#include "parametric_hull/hull_form.h"
#include "seakeeping/green/panel.h"
#include "seakeeping/strip/strip_kernel.h"

namespace hullopt::sk {

struct StripGeometryOptions {
  int sections = 40;  ///< strip steps along the hull (paper: 40), >= 2
  int panels = 14;    ///< panels per wetted section of one body (paper: 14), even, >= 4
  /// Bodies to include: -1 all bodies (multihull hulls share the strips and interact), otherwise only the
  /// body of that index, without its mirror (one demihull alone).
  int body = -1;
  StationLayout layout = kDefaultStationLayout;  ///< kCellFaces needs sections >= 3
  /// How the panels of a section are spread over its girth (end_spacing in (0, 1], grading in (0, 10]).
  PanelSpacing spacing;
  bool IsValid(std::string* error) const;
};

/// A StripKernel with the geometry filled in (speed, dx, dt = dx/U, ρ, g, x_m, panels) and every force row
/// zero: the kernel solver fills `force`; as it stands it is the "no disturbance potential" model
/// (hydrostatics, Froude–Krylov and damping only). Stations where a body is dry (outside its length or keel
/// above the waterline) contribute no panels. Throws std::invalid_argument for bad options or speed, and
/// std::domain_error naming the body and x if a wetted section does not reach the waterline (contour ending
/// below z = T, e.g. a submerged deck edge) or does not start at the centreline.
StripKernel StripKernelGeometry(const hull::HullForm& hull, const StripGeometryOptions& options,
                                double speed_m_s, double rho_kg_m3, double g_m_s2);

/// The panels of the bodies' sections at x_m [m from AP] (the bodies options.body selects, mirror pairs on
/// both sides) cut at the waterline z = draught_m [m above the baseline] and shifted to z = 0 there: the
/// section of one strip step. Empty where every body is dry. With `contour`, also the wetted contour itself
/// (the segments of the hull's section polyline, both sides of every body, in no particular order), which the
/// panels' chords approximate. Throws std::domain_error as StripKernelGeometry.
std::vector<Panel> StripSectionPanels(const hull::HullForm& hull, double x_m, double draught_m,
                                      const StripGeometryOptions& options, std::vector<Panel>* contour = nullptr);

/// One strip kernel from independent ones on the same steps (same x_m, dx, dt): panels concatenated, force
/// rows side by side, i.e. bodies in the same strips that do not see each other's disturbance. Used for
/// "demihulls without interaction" and for checking the interaction effect. Throws std::invalid_argument on
/// mismatch.
StripKernel CombineIndependentKernels(const std::vector<StripKernel>& parts);

}  // namespace hullopt::sk
