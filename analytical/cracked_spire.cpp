#include "analytical/cracked_spire.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analytical/constants.hpp"

namespace polydem::analytical {

void validate(const SpireGeometry& s) {
  if (!(s.H > 0.0) || !(s.r_b > 0.0) || !(s.tip_height > 0.0) || !(s.tip_height < s.H) ||
      !(s.wall_thickness > 0.0) || !(s.density > 0.0))
    throw std::invalid_argument("spire geometry: need H, r_b, wall_thickness, density > 0 and 0 < tip_height < H");
}

RockingBody cracked_spire_body(const SpireGeometry& s, double H_bar, double g) {
  validate(s);
  if (!(H_bar >= s.tip_height) || !(H_bar <= s.H))
    throw std::invalid_argument("cracked_spire_body: need tip_height <= H_bar <= H");
  auto radius = [&](double y) { return s.r_b * (1.0 - y / s.H); };
  const double yA = s.H - s.tip_height, rA = radius(yA);  // crack start, tension face
  const double yO = s.H - H_bar, rO = radius(yO);         // pivot, lower end of the crack
  // Positions relative to O: the pivot axis runs through O normal to the rocking plane.

  // Solid tip: cone of base radius rA standing on y = yA, axis at x = 0.
  const double Mt = s.density * pi * rA * rA * s.tip_height / 3.0;
  const double tip_dx = -rO, tip_dy = yA + s.tip_height / 4.0 - yO;
  double M = Mt;
  double Sx = Mt * tip_dx;  // first moments about O
  double Sy = Mt * tip_dy;
  // 3/20 M r² + 3/80 M h² about its own centroid, then parallel axes to O.
  double I0 = Mt * (0.15 * rA * rA + 0.0375 * s.tip_height * s.tip_height + tip_dx * tip_dx + tip_dy * tip_dy);

  if (H_bar > s.tip_height) {
    // Shell above the crack, integrated ring by ring. On a ring of radius r
    // the points above the crack plane are those with r cos φ ≥ x_lim(y): an
    // arc φ ∈ [−φ0, φ0] whose φ-integrals are closed form; the y-integral is
    // composite Simpson.
    const double slope = (yA - yO) / (rA + rO);  // −dy/dx of the crack plane
    const double area_per_dy = s.density * s.wall_thickness * std::hypot(1.0, s.r_b / s.H);  // × r dφ
    constexpr int n = 4000;  // even; the arc angle has √ end behaviour, so keep n large
    const double dy = (yA - yO) / n;
    for (int i = 0; i <= n; ++i) {
      const double y = yO + i * dy, r = radius(y);
      const double c = std::clamp((-rA + (yA - y) / slope) / r, -1.0, 1.0);
      const double phi0 = std::acos(c);
      const double L0 = 2.0 * phi0;                          // ∫ dφ
      const double L1 = 2.0 * std::sin(phi0);                // ∫ cos φ dφ
      const double L2 = phi0 + 0.5 * std::sin(2.0 * phi0);   // ∫ cos² φ dφ
      const double w = area_per_dy * r * dy * ((i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0)) / 3.0;
      const double ey = y - yO;
      M += w * L0;
      Sx += w * (r * L1 - rO * L0);
      Sy += w * ey * L0;
      I0 += w * (r * r * L2 - 2.0 * r * rO * L1 + (rO * rO + ey * ey) * L0);
    }
  }
  const double dx = Sx / M, dyc = Sy / M;  // centroid relative to O (dx < 0: inward)
  return make_rocking_body(M, std::hypot(dx, dyc), std::atan2(-dx, dyc), I0, g);
}

CrackedSpireMaximum cracked_spire_p_max(const SpireGeometry& s, double g) {
  validate(s);
  auto p_of = [&](double hb) { return cracked_spire_body(s, hb, g).p; };
  constexpr int n = 120;
  const double step = (s.H - s.tip_height) / n;
  int best = 0;
  double best_p = p_of(s.tip_height);
  for (int i = 1; i <= n; ++i) {
    const double v = p_of(s.tip_height + i * step);
    if (v > best_p) { best_p = v; best = i; }
  }
  double a = s.tip_height + std::max(0, best - 1) * step, b = s.tip_height + std::min(n, best + 1) * step;
  const double gr = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 80 && b - a > 1e-9; ++it) {
    const double c = b - gr * (b - a), d = a + gr * (b - a);
    if (p_of(c) >= p_of(d)) b = d; else a = c;
  }
  const double hb = 0.5 * (a + b);
  return {hb, p_of(hb)};
}

CrackedSpireCurve cracked_spire_curve(const SpireGeometry& s, int count, double g) {
  if (count < 2) throw std::invalid_argument("cracked_spire_curve: need count >= 2");
  CrackedSpireCurve c;
  c.spire = s;
  c.g = g;
  c.p_max = cracked_spire_p_max(s, g);
  for (int i = 0; i < count; ++i) {
    const double hb = s.tip_height + (s.H - s.tip_height) * i / (count - 1);
    c.points.push_back({hb, cracked_spire_body(s, hb, g)});
  }
  return c;
}

}  // namespace polydem::analytical
