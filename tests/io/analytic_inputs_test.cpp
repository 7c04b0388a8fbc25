// What `polydem analytic` reads (io/analytic_inputs.hpp): the default spire,
// the unit arch, and the rocking models' records with their messages.
#include "io/analytic_inputs.hpp"

#include "io/deck.hpp"
#include "structures/generator_specs.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace polydem {
namespace {

std::string write(const std::string& name, const std::string& text) {
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  std::ofstream(path) << text;
  return path;
}

std::string message(const std::string& path) {
  try {
    read_uniform_record(path);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(AnalyticInputs, DefaultSpireWithAndWithoutWindows) {
  const SceneSpec s = analytic_scene("", false);
  EXPECT_EQ(s.deck_path, kDefaultSpireName);
  ASSERT_TRUE(spire_of(s.generators));
  EXPECT_FALSE(spire_of(s.generators)->window_faces.empty());
  EXPECT_TRUE(spire_of(analytic_scene("", true).generators)->window_faces.empty());
  const std::string pillar = std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/rocking_onset.toml";
  EXPECT_FALSE(spire_of(analytic_scene(pillar, false).generators));
  try {
    analytic_spire_scene(pillar, false);
    ADD_FAILURE() << "a deck without a [spire]";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "the deck " + pillar + " has no [spire]");
  }
  EXPECT_THROW(analytic_scene("/nonexistent/deck.toml", false), DeckError);
}

TEST(AnalyticInputs, UnitArchHasItsVoussoirsOnABase) {
  const SceneSpec s = unit_semicircular_arch(9, 0.12);
  int fixed = 0;
  for (const BlockSpec& b : s.blocks) fixed += b.motion == BlockMotion::fixed;
  EXPECT_EQ(s.blocks.size(), 10u);
  EXPECT_EQ(fixed, 1);
}

TEST(AnalyticInputs, RecordInGAndShiftedToZero) {
  const auto r = read_uniform_record(
      write("polydem_rec_a.csv", "# comment\ntime_s,acceleration_cm_s2\n0.5,98.0665\n0.52 -196.133\n0.54,0\n"));
  EXPECT_NEAR(r.dt, 0.02, 1e-15);
  ASSERT_EQ(r.acceleration.size(), 3u);
  EXPECT_NEAR(r.acceleration[0], 0.1, 1e-15);
  EXPECT_NEAR(r.acceleration[1], -0.2, 1e-15);
  EXPECT_TRUE(r.shifted);
  const auto g = read_uniform_record(write("polydem_rec_b.csv", "# units: g\n0 1\n0.1 2\n"));
  EXPECT_FALSE(g.shifted);
  EXPECT_EQ(g.acceleration, (std::vector<double>{1.0, 2.0}));
}

// The record readers' rules and messages (io/ground_motion_record.hpp): a
// two-column file must declare its unit.
TEST(AnalyticInputs, RecordErrorsNameTheFileAndLine) {
  const std::string bad = write("polydem_rec_c.csv", "t a_g\n0 0\n0.01 x\n");
  EXPECT_EQ(message(bad), bad + ":3: non-numeric value 'x' in column 2 (acceleration)");
  const std::string no_unit = write("polydem_rec_f.csv", "0 0\n0.01 0.1\n");
  EXPECT_NE(message(no_unit).find(no_unit + ":1: no acceleration unit declared"), std::string::npos);
  const std::string one = write("polydem_rec_d.csv", "# units: g\n0 0\n");
  EXPECT_EQ(message(one), one + ":2: only one data row: a record needs at least two");
  const std::string uneven = write("polydem_rec_e.csv", "# units: g\n0 0\n0.01 0\n0.03 0\n");
  EXPECT_EQ(message(uneven), uneven + ": time step must be uniform (the rocking models sample the record every dt)");
  EXPECT_NE(message("/nonexistent/r.csv").find("/nonexistent/r.csv: cannot open"), std::string::npos);
}

}  // namespace
}  // namespace polydem
