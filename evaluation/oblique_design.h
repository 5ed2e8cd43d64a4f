#pragma once
// The oblique-sea strip theory (seakeeping/motions/oblique_strip_theory.h) for a built design: its running
// hull's strip stations on the design's strip grid (solver.sections, solver.panels), its mass with the roll and
// yaw radii of gyration, at any speed and list of headings. No I/O.
#include <string>
#include <vector>

#include "evaluation/design_case.h"
#include "seakeeping/motions/oblique_strip_theory.h"
#include "seakeeping/motions/roll_damping.h"

namespace hullopt::eval {

/// The rule of a list of wave headings [deg] (an options struct's field named `key`, e.g. "headings_deg"): each
/// within [0, 360), none twice. Returns "" or the first fault, naming the entry and its value
/// ("headings_deg[1] = 360: must be within [0, 360)").
std::string CheckHeadingList(const std::vector<double>& headings_deg, const std::string& key);

/// The roll radius of gyration taken when none is given: 0.35 × the overall beam of the hull's offsets (every
/// body at its lateral position), the usual estimate for ships and small craft [m].
double DefaultRollRadiusOfGyration(const hull::HullForm& hull);

/// The design's mass for the oblique strip theory: mass, LCG (from the AP, the stations' x), z_G = KG − the
/// running draught, I44 = m kxx², I55 = m kyy², I66 = m kyy² (yaw's radius of gyration taken as pitch's).
sk::ObliqueMassProperties ObliqueMassOf(const DesignCase& design, double kxx_m);

/// The fault that keeps a design's solver settings off the time-domain strip method in oblique seas (the
/// kernel's lateral rows need the momentum form, the source sum and all bodies sharing the strips), or "".
std::string ObliqueTimeDomainFault(const SolverSettings& solver);

/// Why SolveObliqueDesign cannot solve the design at speed_m_s (the time-domain strip method at speed <= 0), or "".
std::string ObliqueSpeedFault(const DesignCase& design, double speed_m_s);

/// Which method a design's oblique solve takes, for notes in outputs: "the time-domain strip method (periodic
/// steady state, Cs = ... in heave and pitch)" or "the oblique-sea strip theory (STF, Cs = ... in heave and
/// pitch)".
std::string ObliqueMethodNote(const DesignCase& design);

/// Sway, heave, roll, pitch and yaw at every heading [deg] and wave frequency [rad/s] at speed_m_s (the running
/// hull of the design's own speed: the attitude is not re-solved per speed), with the design's water, strip
/// grid, Cs and method (solver.method): the time-domain strip method's periodic steady state on the kernel with
/// its lateral rows (sk::SolveObliquePeriodic; at 180 deg heave and pitch are the head-sea path's), or the
/// oblique-sea strip theory (sk::SolveObliqueStripTheory). `options` gives the roll damping (its rho, g, speed
/// and Cs are replaced by the design's and speed_m_s). `warnings`, when given, receives the strip kernel's
/// warnings and, for the time-domain method, its validity range at this speed (sk::ValidityWarnings). Throws
/// what the solvers throw (std::domain_error for an encounter frequency <= 0), std::invalid_argument for
/// kxx_m <= 0, for settings with an ObliqueTimeDomainFault and for the time-domain method at speed <= 0.
sk::ObliqueStripResult SolveObliqueDesign(const DesignCase& design, double speed_m_s,
                                          const std::vector<double>& omega_rad_s,
                                          const std::vector<double>& headings_deg, double kxx_m,
                                          sk::ObliqueStripOptions options = {},
                                          std::vector<std::string>* warnings = nullptr);

/// The hull particulars of the viscous roll damping (seakeeping/motions/roll_damping.h): L, B, d, Cb, Cm of one
/// hull from `hs` (hydrostatics at rest), OG = og_m (the CG below the waterline, positive down); for a
/// multihull every physical body's |y| and waterplane area (a mirror pair twice).
sk::RollDampingHull RollDampingHullOf(const hull::HullForm& hull, const hull::Hydrostatics& hs, double og_m,
                                      double rho_kg_m3);

/// The design's viscous roll damping in `options`: `roll` (model, roll amplitude, viscosity) with the hull
/// particulars of RollDampingHullOf (hull and hydrostatics at rest, OG = the running draught − KG, the design's
/// water) and, for a multihull, the Cs of the design's solver. model kNone leaves `options` as it is, so that
/// the solve is bitwise the one without viscous roll damping.
void SetDesignRollDamping(const DesignCase& design, const sk::RollDampingOptions& roll,
                          sk::ObliqueStripOptions* options);

/// What the viscous roll damping of `options` is, for notes in outputs: "potential only", or the model
/// (Ikeda's components for a monohull, the demihulls' Cs heave damping for a multihull) and the roll amplitude
/// it is linearised at.
std::string RollDampingNote(const sk::ObliqueStripOptions& options);

/// The roll natural frequency among the solved encounter frequencies: where ω² (I44 + A44(ω)) − C44 is closest
/// to zero (0 when the hull has no positive roll stiffness).
double RollNaturalFrequency(const sk::ObliqueStripResult& r);

}  // namespace hullopt::eval
