// Model 2 of issue 4: the collapse multiplier of the block model.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "analytical/refined_lambda.hpp"
#include "analytical/static_overturning.hpp"
#include "structures/spire.hpp"

namespace pa = polydem::analytical;
using polydem::SpireSpec;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

polydem::SpireModel one_box(double w, double depth, double h) {
  polydem::SpireModel m;
  polydem::GeneratedBlock b;
  b.shape = polydem::make_box(polydem::Vec3(w, depth, h), polydem::Vec3(0, 0, 0.5 * h));
  b.kind = polydem::BlockKind::stone;
  b.course = 0;
  b.face = 0;
  b.name = "box";
  m.blocks.push_back(b);
  m.n_courses = 1;
  return m;
}

// Windowless spire of fine courses and narrow stones, straight joints.
SpireSpec fine_spire() {
  SpireSpec s;
  s.window_faces = {};
  s.joint_pattern = polydem::SpireJointPattern::aligned;
  s.course_height = 0.05;
  s.stones_per_face = 4;
  return s;
}

// λ of the continuous spire (the same octagonal frustum, hollow below the
// tip, solid tip) cut by the plane of angle β through the base edge of face
// 0, by the midpoint rule on a grid: independent of the blocks.
std::vector<double> continuum_plane_lambda(const SpireSpec& s, const std::vector<double>& betas) {
  const int nz = 470, nxy = 240;
  const double top_shell = s.height - s.tip_height;
  const double a0 = polydem::spire_outer_inradius(s, 0.0);
  const double half = a0 / std::cos(std::numbers::pi / 8.0) * 1.001;
  const double dz = s.height / nz, dx = 2.0 * half / nxy;
  std::vector<double> num(betas.size(), 0.0), den(betas.size(), 0.0);
  std::vector<double> tb(betas.size());
  for (std::size_t k = 0; k < betas.size(); ++k) tb[k] = std::tan(betas[k]);
  for (int iz = 0; iz < nz; ++iz) {
    const double z = (iz + 0.5) * dz;
    const double ao = polydem::spire_outer_inradius(s, z);
    const double ai = z < top_shell ? polydem::spire_inner_inradius(s, z) : -1.0;
    for (int ix = 0; ix < nxy; ++ix) {
      const double x = -half + (ix + 0.5) * dx;
      for (int iy = 0; iy < nxy; ++iy) {
        const double y = -half + (iy + 0.5) * dx;
        double ap = -1e300;
        for (int f = 0; f < 8; ++f)
          ap = std::max(ap, x * std::cos(f * std::numbers::pi / 4) + y * std::sin(f * std::numbers::pi / 4));
        if (ap > ao || ap < ai) continue;
        const double lever = a0 - x;
        for (std::size_t k = 0; k < betas.size(); ++k)
          if (z > tb[k] * lever) {
            num[k] += lever;
            den[k] += z;
          }
      }
    }
  }
  std::vector<double> out(betas.size());
  for (std::size_t k = 0; k < betas.size(); ++k) out[k] = num[k] / den[k];
  return out;
}

}  // namespace

TEST(RefinedLambda, RigidPrismIsHalfWidthOverHalfHeight) {
  const double w = 0.6, depth = 0.4, h = 2.0;
  const auto m = one_box(w, depth, h);
  const pa::LoadDirection x{"x", 0.0};
  // Pivot: the edge at x = w/2, centroid at height h/2: λ = (w/2)/(h/2) = b/h.
  const auto plane = pa::plane_crack_mechanism(m, 2000.0, x, 0.0);
  ASSERT_TRUE(plane.admissible);
  EXPECT_DOUBLE_EQ(plane.lambda, w / h);
  EXPECT_DOUBLE_EQ(pa::stepped_crack_mechanism(m, 2000.0, x, 0).lambda, w / h);
  EXPECT_NEAR(plane.mass, 2000.0 * w * depth * h, 1e-9);
  // About y the pivot is the edge at y = depth/2.
  EXPECT_DOUBLE_EQ(pa::plane_crack_mechanism(m, 2000.0, {"y", std::numbers::pi / 2}, 0.0).lambda, depth / h);
  // Diagonal: the pivot is the corner, d·corner = (w + depth)/(2√2).
  const auto diag = pa::plane_crack_mechanism(m, 2000.0, {"d", std::numbers::pi / 4}, 0.0);
  EXPECT_NEAR(diag.lambda, (w + depth) / (2.0 * std::sqrt(2.0)) / (0.5 * h), 1e-12);
  // A plane above the centroid leaves nothing: not a mechanism.
  EXPECT_FALSE(pa::plane_crack_mechanism(m, 2000.0, x, 80 * kDeg).admissible);
  // The search finds the block itself, in the narrow direction.
  pa::RefinedLambdaOptions o;
  o.directions = {x, {"y", std::numbers::pi / 2}};
  const auto r = pa::refined_lambda(m, 2000.0, o);
  EXPECT_DOUBLE_EQ(r.governing.lambda, depth / h);
  EXPECT_EQ(r.governing.direction.name, "y");
}

// The windowless spire of 0.05 m courses, 4 stones per face, against the same
// geometry as a continuum, and against eq. 1-2.
//
// Measured (face 0 direction; λ of the blocks above the plane by the centroid
// rule / by the cover rule / continuum): β = 0: 0.4303 / 0.4303 / 0.4303;
// 30°: 0.3430 / 0.3506 / 0.3426; 60°: 0.2505 / 0.2609 / 0.2502; 75°: 0.1837 /
// 0.1942 / 0.1828. The centroid rule is the continuum to < 0.5 %; the cover
// rule (whole cut stones go with the part: a wall-thick, stone-wide band
// along the crack) is 2-6 % above it. The centroid rule cannot be searched
// on its own here: it drops the pivot stone (centroid t/2 behind and h/2
// above the pivot) beyond β = atan(h/t) = 11°, hence the cover family.
//
// Against the paper: the whole spire (β = 0) is 0.430, not eq. 1's 0.340:
// the pivot is at the outer apothem 1.189 m, not the mid-wall 1.064 m
// (×1.12: 0.379), and the wall tapering from 0.25 to 0.15 m puts the
// centroid below H/3 (another ×1.13). Eq. 2 is not an exact plane crack:
// expanding it, the moving part at height z < h_c keeps the fraction z/h_c
// of each thin ring, with a lever term r_b h_c/(2π² H) for the part removed.
// An exact plane through the base corner of a thin cone gives less (0.245
// at β = 50°, 0.16 at 75°) and tends to r_b/H = 0.113 as the plane becomes
// tangent to the front face (β_max = atan(H/r_b)); eq. 2's governing 0.192
// lies between the thin-cone planes at 65° and 72°. The block spire's thick
// wall and solid tip (which must go whole) give its plane family an interior
// minimum instead, 0.175 at β = 81.3°, just below β_max = atan(H/a_out) =
// 82.8° (the paper: the crack is "approximately β_max"), 9 % below eq. 2.
TEST(RefinedLambda, FineWindowlessSpireMatchesContinuumPlaneCracks) {
  const SpireSpec s = fine_spire();
  const auto model = polydem::build_spire(s);
  const pa::LoadDirection face0{"face 0", 0.0};
  const std::vector<double> betas = {0.0, 30 * kDeg, 60 * kDeg, 75 * kDeg};
  const auto cont = continuum_plane_lambda(s, betas);
  double previous = 1e9;
  for (std::size_t k = 0; k < betas.size(); ++k) {
    const auto m = pa::plane_crack_mechanism(model, 2600.0, face0, betas[k], pa::CrackFamily::plane_cover);
    ASSERT_TRUE(m.admissible);
    // The centroid rule, admissible or not: the moments are still those of
    // the blocks above the plane.
    const auto c = pa::plane_crack_mechanism(model, 2600.0, face0, betas[k], pa::CrackFamily::plane);
    const double lc = c.restoring_moment / c.overturning_moment;
    std::printf("beta %5.1f deg: cover %.5f (%+.2f %%), centroid %.5f (%+.2f %%), continuum %.5f\n", betas[k] / kDeg,
                m.lambda, 100.0 * (m.lambda / cont[k] - 1.0), lc, 100.0 * (lc / cont[k] - 1.0), cont[k]);
    EXPECT_NEAR(lc, cont[k], 0.01 * cont[k]) << "beta = " << betas[k] / kDeg;
    EXPECT_GE(m.lambda, cont[k] * (1.0 - 1e-3)) << "beta = " << betas[k] / kDeg;
    EXPECT_NEAR(m.lambda, cont[k], 0.07 * cont[k]) << "beta = " << betas[k] / kDeg;
    EXPECT_LT(m.lambda, previous);  // steeper crack, smaller λ
    previous = m.lambda;
  }
  // Monotone decrease up to near β_max = atan(H / a_out) = 82.8°.
  previous = 1e9;
  for (double b = 0.0; b <= 78.0; b += 3.0) {
    const double lam =
        pa::plane_crack_mechanism(model, 2600.0, face0, b * kDeg, pa::CrackFamily::plane_cover).lambda;
    EXPECT_LT(lam, previous) << "beta = " << b;
    previous = lam;
  }
  // The whole spire (β = 0) against eq. 1 with the pivot at the outer
  // apothem: the thick wall and the solid tip move the centroid, so within
  // 20 % only (quantified here).
  const double a_out = s.base_inradius + 0.5 * s.wall_thickness;
  const double whole = pa::plane_crack_mechanism(model, 2600.0, face0, 0.0, pa::CrackFamily::plane_cover).lambda;
  std::printf("whole spire %.5f, eq. 1 with r_b = a_out %.5f, eq. 1 %.5f, eq. 2 %.5f\n", whole,
              pa::lambda_cone(a_out, s.height), pa::lambda_cone(s.base_inradius, s.height),
              pa::governing_crack(s.base_inradius, s.height).lambda);
  EXPECT_NEAR(whole, pa::lambda_cone(a_out, s.height), 0.2 * whole);
  // Governing plane crack: near β_max, below eq. 2.
  pa::RefinedLambdaOptions o;
  o.directions = {face0};
  const auto r = pa::refined_lambda(model, 2600.0, o);
  ASSERT_EQ(r.plane_cover.size(), 1u);
  const auto& pc = r.plane_cover[0];
  std::printf("governing plane-cover %.5f at beta (%.2f, %.2f] deg; stepped %.5f\n", pc.lambda, pc.beta_low / kDeg,
              pc.beta_high / kDeg, r.stepped[0].lambda);
  EXPECT_GT(pc.beta_high, 75 * kDeg);
  EXPECT_LT(pc.beta_low, std::atan(s.height / a_out));
  EXPECT_LT(pc.lambda, pa::governing_crack(s.base_inradius, s.height).lambda);
}

// The paper's spire (default SpireSpec: windows, 0.3 m courses).
TEST(RefinedLambda, DefaultSpire) {
  const auto model = polydem::build_spire(SpireSpec{});
  const auto r = pa::refined_lambda(model, 2600.0);
  ASSERT_EQ(r.plane.size(), 16u);
  ASSERT_EQ(r.stepped.size(), 16u);
  ASSERT_TRUE(r.governing.admissible);
  std::printf("refined lambda %.5f (%s, %s, %zu blocks, %.1f kg)\n", r.governing.lambda,
              r.governing.direction.name.c_str(), pa::to_string(r.governing.family), r.governing.blocks.size(),
              r.governing.mass);
  // Paper: refined 0.168, DEM 0.164-0.176, eq. 2 0.192.
  EXPECT_GT(r.governing.lambda, 0.16);
  EXPECT_LT(r.governing.lambda, 0.18);
  for (const auto* list : {&r.plane, &r.plane_cover, &r.stepped})
    for (const auto& m : *list) {
      EXPECT_TRUE(m.admissible) << m.direction.name;
      EXPECT_GE(m.lambda, r.governing.lambda);
      // Every reported λ is its moments' ratio.
      EXPECT_NEAR(m.lambda, m.restoring_moment / m.overturning_moment, 1e-12);
    }
  // Stepped n = 0 and the plane at β = 0: the whole spire, the same set.
  const pa::LoadDirection face0{"face 0", 0.0};
  const auto whole = pa::stepped_crack_mechanism(model, 2600.0, face0, 0);
  EXPECT_NEAR(whole.mass, r.total_mass, 1e-9 * r.total_mass);
  EXPECT_NEAR(whole.lambda, pa::plane_crack_mechanism(model, 2600.0, face0, 0.0).lambda, 1e-12);
  // Eightfold pattern of the faces with windows (0, 2, 4, 6): same λ.
  EXPECT_NEAR(r.stepped[0].lambda, r.stepped[2].lambda, 1e-9);
  EXPECT_NEAR(r.stepped[1].lambda, r.stepped[3].lambda, 1e-9);
}
