// Self-weight equilibrium by two limit-analysis LPs, and the bisection on a
// parameter; why two LPs decide it is at the top of studies/standing.hpp.
#include "studies/standing.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace polydem {

namespace {

bool admits_zero(const LimitAnalysisResult& r) {
  if (r.status == LimitStatus::unbounded) return true;
  return r.status == LimitStatus::optimal && r.lambda >= 0.0;
}

}  // namespace

StandingCheck can_stand(const LimitModel& model, const LimitAnalysisOptions& options) {
  StandingCheck c;
  LimitAnalysisOptions o = options;
  c.plus = limit_analysis(model, o);
  o.direction = -options.direction;
  c.minus = limit_analysis(model, o);
  c.stands = admits_zero(c.plus) && admits_zero(c.minus);
  return c;
}

ThinnestStanding thinnest_standing(const std::function<SceneSpec(double)>& scene_at, double falls, double stands,
                                   double tolerance, const LimitAnalysisOptions& options) {
  if (!(tolerance > 0)) throw std::invalid_argument("thinnest_standing: tolerance must be > 0");
  ThinnestStanding r;
  auto trial = [&](double p) {
    ++r.trials;
    return can_stand(limit_model(scene_at(p)), options).stands;
  };
  if (trial(falls))
    throw std::invalid_argument("thinnest_standing: the scene stands at the lower end of the bracket, " +
                                std::to_string(falls));
  if (!trial(stands))
    throw std::invalid_argument("thinnest_standing: the scene cannot stand at the upper end of the bracket, " +
                                std::to_string(stands));
  r.falls = falls;
  r.stands = stands;
  while (std::abs(r.stands - r.falls) > tolerance) {
    const double mid = 0.5 * (r.falls + r.stands);
    if (mid == r.falls || mid == r.stands) break;  // the bracket is as narrow as doubles allow
    (trial(mid) ? r.stands : r.falls) = mid;
  }
  return r;
}

ThinnestArch thinnest_arch(int voussoirs, const std::function<SceneSpec(int, double)>& arch_at,
                           const ThinnestArchOptions& o) {
  LimitAnalysisOptions options;
  options.friction_angle_deg = o.friction_angle_deg;
  options.method = LpMethod::simplex;
  ThinnestArch a;
  a.voussoirs = voussoirs;
  const auto start = std::chrono::steady_clock::now();
  try {
    a.bracket = thinnest_standing([&](double t_over_R) { return arch_at(voussoirs, t_over_R); }, 0.001, 0.6,
                                  o.tolerance, options);
  } catch (const std::invalid_argument&) {
    // It stands at t/R = 0.001 (few voussoirs: an equilibrium of the hinged
    // chain through the joints' points exists however thin).
    a.bracket.falls = 0.0;
    a.bracket.stands = 0.001;
    a.bracket.trials = 1;
  }
  a.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return a;
}

}  // namespace polydem
