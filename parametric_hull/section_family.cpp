#include "parametric_hull/section_family.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "parametric_hull/section_geometry.h"

namespace hullopt::hull {
namespace {

constexpr double kSectionPi = 3.14159265358979323846;
// Reach of the round-bilge family (superellipse exponent 0.35 .. 60): hollower sections than σ = 0.15 are
// needle-like, fuller than 0.98 are boxes that belong to the hard-chine family.
constexpr double kRoundBilgeMinSigma = 0.15, kRoundBilgeMaxSigma = 0.98;
constexpr double kMinLogN = -1.05, kMaxLogN = 4.1;
// Relative area tolerance of the section solve: round-off level, so hydrostatic targets are met exactly.
constexpr double kSectionAreaTol = 1e-12;

[[noreturn]] void Refuse(const SectionTarget& t, const std::string& family, double sigma,
                         const std::string& rule) {
  std::ostringstream s;
  s << family << " section at x = " << t.x_m << " m needs area coefficient A/(b d) = " << sigma
    << " (b = " << 2 * t.half_beam_m << " m, d = " << t.draught_m << " m, A = " << t.area_m2
    << " m^2): " << rule;
  throw std::domain_error(s.str());
}

void AddDeck(const SectionTarget& t, Station* s) {
  s->y_m.push_back(t.deck_half_beam_m);
  s->z_m.push_back(t.deck_z_m);
}

// Degenerate sections: the stem line, or a flat bottom on the waterline.
bool Degenerate(const SectionTarget& t, Station* s) {
  if (t.half_beam_m > 0.0 && t.draught_m > 0.0 && t.area_m2 > 0.0) return false;
  const double keel = t.waterline_z_m - (t.half_beam_m > 0.0 ? 0.0 : t.draught_m);
  s->y_m = {0.0};
  s->z_m = {keel};
  if (t.half_beam_m > 0.0) {
    s->y_m.push_back(t.half_beam_m);
    s->z_m.push_back(t.waterline_z_m);
  } else if (keel < t.waterline_z_m) {
    s->y_m.push_back(0.0);
    s->z_m.push_back(t.waterline_z_m);
  }
  AddDeck(t, s);
  return true;
}

Station Superellipse(const SectionTarget& t, double n) {
  Station s;
  s.x_m = t.x_m;
  const int m = t.points;
  s.y_m.resize(m);
  s.z_m.resize(m);
  for (int j = 0; j < m; ++j) {
    const double th = 0.5 * kSectionPi * j / (m - 1);
    const double sn = j == m - 1 ? 1.0 : std::sin(th), cs = j == m - 1 ? 0.0 : std::cos(th);
    s.y_m[j] = t.half_beam_m * std::pow(sn, 2.0 / n);
    s.z_m[j] = t.waterline_z_m - t.draught_m * std::pow(cs, 2.0 / n);
  }
  s.z_m[0] = t.waterline_z_m - t.draught_m;
  AddDeck(t, &s);
  return s;
}

}  // namespace

double SectionArea(const Station& s, double waterline_z_m) {
  return 2.0 * ComputeSectionProperties(s, waterline_z_m).area_m2;
}

Station RoundBilgeSection(const SectionTarget& t) {
  Station s;
  s.x_m = t.x_m;
  if (Degenerate(t, &s)) return s;
  const double sigma = t.area_m2 / (2.0 * t.half_beam_m * t.draught_m);
  if (!(sigma >= kRoundBilgeMinSigma && sigma <= kRoundBilgeMaxSigma))
    Refuse(t, "round-bilge", sigma, "outside the reach 0.15..0.98 of round-bilge sections");
  // Start from the exponent of the exact superellipse, σ(n) = Γ(1+1/n)² / Γ(1+2/n) (bisection on log n, no
  // allocation), then secant steps on the polyline's own area; Illinois regula falsi if those stall.
  const auto analytic = [](double ln) {
    const double n = std::exp(ln);
    return std::exp(2.0 * std::lgamma(1.0 + 1.0 / n) - std::lgamma(1.0 + 2.0 / n));
  };
  double lo = kMinLogN, hi = kMaxLogN;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (analytic(mid) < sigma ? lo : hi) = mid;
  }
  auto f = [&](double ln) {
    return SectionArea(Superellipse(t, std::exp(ln)), t.waterline_z_m) / t.area_m2 - 1.0;
  };
  double x0 = 0.5 * (lo + hi), x1 = x0 + 0.01, f0 = f(x0), f1 = f(x1);
  for (int it = 0; it < 12 && std::fabs(f1) > kSectionAreaTol && f1 != f0; ++it) {
    const double x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
    if (!(x2 > kMinLogN && x2 < kMaxLogN)) break;
    x0 = x1;
    f0 = f1;
    x1 = x2;
    f1 = f(x1);
  }
  if (std::fabs(f1) <= kSectionAreaTol) return Superellipse(t, std::exp(x1));
  double a = kMinLogN, b = kMaxLogN, fa = f(a), fb = f(b);
  if (fa > 0.0 || fb < 0.0)
    Refuse(t, "round-bilge", sigma, "outside the reach of round-bilge sections with this many points");
  int side = 0;
  double c = 0.5 * (a + b);
  for (int it = 0; it < 100; ++it) {
    c = (a * fb - b * fa) / (fb - fa);
    const double fc = f(c);
    if (std::fabs(fc) < kSectionAreaTol) break;
    if (fc < 0.0) {
      a = c;
      fa = fc;
      if (side == -1) fb *= 0.5;
      side = -1;
    } else {
      b = c;
      fb = fc;
      if (side == 1) fa *= 0.5;
      side = 1;
    }
  }
  return Superellipse(t, std::exp(c));
}

Station HardChineSection(const SectionTarget& t) {
  Station s;
  s.x_m = t.x_m;
  if (Degenerate(t, &s)) return s;
  const double sigma = t.area_m2 / (2.0 * t.half_beam_m * t.draught_m);
  if (!(sigma >= 0.5 && sigma <= 1.0))
    Refuse(t, "hard-chine", sigma,
           "outside the reach 0.5..1 of hard-chine sections (chine between waterline and keel)");
  const double keel = t.waterline_z_m - t.draught_m;
  const double chine = keel + 2.0 * t.draught_m * (1.0 - sigma);
  s.y_m = {0.0, t.half_beam_m};
  s.z_m = {keel, chine};
  if (chine < t.waterline_z_m) {
    s.y_m.push_back(t.half_beam_m);
    s.z_m.push_back(t.waterline_z_m);
  }
  AddDeck(t, &s);
  return s;
}

Station SwathSection(const SectionTarget& t, double e, double h, double nb, double nb_lower) {
  if (!(nb_lower > 0.0)) nb_lower = nb;
  Station s;
  s.x_m = t.x_m;
  const double keel = t.waterline_z_m - t.draught_m;
  const double st = t.half_beam_m;
  const double ew = std::max(e, st);  // a bulb narrower than the strut is widened to the strut
  const int m = std::max(4, t.points / 2);
  // Powers of the superellipse; the default elliptic bulb (nb = 2) needs none (this is the hot loop of SWATH
  // generation).
  const bool ellipse = nb == 2.0;
  const bool ellipse_lower = nb_lower == 2.0;
  const auto pw = [&](double v, double ex) { return ellipse && ex == 1.0 ? v : std::pow(v, ex); };
  const auto pwl = [&](double v, double ex) { return ellipse_lower && ex == 1.0 ? v : std::pow(v, ex); };
  // Lower half of the bulb: superellipse quadrant from the keel to the widest point.
  for (int j = 0; j < m; ++j) {
    const double th = 0.5 * kSectionPi * j / (m - 1);
    const double sn = j == m - 1 ? 1.0 : std::sin(th), cs = j == m - 1 ? 0.0 : std::cos(th);
    s.y_m.push_back(ew * pwl(sn, 2.0 / nb_lower));
    s.z_m.push_back(keel + 0.5 * h * (1.0 - pwl(cs, 2.0 / nb_lower)));
  }
  // Upper half of the bulb back in to the strut: y = ew (1 - w^nb)^(1/nb), w = (z - zc)/(h/2) from 0 to w_j.
  const double zc = keel + 0.5 * h;
  if (ew > st) {
    const double wj =
        ellipse ? std::sqrt(1.0 - (st / ew) * (st / ew)) : std::pow(1.0 - std::pow(st / ew, nb), 1.0 / nb);
    for (int j = 1; j < m; ++j) {
      const double th = 0.5 * kSectionPi * j / (m - 1);
      // Parametrise by angle for even spacing, clipped at w_j.
      double w = pw(std::sin(th), 2.0 / nb);
      if (w >= wj || j == m - 1) w = wj;
      const double y = ellipse ? ew * std::sqrt(std::max(0.0, 1.0 - w * w))
                               : ew * std::pow(std::max(0.0, 1.0 - std::pow(w, nb)), 1.0 / nb);
      s.y_m.push_back(std::max(st, y));
      s.z_m.push_back(zc + 0.5 * h * w);
      if (w == wj) break;
    }
  }
  if (s.z_m.back() < t.waterline_z_m) {
    s.y_m.push_back(st);
    s.z_m.push_back(t.waterline_z_m);
  }
  AddDeck(t, &s);
  return s;
}

}  // namespace hullopt::hull
