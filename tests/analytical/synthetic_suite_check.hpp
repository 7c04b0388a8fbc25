#pragma once
// A suite simulated for fixed parameters and measured: what the checks of
// the stochastic model against its own targets (synthetic_target_test.cpp,
// synthetic_target_slow_test.cpp) compare with analytical::synthetic_target.
#include "analytical/response_spectrum.hpp"
#include "analytical/synthetic_ground_motion.hpp"
#include "analytical/synthetic_target.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace polydem::analytical::testing {

inline double sample_median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct MeasuredSuite {
  int records = 0;
  std::vector<double> median_psa;     // per period, the sample median
  double mean_arias = 0.0, arias_standard_error = 0.0;
  double median_d5_95 = 0.0, median_t45 = 0.0;
};

// `count` records for the parameters `p`, record i drawing its noise from
// RandomStream(mix_seed(seed, i)).
inline MeasuredSuite measure_suite(const SyntheticMotionParameters& p, const SyntheticOptions& o,
                                   const std::vector<double>& periods, int count, std::uint64_t seed) {
  MeasuredSuite s;
  s.records = count;
  std::vector<std::vector<double>> psa(periods.size());
  std::vector<double> arias, d5_95, t45;
  for (int i = 0; i < count; ++i) {
    RandomStream rs(mix_seed(seed, static_cast<std::uint64_t>(i)));
    const SyntheticRecord r = simulate_record(p, o, rs);
    std::vector<double> time(r.acceleration.size());
    for (std::size_t k = 0; k < time.size(); ++k) time[k] = static_cast<double>(k) * r.dt;
    const ResponseSpectrum spectrum = response_spectrum(time, r.acceleration, periods);
    for (std::size_t j = 0; j < periods.size(); ++j) psa[j].push_back(spectrum.pseudo_acceleration[j]);
    const RecordMeasures m = record_measures(r.dt, r.acceleration, o.g);
    arias.push_back(m.arias_intensity);
    d5_95.push_back(m.d5_95);
    t45.push_back(m.t45);
  }
  for (const auto& column : psa) s.median_psa.push_back(sample_median(column));
  const double n = static_cast<double>(count);
  for (double x : arias) s.mean_arias += x / n;
  double squares = 0.0;
  for (double x : arias) squares += (x - s.mean_arias) * (x - s.mean_arias);
  s.arias_standard_error = std::sqrt(squares / (n - 1.0) / n);
  s.median_d5_95 = sample_median(d5_95);
  s.median_t45 = sample_median(t45);
  return s;
}

// The tolerance on |ln(sample median / target median)| at period j: the
// first-passage approximation's error (`approximation`, in ln) plus three
// standard errors of the sample median of `count` peaks, 1.2533 β/√count
// (the median of a normal sample, applied to ln PSa with the target's β).
inline double median_tolerance(const SyntheticTarget& t, std::size_t j, int count, double approximation) {
  return approximation + 3.0 * 1.2533 * t.dispersion[j] / std::sqrt(static_cast<double>(count));
}

}  // namespace polydem::analytical::testing
