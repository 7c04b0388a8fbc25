// The column generator: volumes against closed forms computed here (the
// inscribed polygon ½ N r² sin(2π/N) times the height; the frustum's
// h/3 (A0 + A1 + √(A0 A1))), beds shared exactly, and the spec errors.
#include "structures/column.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace polydem {
namespace {

constexpr double kPi = std::numbers::pi;

double volume(const Polyhedron& p) { return mass_properties(p).volume; }
double polygon_area(int n, double r) { return 0.5 * n * r * r * std::sin(2 * kPi / n); }

double z_extent(const Polyhedron& p, bool top) {
  double z = top ? -1e300 : 1e300;
  for (const Vec3& v : p.vertices) z = top ? std::max(z, v.z()) : std::min(z, v.z());
  return z;
}

TEST(Column, DrumsPlinthAndAbacusAreExact) {
  ColumnSpec s;
  s.drums = 5;
  s.radius = 0.4;
  s.sides = 20;
  s.height = 3.0;
  s.plinth_height = 0.2;
  s.plinth_width = 1.1;
  s.capital = ColumnCapital::abacus;
  s.capital_width = 1.0;
  s.capital_height = 0.15;
  s.origin = Vec3(1, 2, 0.5);
  const ColumnModel m = build_column(s);
  ASSERT_EQ(m.blocks.size(), 1u + 1 + 5 + 1);
  EXPECT_EQ(m.blocks[0].name, "base");
  EXPECT_EQ(m.blocks[1].name, "plinth");
  EXPECT_EQ(m.blocks[2].name, "drum00");
  EXPECT_EQ(m.blocks.back().name, "capital");
  double drums = 0;
  for (const auto& b : m.blocks)
    if (b.kind == BlockKind::drum) {
      drums += volume(b.shape);
      EXPECT_NEAR(volume(b.shape), polygon_area(20, 0.4) * 0.6, 1e-9 * 0.6) << b.name;
    }
  const double shaft = polygon_area(20, 0.4) * 3.0;
  EXPECT_NEAR(drums, shaft, 1e-9 * shaft);
  EXPECT_NEAR(volume(m.blocks[1].shape), 1.1 * 1.1 * 0.2, 1e-12);
  EXPECT_NEAR(volume(m.blocks.back().shape), 1.0 * 0.15, 1e-12);
  // Base: twice the widest block (the plinth), 0.3 thick, under origin.z.
  EXPECT_NEAR(volume(m.blocks[0].shape), 2.2 * 2.2 * 0.3, 1e-12);
  EXPECT_NEAR(z_extent(m.blocks[0].shape, true), 0.5, 0);
  // Each block's bed is exactly its neighbour's top.
  for (std::size_t i = 0; i + 1 < m.blocks.size(); ++i)
    EXPECT_EQ(z_extent(m.blocks[i].shape, true), z_extent(m.blocks[i + 1].shape, false)) << m.blocks[i].name;
  EXPECT_NEAR(m.top, 0.2 + 3.0 + 0.15, 1e-12);
  const MassProperties shaft_mp = mass_properties(m.blocks[4].shape);
  EXPECT_NEAR(shaft_mp.centroid.x(), 1.0, 1e-12);
  EXPECT_NEAR(shaft_mp.centroid.y(), 2.0, 1e-12);
}

TEST(Column, FrustumCapitalAndListedDrumHeights) {
  ColumnSpec s;
  s.drums = 3;
  s.radius = 0.3;
  s.sides = 12;
  s.drum_heights = {0.5, 0.7, 0.4};
  s.capital = ColumnCapital::frustum;
  s.capital_width = 0.9;
  s.capital_height = 0.25;
  const ColumnModel m = build_column(s);
  ASSERT_EQ(m.blocks.size(), 1u + 3 + 1);
  const double a0 = polygon_area(12, 0.3), a1 = polygon_area(12, 0.45);
  EXPECT_NEAR(volume(m.blocks.back().shape), 0.25 / 3 * (a0 + a1 + std::sqrt(a0 * a1)), 1e-12);
  EXPECT_NEAR(volume(m.blocks[2].shape), a0 * 0.7, 1e-12);
  EXPECT_NEAR(m.top, 1.6 + 0.25, 1e-12);
  for (const auto& b : m.blocks) EXPECT_NO_THROW(validate(b.shape)) << b.name;
}

void expect_spec_error(const ColumnSpec& s, const std::string& field, const std::string& fragment) {
  try {
    build_column(s);
    ADD_FAILURE() << "accepted; expected an error on " << field;
  } catch (const ColumnSpecError& e) {
    EXPECT_EQ(e.field, field) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(Column, BadSpecsNameTheirField) {
  auto with = [](auto change) {
    ColumnSpec c;
    change(c);
    return c;
  };
  expect_spec_error(with([](ColumnSpec& c) { c.drums = 0; }), "drums", "[1, 1000]");
  expect_spec_error(with([](ColumnSpec& c) { c.sides = 3; }), "sides", "[4, 128]");
  expect_spec_error(with([](ColumnSpec& c) { c.radius = -1; }), "radius", "> 0");
  expect_spec_error(with([](ColumnSpec& c) { c.drum_heights = {1, 2}; }), "drum_heights", "one height per drum");
  expect_spec_error(with([](ColumnSpec& c) { c.plinth_height = 0.2, c.plinth_width = 0.5; }), "plinth_width",
                    "at least the drums' diameter");
  expect_spec_error(with([](ColumnSpec& c) { c.plinth_width = 1.0; }), "plinth_width", "no plinth");
  expect_spec_error(with([](ColumnSpec& c) { c.capital_height = 0.2; }), "capital_height", "no capital");
  expect_spec_error(with([](ColumnSpec& c) { c.capital = ColumnCapital::frustum, c.capital_width = 0.6; }),
                    "capital_width", "one more drum");
  expect_spec_error(with([](ColumnSpec& c) { c.base_width = 0.5; }), "base_width", "at least as wide");
  expect_spec_error(with([](ColumnSpec& c) { c.base_thickness = 0; }), "base_thickness", "> 0");
}

}  // namespace
}  // namespace polydem
