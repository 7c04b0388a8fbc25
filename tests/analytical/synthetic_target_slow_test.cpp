// The first-passage approximation of analytical/synthetic_target.hpp
// measured: suites of 2000 records for the median parameters of three
// scenarios, their sample median spectrum at 0.1-2 s against Vanmarcke's
// and Poisson's medians; with the sampling error this small, the check
// also sees a filter damping ζ_f 20 % off. About a minute (label `slow`).
#include "synthetic_suite_check.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace pa = polydem::analytical;
namespace pt = polydem::analytical::testing;

namespace {

const std::vector<double> kPeriods = {0.1, 0.2, 0.3, 0.5, 1.0, 2.0};
constexpr int kRecords = 2000;
constexpr double kApproximation = 0.06;  // as in synthetic_target_test.cpp

struct Case {
  pa::EarthquakeScenario scenario;
  const char* name;
};

// The scenario's name in the test list, not the struct's bytes.
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class SyntheticTargetSlow : public ::testing::TestWithParam<Case> {};

}  // namespace

TEST_P(SyntheticTargetSlow, SuiteOf2000MatchesVanmarckeAndSeesZetaOff) {
  const pa::SyntheticMotionParameters p = pa::median_parameters(GetParam().scenario);
  const pa::SyntheticTarget t = pa::synthetic_target(p, {}, kPeriods);
  const pt::MeasuredSuite s = pt::measure_suite(p, {}, kPeriods, kRecords, 4049);
  for (std::size_t j = 0; j < kPeriods.size(); ++j) {
    const double vanmarcke = s.median_psa[j] / t.median_pseudo_acceleration[j];
    const double poisson = s.median_psa[j] / t.poisson_median_pseudo_acceleration[j];
    std::ostringstream key, value;
    key << "T" << kPeriods[j];
    value << "suite " << s.median_psa[j] << ", suite/Vanmarcke " << vanmarcke << ", suite/Poisson " << poisson;
    RecordProperty(key.str(), value.str());
    EXPECT_LT(std::fabs(std::log(vanmarcke)), pt::median_tolerance(t, j, kRecords, kApproximation))
        << "T = " << kPeriods[j] << " s";
    EXPECT_LT(poisson, 1.0) << "T = " << kPeriods[j] << " s";
  }
  EXPECT_NEAR(s.mean_arias, t.arias_intensity, 3.0 * s.arias_standard_error);
  for (double factor : {0.8, 1.2}) {
    pa::SyntheticMotionParameters off = p;
    off.zeta_f *= factor;
    const pa::SyntheticTarget wrong = pa::synthetic_target(off, {}, kPeriods);
    int misses = 0;
    for (std::size_t j = 0; j < kPeriods.size(); ++j)
      if (std::fabs(std::log(s.median_psa[j] / wrong.median_pseudo_acceleration[j])) >
          pt::median_tolerance(t, j, kRecords, kApproximation))
        ++misses;
    std::ostringstream key;
    key << "zeta_f_x" << factor << "_misses";
    RecordProperty(key.str(), misses);
    EXPECT_GE(misses, 1) << "zeta_f x " << factor;
  }
}

INSTANTIATE_TEST_SUITE_P(Scenarios, SyntheticTargetSlow,
                         ::testing::Values(Case{{6.5, 20.0, 760.0, false}, "M65_R20_V760"},
                                           Case{{5.2, 50.0, 400.0, false}, "M52_R50_V400"},
                                           Case{{7.5, 10.0, 760.0, true}, "M75_R10_V760_reverse"}),
                         [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });
