#include "analytical/fragility.hpp"

#include "analytical/probability.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <stdexcept>

namespace polydem::analytical {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

// Dispersions outside this range mean the likelihood has no interior
// maximum (a step, or a flat curve): the data do not identify the fit.
constexpr double beta_min = 1e-4, beta_max = 20.0;

using Point2 = std::array<double, 2>;

// Nelder-Mead on a function of two variables (reflection 1, expansion 2,
// contraction 1/2, shrink 1/2), restarted from its best vertex until a
// restart no longer improves the value: the likelihoods here are smooth
// and unimodal in (ln θ, ln β), so this finds their maximum to ~1e-10
// without derivatives. `step` sizes the first simplex.
Point2 nelder_mead(const std::function<double(const Point2&)>& f, Point2 start, double step) {
  Point2 best = start;
  double best_value = f(best);
  for (int restart = 0; restart < 6; ++restart) {
    std::array<Point2, 3> x = {best, Point2{best[0] + step, best[1]}, Point2{best[0], best[1] + step}};
    std::array<double, 3> v = {best_value, f(x[1]), f(x[2])};
    for (int it = 0; it < 2000; ++it) {
      std::array<int, 3> o = {0, 1, 2};
      std::sort(o.begin(), o.end(), [&](int a, int b) { return v[a] < v[b]; });
      const Point2 lo = x[o[0]], mid = x[o[1]], hi = x[o[2]];
      const double f_lo = v[o[0]], f_mid = v[o[1]], f_hi = v[o[2]];
      const double size = std::max(std::fabs(hi[0] - lo[0]) + std::fabs(hi[1] - lo[1]),
                                   std::fabs(mid[0] - lo[0]) + std::fabs(mid[1] - lo[1]));
      if (size < 1e-11 && std::fabs(f_hi - f_lo) <= 1e-13 * (1.0 + std::fabs(f_lo))) break;
      const Point2 c = {0.5 * (lo[0] + mid[0]), 0.5 * (lo[1] + mid[1])};
      auto along = [&](double t) { return Point2{c[0] + t * (hi[0] - c[0]), c[1] + t * (hi[1] - c[1])}; };
      const Point2 r = along(-1.0);
      const double f_r = f(r);
      int h = o[2];
      if (f_r < f_lo) {
        const Point2 e = along(-2.0);
        const double f_e = f(e);
        if (f_e < f_r) x[h] = e, v[h] = f_e;
        else x[h] = r, v[h] = f_r;
      } else if (f_r < f_mid) {
        x[h] = r, v[h] = f_r;
      } else {
        const Point2 k = f_r < f_hi ? along(-0.5) : along(0.5);
        const double f_k = f(k);
        if (f_k < std::min(f_r, f_hi)) {
          x[h] = k, v[h] = f_k;
        } else {
          for (int i : {o[1], o[2]}) {
            x[i] = {0.5 * (x[i][0] + lo[0]), 0.5 * (x[i][1] + lo[1])};
            v[i] = f(x[i]);
          }
        }
      }
    }
    const int i = static_cast<int>(std::min_element(v.begin(), v.end()) - v.begin());
    const bool improved = v[i] < best_value - 1e-12 * (1.0 + std::fabs(best_value));
    if (v[i] < best_value) best = x[i], best_value = v[i];
    if (!improved && restart > 0) break;
    step *= 0.5;
  }
  return best;
}

std::optional<LognormalFragility> identified(double log_theta, double beta) {
  if (!std::isfinite(log_theta) || !(beta >= beta_min && beta <= beta_max)) return std::nullopt;
  return LognormalFragility{std::exp(log_theta), beta};
}

// The runs of each record (IDA) or each IM (MSA) for one state.
std::vector<FragilityPoint> ida_points(const std::vector<FragilityRun>& runs, DamageState ds) {
  std::map<std::string, FragilityPoint> by_record;
  for (const FragilityRun& r : runs) {
    auto [it, fresh] = by_record.try_emplace(r.record, FragilityPoint{r.record, r.im, 1, 0});
    FragilityPoint& p = it->second;
    const bool reached = r.state >= ds;
    if (fresh) {
      p.reached = reached;
    } else if (reached) {
      p.im = p.reached ? std::min(p.im, r.im) : r.im;
      p.reached = 1;
    } else if (!p.reached) {
      p.im = std::max(p.im, r.im);
    }
  }
  std::vector<FragilityPoint> points;
  for (auto& [name, p] : by_record) points.push_back(p);
  return points;
}

std::vector<FragilityPoint> stripe_points(const std::vector<FragilityRun>& runs, DamageState ds) {
  std::map<double, FragilityPoint> by_im;
  for (const FragilityRun& r : runs) {
    auto [it, fresh] = by_im.try_emplace(r.im, FragilityPoint{"", r.im, 0, 0});
    it->second.runs += 1;
    it->second.reached += r.state >= ds ? 1 : 0;
  }
  std::vector<FragilityPoint> points;
  for (auto& [im, p] : by_im) points.push_back(p);
  return points;
}

std::optional<LognormalFragility> fit_points(const std::vector<FragilityPoint>& points, FragilityMethod method) {
  if (method == FragilityMethod::ida) {
    std::vector<double> capacities, censored;
    for (const FragilityPoint& p : points) (p.reached ? capacities : censored).push_back(p.im);
    return fit_capacities(capacities, censored);
  }
  std::vector<Stripe> stripes;
  for (const FragilityPoint& p : points) stripes.push_back({p.im, p.runs, p.reached});
  return fit_stripes(stripes);
}

// One bootstrap resample: records drawn with replacement (IDA), or each
// stripe's runs redrawn with its observed fraction (MSA).
std::vector<FragilityPoint> resample(const std::vector<FragilityPoint>& points, FragilityMethod method,
                                     RandomStream& rs) {
  std::vector<FragilityPoint> out;
  out.reserve(points.size());
  if (method == FragilityMethod::ida) {
    for (std::size_t i = 0; i < points.size(); ++i) out.push_back(points[rs.index(points.size())]);
    return out;
  }
  for (FragilityPoint p : points) {
    const double fraction = static_cast<double>(p.reached) / p.runs;
    int reached = 0;
    for (int k = 0; k < p.runs; ++k) reached += rs.uniform() < fraction ? 1 : 0;
    p.reached = reached;
    out.push_back(p);
  }
  return out;
}

FitStatus status_of(const std::vector<FragilityPoint>& points, FragilityMethod method) {
  int runs = 0, reached = 0;
  for (const FragilityPoint& p : points) runs += p.runs, reached += p.reached;
  if (reached == 0) return FitStatus::none_reached;
  if (method == FragilityMethod::stripes && reached == runs) return FitStatus::all_reached;
  return FitStatus::fitted;
}

FragilityCurveFit fit_state(const std::vector<FragilityRun>& runs, DamageState ds, const FragilityOptions& o,
                            const std::vector<double>& grid) {
  FragilityCurveFit fit;
  fit.state = ds;
  fit.points = o.method == FragilityMethod::ida ? ida_points(runs, ds) : stripe_points(runs, ds);
  for (const FragilityPoint& p : fit.points) fit.observations += p.runs, fit.reached += p.reached;
  fit.curve = {nan, nan};
  fit.theta_low = fit.theta_high = fit.beta_low = fit.beta_high = nan;
  fit.probability.assign(grid.size(), nan);
  fit.band_low.assign(grid.size(), nan);
  fit.band_high.assign(grid.size(), nan);
  fit.status = status_of(fit.points, o.method);
  if (fit.status != FitStatus::fitted) return fit;
  const std::optional<LognormalFragility> curve = fit_points(fit.points, o.method);
  if (!curve) {
    fit.status = FitStatus::not_identified;
    return fit;
  }
  fit.curve = *curve;
  for (std::size_t i = 0; i < grid.size(); ++i) fit.probability[i] = fragility_probability(*curve, grid[i]);
  if (o.bootstrap == 0) return fit;

  RandomStream rs(mix_seed(o.seed, static_cast<std::uint64_t>(ds)));
  std::vector<double> thetas, betas;
  std::vector<std::vector<double>> at(grid.size());
  for (int b = 0; b < o.bootstrap; ++b) {
    const std::optional<LognormalFragility> f = fit_points(resample(fit.points, o.method, rs), o.method);
    if (!f) continue;
    thetas.push_back(f->theta);
    betas.push_back(f->beta);
    for (std::size_t i = 0; i < grid.size(); ++i) at[i].push_back(fragility_probability(*f, grid[i]));
  }
  fit.bootstrap_fitted = static_cast<int>(thetas.size());
  if (thetas.empty()) return fit;
  const double lo = 0.5 * (1.0 - o.confidence), hi = 1.0 - lo;
  fit.theta_low = percentile(thetas, lo);
  fit.theta_high = percentile(thetas, hi);
  fit.beta_low = percentile(betas, lo);
  fit.beta_high = percentile(betas, hi);
  for (std::size_t i = 0; i < grid.size(); ++i) {
    fit.band_low[i] = percentile(at[i], lo);
    fit.band_high[i] = percentile(at[i], hi);
  }
  return fit;
}

}  // namespace

const char* to_string(DamageState s) {
  switch (s) {
    case DamageState::intact: return "intact";
    case DamageState::damaged: return "damaged";
    case DamageState::stones_lost: return "stones_lost";
    case DamageState::collapsed: return "collapsed";
  }
  return "?";
}

std::optional<DamageState> damage_state_named(std::string_view name) {
  if (name == "intact" || name == "0") return DamageState::intact;
  if (name == "damaged" || name == "1") return DamageState::damaged;
  if (name == "stones_lost" || name == "stones-lost" || name == "2") return DamageState::stones_lost;
  if (name == "collapsed" || name == "3") return DamageState::collapsed;
  return std::nullopt;
}

const char* to_string(FragilityMethod m) { return m == FragilityMethod::ida ? "ida" : "stripes"; }

const char* to_string(FitStatus s) {
  switch (s) {
    case FitStatus::fitted: return "fitted";
    case FitStatus::none_reached: return "none_reached";
    case FitStatus::all_reached: return "all_reached";
    case FitStatus::not_identified: return "not_identified";
  }
  return "?";
}

double fragility_probability(const LognormalFragility& f, double im) {
  if (!(im > 0.0)) return 0.0;
  return normal_cdf(std::log(im / f.theta) / f.beta);
}

std::optional<LognormalFragility> fit_capacities(const std::vector<double>& capacities,
                                                 const std::vector<double>& censored) {
  for (const std::vector<double>* v : {&capacities, &censored})
    for (double x : *v)
      if (!(x > 0.0) || !std::isfinite(x)) throw std::invalid_argument("fit_capacities: values must be finite and > 0");
  if (capacities.empty()) return std::nullopt;
  const double n = static_cast<double>(capacities.size());
  double mean = 0.0, var = 0.0;
  for (double c : capacities) mean += std::log(c) / n;
  for (double c : capacities) var += (std::log(c) - mean) * (std::log(c) - mean) / n;
  if (censored.empty()) return identified(mean, std::sqrt(var));

  // −ln L in (ln θ, ln β), the constant ln(c √2π) of each density dropped.
  auto minus_log_likelihood = [&](const Point2& p) {
    const double mu = p[0], beta = std::exp(p[1]);
    double ll = -n * p[1];
    for (double c : capacities) ll -= 0.5 * std::pow((std::log(c) - mu) / beta, 2);
    for (double c : censored) ll += log_normal_sf((std::log(c) - mu) / beta);
    return std::isnan(ll) ? inf : -ll;
  };
  const Point2 best = nelder_mead(minus_log_likelihood, {mean, std::log(std::max(std::sqrt(var), 0.1))}, 0.3);
  return identified(best[0], std::exp(best[1]));
}

std::optional<LognormalFragility> fit_stripes(const std::vector<Stripe>& stripes) {
  int runs = 0, reached = 0;
  for (const Stripe& s : stripes) {
    if (!(s.im > 0.0) || !std::isfinite(s.im) || s.runs < 1 || s.reached < 0 || s.reached > s.runs)
      throw std::invalid_argument("fit_stripes: each stripe needs im > 0 and 0 <= reached <= runs >= 1");
    runs += s.runs;
    reached += s.reached;
  }
  if (reached == 0 || reached == runs) return std::nullopt;
  // Separated: every stripe all or nothing, the nothings all below the alls.
  double highest_none = 0.0, lowest_all = inf;
  bool all_or_nothing = true;
  for (const Stripe& s : stripes) {
    if (s.reached == 0) highest_none = std::max(highest_none, s.im);
    else if (s.reached == s.runs) lowest_all = std::min(lowest_all, s.im);
    else all_or_nothing = false;
  }
  if (all_or_nothing && highest_none < lowest_all) return std::nullopt;

  // Start: a probit line through the stripes with 0 < z < n, else the
  // stripes' mean ln IM and β = 0.5.
  double sw = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0, log_mean = 0.0;
  for (const Stripe& s : stripes) log_mean += s.runs * std::log(s.im) / runs;
  for (const Stripe& s : stripes) {
    if (s.reached == 0 || s.reached == s.runs) continue;
    const double x = std::log(s.im), y = normal_quantile(static_cast<double>(s.reached) / s.runs);
    sw += 1.0, sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  Point2 start = {log_mean, std::log(0.5)};
  const double det = sw * sxx - sx * sx;
  if (sw >= 2.0 && det > 1e-12) {
    const double slope = (sw * sxy - sx * sy) / det, intercept = (sy - slope * sx) / sw;
    if (slope > 0.0) start = {-intercept / slope, std::log(std::clamp(1.0 / slope, 0.05, 5.0))};
  }
  auto minus_log_likelihood = [&](const Point2& p) {
    const double mu = p[0], beta = std::exp(p[1]);
    double ll = 0.0;
    for (const Stripe& s : stripes) {
      const double u = (std::log(s.im) - mu) / beta;
      if (s.reached > 0) ll += s.reached * log_normal_cdf(u);
      if (s.reached < s.runs) ll += (s.runs - s.reached) * log_normal_sf(u);
    }
    return std::isnan(ll) ? inf : -ll;
  };
  const Point2 best = nelder_mead(minus_log_likelihood, start, 0.3);
  return identified(best[0], std::exp(best[1]));
}

FragilityResult fit_fragility(const std::vector<FragilityRun>& runs, const FragilityOptions& options) {
  const FragilityOptions& o = options;
  if (runs.empty()) throw std::invalid_argument("fragility: no runs");
  if (o.bootstrap < 0 || o.bootstrap > 1000000) throw std::invalid_argument("fragility: bootstrap must be in [0, 1e6]");
  if (!(o.confidence > 0.0 && o.confidence < 1.0)) throw std::invalid_argument("fragility: confidence must be in (0, 1)");
  if (o.points < 2 || o.points > 100000) throw std::invalid_argument("fragility: points must be in [2, 100000]");
  double largest = 0.0;
  for (const FragilityRun& r : runs) {
    if (!(r.im > 0.0) || !std::isfinite(r.im)) throw std::invalid_argument("fragility: every IM must be finite and > 0");
    if (o.method == FragilityMethod::ida && r.record.empty())
      throw std::invalid_argument("fragility: IDA needs each run's record");
    largest = std::max(largest, r.im);
  }
  FragilityResult result;
  result.options = o;
  for (int i = 0; i < o.points; ++i) result.im.push_back(1.25 * largest * i / (o.points - 1));
  for (DamageState ds : {DamageState::damaged, DamageState::stones_lost, DamageState::collapsed})
    result.states.push_back(fit_state(runs, ds, o, result.im));
  return result;
}

}  // namespace polydem::analytical
