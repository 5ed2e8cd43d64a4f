#include "parametric_hull/design_variables.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hullopt::hull {

HullType ParseHullType(const std::string& name) {
  if (name == "monohull") return HullType::kMonohull;
  if (name == "catamaran") return HullType::kCatamaran;
  if (name == "swath") return HullType::kSwath;
  if (name == "trihull") return HullType::kTrihull;
  throw std::invalid_argument("hull type '" + name + "' is not one of: monohull, catamaran, swath, trihull");
}

std::string ToString(HullType type) {
  switch (type) {
    case HullType::kMonohull:
      return "monohull";
    case HullType::kCatamaran:
      return "catamaran";
    case HullType::kSwath:
      return "swath";
    case HullType::kTrihull:
      return "trihull";
  }
  return "?";
}

SectionStyle ParseSectionStyle(const std::string& name) {
  if (name == "round_bilge") return SectionStyle::kRoundBilge;
  if (name == "hard_chine") return SectionStyle::kHardChine;
  if (name == "swath_bulb") return SectionStyle::kSwathBulb;
  throw std::invalid_argument("section style '" + name +
                              "' is not one of: round_bilge, hard_chine, swath_bulb");
}

std::string ToString(SectionStyle style) {
  switch (style) {
    case SectionStyle::kRoundBilge:
      return "round_bilge";
    case SectionStyle::kHardChine:
      return "hard_chine";
    case SectionStyle::kSwathBulb:
      return "swath_bulb";
  }
  return "?";
}

namespace {
// Range check helper: records "name = value: rule" on failure.
bool Check(bool ok, const char* name, double value, const std::string& rule,
           std::optional<InvalidDesignVariable>* bad) {
  if (ok) return true;
  std::ostringstream s;
  s << value;
  *bad = InvalidDesignVariable{name, value, s.str(), rule};
  return false;
}
}  // namespace

const std::vector<DesignVariableField>& DesignVariableFields() {
  using D = DesignVariables;
  static const std::vector<DesignVariableField> fields = {
      {"displacement_t", &D::displacement_t, "t", true, true, false},
      {"L_over_B", &D::L_over_B, "-", true, true, true},
      {"B_over_T", &D::B_over_T, "-", true, true, true},
      {"Cb", &D::Cb, "-", true, true, true},
      {"Cp", &D::Cp, "-", true, true, true},
      {"Cwp", &D::Cwp, "-", true, true, true},
      {"LCB_pct_L", &D::LCB_pct_L, "% L", true, true, true},
      {"LCF_pct_L", &D::LCF_pct_L, "% L", true, true, true},
      {"transom_immersion", &D::transom_immersion, "-", false, true, true},
      {"transom_beam_ratio", &D::transom_beam_ratio, "-", false, true, true},
      {"keel_rise", &D::keel_rise, "-", false, true, true},
      {"spacing_over_L", &D::spacing_over_L, "-", false, true, true},
      {"spacing_m", &D::spacing_m, "m", false, false, true},
      {"strut_ratio", &D::strut_ratio, "-", false, true, true},
      {"bulb_height_ratio", &D::bulb_height_ratio, "-", false, true, true},
      {"outrigger_length_ratio", &D::outrigger_length_ratio, "-", false, true, true},
      {"outrigger_L_over_B", &D::outrigger_L_over_B, "-", false, true, true},
      {"outrigger_B_over_T", &D::outrigger_B_over_T, "-", false, true, true},
      {"outrigger_offset_over_L", &D::outrigger_offset_over_L, "-", false, true, true},
      {"freeboard_over_T", &D::freeboard_over_T, "-", false, true, false},
  };
  return fields;
}

const DesignVariableField* FindDesignVariable(const std::string& name) {
  for (const auto& f : DesignVariableFields())
    if (name == f.name) return &f;
  return nullptr;
}

bool DesignVariables::IsValid(std::string* error) const {
  const auto bad = FirstInvalid();
  if (bad && error) *error = bad->Message();
  return !bad;
}

std::optional<InvalidDesignVariable> DesignVariables::FirstInvalid() const {
  std::optional<InvalidDesignVariable> error;
  const auto fin = [](double v) { return std::isfinite(v); };
  // clang-format off
  const bool ok = Check(fin(displacement_t) && displacement_t > 0, "displacement_t", displacement_t, "must be > 0 t", &error) &&
      Check(displacement_t <= 1e7, "displacement_t", displacement_t, "must be <= 1e7 t (the largest ships displace under 1e6 t)", &error) &&
      Check(fin(rho_kg_m3) && rho_kg_m3 > 0, "rho_kg_m3", rho_kg_m3, "must be > 0 kg/m^3", &error) &&
      Check(fin(L_over_B) && L_over_B > 1, "L_over_B", L_over_B, "must be > 1", &error) &&
      Check(fin(B_over_T) && B_over_T > 0, "B_over_T", B_over_T, "must be > 0", &error) &&
      Check(fin(Cb) && Cb > 0 && Cb < 1, "Cb", Cb, "must lie in (0, 1)", &error) &&
      Check(fin(Cp) && Cp > 0 && Cp < 1, "Cp", Cp, "must lie in (0, 1) (Cp >= 1 would need a section larger than midships everywhere)", &error) &&
      Check(Cb / Cp <= 1.0, "Cm = Cb/Cp", Cb / Cp, "must be <= 1 (Cb = " + std::to_string(Cb) + " > Cp = " + std::to_string(Cp) + " means a midship section larger than B*T)", &error) &&
      Check(fin(Cwp) && Cwp > 0 && Cwp < 1, "Cwp", Cwp, "must lie in (0, 1)", &error) &&
      Check(Cb < Cwp || type == HullType::kSwath, "Cvp = Cb/Cwp", Cb / Cwp, "must be < 1 for a monohull/catamaran/trihull (the hull is widest at the waterline); only a SWATH has Cvp >= 1", &error) &&
      Check(fin(LCB_pct_L) && std::fabs(LCB_pct_L) < 25, "LCB_pct_L", LCB_pct_L, "must lie in (-25, 25) % L", &error) &&
      Check(fin(LCF_pct_L) && std::fabs(LCF_pct_L) < 25, "LCF_pct_L", LCF_pct_L, "must lie in (-25, 25) % L", &error) &&
      Check(fin(transom_immersion) && transom_immersion >= 0 && transom_immersion < 1, "transom_immersion", transom_immersion, "must lie in [0, 1)", &error) &&
      Check(fin(transom_beam_ratio) && transom_beam_ratio >= 0 && transom_beam_ratio <= 1, "transom_beam_ratio", transom_beam_ratio, "must lie in [0, 1]", &error) &&
      Check(fin(keel_rise) && keel_rise >= 0 && keel_rise < 1, "keel_rise", keel_rise, "must lie in [0, 1)", &error) &&
      Check(fin(spacing_over_L) && spacing_over_L > 0, "spacing_over_L", spacing_over_L, "must be > 0", &error) &&
      Check(fin(spacing_m) && spacing_m >= 0, "spacing_m", spacing_m, "must be >= 0 (0 = use spacing_over_L)", &error) &&
      Check(fin(strut_ratio) && strut_ratio >= 0 && strut_ratio <= 1, "strut_ratio", strut_ratio, "must lie in [0, 1] (0 = automatic)", &error) &&
      Check(fin(bulb_height_ratio) && bulb_height_ratio >= 0 && bulb_height_ratio < 1, "bulb_height_ratio", bulb_height_ratio, "must lie in [0, 1) (0 = elliptic bulb scaled to the ends)", &error) &&
      Check(fin(outrigger_length_ratio) && outrigger_length_ratio > 0.1 && outrigger_length_ratio <= 1, "outrigger_length_ratio", outrigger_length_ratio, "must lie in (0.1, 1]", &error) &&
      Check(fin(outrigger_L_over_B) && outrigger_L_over_B > 2, "outrigger_L_over_B", outrigger_L_over_B, "must be > 2", &error) &&
      Check(fin(outrigger_B_over_T) && outrigger_B_over_T > 0, "outrigger_B_over_T", outrigger_B_over_T, "must be > 0", &error) &&
      Check(fin(outrigger_offset_over_L) && outrigger_offset_over_L > 0, "outrigger_offset_over_L", outrigger_offset_over_L, "must be > 0", &error) &&
      Check(fin(freeboard_over_T) && freeboard_over_T > 0, "freeboard_over_T", freeboard_over_T, "must be > 0", &error) &&
      Check(stations >= 11 && stations <= 1001 && stations % 2 == 1, "stations", stations, "must be odd and in [11, 1001] (midships must be a station)", &error) &&
      Check(section_points >= 8 && section_points <= 400, "section_points", section_points, "must lie in [8, 400]", &error);

  // clang-format on
  if (ok && (type == HullType::kSwath) != (section_style == SectionStyle::kSwathBulb))
    return InvalidDesignVariable{"section_style", 0.0, ToString(section_style),
                                 "swath_bulb sections go with type swath, and a swath needs swath_bulb sections "
                                 "(type is " + ToString(type) + ")"};
  return error;
}


}  // namespace hullopt::hull
