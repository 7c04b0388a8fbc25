// Self-weight equilibrium by two limit-analysis LPs, and the bisection on a
// parameter; why two LPs decide it is at the top of studies/standing.hpp.
#include "studies/standing.hpp"

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

}  // namespace polydem
