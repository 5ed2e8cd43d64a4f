#pragma once
// Frequency-domain 2D panel solver for one or several sections side by side in a strip of deep water: the
// independent check of the time-domain strip solver and the basis of conventional strip theory (Salvesen,
// Tuck & Faltinsen 1970).
//
// Method: constant-strength source panels (or, with SectionFormulation::kDirect, the body potential from
// Green's second identity) with the pulsating-source Green function of deep water (frequency_domain_green.h),
// collocation at panel midpoints. The ln r + ln r' part of every panel integral
// is in closed form (rankine_panel.h); the smooth wave part is integrated with Gauss–Legendre on sub-segments
// refined towards the image of the field point and to a fraction of a wavelength. Irregular frequencies are
// removed with the extended boundary condition of the source formulation: source panels on each section's
// interior free surface (the "lid", z = 0 between the waterline points, cosine-spaced) and the condition
// ∂φ/∂z + (2q − 1)νφ = 0 just below the lid midpoints: in the middle of the lid (q = 1) the free-surface
// condition with the opposite sign, tapering linearly to the exterior one (q = 0) at the waterline corners.
// Without it the interior problem (φ = 0 on the body, ∂φ/∂z − νφ = 0 on the lid) has the irregular
// frequencies as eigenvalues; with it they are pushed far above the range of interest, and the interior
// solution stays regular at the corners (an untapered lid, q = 1 everywhere, makes the body source density
// log-singular there and the solver first-order; a Dirichlet lid, φ = 0, makes it singular like 1/r), so the
// lid leaves the exterior solution unchanged up to a second-order discretisation error.
//
// Conventions: time factor e^{iωt}; motion amplitude X_j of mode j (0 sway along +y, 1 heave along +z, 2 roll
// about +x through the strip origin y = z = 0, so the generalised normal is n_roll = y n_z − z n_y); force on
// the body F_j = −Σ_k (−ω² a_jk + iω b_jk) X_k. Normals point into the fluid.
#include <Eigen/Dense>
#include <array>
#include <complex>
#include <memory>
#include <string>
#include <vector>

#include "seakeeping/green/panel.h"

namespace hullopt::sk {

/// How the body boundary-value problem is discretised (constant strength per panel, collocation at the panel
/// midpoints in both).
enum class SectionFormulation {
  /// A source distribution on the body (and the lid): the strip solvers' formulation. Its density is the jump
  /// between the exterior flow and an interior one, which is singular at a re-entrant corner of the body (a
  /// strut meeting a bulb, interior angle above 180°), so constant panels converge only at first order there.
  kSource,
  /// Green's second identity for the body potential itself: ½φ_i + Σ_j φ_j ∫_j ∂G/∂n_ξ ds = Σ_j V_j ∫_j G ds,
  /// V the body's normal velocity. The potential stays bounded and smooth at re-entrant corners (it is the
  /// exterior flow alone), and the chords of a curved contour need no curvature term. Irregular frequencies:
  /// the same lid points as kSource, where Green's representation must vanish (they lie outside the fluid),
  /// added as extra rows and the overdetermined system solved in least squares (the extended boundary
  /// condition of the direct formulation).
  kDirect,
};

struct FrequencyDomainOptions {
  double rho_kg_m3 = 1025.0;  ///< [kg/m³] water density
  double g_m_s2 = 9.81;       ///< [m/s²] gravity
  SectionFormulation formulation = SectionFormulation::kSource;
  /// Lid panels per section on the interior free surface (irregular-frequency removal). −1: automatic (half
  /// the section's body panels, at least 4); 0: no lid — then results are wrong near the irregular
  /// frequencies.
  int lid_panels = -1;
  int gauss_points = 8;      ///< Gauss–Legendre points per sub-segment of the wave-part integrals (2..20)
  int max_subdivision = 14;  ///< maximum halvings of a source panel towards a near-singular image point
  bool IsValid(std::string* error) const;
};

/// Radiation and beam-sea wave results of one strip at one frequency, per unit length of the strip.
struct SectionHydrodynamics {
  double omega_rad_s = 0.0;        ///< [rad/s]
  double wave_number_per_m = 0.0;  ///< [1/m] ν = ω²/g
  /// a_jk [kg/m, kg·m/m, kg·m²/m by mode], b_jk [same per s]; modes 0 sway, 1 heave, 2 roll (see file
  /// comment).
  Eigen::Matrix3d added_mass = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d damping = Eigen::Matrix3d::Zero();
  double a33() const { return added_mass(1, 1); }  ///< [kg/m] heave added mass
  double b33() const { return damping(1, 1); }     ///< [kg/(m·s)] heave damping
  /// Beam-sea incident wave travelling towards +y, elevation Re[A e^{i(ωt − νy)}]: force per unit length and
  /// unit amplitude A [N/m per m] (roll moment [N·m/m per m]). Froude–Krylov part, and total exciting force
  /// from the diffraction solution (FK + diffraction) and, independently, from the radiation potentials
  /// (Haskind).
  std::array<std::complex<double>, 3> froude_krylov{};
  std::array<std::complex<double>, 3> exciting_force{};
  std::array<std::complex<double>, 3> exciting_force_haskind{};
  /// Radiated wave elevation amplitude far away towards +y and −y per unit motion amplitude of each mode
  /// [m/m] (from the source distribution's far field, Kochin form); energy balance: Σ±|A±|² = 2ω³ b_jj/(ρ
  /// g²).
  std::array<std::complex<double>, 3> far_wave_plus{};
  std::array<std::complex<double>, 3> far_wave_minus{};
  /// Body panels (all sections, in input order) and the radiation potential per unit velocity of each mode at
  /// their midpoints [m²/s per m/s]: columns sway, heave, roll. For strip-theory diffraction integrals.
  std::vector<Panel> panels;
  Eigen::MatrixXcd radiation_potential;
};

/// Solves the strip holding the given sections (each panelled port waterline → keel → starboard waterline, as
/// PanelSymmetricSection makes them; sections must not overlap) at the wave frequency omega_rad_s > 0.
/// Throws std::invalid_argument for invalid options, an empty strip, or a section not touching z = 0 at both
/// ends.
SectionHydrodynamics SolveSectionFrequencyDomain(const std::vector<std::vector<Panel>>& sections,
                                                 double omega_rad_s, const FrequencyDomainOptions& options);

/// The same at several frequencies (solved in parallel when OpenMP is on).
std::vector<SectionHydrodynamics> SolveSectionFrequencyDomain(const std::vector<std::vector<Panel>>& sections,
                                                              const std::vector<double>& omegas_rad_s,
                                                              const FrequencyDomainOptions& options);

/// Whether panels b are the mirror images of panels a about the line y = y_axis_m in reverse order (b[k] is
/// a[size − 1 − k] mirrored, its end points swapped: the two halves of a PanelSymmetricSection, or two
/// bodies placed symmetrically), to tol_m [m] in every coordinate and 1e-12 in the turning.
bool MirrorImagePanels(const std::vector<Panel>& a, const std::vector<Panel>& b, double y_axis_m, double tol_m);

/// The heave radiation potential of one strip at many frequencies (conventional strip theory needs only
/// that): the panels, the lid and the frequency-independent Rankine parts of the influence matrices (the
/// closed-form ln r + ln r' integrals) are prepared once, so each frequency costs only the wave part and the
/// solve. A strip that is mirror-symmetric about a vertical line (each panel the reversed mirror image of its
/// partner to 1e-12 of the strip's size, as PanelSymmetricSection and symmetric multihulls make them) is
/// solved on one half: the heave potential is symmetric, so the source densities of mirror panels are equal
/// and the system has the rows and columns of one half only (collocation at that half's points). Otherwise
/// the full system (SectionFormulation::kDirect: the full solve at each frequency). Same validation and
/// exceptions as SolveSectionFrequencyDomain; thread-safe const use.
class SectionHeaveSolver {
 public:
  SectionHeaveSolver(const std::vector<std::vector<Panel>>& sections, const FrequencyDomainOptions& options);
  /// ψ_heave per unit heave velocity [m²/s per m/s] at the body panel midpoints (all sections, input order)
  /// at omega_rad_s > 0: SolveSectionFrequencyDomain(...).radiation_potential.col(1) to rounding.
  Eigen::VectorXcd HeavePotential(double omega_rad_s) const;
  /// Whether the half-strip (mirror) reduction is used.
  bool mirror_symmetric() const;

 private:
  struct Data;
  std::shared_ptr<const Data> data_;
};

/// Sectional wave-load integrals for strip theory: an incident wave of elevation Re[A e^{i(ω₀t − k x cosβ −
/// k_y y)}] (k [1/m] its wavenumber, k_y = k sinβ its transverse wavenumber) seen by the section of `hydro`
/// (whose radiation potentials were solved at the encounter frequency). Per unit amplitude and unit length:
///   froude_krylov_j = −ρ g ∫ e^{kz − i k_y y} n_j ds,
///   diffraction_j   =  ρ g ∫ ψ_j (k n_z − i k_y n_y) e^{kz − i k_y y} ds   (Haskind form, ψ_j per unit
///   velocity).
/// For beam seas at zero speed (k = ν, k_y = ν) their sum is exciting_force_haskind.
struct SectionWaveLoads {
  std::array<std::complex<double>, 3> froude_krylov{};
  std::array<std::complex<double>, 3> diffraction{};
};
SectionWaveLoads SectionWaveLoadIntegrals(const SectionHydrodynamics& hydro, double k_per_m, double k_y_per_m,
                                          double rho_kg_m3, double g_m_s2);

}  // namespace hullopt::sk
