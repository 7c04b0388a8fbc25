// Stiff and extreme cases (issue 5), the full sweep (`slow` label): joint
// stiffness at every decade from 1e8 to 1e14 Pa/m and every other scene of
// extreme_cases.hpp over a longer time. Prints the table of README.md
// ("Stiff and extreme cases") and docs/robustness.md: run
//   build/tests/verification/verification_slow_tests --gtest_filter='*Extreme*' | grep EXTREME_ROW
#include "extreme_cases.hpp"

namespace polydem::extreme {
namespace {

std::vector<Case> slow_cases() {
  std::vector<Case> c;
  for (double kn : {1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14}) c.push_back(stiffness_case(kn, 0.2));
  for (Case x : {size_density_case(1.0), pulse_stack_case(1.0), pulse_frictionless_case(0.5),
                 pulse_high_friction_case(1.0), slope_frictionless_case(1.0), slope_high_friction_case(1.0),
                 impact_case(98e9, 0.05), impact_case(1e14, 0.05), plates_case(0.5), rod_case(1.0),
                 column_case(1.0), damping_case(0.2)})
    c.push_back(x);
  return c;
}

class ExtremeCaseSlow : public testing::TestWithParam<std::size_t> {};

TEST_P(ExtremeCaseSlow, StaysStableOrStopsNamingTheCauseAndStep) {
  static const std::vector<Case> cases = slow_cases();
  if (GetParam() == 0) print_table_header();
  run_case(cases[GetParam()]);
}

INSTANTIATE_TEST_SUITE_P(Sweep, ExtremeCaseSlow, testing::Range<std::size_t>(0, 19));

}  // namespace
}  // namespace polydem::extreme
