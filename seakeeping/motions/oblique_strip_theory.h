#pragma once
// Strip theory in oblique seas for sway, heave, roll, pitch and yaw (Salvesen, Tuck & Faltinsen 1970): each
// station is a 2D frequency-domain problem (frequency_domain_section.h, modes sway, heave and roll) at the
// encounter frequency, its coefficients are moved to roll about the centre of gravity and integrated along
// the hull with STF's forward-speed terms (the substantial derivative along the hull on the station grid, as
// strip_theory_stf.h; transom terms included), the wave excitation is the Froude–Krylov pressure of the
// oblique wave over the hull (each section's girth and, for pitch and yaw, the longitudinal slope) plus the
// STF (Haskind) diffraction force with its speed term, and the 5-dof linear equations give the RAOs.
// docs/theory.md, "Oblique seas at zero speed" and its "Forward speed" paragraph, states the formulas.
//
// Axes and conventions (the same as the 3D panel-method data in data/peers-oblique/, docs/conventions.md):
// x forward, y to port, z up, origin on the still waterline; dofs 1 surge, 2 sway (+ to port), 3 heave
// (+ up), 4 roll (right-handed about x: + starboard down), 5 pitch (right-handed about y: + bow down), 6 yaw
// (right-handed about z: + bow to port); rotations and moments about the centre of gravity (CG). Heading β:
// the direction the waves travel, from +x counter-clockwise seen from above (180° head seas, 90° beam seas
// from starboard, travelling towards +y). Wave elevation Re[A e^{i(ωt − k((x − x_G) cosβ + y sinβ))}], deep
// water k = ω²/g, so phases are leads over the wave crest at the CG. At speed U the ship sees the encounter
// frequency ω_e = ω − kU cosβ; motions are Re[X e^{iω_e t}].
//
// Not included (hooks): surge (its row and column stay zero and its RAO is not solved, so the surge–pitch
// coupling A15, B15 is left out: on the slender Wigley hull the pitch RAO still agrees within 3.4 % with a
// free-surge 3D solve), encounter frequencies <= 0 (following and quartering seas at speed: refused). Roll has
// potential damping only unless ObliqueStripOptions::roll_damping names a viscous model (roll_damping.h), whose
// equivalent linear B44 at each encounter frequency is added to B(3,3) before solving.
#include <Eigen/Dense>
#include <array>
#include <complex>
#include <stdexcept>
#include <string>
#include <vector>

#include "parametric_hull/hull_form.h"
#include "seakeeping/green/panel.h"
#include "seakeeping/motions/roll_damping.h"
#include "seakeeping/sections/frequency_domain_section.h"
#include "seakeeping/strip/strip_geometry.h"

namespace hullopt::sk {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

/// One strip station: the section at x_m [m, any longitudinal origin, x forward] panelled as
/// PanelSymmetricSection makes it (port waterline → keel → starboard waterline, z = 0 the still waterline,
/// y from the centreline, several bodies allowed), standing for weight_m [m] of hull length in the hull
/// integrals ∫ f dx ≈ Σ weight f. A station with no panels is dry and contributes nothing.
struct ObliqueStripStation {
  double x_m = 0.0;
  double weight_m = 0.0;
  std::vector<Panel> panels;
};

/// The stations of a hull on the strip solvers' grid (strip_geometry.h): options.sections cells over the
/// extreme stations of the bodies, at the cell midpoints or faces (options.layout) with their quadrature
/// weights, each section cut at the hull's draught and panelled (StripSectionPanels; x from the AP). Throws as
/// StripKernelGeometry (bad options, no length, draught <= 0, a section not reaching the waterline).
std::vector<ObliqueStripStation> ObliqueStripStations(const hull::HullForm& hull,
                                                      const StripGeometryOptions& options);

/// Rigid-body mass: mass [kg], CG (x_g_m in the stations' x, on the centreline, z_g_m from the waterline,
/// negative below it) and the inertia matrix about the CG [kg m²] in the axes x, y, z (I44 = inertia(0,0),
/// I55 = (1,1), I66 = (2,2), I46 = −product of inertia = inertia(0,2)).
struct ObliqueMassProperties {
  double mass_kg = 0.0;
  double x_g_m = 0.0;
  double z_g_m = 0.0;
  Eigen::Matrix3d inertia_kg_m2 = Eigen::Matrix3d::Zero();
  bool IsValid(std::string* error) const;
};

struct ObliqueStripOptions {
  double rho_kg_m3 = 1025.0;  ///< [kg/m³]
  double g_m_s2 = 9.81;       ///< [m/s²]
  /// [m/s] ship speed U (finite; negative: going astern). At U = 0 the zero-speed path; otherwise the STF speed
  /// terms, and a (heading, frequency) with encounter frequency <= 0 throws std::domain_error.
  double speed_m_s = 0.0;
  /// Froude–Krylov moment of the incident pressure on the hull's longitudinal slope (the n_x parts of the pitch
  /// normal (z − z_G) n_x and of the yaw normal −y n_x), from the volume form −∫∫∫ (z − z_G) ∂p/∂x dV section by
  /// section: with it the long-wave pitch RAO tends to 1; without it (conventional STF, n_x neglected) to
  /// I_L/(I_L + V(z_B − z_G)). Diffraction and radiation keep the strip normals either way.
  bool longitudinal_froude_krylov = true;
  /// Cs [-] of the paper's empirical sectional damping D = ½ Cs ρ U B (v − ζ_t) on heave and pitch
  /// (head_sea_ship_model.h; the value the head-sea path uses or `hullopt calibrate` fits), with the incident
  /// surface's rate averaged over each section's waterline. Roll's viscous damping is roll_damping's (for a
  /// multihull the same Cs term through the demihulls' heave). Only at speed (it is ∝ U). 0, the default: none,
  /// every result bitwise as without it.
  double damping_cs = 0.0;
  /// Settings of the 2D section solver (its rho and g are replaced by the two above).
  FrequencyDomainOptions section;
  /// Viscous roll damping (roll_damping.h; its rho and g are replaced by the two above) of the hull described
  /// by roll_damping_hull, at each encounter frequency and the speed above. model kNone (the default): none,
  /// every result bitwise as without these fields.
  RollDampingOptions roll_damping;
  RollDampingHull roll_damping_hull;
  bool IsValid(std::string* error) const;
};

/// Hydrostatics from the stations' panels (each section closed by its waterline): exact for the polygonal
/// sections, then integrated along x with the station weights.
struct ObliqueHydrostatics {
  double volume_m3 = 0.0;
  double x_b_m = 0.0;                ///< [m] centre of buoyancy, stations' x
  double z_b_m = 0.0;                ///< [m] from the waterline (negative)
  double waterplane_area_m2 = 0.0;
  double x_f_m = 0.0;                ///< [m] centre of flotation, stations' x
  double waterplane_i_t_m4 = 0.0;    ///< [m⁴] transverse second moment about the centreline
  double waterplane_i_l_cg_m4 = 0.0; ///< [m⁴] longitudinal second moment about the CG's transverse axis
};
ObliqueHydrostatics ObliqueStationHydrostatics(const std::vector<ObliqueStripStation>& stations, double x_g_m);

/// Restoring matrix about the CG (dofs surge..yaw as indices 0..5): C33 = ρg A_wp, C35 = C53 = −ρg A_wp (x_F −
/// x_G), C44 = ρg (I_T + V (z_B − z_G)) = ρgV GM_T, C55 = ρg (I_L + V (z_B − z_G)); the buoyancy ρgV stands
/// for the weight (free floating: mass = ρV).
Matrix6d ObliqueRestoring(const ObliqueHydrostatics& h, double x_g_m, double z_g_m, double rho_kg_m3,
                           double g_m_s2);

/// Sectional coefficients of one station at one frequency, per unit length, modes sway, heave and roll about
/// the CG's height (y = 0, z = z_G): a' = T a Tᵀ with the 2D solver's a about y = z = 0 and T the rows (1 0 0;
/// 0 1 0; z_G 0 1) (the roll normal about z_G is n_4 + z_G n_2).
struct ObliqueSectionCoefficients {
  Eigen::Matrix3d added_mass = Eigen::Matrix3d::Zero();  ///< [kg/m, kg, kg m]
  Eigen::Matrix3d damping = Eigen::Matrix3d::Zero();     ///< [kg/(m s), kg/s, kg m/s]
};

/// Radiation coefficients at one frequency (indices 0..5 = dofs 1..6 surge..yaw; surge row and column zero),
/// the strip sums without speed terms (at speed: STF's zero-speed parts A⁰, B⁰ at that encounter frequency).
struct ObliqueFrequencyResult {
  double omega_rad_s = 0.0;
  double k_per_m = 0.0;
  Matrix6d added_mass = Matrix6d::Zero();  ///< A_jk: force j per unit acceleration of k, about the CG
  Matrix6d damping = Matrix6d::Zero();     ///< B_jk
  std::vector<ObliqueSectionCoefficients> sections;  ///< per station (zero for dry stations)
};

/// Wave excitation and motions at one (heading, frequency), per unit wave amplitude A (indices 0..5 = dofs
/// 1..6; surge stays zero). Forces [N/m], moments [N m/m]; rao: translations per A [m/m], rotations per
/// wave slope kA [rad/rad].
struct ObliqueWaveResult {
  double heading_deg = 0.0;
  double omega_rad_s = 0.0;
  double omega_e_rad_s = 0.0;       ///< [rad/s] encounter frequency ω − kU cosβ (ω at U = 0)
  std::size_t frequency_entry = 0;  ///< ObliqueStripResult::frequencies entry of its sections' ω_e
  Matrix6d added_mass = Matrix6d::Zero();  ///< A_jk at ω_e with the speed terms (U = 0: the entry's)
  Matrix6d damping = Matrix6d::Zero();     ///< B_jk likewise (potential damping only)
  double viscous_roll_damping = 0.0;       ///< [N m s] the viscous B44 added to damping(3, 3) in the solve
  /// The Cs damping (ObliqueStripOptions::damping_cs; zero without it), added to damping, restoring and the
  /// excitation in the solve: B_jk of heave and pitch, its U x5 part C_j5, and its wave part.
  Matrix6d cs_damping = Matrix6d::Zero();
  Matrix6d cs_restoring = Matrix6d::Zero();
  std::array<std::complex<double>, 6> cs_excitation{};
  std::array<std::complex<double>, 6> froude_krylov{};
  std::array<std::complex<double>, 6> diffraction{};
  std::array<std::complex<double>, 6> excitation{};  ///< froude_krylov + diffraction + cs_excitation
  std::array<std::complex<double>, 6> rao{};
};

struct ObliqueStripResult {
  ObliqueHydrostatics hydrostatics;
  Matrix6d mass = Matrix6d::Zero();       ///< about the CG
  Matrix6d restoring = Matrix6d::Zero();  ///< ObliqueRestoring
  std::vector<double> headings_deg;
  /// U = 0: one per ω, input order. At speed: one per distinct encounter frequency (in order of first use);
  /// each wave result names its entry (ObliqueWaveResult::frequency_entry).
  std::vector<ObliqueFrequencyResult> frequencies;
  std::vector<ObliqueWaveResult> waves;  ///< heading-major: waves[h * (number of ω) + f]
  const ObliqueWaveResult& Wave(std::size_t heading, std::size_t frequency) const {
    const std::size_t nf = headings_deg.empty() ? 0 : waves.size() / headings_deg.size();
    if (frequency >= nf) throw std::out_of_range("ObliqueStripResult::Wave: frequency index out of range");
    return waves.at(heading * nf + frequency);
  }
};

/// The viscous roll damping of options.roll_damping (roll_damping.h) at encounter frequency we [rad/s] and
/// options.speed_m_s: its equivalent linear B44 [N m s]; 0 for model kNone.
double ObliqueViscousRollB44(const ObliqueStripOptions& options, double we);

/// The 5-dof motion matrix (sway..yaw: the bottom-right 5 × 5 of the 6 × 6 matrices, surge left out) at
/// encounter frequency we, factorised: [−ω_e²(M + A) + iω_e B + C] X = F, with viscous_b44 added to B44.
Eigen::PartialPivLU<Eigen::MatrixXcd> ObliqueMotionMatrix(double we, const Matrix6d& mass,
                                                          const Matrix6d& added_mass, Matrix6d damping,
                                                          const Matrix6d& restoring, double viscous_b44);

/// The strip-theory solution at every ω (> 0) and heading (degrees, any) at options.speed_m_s. Throws
/// std::invalid_argument for invalid options or mass, an empty frequency list or no wet station, and
/// std::domain_error at speed for an encounter frequency <= 0. Stations are passed bow to stern in the speed
/// terms whatever their order (sorted by x); dry stations between wet ones count as G = 0 there.
ObliqueStripResult SolveObliqueStripTheory(const std::vector<ObliqueStripStation>& stations,
                                           const ObliqueMassProperties& mass,
                                           const std::vector<double>& omega_rad_s,
                                           const std::vector<double>& headings_deg,
                                           const ObliqueStripOptions& options);

}  // namespace hullopt::sk
