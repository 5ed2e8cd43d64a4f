#include "io/formats/hydrostatics_json.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/formats/finite_json.h"
#include "io/formats/atomic_file.h"
#include "io/formats/input_error.h"

namespace hullopt::io {

void WriteHydrostaticsJson(const std::string& path, const hull::HullForm& hull, const HydrostaticsReport& r) {
  const auto& h = r.hs;
  nlohmann::ordered_json j;
  j["conventions"] =
      "SI units; x from AP forward, z from baseline; L waterline length, B max breadth of one hull below the "
      "waterline, T draught; coefficients per reference hull (one demihull of a catamaran/SWATH; a trihull's "
      "include its outriggers); LCB/LCF in % L from midships, positive forward; volume and displacement of "
      "all "
      "bodies";
  j["type"] = hull.type;
  j["L_m"] = h.L_m;
  j["B_m"] = h.B_m;
  j["T_m"] = h.T_m;
  j["volume_m3"] = h.volume_m3;
  j["displacement_t"] = h.displacement_t;
  j["Cb"] = h.Cb;
  j["Cp"] = h.Cp;
  j["Cm"] = h.Cm;
  j["Cwp"] = h.Cwp;
  j["Cvp"] = h.Cvp;
  j["LCB_pct_L"] = h.LCB_pct_L;
  j["LCF_pct_L"] = h.LCF_pct_L;
  if (r.speed_m_s) {
    j["Fr"] = *r.speed_m_s / std::sqrt(r.g_m_s2 * h.L_m);
    j["speed_m_s"] = *r.speed_m_s;
  } else {
    j["Fr"] = nullptr;  // no speed: in the config
  }
  const int bodies = hull.BodyCount();
  if (bodies > 1) {
    j["hulls"] = bodies;
    for (const auto& b : hull.bodies)
      if (b.y_centre_m > 0.0 && b.role != "outrigger") j["spacing_m"] = 2.0 * b.y_centre_m;
    for (const auto& b : hull.bodies)
      if (b.role == "outrigger") j["outrigger_offset_m"] = b.y_centre_m;
  }
  j["reference_hulls"] = h.reference_hulls;
  j["rho_kg_m3"] = r.rho_kg_m3;
  j["g_m_s2"] = r.g_m_s2;
  j["displacement_kg"] = h.displacement_kg;
  j["lcb_m_from_ap"] = h.lcb_m_from_ap;
  j["vcb_m"] = h.vcb_m;
  j["awp_m2"] = h.awp_m2;
  j["lcf_m_from_ap"] = h.lcf_m_from_ap;
  j["midship_area_m2"] = h.midship_area_m2;
  j["i_l_m4"] = h.i_l_m4;
  j["i_t_m4"] = h.i_t_m4;
  j["bm_l_m"] = h.bm_l_m;
  j["bm_t_m"] = h.bm_t_m;
  j["kg_m"] = h.kg_m;
  j["gm_l_m"] = h.gm_l_m;
  j["gm_t_m"] = h.gm_t_m;
  j["wetted_surface_m2"] = h.wetted_surface_m2;
  j["heave_stiffness_N_per_m"] = r.rho_kg_m3 * r.g_m_s2 * h.awp_m2;
  if (!r.warnings.empty()) j["warnings"] = r.warnings;
  j["adjustments"] = r.adjustments;
  if (r.running) {
    const hull::Hydrostatics& a = *r.running;
    nlohmann::ordered_json ra;
    ra["conventions"] =
        "hull at its steady running attitude: sinkage + down at pivot_x_m, trim + bow up; the waterline cuts the "
        "trimmed hull, x and z in the hull's own axes; the quantities above are at rest, even keel";
    ra["sinkage_m"] = r.attitude.sinkage_m;
    ra["trim_deg"] = r.attitude.trim_deg;
    ra["pivot_x_m"] = r.attitude.pivot_x_m;
    ra["volume_m3"] = a.volume_m3;
    ra["displacement_kg"] = a.displacement_kg;
    ra["displacement_t"] = a.displacement_t;
    ra["buoyancy_over_rest"] = h.volume_m3 > 0.0 ? a.volume_m3 / h.volume_m3 : 0.0;
    ra["lcb_m_from_ap"] = a.lcb_m_from_ap;
    ra["vcb_m"] = a.vcb_m;
    ra["awp_m2"] = a.awp_m2;
    ra["lcf_m_from_ap"] = a.lcf_m_from_ap;
    ra["i_l_m4"] = a.i_l_m4;
    ra["wetted_surface_m2"] = a.wetted_surface_m2;
    ra["wetted_x_aft_m"] = a.x_ap_m;
    ra["heave_stiffness_N_per_m"] = r.rho_kg_m3 * r.g_m_s2 * a.awp_m2;
    j["running_attitude"] = ra;
  }
  RequireFiniteJson(j, path);
  WriteFileAtomically(path, j.dump(2) + "\n");
}

}  // namespace hullopt::io
