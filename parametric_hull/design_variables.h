#pragma once
// The handful of numbers a naval architect uses to describe a hull in concept design (the reference paper's
// Table 1), plus the shape choices the generator needs. Coefficients follow hydrostatics.h: those of one
// demihull for catamarans and SWATHs, of the whole (main hull + outriggers) for the trihull, with L, B, T of
// the main hull / demihull.
#include <optional>
#include <string>
#include <vector>

namespace hullopt::hull {

enum class HullType { kMonohull, kCatamaran, kSwath, kTrihull };
enum class SectionStyle {
  kRoundBilge,  ///< superellipse (Lamé) sections |y/(b/2)|^n + |(T-z)/d|^n = 1, any area coefficient
                ///< 0.15–0.98
  kHardChine,   ///< straight deadrise to a chine, wall-sided above it; area coefficient 0.5–1
  kSwathBulb,   ///< submerged elliptic bulb of breadth B under a thinner strut through the waterline
};

/// Parses "monohull|catamaran|swath|trihull" (throws std::invalid_argument naming the choices).
HullType ParseHullType(const std::string& name);
std::string ToString(HullType type);
/// Parses "round_bilge|hard_chine|swath_bulb".
SectionStyle ParseSectionStyle(const std::string& name);
std::string ToString(SectionStyle style);

/// What the generator does with a waterplane (Cwp, LCF) its family of curves cannot meet: refuse (default;
/// the message offers the nearest feasible combination) or build that nearest combination and record the
/// change in HullForm::adjustments.
enum class OnInfeasible { kRefuse, kNearest };

/// A design variable outside its rule: the variable (or the ratio of two, e.g. "Cm = Cb/Cp"), its value and
/// the rule.
struct InvalidDesignVariable {
  std::string field;
  double value = 0.0;
  std::string value_text;  ///< the value as written in Message() (a name for section_style)
  std::string rule;
  /// "<field> = <value>: <rule>"
  std::string Message() const { return field + " = " + value_text + ": " + rule; }
};

struct DesignVariables {
  HullType type = HullType::kCatamaran;
  SectionStyle section_style = SectionStyle::kRoundBilge;  ///< must be kSwathBulb for a SWATH and only then
  double displacement_t = 1000.0;                          ///< [t] whole vessel (all bodies)
  double rho_kg_m3 = 1025.0;  ///< [kg/m^3] water density used for the displacement
  double L_over_B = 11.0;     ///< L / B (B: max breadth of one hull below the waterline)
  double B_over_T = 2.0;      ///< B / T
  double Cb = 0.40;           ///< block coefficient
  double Cp = 0.69;           ///< prismatic coefficient (on the midship section)
  double Cwp = 0.76;          ///< waterplane coefficient
  double LCB_pct_L = -6.4;    ///< [% L from midships, + forward]
  double LCF_pct_L = -8.3;    ///< [% L from midships, + forward]
  /// Transom draught / T, in [0, 1): 0 = the transom clears the water (zero-area aft end).
  double transom_immersion = 0.3;
  /// Transom waterline breadth / B, in [0, 1].
  double transom_beam_ratio = 0.6;
  /// Keel rise towards the ends, in [0, 1): the section area coefficient used to set local draught rises from
  /// Cm at midships to Cm + keel_rise (1 - Cm) at the ends, making end sections shallower (more keel rise).
  double keel_rise = 0.3;
  /// Demihull centreline spacing / L (catamaran, SWATH); ignored for other types. Overridden by spacing_m >
  /// 0.
  double spacing_over_L = 0.25;
  double spacing_m = 0.0;  ///< [m] absolute demihull spacing, if > 0 (wins over spacing_over_L)
  /// SWATH strut: maximum waterline breadth / B, in (0, 1] (1: the strut is as wide as the bulb where the
  /// waterplane peaks). 0 = choose Cwp / 0.8 (strut waterline fullness 0.8).
  double strut_ratio = 0.0;
  /// SWATH bulb height at midships / T, in [0, 1). 0 = the elliptic bulb of breadth B whose height the
  /// midship area sets, scaled in breadth and height together towards the ends (it can flatten into a thin
  /// plate). > 0 = the rounded-bulb family: the bulb keeps this height to the ends and narrows to meet the
  /// sectional area (its fullness, a superelliptic exponent, is solved at midships for Cm), with a
  /// flat-bottomed, chined run over the aft kSwathChineFraction of L.
  double bulb_height_ratio = 0.0;
  /// Trihull outriggers (each): length / L (they end at the transom), L/B, B/T and centreline offset from the
  /// ship centreline / L.
  double outrigger_length_ratio = 0.6;
  double outrigger_L_over_B = 20.0;
  double outrigger_B_over_T = 2.0;
  double outrigger_offset_over_L = 0.2;
  double freeboard_over_T = 0.6;  ///< deck edge height above the waterline / T (plots only; no hydrostatics)
  int stations = 41;              ///< stations per body (odd, so midships is a station), >= 11
  int section_points = 25;        ///< points per section contour below the waterline, >= 8
  OnInfeasible on_infeasible = OnInfeasible::kRefuse;

  /// The first range rule the values break (checked one by one), or none.
  std::optional<InvalidDesignVariable> FirstInvalid() const;
  /// As FirstInvalid; on failure writes its Message() and returns false.
  bool IsValid(std::string* error) const;
};

/// One number of the design variables: its key in a config's hull.parametric map (and a campaign's variable
/// name), the field it sets and its unit. The one list the config reader, the campaign's variables and the
/// trial designs of a campaign go through.
struct DesignVariableField {
  const char* name;
  double DesignVariables::*field;
  const char* unit;       ///< "-" for ratios and coefficients
  bool required;          ///< a parametric hull must give it (else the default stands)
  bool parametric_key;    ///< read from hull.parametric (spacing_m is hull.spacing_m)
  bool campaign_variable; ///< a campaign may vary it (the displacement is held fixed; freeboard is for plots)
};

/// Every number of DesignVariables in config order.
const std::vector<DesignVariableField>& DesignVariableFields();
/// The field of that name, or nullptr.
const DesignVariableField* FindDesignVariable(const std::string& name);

}  // namespace hullopt::hull
