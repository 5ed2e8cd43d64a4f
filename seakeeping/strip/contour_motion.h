#pragma once
// How a strip's wetted contour moves from one step to the next as the hull passes through the strip: the
// normal speed of every panel and the speed of every waterline point. These are the geometric inputs of the
// transport term that separates the fixed-point pressure integral from the rate of change of the strip's
// momentum (docs/theory.md, "Sectional force in a strip whose section changes"):
//   ρ ∫_S φ_t n_z dl = dI/dt − ρ [ ∫_S W_n ∂φ/∂z dl − Σ_wl φ ẏ_out ],
// W_n the contour's speed along its normal (into the fluid), ẏ_out the speed of a waterline point away from
// its body along the free surface. Both follow from the panel sets of the neighbouring steps, taken dt apart
// in time, by central differences (one-sided at the first and last step and next to an empty step).
#include <vector>

#include "seakeeping/green/panel.h"

namespace hullopt::sk {

/// A panel end on the free surface (z = 0) that does not meet another panel: where a body's contour meets the
/// water line.
struct WaterlinePoint {
  int panel = 0;            ///< index of the panel whose end it is
  bool at_end = false;      ///< the panel's second end point (p2) if true, else its first (p1)
  double y_m = 0.0;         ///< [m] its y
  double outward = 1.0;     ///< +1 if the free surface beside it lies towards +y, −1 towards −y
  double speed_m_s = 0.0;   ///< [m/s] ẏ_out: its speed away from the body along the free surface
};

struct ContourMotion {
  std::vector<double> normal_speed_m_s;  ///< [m/s] per panel: W_n at the collocation point, + into the fluid
  std::vector<WaterlinePoint> waterline;
};

/// The waterline points of one step's panels (speeds zero). A panel end counts when |z| <= tol_m and no other
/// panel of the step starts or ends there.
std::vector<WaterlinePoint> FindWaterlinePoints(const std::vector<Panel>& panels, double tol_m);

/// The motion of the contour of step n of `steps` (all panels of each step, dt [s] between steps). The normal
/// offset of a neighbouring contour is measured from each collocation point to the closest point of that
/// contour, along the panel normal (exact to second order in the offset for a smooth contour); a waterline
/// point moves to the neighbour's waterline point nearest in y with the same outward side. A step whose
/// neighbours are both empty does not move.
/// With `contours` (per step, the segments of the wetted contour the panels stand for, e.g. from
/// StripSectionPanels), the offsets are measured to those instead of to the neighbours' panels, less the
/// offset of the step's own contour: the chords' sagitta then cancels, and panels that slide along the contour
/// from step to step (a waterline cut that moves with the hull) do not read as normal motion.
ContourMotion StepContourMotion(const std::vector<std::vector<Panel>>& steps, int n, double dt,
                                const std::vector<std::vector<Panel>>* contours = nullptr);

}  // namespace hullopt::sk
