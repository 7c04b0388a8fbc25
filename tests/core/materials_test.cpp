// Materials: the joint stiffness of stone and mortar in series, against
// Table 1 of the paper worked by hand.
#include "core/materials.hpp"

#include <gtest/gtest.h>

namespace polydem {
namespace {

TEST(Materials, SeriesNormalStiffnessOfTable1) {
  // h = 0.3 m, t = 0.01 m, E_stone = 30 GPa, E_mortar = 10 GPa:
  // 1/kn = 0.29/30e9 + 0.01/10e9 = (0.29 + 0.03)/30e9 = 0.32/30e9 m/Pa,
  // kn = 30e9/0.32 = 93.75e9 Pa/m.
  const double kn = series_joint_normal_stiffness(0.3, 0.01, 30e9, 10e9);
  EXPECT_NEAR(kn, 93.75e9, 1.0);  // 1 Pa/m: round-off only
  // Bit for bit as io/deck.cpp computed it before the formula moved here.
  EXPECT_EQ(kn, 1.0 / ((0.3 - 0.01) / 30e9 + 0.01 / 10e9));
}

TEST(Materials, SeriesNormalStiffnessLimits) {
  // No mortar: the stone alone over the pitch, E/h.
  EXPECT_DOUBLE_EQ(series_joint_normal_stiffness(0.5, 0.0, 20e9, 1e9), 20e9 / 0.5);
  // Equal moduli: the mortar is just more stone.
  EXPECT_DOUBLE_EQ(series_joint_normal_stiffness(0.4, 0.1, 8e9, 8e9), 8e9 / 0.4);
}

TEST(Materials, ShearStiffnessIsTheRatioOfTheNormal) {
  EXPECT_DOUBLE_EQ(joint_shear_stiffness(93.75e9, 0.4), 37.5e9);
}

}  // namespace
}  // namespace polydem
