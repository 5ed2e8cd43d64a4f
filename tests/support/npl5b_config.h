#pragma once
// The NPL 5b-like catamaran of Table 1 (configs/davis-holloway-2003/hull02_NPL5b.yaml) at 40 kn as config
// text: hull, water and speed blocks (a test adds its solver and mass).
namespace hullopt::test {

constexpr const char* kNpl5bDesignYaml =
    "hull:\n"
    "  parametric: { type: catamaran, section_style: round_bilge, displacement_t: 1000, L_over_B: 11.0,\n"
    "                B_over_T: 2.0, Cb: 0.40, Cp: 0.69, Cwp: 0.76, LCB_pct_L: -6.4, LCF_pct_L: -8.3,\n"
    "                transom_immersion: 0.3, spacing_over_L: 0.25 }\n"
    "water: { rho_kg_m3: 1025, g_m_s2: 9.81 }\n"
    "speed: { kn: 40 }\n";

}  // namespace hullopt::test
