// Stiff and extreme cases (issue 5), the default suite: every scene of
// extreme_cases.hpp with short end times (the whole file runs in seconds).
// The full sweep with longer runs is extreme_cases_slow_test.cpp.
#include "extreme_cases.hpp"

namespace polydem::extreme {
namespace {

std::vector<Case> default_cases() {
  return {stiffness_case(1e8, 0.02),      stiffness_case(1e11, 0.02),       stiffness_case(1e14, 0.005),
          size_density_case(0.05),        pulse_stack_case(0.25),           pulse_frictionless_case(0.22),
          pulse_high_friction_case(0.25), slope_frictionless_case(0.2),     slope_high_friction_case(0.1),
          impact_case(98e9, 0.03),        plates_case(0.05),                rod_case(0.05),
          column_case(0.1),               damping_case(0.02)};
}

class ExtremeCase : public testing::TestWithParam<std::size_t> {};

TEST_P(ExtremeCase, StaysStableOrStopsNamingTheCauseAndStep) {
  static const std::vector<Case> cases = default_cases();
  if (GetParam() == 0) print_table_header();
  run_case(cases[GetParam()]);
}

INSTANTIATE_TEST_SUITE_P(Default, ExtremeCase, testing::Range<std::size_t>(0, 14));

}  // namespace
}  // namespace polydem::extreme
