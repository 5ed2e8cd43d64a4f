#pragma once
// Frequency-independent operators of one 2D water strip in the time domain (docs/ship-motions.md;
// the first stage, used by strip_marcher.h).
//
// Model (docs/theory.md, 'Transient Green function: source-distribution potential and signs' and
// 'Transient Green function: panel and time integrals'). At step n (t_n = n·dt) the strip holds the panels
// P_n (all bodies sharing the strip: catamaran demihulls, SWATH struts, outriggers). Panel j of step k
// carries a source density σ_{k,j} [m/s], constant on the panel and over the time interval
// [max(0, t_k − dt/2), t_k + dt/2] (cut at t_n for k = n): past sources sit on past panels. The potential is
//   φ(p, t_n) = Σ_j σ_{n,j} R_j(p) − Σ_{k<=n} Σ_j σ_{k,j} (1/2π) ∫_interval ∫_{panel k,j} G~(p, q, t_n − τ)
//   ds dτ,
// R_j = (1/2π)∫(ln r − ln r') ds the Rankine pair. The body condition ∂φ/∂n = V at the collocation points
// (panel mid-points) of step n reads
//   System(n) σ_n = V_n + Σ_{k<n} Memory(n, k) σ_k,
// System(n) = A_n − M_{n,n} (A_n: Rankine normal velocity incl. the +1/2 self term; M_{n,n}: the memory of
// the current sources over [t_n − dt/2, t_n]), Memory(n, k) = (1/2π)∫∫ ∂G~/∂n over interval k (exact in space
// and time, docs/theory.md, 'Transient Green function: panel and time integrals'). The vertical momentum of
// the strip's disturbance flow,
//   I_n = ρ ∫_{S_n} φ n_z dl = MomentumCurrent(n) σ_n + Σ_{k<n} MomentumMemory(n, k) σ_k   [kg/s],
// gives the sectional force f = dI/dt (n into the fluid), see strip_marcher.h and docs/theory.md. The
// alternative pressure form (SectionalForce::kPressure) subtracts the transport term of the moving contour,
// TransportCurrent/TransportMemory/TransportDirect.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "seakeeping/green/panel.h"
#include "seakeeping/strip/contour_motion.h"
#include "seakeeping/strip/strip_kernel.h"

namespace hullopt::sk {

/// How the sectional force follows from the strip's potential (docs/theory.md, "Sectional force in a strip
/// whose section changes").
enum class SectionalForce {
  /// f = dI/dt, I = ρ∫_{S(t)} φ n_z dl on the moving contour: the slender-body (STF-consistent) form, the
  /// default.
  kMomentum,
  /// f = ρ∫_{S(t)} φ_t n_z dl with φ_t at FIXED points of the current contour, taken on the fluid side: the
  /// reference paper's written formula, f = −ρ∫ ∂φ/∂t n_z dl (its n into the body). Evaluated as dI/dt minus
  /// the transport term ρ[∫ W_n ∂φ/∂z dl − Σ_wl φ ẏ_out] of the moving contour (contour_motion.h), so that
  /// only exterior values of φ enter (earlier potentials evaluated at points an earlier contour enclosed would
  /// be the source layer's interior potential). Differs from kMomentum only where the section changes.
  kPressure,
};

/// How the momentum of the current sources' instantaneous (Rankine) potential is evaluated. The memory, and the
/// source densities that carry it, are the same either way.
enum class BodyPotential {
  /// The potential of the source sum Σ σ_j (1/2π)∫(ln r − ln r′) ds on the body: the paper's formulation.
  kSourceSum,
  /// The body potential of that flow from Green's identity, given its normal velocity at the collocation points
  /// (the direct formulation with the Rankine pair, zero on z = 0). σ is singular at a re-entrant corner (a SWATH
  /// strut meeting its bulb), and constant source panels then give the potential at first order only; the
  /// potential itself stays bounded and converges at second order (docs/sections.md). Momentum form only.
  kGreenIdentity,
};

struct StripOperatorOptions {
  /// Gauss points per body panel for the momentum integral ∫φ n_z dl (1 = panel mid-points).
  int field_points_per_panel = 2;
  /// When every step's panels are mirror-symmetric about one vertical line y = y_c (monohull, catamaran,
  /// SWATH and trimaran sections; one demihull alone), solve only the symmetric part of the problem on the
  /// panels with y > y_c (sources σ_j = σ_j′ of mirror pairs): half the kernel evaluations and 1/8 of the
  /// reduction work. Exact for the vertical force, which the antisymmetric part of any input does not produce.
  /// Then PanelsAt(n) is the half set; FullPanelsAt/ReducedIndex/ReducedShare map inputs on all panels to it.
  /// Off by default: the marching path feeds normal velocities for all panels.
  bool use_mirror_symmetry = false;
  /// Station layout the steps stand for, which sets the force difference (StripForceStencil) of the strip
  /// marcher and the kernel reduction. Operators of a fixed section (BuildFixedSectionOperators) always use
  /// plain BDF2.
  StationLayout layout = kDefaultStationLayout;
  /// Sectional force form (general operators; a fixed section gives the same force either way).
  SectionalForce sectional_force = SectionalForce::kMomentum;
  /// How the current sources' potential enters the momentum (kGreenIdentity needs kMomentum).
  BodyPotential body_potential = BodyPotential::kSourceSum;
  /// Also the lateral momentum rows of the strip (general operators only): I_y = ρ∫φ n_y dl and the roll
  /// momentum I_4 = ρ∫φ (y n_z − z n_y) dl about y = z = 0 (LateralMomentumCurrent/Memory), from the same
  /// sources, for the sway force and roll moment of the antisymmetric modes and oblique waves. Needs full
  /// sections (use_mirror_symmetry off), kMomentum and kSourceSum. Off: every result bitwise as without it;
  /// on: the vertical rows are still bitwise the same.
  bool lateral_rows = false;
  bool IsValid(std::string* error) const;
};

class StripOperators {
 public:
  int Steps() const { return steps_; }
  double Dt() const { return dt_; }
  double Rho() const { return rho_; }
  double G() const { return g_; }
  /// True when built for a section that does not change (then Memory depends on n − k only).
  bool TimeInvariant() const { return invariant_; }
  StationLayout Layout() const { return layout_; }
  /// f_n = (c[0] I_n + c[1] I_{n−1} + c[2] I_{n−2}) / (2 dt) (StripForceStencil of the layout).
  std::array<double, 3> ForceStencil(int n) const { return StripForceStencil(layout_, n, steps_); }
  const std::vector<Panel>& PanelsAt(int n) const { return panels_[invariant_ ? 0 : n]; }
  int PanelCount(int n) const { return static_cast<int>(PanelsAt(n).size()); }
  /// True when built on the mirror-symmetric half (StripOperatorOptions::use_mirror_symmetry).
  bool MirrorReduced() const { return reduced_; }
  /// All panels of step n as given (== PanelsAt(n) unless MirrorReduced()).
  const std::vector<Panel>& FullPanelsAt(int n) const { return reduced_ ? full_panels_[n] : PanelsAt(n); }
  /// Per panel of FullPanelsAt(n): the index of its panel in PanelsAt(n), and the share of that reduced
  /// panel's input it carries (½ for each panel of a mirror pair, 1 for a panel on the symmetry line), so that
  /// V_reduced(r) = Σ_j share_j V_j over the panels j with index r (the symmetric part of V). Identity and 1
  /// when not reduced.
  const std::vector<int>& ReducedIndex(int n) const { return reduced_index_[invariant_ ? 0 : n]; }
  const std::vector<double>& ReducedShare(int n) const { return reduced_share_[invariant_ ? 0 : n]; }

  /// A_n − M_{n,n} [-] (P_n × P_n).
  const Eigen::MatrixXd& System(int n) const;
  /// Solves System(n) σ = rhs (stored LU).
  Eigen::MatrixXd Solve(int n, const Eigen::MatrixXd& rhs) const;
  /// Estimate of the L1 condition number of System(n) (Eigen's rcond of the stored LU; 1 for an empty step):
  /// a few for a well-panelled section, large when the panels cannot resolve it (e.g. a thin plate-like bulb).
  double ConditionEstimate(int n) const;
  /// Memory normal velocity at the collocation points of step n per unit σ of step k < n [-] (P_n × P_k).
  const Eigen::MatrixXd& Memory(int n, int k) const;
  /// Row vectors of I_n [kg/s per (m/s) of σ = kg/m]: the current sources and the sources of step k < n.
  const Eigen::RowVectorXd& MomentumCurrent(int n) const;
  const Eigen::RowVectorXd& MomentumMemory(int n, int k) const;
  /// True when built with StripOperatorOptions::lateral_rows.
  bool HasLateralRows() const { return !lateral_current_.empty(); }
  /// Lateral rows only: the rows (sway momentum I_y, roll momentum I_4 about y = z = 0) of the current
  /// sources and of the sources of step k < n [2 × P; kg/m and kg]. std::logic_error without lateral rows.
  const Eigen::MatrixXd& LateralMomentumCurrent(int n) const;
  const Eigen::MatrixXd& LateralMomentumMemory(int n, int k) const;
  /// The sectional force form the operators were built for (kMomentum for a fixed section, where both agree).
  SectionalForce Force() const { return force_; }
  /// kPressure only (general operators): the transport term ρT_n of step n (contour_motion.h), by which the
  /// fixed-point pressure integral differs from dI/dt: f_pressure = f_momentum − ρT_n with
  ///   ρT_n = TransportCurrent(n)·σ_n + Σ_{k<n} TransportMemory(n, k)·σ_k + TransportDirect(n)·V_n
  /// [N/m]; the first two per unit σ [kg/s² per m/s], the last per unit normal velocity of step n's panels.
  const Eigen::RowVectorXd& TransportCurrent(int n) const;
  const Eigen::RowVectorXd& TransportMemory(int n, int k) const;
  const Eigen::RowVectorXd& TransportDirect(int n) const;

  /// Time-invariant operators only: memory over a FULL interval centred at lag l·dt (l >= 1), the
  /// steady-state form used for frequency responses. Valid for 1 <= l < Steps().
  const Eigen::MatrixXd& LagMemory(int l) const;
  const Eigen::RowVectorXd& LagMomentum(int l) const;

 private:
  friend StripOperators BuildStripOperators(const std::vector<std::vector<Panel>>&, double, double, double,
                                            const StripOperatorOptions&, const std::vector<ContourMotion>*);
  friend StripOperators BuildFixedSectionOperators(const std::vector<Panel>&, int, double, double, double,
                                                   const StripOperatorOptions&, bool);
  int steps_ = 0;
  double dt_ = 0, rho_ = 0, g_ = 0;
  bool invariant_ = false;
  StationLayout layout_ = StationLayout::kCellMidpoints;
  bool has_start_ = true;  // time-invariant: memory of the first half interval available
  bool reduced_ = false;    // mirror-symmetric half (general operators only)
  std::vector<std::vector<Panel>> panels_, full_panels_;
  std::vector<std::vector<int>> reduced_index_;
  std::vector<std::vector<double>> reduced_share_;
  // General: index n (system, lu, momentum_current), [n][k] (memory, momentum_memory).
  // Time-invariant: system/lu/momentum_current [0] for n = 0 (no self memory) and [1] for n >= 1;
  // memory/momentum_memory [0][l] full interval at lag l, [1][n] the first half interval [0, dt/2] seen at
  // t_n.
  std::vector<Eigen::MatrixXd> system_;
  std::vector<Eigen::PartialPivLU<Eigen::MatrixXd>> lu_;
  std::vector<Eigen::RowVectorXd> momentum_current_;
  std::vector<std::vector<Eigen::MatrixXd>> memory_;
  std::vector<std::vector<Eigen::RowVectorXd>> momentum_memory_;
  // Lateral rows (general operators only): current by n, memory [n][k] for k < n.
  std::vector<Eigen::MatrixXd> lateral_current_;
  std::vector<std::vector<Eigen::MatrixXd>> lateral_memory_;
  SectionalForce force_ = SectionalForce::kMomentum;
  // kPressure (general operators): transport rows by n, and [n][k] for k < n.
  std::vector<Eigen::RowVectorXd> transport_current_, transport_direct_;
  std::vector<std::vector<Eigen::RowVectorXd>> transport_memory_;
};

/// Operators for a sequence of panel sets (one per step; a step may hold several bodies, and may be empty),
/// time step dt [s], water density rho [kg/m³], gravity g [m/s²]. Cost O(N² P² ·quadrature); OpenMP-parallel
/// over n, bitwise identical results for any thread count. Throws std::invalid_argument on bad input (panel
/// above z = 0, zero-length panel, dt/rho/g not positive, invalid options). The pressure form's transport
/// term takes the contour's motion from `motions` (one per step, for all its panels) when given, else from the
/// panels of the neighbouring steps (StepContourMotion).
StripOperators BuildStripOperators(const std::vector<std::vector<Panel>>& panels_per_step, double dt,
                                   double rho, double g, const StripOperatorOptions& options = {},
                                   const std::vector<ContourMotion>* motions = nullptr);

/// Operators of a section that does not change, for `steps` steps (memory by lag only; cost O(N P²) kernel
/// quadratures). steady_state_only: skip the memory of the first half interval seen at later steps (half the
/// cost and storage); the operators then serve LagMemory/LagMomentum (steady-state transforms) but not time
/// marching from rest (Memory(n, 0) and MomentumMemory(n, 0) throw std::logic_error).
StripOperators BuildFixedSectionOperators(const std::vector<Panel>& panels, int steps, double dt, double rho,
                                          double g, const StripOperatorOptions& options = {},
                                          bool steady_state_only = false);

}  // namespace hullopt::sk
