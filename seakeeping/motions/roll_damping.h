#pragma once
// Viscous roll damping: what potential flow leaves out of B44, for the oblique-sea strip theory
// (oblique_strip_theory.h) to add to its potential roll damping before solving. No I/O.
//
// Monohull: Ikeda's component method (Ikeda, Himeno & Tanaka 1978, "A prediction method for ship roll
// damping", Univ. Osaka Prefecture report 00405; Himeno 1981, "Prediction of ship roll damping: state of the
// art", Univ. Michigan report 239) in the closed forms of Kawahara, Maekawa & Ikeda (2009/2011, "A simple
// prediction formula of roll damping of conventional cargo ships on the basis of Ikeda's method and its
// limitation", Contemporary Ideas on Ship Stability and Capsizing in Waves, pp. 465-486; their program
// Roll_Damping.for, 2009). Components (docs/theory.md, "Viscous roll damping"):
//  - hull skin friction, Kato (1957) laminar form with Ikeda's speed factor 1 + 4.1 U/(ωL);
//  - eddy making of the naked hull, Kawahara's C_R fit with Ikeda's speed reduction (0.04K)²/(1 + (0.04K)²),
//    K = ωL/U;
//  - hull lift at forward speed (Ikeda; Himeno 1981 eq. for B_L);
//  - bilge keels, Kawahara's fit (zero when the hull has none).
// The wave (radiation) part is the strips' potential damping and is not repeated here.
// Quadratic parts are linearised at a stated roll amplitude φa: B_eq = B1 + (8/(3π)) ω φa B2 (equal energy
// dissipated over one cycle of φ = φa sin ωt).
//
// Multihull (two or more bodies): the roll of a demihull pair is dominated by the demihulls' heave, so its
// viscous part is their cross-flow heave damping at their lateral offsets: Davis & Holloway's (2003) sectional
// force D = ½ Cs ρ U v B (docs/theory.md) with v = −y_i φ̇ on demihull i gives B44 = Σ_i y_i² · ½ Cs ρ U
// A_wp,i (A_wp,i the demihull's waterplane area). Ikeda's monohull formulae do not cover a demihull pair.
//
// Axes: as oblique_strip_theory.h; OG is the roll axis (the CG) below the still waterline, positive down
// (Kawahara's sign: OG/d < 0 is a CG above the waterline).
#include <string>
#include <vector>

namespace hullopt::sk {

/// The hull particulars the formulae need. Monohull: L, B, d, Cb, Cm of the hull; multihull: the offsets and
/// waterplane areas of the bodies (L..Cm then describe one demihull and only feed the range check).
struct RollDampingHull {
  double length_m = 0.0;              ///< [m] L (waterline length)
  double breadth_m = 0.0;             ///< [m] B (waterline breadth of one hull)
  double draught_m = 0.0;             ///< [m] d
  double block_coefficient = 0.0;     ///< Cb = ∇/(L B d) of one hull
  double midship_coefficient = 0.0;   ///< Cm = A_M/(B d)
  double og_m = 0.0;                  ///< [m] OG: roll axis (CG) below the still waterline, positive down
  double bilge_keel_length_m = 0.0;   ///< [m] total length of one bilge keel (0: none)
  double bilge_keel_breadth_m = 0.0;  ///< [m] its breadth (height off the hull)
  /// Multihull: each body's |y| of its centreplane [m] and waterplane area [m²]; empty for a monohull.
  std::vector<double> body_offset_m;
  std::vector<double> body_waterplane_m2;
  bool Multihull() const { return body_offset_m.size() > 1; }
  bool IsValid(std::string* error) const;
};

enum class RollDampingModel { kNone, kIkeda };

struct RollDampingOptions {
  /// kNone: no viscous roll damping (the strip theory's potential damping only). kIkeda: Ikeda's components
  /// for a monohull, the demihulls' Cs heave damping for a multihull.
  RollDampingModel model = RollDampingModel::kNone;
  /// [rad] roll amplitude φa at which the quadratic parts are linearised, > 0 and < 0.5 (29°). 5° by default:
  /// the roll seakeeping criteria lie there (NORDFORSK 1987: 4° to 6° rms), so the damping is that of the
  /// motions operability is decided at; smaller amplitudes give less damping and a larger roll peak.
  double roll_amplitude_rad = 5.0 * 3.14159265358979323846 / 180.0;
  /// [m²/s] kinematic viscosity (ITTC 7.5-02-01-03: sea water at 15 °C, 1.19e-6) for the skin friction.
  double kinematic_viscosity_m2_s = 1.19e-6;
  double rho_kg_m3 = 1025.0;  ///< [kg/m³]
  double g_m_s2 = 9.81;       ///< [m/s²]
  /// Cs [-] of Davis & Holloway's sectional damping (multihull model; the same Cs as the heave-pitch solver).
  double damping_cs = 0.0;
  bool IsValid(std::string* error) const;
};

/// The components at one frequency and speed, each as B1 (linear, N m s) or B2 (quadratic, N m s², so that
/// its equivalent linear part is (8/(3π)) ω φa B2).
struct RollDampingComponents {
  double friction = 0.0;        ///< B1: skin friction with its speed factor
  double lift = 0.0;            ///< B1: hull lift (0 at zero speed)
  double demihull_cs = 0.0;     ///< B1: multihull, Σ y_i² ½ Cs ρ U A_wp,i
  double eddy_quadratic = 0.0;  ///< B2: eddy making with its speed reduction
  double bilge_keel_quadratic = 0.0;  ///< B2: bilge keels at φa (their fit is not purely quadratic)
  double linear = 0.0;          ///< B1 total
  double quadratic = 0.0;       ///< B2 total
  double equivalent = 0.0;      ///< [N m s] B_eq = B1 + (8/(3π)) ω φa B2
};

/// B_eq = b1 + (8/(3π)) ω φa b2: the linear damping that dissipates, over one cycle of φ = φa sin ωt, the
/// energy of the moment b1 φ̇ + b2 φ̇|φ̇|.
double EquivalentLinearRollDamping(double b1, double b2, double omega_rad_s, double roll_amplitude_rad);

/// Kato's skin-friction roll damping at zero speed (Kawahara et al. 2009, friction component; Himeno 1981
/// eq. for B_F0, laminar): r_f = d[(0.887 + 0.145 Cb)(1.7 + Cb B/d) − 2 OG/d]/π, S_f = L(1.75 d + Cb B),
/// C_f = 1.328 (3.22 r_f² φa²/(T ν))^(−1/2) with T = 2π/ω, B_F0 = (4/(3π)) ρ S_f r_f³ φa ω C_f [N m s].
double KatoFrictionRollDamping(const RollDampingHull& hull, double omega_rad_s, const RollDampingOptions& o);

/// Kawahara's eddy-making coefficient C_R of the naked hull at zero speed (their eddy component), so that
/// B_E0 = (4/(3π)) ρ L d⁴ ω φa C_R, i.e. B2 = ½ ρ L d⁴ C_R.
double KawaharaEddyCoefficient(const RollDampingHull& hull);

/// Every component at frequency ω (the encounter frequency, > 0) and ship speed U [m/s] (its magnitude
/// counts). model kNone gives zeros. Throws std::invalid_argument for invalid options or hull, or ω <= 0.
RollDampingComponents ViscousRollDamping(const RollDampingHull& hull, double omega_rad_s, double speed_m_s,
                                         const RollDampingOptions& o);

/// Where the hull (and ω, the roll natural frequency where the damping decides the response, as ω̂ =
/// ω √(B/(2g))) lies outside the range the method was fitted in (Kawahara et al.: Cb 0.5-0.85, B/d 2.5-4.5,
/// OG/d −1.5-0.2, Cm 0.9-0.99, bilge keels b/B 0.01-0.06 and l/L 0.05-0.4, ω̂ <= 1), one sentence per parameter
/// naming it, its value and the range, and where Kawahara's eddy fit turns negative, that the eddy damping is
/// taken as 0; for a multihull, that Ikeda's range does not cover a demihull pair and what is used instead
/// (and, at zero speed or Cs = 0, that its viscous roll damping is zero). Empty: inside. model kNone: empty.
std::vector<std::string> RollDampingRangeFlags(const RollDampingHull& hull, double omega_rad_s,
                                               double speed_m_s, const RollDampingOptions& o);

}  // namespace hullopt::sk
