#include "analytical/collapse_diagram.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace polydem::analytical {

RockingResult pulse_response(const RockingBody& body, double a_p_g, double T_p, const CollapseScanOptions& opt) {
  if (!(T_p > 0.0)) throw std::invalid_argument("pulse_response: T_p must be > 0");
  const double T_free = 2.0 * pi / body.p;
  RockingOptions ro;
  ro.g = opt.g;
  ro.form = opt.form;
  ro.restitution = opt.restitution;
  ro.overturn = opt.overturn;
  ro.dt = std::min(T_p, T_free) / opt.steps_per_pulse;
  ro.t_end = T_p + opt.free_periods * T_free;
  return simulate_rocking(body, sine_pulse_ground_motion(a_p_g * opt.g, T_p), ro);
}

CollapseColumn collapse_column(const RockingBody& body, double T_p, const CollapseScanOptions& opt) {
  if (opt.coarse_points < 2 || !(opt.tolerance_g > 0.0)) throw std::invalid_argument("collapse_column: bad scan options");
  const double lo = opt.a_min_g < 0.0 ? std::tan(body.alpha) : opt.a_min_g;
  if (!(opt.a_max_g > lo)) throw std::invalid_argument("collapse_column: a_max_g must exceed a_min_g");
  auto outcome = [&](double a) { return pulse_response(body, a, T_p, opt).mode; };

  CollapseColumn col;
  col.T_p = T_p;
  col.omega_ratio = 2.0 * pi / (T_p * body.p);
  const int n = opt.coarse_points;
  std::vector<double> a(n);
  std::vector<CollapseMode> m(n);
  for (int i = 0; i < n; ++i) {
    a[i] = lo + (opt.a_max_g - lo) * i / (n - 1);
    m[i] = outcome(a[i]);
  }
  // Bisects [l, h] (outcomes ml ≠ mh) to the tolerance. A midpoint with a
  // third outcome splits the interval and both halves are bisected, so a
  // coarse interval holding two changes (e.g. Mode I → safe → Mode II, a
  // Mode I loop closing just below the Mode II boundary) keeps both.
  auto bisect = [&](auto&& self, double l, CollapseMode ml, double h, CollapseMode mh) -> void {
    while (h - l > opt.tolerance_g) {
      const double mid = 0.5 * (l + h);
      const CollapseMode mm = outcome(mid);
      if (mm == ml) {
        l = mid;
      } else if (mm == mh) {
        h = mid;
      } else {
        self(self, l, ml, mid, mm);
        self(self, mid, mm, h, mh);
        return;
      }
    }
    col.transitions.push_back({0.5 * (l + h), ml, mh});
  };
  for (int i = 0; i + 1 < n; ++i)
    if (m[i] != m[i + 1]) bisect(bisect, a[i], m[i], a[i + 1], m[i + 1]);
  // Summaries from the scan plus transitions.
  if (m[0] != CollapseMode::none) {
    col.min_collapse_g = lo;
  } else {
    for (const auto& t : col.transitions)
      if (t.below == CollapseMode::none && t.above != CollapseMode::none) { col.min_collapse_g = t.a_g; break; }
  }
  if (m[n - 1] == CollapseMode::mode_2) {
    col.mode2_boundary_g = lo;
    for (const auto& t : col.transitions)
      if (t.above == CollapseMode::mode_2) col.mode2_boundary_g = t.a_g;  // last entry into Mode II
  }
  double start = m[0] == CollapseMode::mode_1 ? lo : -1.0;
  for (const auto& t : col.transitions) {
    if (t.above == CollapseMode::mode_1) start = t.a_g;
    if (t.below == CollapseMode::mode_1 && start >= 0.0) { col.mode1_intervals.emplace_back(start, t.a_g); start = -1.0; }
  }
  if (start >= 0.0) col.mode1_intervals.emplace_back(start, opt.a_max_g);
  return col;
}

std::vector<CollapseColumn> collapse_diagram(const RockingBody& body, const std::vector<double>& T_p_values,
                                             const CollapseScanOptions& opt) {
  std::vector<CollapseColumn> out;
  out.reserve(T_p_values.size());
  for (double T : T_p_values) out.push_back(collapse_column(body, T, opt));
  return out;
}

}  // namespace polydem::analytical
