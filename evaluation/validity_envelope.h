#pragma once
// The validity envelope of the method: one table of rules, each a quantity with the range outside which a
// result is flagged (a warning in every output of the run) and the range outside which the input is refused
// (one-line error naming the key and the rule), and the source of both numbers. docs/bad-inputs.md
// ("Validity envelope") lists the same table; tests/unit/test_validity_envelope.cpp checks each row.
//
// The rules cover what the other plausibility checks (parametric_hull/plausibility.h: a hull that cannot
// float, units of offsets; seakeeping/motions/validity_range.h: the low-Froude-number side of the 2D+t method)
// do not: speed against planing, sea steepness, the responses linear theory can still describe, the damping
// coefficient Cs, the water and gravity, the mass at rest, the hull spacing and the absolute size of a hull.
// No I/O: the commands (io/, app/) apply them and carry the warnings.
#include <cmath>
#include <string>
#include <vector>

#include "parametric_hull/hull_form.h"
#include "parametric_hull/hydrostatics.h"
#include "seas/design_evaluation.h"

namespace hullopt::eval {

enum class EnvelopeQuantity {
  kFroudeNumber,           ///< Fn = U / sqrt(g L)
  kVolumetricFroude,       ///< Fn_vol = U / sqrt(g V^(1/3)), V the displaced volume of all bodies
  kWaveSteepness,          ///< Hs / lambda_p, lambda_p = g Tp^2 / (2 pi)
  kRmsAccelerationG,       ///< sigma_a / g at a passenger position
  kDampingCs,              ///< Cs of the sectional damping D = 1/2 Cs rho U v B
  kGravity,                ///< g [m/s^2]
  kWaterDensity,           ///< rho [kg/m^3]
  kStaticTrimDeg,          ///< atan(|LCG - LCB| / BM_L) [deg]: the trim the mass would give at rest
  kKgOverDepth,            ///< KG / D, D the top of the hull's stations above the baseline
  kKyyOverL,               ///< k_yy / L
  kHullSpacingOverL,       ///< largest centre distance between two hulls / L
  kHullLength,             ///< L [m]
  kDisplacementTonnes,     ///< displacement [t]
};

struct EnvelopeRule {
  EnvelopeQuantity quantity;
  const char* name;        ///< as in messages, e.g. "Fn"
  const char* definition;  ///< e.g. "U / sqrt(g L)"
  double flag_min, flag_max;  ///< flagged outside [flag_min, flag_max] (+-infinity: no bound on that side)
  double hard_min, hard_max;  ///< refused outside [hard_min, hard_max] (+-infinity: never refused that side)
  const char* flag_source;    ///< why the flag range (a reference or a physical argument)
  const char* hard_source;    ///< why the hard range
};

/// The whole table, in the order of docs/bad-inputs.md.
const std::vector<EnvelopeRule>& EnvelopeRules();
/// The row of one quantity.
const EnvelopeRule& EnvelopeRuleOf(EnvelopeQuantity q);

struct EnvelopeFinding {
  EnvelopeQuantity quantity;
  std::string key;      ///< config key the value comes from ("speed", "water.g_m_s2", "mass.kg_m", "hull", ...)
  std::string message;  ///< the value, its context, the bound crossed and the source
  bool refuse = false;  ///< beyond the hard limit (else a warning)
};

/// One value against its row: nothing inside the flag range, a warning between the flag and the hard limit,
/// a refusal beyond it. `context` (e.g. "U 20.6 m/s, L 89.3 m") goes into the message in brackets.
std::vector<EnvelopeFinding> CheckEnvelopeValue(EnvelopeQuantity q, double value, const std::string& key,
                                                const std::string& context = "");

/// What a design as configured is checked for; a value that is NaN (or a null pointer) is not known to the
/// command and its rules are not applied.
struct EnvelopeInput {
  double rho_kg_m3 = NAN;
  double g_m_s2 = NAN;
  double speed_m_s = NAN;  ///< at the hull's length and displacement (needs hs)
  double cs = NAN;
  const hull::HullForm* hull = nullptr;        ///< spacing, depth for KG
  const hull::Hydrostatics* hs = nullptr;      ///< L, displacement, LCB, BM_L
  const hull::MassProperties* mass = nullptr;  ///< LCG, KG (k_yy: parametric_hull/plausibility.h)
};

/// Every rule the input has the values for, refusals first.
std::vector<EnvelopeFinding> CheckEnvelope(const EnvelopeInput& in);

/// Flags of the results of an evaluation: sea steepness and rms vertical acceleration above 1 g (per sea and
/// position; linear theory assumes the hull stays in the water). g_m_s2 converts Tp to the peak wave length.
std::vector<std::string> ResponseEnvelopeWarnings(const sk::DesignEvaluation& evaluation, double g_m_s2);

/// Peak wave length [m] of a sea state (Tp given or from Tz and the spectrum shape) at gravity g.
double PeakWaveLength(const sk::SeaState& sea, double g_m_s2);

/// Top of the hull's stations above the baseline [m] (the modelled depth), 0 for a hull without stations.
double HullDepth(const hull::HullForm& hull);

/// Largest distance between the centrelines of two hulls [m] (0 for a monohull).
double LargestHullSpacing(const hull::HullForm& hull);

}  // namespace hullopt::eval
