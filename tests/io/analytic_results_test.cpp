// The JSON of `polydem analytic --json` (io/analytic_results.hpp): its
// layout is the command line's interface, pinned here by whole lines.
#include "io/analytic_results.hpp"

#include "io/analytic_inputs.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace polydem {
namespace {

namespace pa = analytical;

TEST(AnalyticResults, LambdaAsPrinted) {
  EXPECT_EQ(cone_overturning_json(pa::cone_overturning(1.06, 9.4, 5.0)).dump(0, kAnalyticDigits),
            R"({"model":"lambda","inputs":{"r_b_m":1.06,"H_m":9.4,"h_c_m":5},"lambda_eq1":0.33829787234,)"
            R"("lambda_eq2_at_h_c":0.23114383909,"lambda_eq2_governing":0.191255174044,"h_c_governing_m":9.4})");
}

TEST(AnalyticResults, BeamAsPrinted) {
  pa::SpireBeam b;
  b.section = pa::SectionShape::octagon;
  b.modes = 1;
  EXPECT_EQ(spire_beam_json(pa::spire_beam_modes(b)).dump(0, kAnalyticDigits),
            R"({"model":"beam","inputs":{"H_m":9.4,"r_b_m":1.06,"thickness_m":0.25,"E_Pa":30000000000,)"
            R"("density_kg_m3":2600,"section":"octagon"},"m_b_kg_m":4027.81268052,"I_b_m4":0.728678853209,)"
            R"("EI_b_Nm2":21860365596.3,"modes":[{"n":1,"Omega":5.31509942365,"f_Hz":22.3033395015}],)"
            R"("rayleigh":{"k_min":2.23960922321,"Omega":5.35966648647,"f_Hz":22.4903528108}})");
}

// Each body and load echoes the options of its own kind only; no uplift,
// no overturning: null times.
TEST(AnalyticResults, RockingEchoesItsBodyAndLoad) {
  pa::RockingCase c;
  c.body.shape = pa::BodyShape::block;
  c.load.kind = pa::LoadKind::constant;
  c.load.a = 0.1;  // below tan(alpha) = 0.2
  c.options.t_end = 0.5;
  const Json j = rocking_json(c, pa::rocking_response(c), 0.25);
  EXPECT_EQ(j.find("body")->dump(0), R"({"kind":"block","b_m":0.2,"h_m":1})");
  EXPECT_EQ(j.find("load")->dump(0), R"({"kind":"constant","a_g":0.1})");
  EXPECT_TRUE(j.find("t_uplift_s")->is_null());
  EXPECT_TRUE(j.find("t_overturn_s")->is_null());
  EXPECT_EQ(j.find("history")->size(), 3u);  // t = 0, 0.25, 0.5
  c.body.shape = pa::BodyShape::cracked;
  EXPECT_EQ(rocking_json(c, pa::rocking_response(c), 1.0).find("body")->dump(0),
            R"({"kind":"cracked","H_bar_m":3.4,"H_m":9.4,"r_b_m":1.06,"tip_m":3.4,"thickness_m":0.25,)"
            R"("density_kg_m3":2600})");
}

// One key per pyramid, in the order asked; a mechanism only when optimal.
TEST(AnalyticResults, LimitStudyKeysItsPyramids) {
  const std::string pillar = std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/rocking_onset.toml";
  LimitStudyOptions o;
  o.pyramids = {FrictionPyramid::inscribed, FrictionPyramid::circumscribed};
  o.method = LpMethod::simplex;
  const Json j = limit_study_json(limit_study(analytic_scene(pillar, false), o));
  EXPECT_EQ(j.find("deck")->as_string(), pillar);
  const Json& c = j.find("cases")->at(0);
  EXPECT_EQ(c.keys(), (std::vector<std::string>{"direction_deg", "friction_angle_deg", "inscribed", "circumscribed"}));
  EXPECT_EQ(c.find("inscribed")->find("mechanism")->find("moving_blocks")->at(0).find("name")->as_string(), "pillar");
}

TEST(AnalyticResults, DemFrequencyCsvIsNineDigits) {
  DemFrequencyResult r;
  r.t = {0.1, 1.0 / 3.0};
  r.u = {-2.5e-7, 1e-3};
  const std::string path = (std::filesystem::temp_directory_path() / "polydem_tip.csv").string();
  write_dem_frequency_csv(path, r);
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "t_s,u_m\n0.1,-2.5e-07\n0.333333333,0.001\n");
  EXPECT_THROW(write_dem_frequency_csv("/nonexistent/dir/tip.csv", r), std::runtime_error);
}

}  // namespace
}  // namespace polydem
