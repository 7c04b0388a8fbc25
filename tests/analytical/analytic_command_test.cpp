#include "apps/analytic_command.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

int run(const std::vector<std::string>& a, std::string* out = nullptr) {
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  const int rc = run_analytic_command(a);
  const std::string o = testing::internal::GetCapturedStdout();
  testing::internal::GetCapturedStderr();
  if (out) *out = o;
  return rc;
}

}  // namespace

TEST(AnalyticCommand, EveryModelRuns) {
  std::string out;
  EXPECT_EQ(run({"analytic", "lambda", "--r_b", "1.06", "--H", "9.4"}, &out), 0);
  EXPECT_NE(out.find("0.338298"), std::string::npos);
  EXPECT_EQ(run({"beam", "--json"}, &out), 0);
  EXPECT_NE(out.find("\"Omega\":5.315"), std::string::npos);
  EXPECT_EQ(run({"rocking", "--body", "block", "--b", "0.2", "--h", "1", "--load", "pulse", "--a_p", "0.5", "--T_p",
                 "0.5", "--t_end", "3"}, &out), 0);
  EXPECT_NE(out.find("impacts"), std::string::npos);
  EXPECT_EQ(run({"rocking", "--load", "constant", "--a", "0.5", "--json", "--t_end", "5"}, &out), 0);
  EXPECT_NE(out.find("\"mode\":\"mode II\""), std::string::npos);
  EXPECT_EQ(run({"collapse-diagram", "--Tp-min", "1", "--Tp-max", "1", "--Tp-count", "1", "--points", "15", "--a_max",
                 "2", "--json"}, &out), 0);
  EXPECT_NE(out.find("\"columns\""), std::string::npos);
  EXPECT_EQ(run({"cracked-cone-p", "--count", "3"}, &out), 0);
  EXPECT_NE(out.find("max p"), std::string::npos);
}

// The first error's message on stderr, naming the option.
std::string error_of(const std::vector<std::string>& a) {
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  EXPECT_EQ(run_analytic_command(a), 2);
  testing::internal::GetCapturedStdout();
  return testing::internal::GetCapturedStderr();
}

TEST(AnalyticCommand, ErrorsNameTheOption) {
  EXPECT_EQ(error_of({"lambda", "--r_b"}), "polydem analytic lambda: --r_b needs a value\n");
  EXPECT_EQ(error_of({"lambda", "--r-b", "1", "--r_b", "2"}), "polydem analytic lambda: --r_b given twice\n");
  EXPECT_EQ(error_of({"lambda", "--bogus", "1"}), "polydem analytic lambda: unknown option --bogus\n");
  EXPECT_EQ(error_of({"lambda", "extra"}), "polydem analytic lambda: unexpected argument 'extra'\n");
  EXPECT_EQ(error_of({"lambda", "--H", "nan"}), "polydem analytic lambda: --H expects a number, got 'nan'\n");
  EXPECT_EQ(error_of({"rocking", "--body", "block", "--H", "9"}),
            "polydem analytic rocking: --H does not apply to --body block\n");
  EXPECT_EQ(error_of({"rocking", "--load", "constant", "--a_p", "1"}),
            "polydem analytic rocking: --a_p does not apply to --load constant\n");
  EXPECT_EQ(error_of({"beam", "--section", "square"}), "polydem analytic beam: --section must be circle or octagon\n");
  EXPECT_NE(error_of({"nonsense"}).find("unknown model 'nonsense' (expected lambda, beam,"), std::string::npos);
}

// Every model has a help of its own (exit 0) listing its options.
TEST(AnalyticCommand, EveryModelHasHelp) {
  for (const std::string model : {"lambda", "beam", "rocking", "collapse-diagram", "cracked-cone-p", "refined-lambda",
                                  "dem-frequency", "limit-lp", "arch-thickness"}) {
    std::string out;
    EXPECT_EQ(run({model, "--help"}, &out), 0) << model;
    EXPECT_NE(out.find("Usage: polydem analytic " + model), std::string::npos) << out;
    EXPECT_NE(out.find("--json"), std::string::npos) << out;
  }
  std::string out;
  EXPECT_EQ(run({"help"}, &out), 0);
  EXPECT_NE(out.find("arch-thickness"), std::string::npos);
}

TEST(AnalyticCommand, BadInputReturnsTwo) {
  EXPECT_EQ(run({}), 2);
  EXPECT_EQ(run({"nonsense"}), 2);
  EXPECT_EQ(run({"lambda", "--r_b"}), 2);
  EXPECT_EQ(run({"lambda", "--r_b", "abc"}), 2);
  EXPECT_EQ(run({"lambda", "--bogus", "1"}), 2);
  EXPECT_EQ(run({"lambda", "--r_b", "-1"}), 2);
  EXPECT_EQ(run({"rocking", "--body", "brick"}), 2);
  EXPECT_EQ(run({"rocking", "--load", "record", "--file", "/nonexistent/file.csv"}), 2);
  EXPECT_EQ(run({"lambda", "--help"}), 0);
}

// limit-lp on the pillar of rocking_onset.toml (0.5 x 0.5 x 2 m on a fixed
// base, friction 30 degrees in the deck): lambda = min(b/h, tan phi).
TEST(AnalyticCommand, LimitLpOnThePillar) {
  const std::string deck = std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/rocking_onset.toml";
  std::string out;
  ASSERT_EQ(run({"limit-lp", "--deck", deck}, &out), 0);
  EXPECT_NE(out.find("lambda circ.  lambda inscr."), std::string::npos) << out;
  EXPECT_NE(out.find("0.25 "), std::string::npos) << out;
  ASSERT_EQ(run({"limit-lp", "--deck", deck, "--phi", "10,30", "--direction", "90", "--pyramid", "inscribed",
                 "--method", "simplex", "--json"}, &out), 0);
  EXPECT_NE(out.find("\"friction_angle_deg\":10,\"inscribed\":{\"status\":\"optimal\",\"lambda\":0.176326980"),
            std::string::npos) << out;
  EXPECT_NE(out.find("\"friction_angle_deg\":30,\"inscribed\":{\"status\":\"optimal\",\"lambda\":0.25"), std::string::npos);
  EXPECT_NE(out.find("\"moving_blocks\":[{\"name\":\"pillar\""), std::string::npos);
  // Errors name the option.
  EXPECT_EQ(run({"limit-lp", "--deck", deck, "--phi", "90"}), 2);
  EXPECT_EQ(run({"limit-lp", "--deck", deck, "--phi", "20,x"}), 2);
  EXPECT_EQ(run({"limit-lp", "--deck", deck, "--sides", "2"}), 2);
  EXPECT_EQ(run({"limit-lp", "--deck", deck, "--pyramid", "round"}), 2);
  EXPECT_EQ(run({"limit-lp", "--deck", deck, "--method", "barrier"}), 2);
  EXPECT_EQ(run({"limit-lp", "--deck", deck, "--no-windows"}), 2);
  testing::internal::CaptureStderr();
  run_analytic_command({"limit-lp", "--deck", deck, "--phi", "20,x"});
  EXPECT_NE(testing::internal::GetCapturedStderr().find("--phi"), std::string::npos);
}

namespace {

// arch-thickness: the thinnest standing 9-voussoir semicircle is the one of
// tests/studies/arch_thickness_test.cpp (t/R = 0.10152); 3 voussoirs stand
// however thin (a hinged chain through the joints' points).
TEST(AnalyticCommand, ArchThickness) {
  std::string out;
  ASSERT_EQ(run({"arch-thickness", "--voussoirs", "3,9", "--json"}, &out), 0);
  EXPECT_NE(out.find("\"voussoirs\":9,\"t_over_R\":0.1015"), std::string::npos) << out;
  ASSERT_EQ(run({"arch-thickness", "--voussoirs", "3"}, &out), 0);
  EXPECT_NE(out.find("< 0.001"), std::string::npos) << out;
  EXPECT_EQ(run({"arch-thickness", "--voussoirs", "2"}), 2);
  EXPECT_EQ(run({"arch-thickness", "--phi", "90"}), 2);
  EXPECT_EQ(run({"arch-thickness", "--tol", "0"}), 2);
}

}  // namespace
