#pragma once
// Conventional (Salvesen–Tuck–Faltinsen 1970 type) strip theory in head seas on the same stations and ship
// equations as the time-domain method: `method: strip_theory_stf`, the comparator the paper shows beside its
// own method.
//
// Each section is a 2D frequency-domain problem at the encounter frequency ω_e. Its response to a normal
// velocity amplitude Ṽ on its panels is a force per unit length R(ω_e)·Ṽ (R·n_z = −(iω_e a33 + b33) for
// heave; for the wave, Haskind: the same row applied to the incident-wave normal velocity gives the
// diffraction force). The forward-speed terms come from the substantial derivative along the hull,
//   f = −(iω_e − U ∂/∂x)[Z w],  −iω_e Z w = R·Ṽ,
// taken on the strip grid as f_n = F_n + (F_n − F_{n−1})/(iω_e Δt), F = −iω_e Z w the section's 2D force (the
// x-derivative a backward difference; the time derivative exact, iω_e). Integrated by parts this is STF's speed-dependent coefficients (A35 = −∫x a dx − (U/ω_e²)B33, B35 =
// −∫x b dx + U A33, A55 = ∫x² a dx + (U²/ω_e²)A33, ...) with the transom terms of a section that ends at the
// stern, and the STF diffraction term (U/iω_e)h3. Froude–Krylov, hydrostatics and Cs damping as in
// head_sea_ship_model.h.
#include <Eigen/Dense>
#include <functional>
#include <vector>

#include "seakeeping/motions/head_sea_coefficients.h"
#include "seakeeping/motions/head_sea_ship_model.h"
#include "seakeeping/motions/rao_table.h"
#include "seakeeping/sections/frequency_domain_section.h"
#include "seakeeping/strip/strip_kernel.h"

namespace hullopt::sk {

/// R_n(ω_e) [N/m per m/s], one complex entry per panel of step n: the 2D frequency-domain force per unit
/// length for a unit normal-velocity amplitude on that panel (e^{iω_e t}). From a panel solver with heave
/// radiation potential ψ per unit velocity (∂ψ/∂n = n_z): R_i = iω_e ρ ψ_i l_i (reciprocity).
using SectionRowProvider = std::function<Eigen::RowVectorXcd(int step, double omega_e_rad_s)>;

/// The row of a section known only by its heave added mass a33 [kg/m] and damping b33 [kg/(m s)] at ω_e,
/// spread like a uniform heave: R = −(iω_e a33 + b33) c, c_i = n_z,i l_i / Σ n_z² l.
Eigen::RowVectorXcd UniformHeaveRow(const std::vector<Panel>& panels, double a33, double b33,
                                    double omega_e_rad_s);

/// Rows from the 2D frequency-domain panel solver (frequency_domain_section.h) for the sections of `geometry`
/// (each step's panels in consecutive groups of panels_per_body, one group per body): R_i = iω_e ρ ψ_i l_i
/// with ψ the heave radiation potential per unit velocity. Solves each (step, ω_e) once and caches it.
/// interaction: all bodies of a step in one 2D problem; false: each body alone. formulation: how each
/// section's potential is solved for (SectionFormulation; kDirect resolves strut-bulb junctions at 14
/// panels, frequency_domain_section.h). geometry must outlive it.
SectionRowProvider FrequencyDomainSectionRows(const StripKernel& geometry, int panels_per_body,
                                              bool interaction = true,
                                              SectionFormulation formulation = SectionFormulation::kSource);

/// The coefficients of the strip-theory equations at each wave frequency (head_sea_coefficients.h), from the
/// same rows and strip grid as SolveStripTheoryRaos. Throws std::invalid_argument for a bad frequency.
std::vector<HeadSeaCoefficients> StripTheoryCoefficients(const HeadSeaShipModel& model,
                                                         const std::vector<double>& omega_rad_s,
                                                         const SectionRowProvider& rows);

/// RAOs by strip theory at the wave frequencies (model: geometry, mass, Cs; its kernel's force rows are not
/// used). Throws like SolvePeriodicRaos.
RaoTable SolveStripTheoryRaos(const HeadSeaShipModel& model, const std::vector<double>& omega_rad_s,
                              const SectionRowProvider& rows);

}  // namespace hullopt::sk
