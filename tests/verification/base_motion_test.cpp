// Verification 7: a kinematic base moving with the ground and the equivalent
// inertial body force on a fixed base give the same rocking history.
#include "run/run_scene.hpp"
#include "io/deck.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace polydem {
namespace {

std::string deck(const std::string& name) { return std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/" + name; }

std::vector<double> column(const HistoryTable& t, const std::string& name) {
  std::vector<double> out;
  std::size_t c = 0;
  while (c < t.columns.size() && t.columns[c] != name) ++c;
  EXPECT_LT(c, t.columns.size()) << name;
  for (std::size_t r = 0; r < t.row_count(); ++r) out.push_back(t.rows[r * t.columns.size() + c]);
  return out;
}

TEST(BaseMotion, KinematicBaseEqualsBodyForce) {
  const RunReport body = run_scene(read_deck(deck("pulse_rocking_body_force.toml")));
  const RunReport kin = run_scene(read_deck(deck("pulse_rocking_kinematic.toml")));
  const auto a = column(body.histories, "pillar.rotation.y");
  const auto b = column(kin.histories, "pillar.rotation.y");
  ASSERT_EQ(a.size(), b.size());
  double peak = 0, diff = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    peak = std::max(peak, std::abs(a[k]));
    diff = std::max(diff, std::abs(a[k] - b[k]));
  }
  std::cout << "  peak rotation " << peak << " rad, largest difference " << diff << " rad (" << 100 * diff / peak
            << " %)\n";
  ASSERT_GT(peak, 0.01) << "the pulse must make the block rock";
  EXPECT_LT(diff, 0.01 * peak);
}

}  // namespace
}  // namespace polydem
