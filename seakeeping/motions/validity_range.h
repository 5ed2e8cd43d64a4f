#pragma once
// Where the time-domain (2D+t) strip method holds, from its assumptions (docs/ship-motions.md, "Validity range"):
//
// 1. Froude number. The 2D+t strips neglect x-derivatives of the flow: each strip of water is solved as a 2D
//    problem in the earth-fixed cross-plane the hull passes through (Davis & Holloway 2003 §2: "valid at high
//    Froude number ... provided the Froude number is not small"; Faltinsen & Zhao 1991). The one wave system
//    this cannot represent is the one with crests across the track, of length λ_T = 2πU²/g = 2π Fn² L; it is
//    longer than the hull, so that its x-variation along the hull is slow, when Fn ≥ 1/√(2π) ≈ 0.40.
//    (The paper's designs run at Fn 0.6–0.9 and its validations at 0.65–0.86.)
// 2. λ/L at a given Fn. The strip is at rest until the bow reaches it: no wave radiated by the hull may travel
//    ahead of it. Waves at encounter frequency ω_e have group velocity g/(2ω_e); they stay behind the bow when
//    τ = U ω_e / g > 1/4. With s = Uω/g = Fn √(2π L/λ) and ω_e = ω + ω²U/g, τ = s + s², so τ > 1/4 ⇔
//    s > (√2 − 1)/2 ⇔ λ/L < 2π Fn² / s*² ≈ 146.5 Fn² (23 at Fn 0.4, 94 at Fn 0.8): a long-wave limit that matters
//    only at low Fn.
// There is no short-wave limit from the theory (strip theory is a high-frequency theory); short waves are
// limited by the section spacing (docs/ship-motions.md).
#include <string>
#include <vector>

namespace hullopt::sk {

/// Lowest Froude number Fn = U/√(gL) of the method: 1/√(2π) (transverse wave length = hull length).
double MinValidFroudeNumber();
/// Longest valid wave length ratio λ/L at Froude number Fn (τ = Uω_e/g > 1/4): 2π Fn² / ((√2 − 1)/2)².
double MaxValidLambdaOverL(double Fn);

/// Warnings (rule and numbers; empty inside the range) for RAOs at wave frequencies omega_rad_s of a hull of
/// length length_m at speed_m_s: Fn below the range, and the wave frequencies whose λ/L lie above it.
std::vector<std::string> ValidityWarnings(double speed_m_s, double length_m, double g_m_s2,
                                          const std::vector<double>& omega_rad_s);

}  // namespace hullopt::sk
