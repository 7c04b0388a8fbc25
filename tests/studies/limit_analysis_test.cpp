// The limit-analysis LP (studies/limit_analysis.hpp) on block assemblies
// whose joint resultants statics alone decides (one box, a box on a slope, a
// stack, a column), where the LP's λ is known in closed form: every joint
// must carry a resultant with its normal part's line of action inside the
// patch and its shear within the pyramid, and the two conditions are
// independent (the shear forces lie in the joint plane, so they have no
// moment about its in-plane axes). So λ = the smallest over the joints of
// the overturning value (lever over height of the part above) and the
// sliding value (friction along d, exact when the pyramid is orientated
// along d).
#include "io/deck.hpp"
#include "studies/limit_analysis.hpp"

#include <gtest/gtest.h>

#include <fmt/core.h>

#include <cmath>
#include <numbers>
#include <string>

namespace polydem {
namespace {

constexpr double kPi = std::numbers::pi;
double deg(double d) { return d * kPi / 180.0; }

// A free box (full width b along x, depth 1, height h) on a fixed base,
// under gravity tilted by `slope_deg` about y (the slope), φ = 30° in the deck.
std::string box_deck(double b, double h, double slope_deg = 0.0) {
  const double s = deg(slope_deg);
  return fmt::format(R"(
[simulation]
gravity = [{:.17g}, 0, {:.17g}]
[[block]]
name = "base"
shape = "box"
size = [4, 4, 0.5]
center = [0, 0, -0.25]
motion = "fixed"
[[block]]
name = "box"
shape = "box"
size = [{:.17g}, 1, {:.17g}]
center = [0, 0, {:.17g}]
)",
                     9.81 * std::sin(s), -9.81 * std::cos(s), b, h, h / 2);
}

LimitModel model_of(const std::string& deck) { return limit_model(parse_deck(deck, "<test>")); }

LimitAnalysisResult solve(const LimitModel& m, double phi, Vec3 d = Vec3(1, 0, 0),
                          FrictionPyramid p = FrictionPyramid::circumscribed, int sides = 8, double rotation = 0.0) {
  LimitAnalysisOptions o;
  o.friction_angle_deg = phi;
  o.direction = d;
  o.pyramid = p;
  o.pyramid_sides = sides;
  o.pyramid_rotation = rotation;
  return limit_analysis(m, o);
}

TEST(LimitAnalysis, ModelHasTheBoxFootprint) {
  const LimitModel m = model_of(box_deck(0.4, 1.0));
  ASSERT_EQ(m.interfaces.size(), 1u);
  ASSERT_EQ(m.vertices, 4);
  const LimitInterface& f = m.interfaces[0];
  EXPECT_TRUE(f.bed);
  // Normal up, into the box, whichever block holds the reference face.
  EXPECT_NEAR((m.free[f.inc] ? 1.0 : -1.0) * f.normal.z(), 1.0, 1e-12);
  for (const Vec3& p : f.vertices) {
    EXPECT_NEAR(std::abs(p.x()), 0.2, 1e-9);
    EXPECT_NEAR(std::abs(p.y()), 0.5, 1e-9);
    EXPECT_NEAR(p.z(), 0.0, 1e-9);
  }
}

// One box b × h: λ = min(b/h, tan φ) to 1e-6, both pyramids (orientated
// along d, so sliding along d is exact), in x and y and diagonally.
TEST(LimitAnalysis, BoxOnBaseTipsOrSlides) {
  for (const auto& [b, h] : {std::pair{0.4, 1.0}, std::pair{1.0, 0.8}}) {
    const LimitModel m = model_of(box_deck(b, h));
    for (const double phi : {10.0, 20.0, 30.0, 45.0, 60.0}) {
      for (const auto p : {FrictionPyramid::inscribed, FrictionPyramid::circumscribed}) {
        const auto r = solve(m, phi, Vec3(1, 0, 0), p);
        ASSERT_EQ(r.status, LimitStatus::optimal);
        EXPECT_NEAR(r.lambda, std::min(b / h, std::tan(deg(phi))), 1e-6) << "b " << b << " phi " << phi;
        const auto ry = solve(m, phi, Vec3(0, -1, 0), p);  // depth 1 m: lever 1/h
        EXPECT_NEAR(ry.lambda, std::min(1.0 / h, std::tan(deg(phi))), 1e-6);
      }
      // Diagonal (1, 1): the resultant's line must stay inside the b × 1
      // rectangle; at tipping its offset λh/2 (1, 1)/√2 reaches the edge x = b/2.
      const auto rd = solve(m, phi, Vec3(1, 1, 0));
      EXPECT_NEAR(rd.lambda, std::min(std::sqrt(2.0) * std::min(b, 1.0) / h, std::tan(deg(phi))), 1e-6);
    }
  }
}

// The mechanism: tipping is one block rotating on an opening joint; sliding
// slides it (with the associative rule's dilatancy).
TEST(LimitAnalysis, BoxMechanismOpensOrSlides) {
  const LimitModel m = model_of(box_deck(0.4, 1.0));
  const auto tip = solve(m, 45.0);
  EXPECT_EQ(tip.mechanism.blocks_moving, 1);
  EXPECT_EQ(tip.mechanism.opening, 1);
  EXPECT_EQ(tip.mechanism.sliding, 0);
  const int box = m.free[0] ? 0 : 1;
  // Rotation about the leading bottom edge (x = b/2, z = 0): about +y.
  const Vec3 w = tip.mechanism.angular_velocity[box];
  EXPECT_GT(w.y(), 0.0);
  // (The interior-point duals are exact to about 1e-6.)
  EXPECT_NEAR(std::abs(w.x()) + std::abs(w.z()), 0.0, 1e-5 * w.norm());
  const Vec3 v_edge = tip.mechanism.velocity[box] + w.cross(Vec3(0.2, 0, 0) - m.centroid[box]);
  EXPECT_NEAR(v_edge.norm(), 0.0, 1e-5 * w.norm());
  const auto slide = solve(m, 15.0);
  EXPECT_EQ(slide.mechanism.blocks_moving, 1);
  EXPECT_EQ(slide.mechanism.sliding, 1);
  const Vec3 v = slide.mechanism.velocity[box];
  EXPECT_GT(v.x(), 0.0);
  EXPECT_NEAR(v.z() / v.x(), std::tan(deg(15.0)), 1e-5);  // dilatancy at φ
}

// The pyramid's error, in closed form. The total shear over the weight must
// be λ d and lie in the pyramid's section (a regular k-gon): the sliding λ is
// the k-gon's radius along d. Turned by π/k from its orientation along d,
// the inscribed k-gon (vertices on the circle μ) gives μ cos(π/k), the
// circumscribed one (sides tangent to it) μ / cos(π/k); halfway, π/(2k):
// μ cos(π/k) / cos(π/2k) and μ / cos(π/2k).
TEST(LimitAnalysis, PyramidErrorAgainstTheRegularPolygon) {
  const LimitModel m = model_of(box_deck(1.0, 0.5));  // tips at 2: sliding governs
  const double mu = std::tan(deg(30.0));
  for (const int k : {4, 6, 8, 16}) {
    const double c = std::cos(kPi / k), c2 = std::cos(kPi / (2 * k));
    const auto solve_k = [&](FrictionPyramid p, double rot) {
      return solve(m, 30.0, Vec3(1, 0, 0), p, k, rot).lambda;
    };
    EXPECT_NEAR(solve_k(FrictionPyramid::inscribed, 0.0), mu, 1e-6);
    EXPECT_NEAR(solve_k(FrictionPyramid::circumscribed, 0.0), mu, 1e-6);
    EXPECT_NEAR(solve_k(FrictionPyramid::inscribed, kPi / k), mu * c, 1e-6) << k;
    EXPECT_NEAR(solve_k(FrictionPyramid::circumscribed, kPi / k), mu / c, 1e-6) << k;
    EXPECT_NEAR(solve_k(FrictionPyramid::inscribed, kPi / (2 * k)), mu * c / c2, 1e-6) << k;
    EXPECT_NEAR(solve_k(FrictionPyramid::circumscribed, kPi / (2 * k)), mu / c2, 1e-6) << k;
  }
}

// A box on a slope of angle θ (gravity tilted; the box's base is the joint):
// pushed downhill it slides at tan(φ − θ) or tips at tan(α − θ), uphill at
// tan(φ + θ) or tan(α + θ), α = atan(b/h). Horizontal here is perpendicular
// to the tilted gravity: d = (cos θ, 0, sin θ) points downhill.
TEST(LimitAnalysis, BoxOnSlope) {
  const double b = 0.6, h = 1.0, alpha = std::atan(b / h);
  for (const double theta : {10.0, 20.0}) {
    const LimitModel m = model_of(box_deck(b, h, theta));
    const double t = deg(theta);
    const Vec3 down(std::cos(t), 0, std::sin(t));
    for (const double phi : {25.0, 35.0, 50.0}) {
      const double f = deg(phi);
      const auto rd = solve(m, phi, down);
      EXPECT_NEAR(rd.lambda, std::min(std::tan(f - t), std::tan(alpha - t)), 1e-6) << theta << " " << phi;
      const auto ru = solve(m, phi, -down);
      EXPECT_NEAR(ru.lambda, std::min(std::tan(f + t), std::tan(alpha + t)), 1e-6) << theta << " " << phi;
    }
    // Steeper than φ: it needs a push uphill to stay (λ < 0 downhill).
    EXPECT_NEAR(solve(m, 5.0, down).lambda, std::tan(deg(5.0) - t), 1e-6);
  }
}

// Two blocks: a slender top block (0.2 × 1 × 0.8) centred on a squat one
// (1.2 × 1 × 0.5). The top tips at b2/h2 = 0.25; the stack about the base
// edge at 0.6 (m1 + m2) / (m1 h1/2 + m2 (h1 + h2/2)); friction is ample.
TEST(LimitAnalysis, StackTopBlockTipsFirst) {
  const std::string deck = box_deck(1.2, 0.5) + R"(
[[block]]
name = "top"
shape = "box"
size = [0.2, 1, 0.8]
center = [0, 0, 0.9]
)";
  const LimitModel m = model_of(deck);
  ASSERT_EQ(m.interfaces.size(), 2u);
  const double m1 = 1.2 * 0.5, m2 = 0.2 * 0.8;
  const double whole = 0.6 * (m1 + m2) / (m1 * 0.25 + m2 * 0.9);
  ASSERT_GT(whole, 0.25);
  const auto r = solve(m, 40.0);
  EXPECT_NEAR(r.lambda, 0.25, 1e-6);
  EXPECT_EQ(r.mechanism.blocks_moving, 1);
  EXPECT_TRUE(r.mechanism.moving[m.names[2] == "top" ? 2 : 1]);
  EXPECT_EQ(r.mechanism.opening, 1);
  EXPECT_EQ(r.mechanism.sliding, 0);
  // With low friction both joints carry the same shear ratio λ: sliding at tan φ.
  EXPECT_NEAR(solve(m, 10.0).lambda, std::tan(deg(10.0)), 1e-6);
}

// A column of three equal blocks (0.3 × 1 × 0.5): the bed joints' resultants
// are fixed by statics, the base joint governs, λ = (b/2) / (3h/2) = b/(3h)
// = 0.2; the whole column turns on one opening joint.
TEST(LimitAnalysis, ThreeBlockColumn) {
  std::string deck = box_deck(0.3, 0.5);
  for (int i = 1; i < 3; ++i)
    deck += fmt::format("[[block]]\nname = \"b{}\"\nshape = \"box\"\nsize = [0.3, 1, 0.5]\ncenter = [0, 0, {}]\n", i,
                        0.25 + 0.5 * i);
  const LimitModel m = model_of(deck);
  ASSERT_EQ(m.interfaces.size(), 3u);
  for (const auto p : {FrictionPyramid::inscribed, FrictionPyramid::circumscribed}) {
    const auto r = solve(m, 35.0, Vec3(1, 0, 0), p);
    EXPECT_NEAR(r.lambda, 0.2, 1e-6);
    EXPECT_EQ(r.mechanism.blocks_moving, 3);
    EXPECT_EQ(r.mechanism.opening, 1);
    EXPECT_EQ(r.mechanism.sliding, 0);
  }
  EXPECT_EQ(solve(m, 35.0).rows, 18);
  EXPECT_EQ(solve(m, 35.0, Vec3(1, 0, 0), FrictionPyramid::circumscribed, 6).columns, 1 + 3 * 4 * 6);
}

// The simplex finds the same λ and mechanism as the interior-point method
// (the default) on the stack.
TEST(LimitAnalysis, SimplexAgreesWithInteriorPoint) {
  const LimitModel m = model_of(box_deck(1.2, 0.5) + "[[block]]\nname = \"top\"\nshape = \"box\"\nsize = [0.2, 1, 0.8]\ncenter = [0, 0, 0.9]\n");
  for (const double phi : {10.0, 40.0}) {
    LimitAnalysisOptions o;
    o.friction_angle_deg = phi;
    const auto ipm = limit_analysis(m, o);
    o.method = LpMethod::simplex;
    const auto spx = limit_analysis(m, o);
    ASSERT_EQ(spx.status, LimitStatus::optimal);
    EXPECT_NEAR(spx.lambda, ipm.lambda, 1e-6);
    if (phi < 20) continue;  // at tan φ either joint may slide: the mechanism is not unique
    EXPECT_EQ(spx.mechanism.blocks_moving, ipm.mechanism.blocks_moving);
    EXPECT_EQ(spx.mechanism.sliding, ipm.mechanism.sliding);
    EXPECT_EQ(spx.mechanism.opening, ipm.mechanism.opening);
  }
}

TEST(LimitAnalysis, BadInputIsNamed) {
  const LimitModel m = model_of(box_deck(0.4, 1.0));
  LimitAnalysisOptions o;
  o.friction_angle_deg = 90.0;
  EXPECT_THROW(limit_analysis(m, o), std::invalid_argument);
  o.friction_angle_deg = 30.0;
  o.pyramid_sides = 2;
  EXPECT_THROW(limit_analysis(m, o), std::invalid_argument);
  o.pyramid_sides = 8;
  o.direction = Vec3(0, 0, 1);
  EXPECT_THROW(limit_analysis(m, o), std::invalid_argument);
  // A box in the air touches nothing.
  const std::string floating = box_deck(0.4, 1.0) + R"(
[[block]]
name = "cloud"
shape = "box"
size = [0.2, 0.2, 0.2]
center = [0, 0, 3]
)";
  try {
    limit_analysis(model_of(floating), LimitAnalysisOptions{});
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'cloud'"), std::string::npos) << e.what();
  }
}

// Without friction a joint holds no shear: the box holds no horizontal
// force, λ = 0, and each vertex has one ray (the normal).
TEST(LimitAnalysis, FrictionlessSlidesAtZero) {
  const LimitModel m = model_of(box_deck(0.4, 1.0));
  const auto r = solve(m, 0.0);
  ASSERT_EQ(r.status, LimitStatus::optimal);
  EXPECT_NEAR(r.lambda, 0.0, 1e-7);
  EXPECT_EQ(r.columns, 1 + 4);
}

// A box between two fixed walls (touching it at t = 0) cannot move along x:
// no mechanism, the LP is unbounded (λ = +inf). Along y too: the rigid
// walls may squeeze it with any normal force (a self-stress, which rigid
// blocks allow at no cost) and friction then holds any shear.
TEST(LimitAnalysis, ConfinedBoxIsUnbounded) {
  std::string deck = box_deck(0.4, 1.0);
  for (const double x : {-0.45, 0.45})
    deck += fmt::format("[[block]]\nshape = \"box\"\nsize = [0.5, 1, 1]\ncenter = [{}, 0, 0.5]\nmotion = \"fixed\"\n", x);
  const LimitModel m = model_of(deck);
  ASSERT_EQ(m.interfaces.size(), 3u);
  const auto r = solve(m, 30.0);
  EXPECT_EQ(r.status, LimitStatus::unbounded);
  EXPECT_TRUE(std::isinf(r.lambda));
  EXPECT_EQ(solve(m, 30.0, Vec3(0, 1, 0)).status, LimitStatus::unbounded);
  // Without friction it slides along y at once.
  EXPECT_NEAR(solve(m, 0.0, Vec3(0, 1, 0)).lambda, 0.0, 1e-7);
}

}  // namespace
}  // namespace polydem

namespace polydem {
namespace {

// The default spire (402 blocks, 2406 equations) at φ = 30°, the static
// force along −y, onto window face 6 (the DEM's ground acceleration along
// +y, "direction 90"): λ of the circumscribed 16-sided pyramid as measured
// on the canonically numbered mesh (0.20710; 0.22052 on the earlier,
// heap-ordered one: three degenerate line contacts differ, docs/analytical.md
// 7), above the DEM's collapse acceleration there (0.1773-0.1828 g), as a
// bound must be. The mechanism
// moves the tip fastest. (One solve: 4-9 s.)
TEST(LimitAnalysis, DefaultSpireAtThirtyDegrees) {
  const LimitModel m = limit_model(parse_deck("[spire]\n", "<default [spire]>"));
  LimitAnalysisOptions o;
  o.friction_angle_deg = 30.0;
  o.direction = Vec3(0, -1, 0);
  const auto r = limit_analysis(m, o);
  ASSERT_EQ(r.status, LimitStatus::optimal);
  EXPECT_EQ(r.rows, 6 * 401);
  EXPECT_NEAR(r.lambda, 0.20710, 3e-4);
  EXPECT_GT(r.lambda, 0.1828);
  int tip = -1;
  for (std::size_t i = 0; i < m.names.size(); ++i)
    if (m.names[i] == "tip") tip = static_cast<int>(i);
  ASSERT_GE(tip, 0);
  EXPECT_NEAR(r.mechanism.speed[tip], 1.0, 1e-6);
}

}  // namespace
}  // namespace polydem
