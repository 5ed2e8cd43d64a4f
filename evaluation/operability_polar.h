#pragma once
// Operability polar: for a design, every (speed, heading) of two lists, the share of a wave scatter diagram's
// probability in which every criterion holds, each cell of the diagram taken as a long-crested sea travelling
// at the heading (no spreading). The motions come from one oblique solve per speed over all headings (the
// design overload: the design's method, eval::SolveObliqueDesign), the point statistics from
// evaluation/oblique_point_response.h. No I/O.
//
// Criteria: rms vertical acceleration [g], rms lateral acceleration [g] (the specific force along the deck's y
// axis, gravity's roll component included), rms roll [deg] and MSI [%] at a passenger position (forward, lcg,
// transom, a user point, or mean = mean of the three standard positions, as the head-sea path), optionally
// off the centreline (y) and above the CG (z).
//
// Encounter frequencies <= 0 (following and quartering seas at speed: ω ≥ g/(U cos β) somewhere on the
// frequency grid) are outside the strip theory: those (speed, heading) cells are not computed and are marked
// (computed = false, a note naming the frequency), never guessed; so are the cells of a speed the method
// cannot solve (the time-domain strip method at zero speed).
#include <functional>
#include <string>
#include <vector>

#include "evaluation/design_case.h"
#include "evaluation/oblique_point_response.h"
#include "seakeeping/motions/oblique_strip_theory.h"
#include "seas/operability.h"

namespace hullopt::eval {

enum class PolarQuantity {
  kRmsVerticalAcceleration,  ///< [g]
  kRmsLateralAcceleration,   ///< [g]
  kRmsRoll,                  ///< [deg]
  kMsi                       ///< [%]
};
/// rms_vertical_acceleration, rms_lateral_acceleration, rms_roll, msi.
std::string PolarQuantityName(PolarQuantity q);
/// g, g, deg, %.
std::string PolarQuantityUnit(PolarQuantity q);

struct PolarCriterion {
  std::string name;
  PolarQuantity quantity = PolarQuantity::kRmsVerticalAcceleration;
  /// forward, lcg, transom, a user point's name, or mean (not for rms_roll, which has no position).
  std::string position = "lcg";
  double y_m = 0.0;  ///< [m] to port of the centreline
  double z_m = 0.0;  ///< [m] above the CG
  double limit = 0.0;  ///< in the quantity's unit, > 0
  std::string source;  ///< where the limit comes from, for reports
};

struct PolarOptions {
  std::vector<double> speeds_m_s;    ///< >= 0, finite, non-empty
  std::vector<double> headings_deg;  ///< within [0, 360), non-empty, no repeats
  std::vector<double> omega_rad_s;   ///< wave frequencies of the solves, > 0, increasing, at least 2
  sk::EvaluationOptions evaluation;  ///< MSI model and quadrature
  /// Viscous roll damping of the design overload (eval::SetDesignRollDamping: Ikeda's components for a
  /// monohull, the demihulls' Cs term for a multihull); model kNone (the default): potential roll damping only.
  sk::RollDampingOptions roll_damping;
  /// The rules above; the error names the field and the value.
  bool IsValid(std::string* error) const;
};

struct PolarCell {
  double speed_m_s = 0.0;
  double heading_deg = 0.0;
  bool computed = true;
  std::string note;                     ///< why a cell was not computed
  double operability = 0.0;             ///< [-] share of the diagram's probability with every criterion met
  std::vector<double> criterion_share;  ///< [-] per criterion
};

/// A flag raised at some of the polar's speeds [m/s]: a sentence of sk::RollDampingRangeFlags (the hull or its
/// roll natural frequency outside the range the roll damping model was fitted in, or a multihull), or of the
/// method's own warnings (the time-domain strip method's validity range at that speed, the strip kernel's).
struct PolarFlag {
  std::string text;
  std::vector<double> speeds_m_s;
  /// The method's own warning (its validity range, the strip kernel's), which questions the motions themselves
  /// at those speeds (the plot marks them), rather than the roll damping model's range.
  bool method = false;
};

struct OperabilityPolar {
  std::vector<PolarCell> cells;  ///< speed-major: cells[s * headings + h]
  /// The design overload: the method (eval::ObliqueMethodNote), the roll damping used (eval::RollDampingNote)
  /// and the flags in the order first raised: the method's warnings at each speed and the roll damping's at
  /// each speed's roll natural frequency (eval::RollNaturalFrequency; none for kNone).
  std::string method;
  std::string roll_damping;
  std::vector<PolarFlag> flags;
};

/// The motions at one speed [m/s] and a list of headings [deg] (on options.omega_rad_s).
using ObliqueSolve = std::function<sk::ObliqueStripResult(double speed_m_s, const std::vector<double>& headings_deg)>;

/// Lowest wave frequency [rad/s] at which the encounter frequency ω − ω²U cos β/g reaches 0: g/(U cos β), or
/// infinity when it never does (U cos β <= 0).
double ZeroEncounterWaveFrequency(double speed_m_s, double heading_deg, double g_m_s2);

/// Why `solve` cannot solve a speed [m/s] at all (e.g. the time-domain strip method at zero speed), or "".
using SpeedFault = std::function<std::string(double speed_m_s)>;

/// The polar by `solve`. hull places the standard positions; user_points are further named positions. The
/// cells of a speed with an `unsolvable` fault are not computed and carry it as their note. Throws
/// std::invalid_argument for invalid options, diagram or criteria (an unknown position, a limit <= 0, a
/// position with rms_roll), and what `solve` throws.
OperabilityPolar ComputeOperabilityPolar(const ObliqueSolve& solve, double g_m_s2, const sk::HullExtent& hull,
                                         const sk::ScatterDiagram& diagram,
                                         const std::vector<PolarCriterion>& criteria,
                                         const std::vector<sk::PassengerPosition>& user_points,
                                         const PolarOptions& options, const SpeedFault& unsolvable = nullptr);

/// The same for a built design (eval::SolveObliqueDesign with roll radius of gyration kxx_m and the viscous
/// roll damping of options.roll_damping: a strip kernel per speed for the time-domain strip method), with the
/// method's and the roll damping's notes and flags.
OperabilityPolar ComputeOperabilityPolar(const DesignCase& design, double kxx_m, const sk::ScatterDiagram& diagram,
                                         const std::vector<PolarCriterion>& criteria,
                                         const std::vector<sk::PassengerPosition>& user_points,
                                         const PolarOptions& options);

}  // namespace hullopt::eval
