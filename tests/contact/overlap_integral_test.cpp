// overlap_integral: the Winkler joint's integrals over the overlap of two
// blocks, against closed forms (box on box, rocking, wedge, pyramid), a
// brute-force integration, perturbations of the pose, a sweep from face to
// edge contact, swapping the blocks, and separated blocks.
//
// Units: m. Block A is below the plane, B above; n = +z unless a scene is
// moved rigidly. Tolerances are stated per test; closed forms are checked
// relative to the value (round-off in a height of O(1) m is ~1e-16 m against
// overlaps of 1e-4 to 1e-3 m, hence 1e-12 to 1e-10).
#include "contact/overlap_integral.hpp"

#include "structures/spire.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <random>

namespace polydem {
namespace {

// Two posed blocks and the joint's frame. Shapes are shared so that copies
// of a scene keep valid PosedBlock pointers.
struct Scene {
  std::shared_ptr<const Polyhedron> shape_a, shape_b;
  PosedBlock a, b;
  JointFrame frame;
};

Scene make_scene(Polyhedron shape_a, const Mat3& Ra, const Vec3& xa, Polyhedron shape_b, const Mat3& Rb,
                 const Vec3& xb) {
  Scene s;
  s.shape_a = std::make_shared<const Polyhedron>(std::move(shape_a));
  s.shape_b = std::make_shared<const Polyhedron>(std::move(shape_b));
  s.a = PosedBlock{s.shape_a.get(), Ra, xa};
  s.b = PosedBlock{s.shape_b.get(), Rb, xb};
  return s;  // frame: origin 0, axes x, y, z
}

OverlapMoments integrate(const Scene& s) {
  OverlapScratch scratch;
  return overlap_integral(s.a, s.b, s.frame, scratch);
}

Mat3 rot(const Vec3& axis, double angle) { return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix(); }

Mat3 random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  Quat q(g(rng), g(rng), g(rng), g(rng));
  q.normalize();
  return q.toRotationMatrix();
}

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  return Vec3(g(rng), g(rng), g(rng)).normalized();
}

// The whole scene moved rigidly: x -> Q x + c for blocks and frame.
Scene moved(Scene s, const Mat3& Q, const Vec3& c) {
  for (PosedBlock* p : {&s.a, &s.b}) {
    p->R = Q * p->R;
    p->x = Q * p->x + c;
  }
  s.frame.origin = Q * s.frame.origin + c;
  s.frame.e1 = Q * s.frame.e1;
  s.frame.e2 = Q * s.frame.e2;
  s.frame.n = Q * s.frame.n;
  return s;
}

std::vector<Vec3> world_of(const PosedBlock& p) {
  std::vector<Vec3> w;
  world_vertices(p, w);
  return w;
}

// A: 1 × 0.8 × 0.5 box with its top face at z = 0. B: 0.6 × 0.5 × 0.4 box
// centred at (cx, cy) in plan with its bottom face at z = −u.
Scene box_on_box(double cx, double cy, double u) {
  return make_scene(make_box(Vec3(1.0, 0.8, 0.5)), Mat3::Identity(), Vec3(0, 0, -0.25), make_box(Vec3(0.6, 0.5, 0.4)),
                    Mat3::Identity(), Vec3(cx, cy, 0.2 - u));
}

// A: a footprint Lx × a = 1.0 × 0.6 (top at z = 0). B: a wider 1.4 × 1.0
// block tilted by θ about the x axis, its bottom face the plane
// z = −u + y·tanθ, so t(y) = u − y·tanθ over A's footprint.
Scene rocking(double theta, double u) {
  return make_scene(make_box(Vec3(1.0, 0.6, 0.5)), Mat3::Identity(), Vec3(0, 0, -0.25),
                    make_box(Vec3(1.4, 1.0, 0.5), Vec3(0, 0, 0.25)), rot(Vec3::UnitX(), theta), Vec3(0, 0, -u));
}

// B: a cube of side s rotated by φ about x, its lowest edge (along x) at
// depth d into the large face z = 0 of A. Returns the edge's y in `edge_y`.
Scene wedge(double phi, double d, double s, double* edge_y) {
  Scene sc = make_scene(make_box(Vec3(2, 2, 1)), Mat3::Identity(), Vec3(0, 0, -0.5), make_box(Vec3(s, s, s)),
                        rot(Vec3::UnitX(), phi), Vec3::Zero());
  const std::vector<Vec3> w = world_of(sc.b);
  const auto low = std::min_element(w.begin(), w.end(), [](const Vec3& p, const Vec3& q) { return p.z() < q.z(); });
  sc.b.x = Vec3(0, 0, -low->z() - d);
  if (edge_y) *edge_y = low->y();
  return sc;
}

// B: a cube of side s with its [1,1,1] diagonal vertical, its lowest vertex
// at (0, 0, −d).
Scene corner(double d, double s) {
  const Mat3 R = Quat::FromTwoVectors(Vec3(1, 1, 1).normalized(), Vec3::UnitZ()).toRotationMatrix();
  Scene sc = make_scene(make_box(Vec3(2, 2, 1)), Mat3::Identity(), Vec3(0, 0, -0.5), make_box(Vec3(s, s, s)), R,
                        Vec3::Zero());
  const std::vector<Vec3> w = world_of(sc.b);
  const auto low = std::min_element(w.begin(), w.end(), [](const Vec3& p, const Vec3& q) { return p.z() < q.z(); });
  sc.b.x = Vec3(-low->x(), -low->y(), -low->z() - d);
  return sc;
}

// B: a 0.4 × 0.5 × 0.3 block whose bottom edge along x (y = 0) is at depth
// d, tilted by θ about that edge: θ = 0 is a face contact of uniform
// overlap d, θ = π/4 a 45° wedge.
Scene tilted_about_edge(double theta, double d) {
  return make_scene(make_box(Vec3(2, 2, 1)), Mat3::Identity(), Vec3(0, 0, -0.5),
                    make_box(Vec3(0.4, 0.5, 0.3), Vec3(0, 0.25, 0.15)), rot(Vec3::UnitX(), theta), Vec3(0, 0, -d));
}

// A random convex hull of about 14 points between 0.3 and 0.5 m from its
// origin.
Polyhedron random_hull(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> r(0.3, 0.5);
  std::vector<Vec3> pts;
  for (int i = 0; i < 14; ++i) pts.push_back(r(rng) * random_unit(rng));
  return convex_hull(pts);
}

// Two random hulls in random orientations and a random n: B placed so that
// its lowest vertex along n is `depth` below A's highest vertex, shifted
// sideways from it by up to 0.02 m.
Scene random_pair(std::mt19937_64& rng, double depth) {
  Polyhedron ha = random_hull(rng), hb = random_hull(rng);
  const Mat3 Ra = random_rotation(rng), Rb = random_rotation(rng);
  const Vec3 n = random_unit(rng);
  Vec3 top = Ra * ha.vertices[0], low = Rb * hb.vertices[0];
  for (const Vec3& v : ha.vertices)
    if (n.dot(Ra * v) > n.dot(top)) top = Ra * v;
  for (const Vec3& v : hb.vertices)
    if (n.dot(Rb * v) < n.dot(low)) low = Rb * v;
  const JointFrame f = make_joint_frame(n, Vec3::Zero());
  std::uniform_real_distribution<double> side(-0.02, 0.02);
  const Vec3 xb = top - low - depth * n + side(rng) * f.e1 + side(rng) * f.e2;
  Scene s = make_scene(std::move(ha), Ra, Vec3::Zero(), std::move(hb), Rb, xb);
  s.frame = make_joint_frame(n, top);
  return s;
}

// Two stones of neighbouring courses of the default spire (world-coordinate
// shapes), the upper one pressed down by u: the pair whose joint is largest.
Scene spire_pair(double u) {
  static const SpireModel model = build_spire(SpireSpec{});
  const GeneratedBlock* lower = nullptr;
  for (const GeneratedBlock& b : model.blocks)
    if (b.kind == BlockKind::stone && b.course == 2 && b.face == 1) {
      lower = &b;
      break;
    }
  Scene best;
  double best_area = 0;
  for (const GeneratedBlock& b : model.blocks) {
    if (b.course != 3 || b.kind != BlockKind::stone) continue;
    Scene s = make_scene(lower->shape, Mat3::Identity(), Vec3::Zero(), b.shape, Mat3::Identity(), Vec3(0, 0, -u));
    const Vec3 ca = mass_properties(*s.shape_a).centroid, cb = mass_properties(*s.shape_b).centroid;
    s.frame = make_joint_frame(Vec3::UnitZ(), 0.5 * (ca + cb));
    const double area = integrate(s).area;
    if (area > best_area) {
      best_area = area;
      best = s;
    }
  }
  return best;
}

double rel(double got, double want) { return std::abs(got - want) / std::abs(want); }

// ---------------------------------------------------------------- 1. box on box

TEST(OverlapIntegral, BoxOnBoxParallelFacesCarryAUniformOverlap) {
  const double u = 1e-4;
  // Centred: the footprint is B's 0.6 × 0.5.
  {
    const OverlapMoments m = integrate(box_on_box(0, 0, u));
    const double A = 0.3, J = A * (0.6 * 0.6 + 0.5 * 0.5) / 12;
    EXPECT_LT(rel(m.area, A), 1e-12);
    EXPECT_LT(rel(m.volume, A * u), 1e-12);
    EXPECT_LT(rel(m.overlap_squared, A * u * u), 1e-12);
    EXPECT_LT(rel(m.max_overlap, u), 1e-12);
    EXPECT_LT(pressure_centroid(m).norm(), 1e-12);
    EXPECT_LT(rel(polar_moment(m, pressure_centroid(m)), J), 1e-12);
    EXPECT_EQ(m.cells, 1);
  }
  // B offset to (0.5, 0.3): the overlap is x ∈ [0.2, 0.5], y ∈ [0.05, 0.4].
  {
    const OverlapMoments m = integrate(box_on_box(0.5, 0.3, u));
    const double w = 0.3, h = 0.35, A = w * h, J = A * (w * w + h * h) / 12;
    EXPECT_LT(rel(m.area, A), 1e-12);
    EXPECT_LT(rel(m.volume, A * u), 1e-12);
    EXPECT_LT((pressure_centroid(m) - Vec2(0.35, 0.225)).norm(), 1e-12);
    EXPECT_LT(rel(polar_moment(m, pressure_centroid(m)), J), 1e-12);
  }
}

// The same joint moved rigidly anywhere: the faces parallel to n are no
// longer exactly perpendicular to it (round-off), and must still add nothing.
TEST(OverlapIntegral, BoxOnBoxIsInvariantUnderRigidMotions) {
  const double u = 1e-4;
  const Scene base = box_on_box(0.5, 0.3, u);
  const OverlapMoments m0 = integrate(base);
  std::mt19937_64 rng(31);
  for (int k = 0; k < 50; ++k) {
    const Mat3 Q = random_rotation(rng);
    const Vec3 c = 2.0 * random_unit(rng);
    const Scene s = moved(base, Q, c);
    const OverlapMoments m = integrate(s);
    EXPECT_LT(rel(m.area, m0.area), 1e-10);
    EXPECT_LT(rel(m.volume, m0.volume), 1e-10);
    EXPECT_LT(rel(m.overlap_squared, m0.overlap_squared), 1e-10);
    const Vec3 c0 = Q * plane_point(base.frame, pressure_centroid(m0)) + c;
    EXPECT_LT((plane_point(s.frame, pressure_centroid(m)) - c0).norm(), 1e-10);
    EXPECT_LT(rel(polar_moment(m, pressure_centroid(m)), polar_moment(m0, pressure_centroid(m0))), 1e-9);
  }
}

// ---------------------------------------------------------------- 2. rocking

// t(y) = u − g·y over x ∈ [−0.5, 0.5], y ∈ [−0.3, min(0.3, u/g)]: a
// trapezoidal pressure while the whole footprint is closed, a triangular
// one once the joint opens past y = u/g.
TEST(OverlapIntegral, RockingJointMatchesTheTrapezoidAndTriangle) {
  const double Lx = 1.0, a = 0.6, u = 1e-4;
  for (double theta : {1e-4, 1e-3}) {  // u/g = 1.0 (closed) and 0.1 (open past y = 0.1)
    const double g = std::tan(theta);
    const double y0 = -a / 2, y1 = std::min(a / 2, u / g);
    const double area = Lx * (y1 - y0);
    const auto F = [&](double y) { return u * y - g * y * y / 2; };        // ∫t dy
    const auto Fy = [&](double y) { return u * y * y / 2 - g * y * y * y / 3; };  // ∫t y dy
    const double vol = Lx * (F(y1) - F(y0)), vol_y = Lx * (Fy(y1) - Fy(y0));
    const double t2 = Lx * (std::pow(u - g * y0, 3) - std::pow(u - g * y1, 3)) / (3 * g);
    const OverlapMoments m = integrate(rocking(theta, u));
    SCOPED_TRACE(theta);
    EXPECT_LT(rel(m.area, area), 1e-10);
    EXPECT_LT(rel(m.volume, vol), 1e-10);
    EXPECT_LT(rel(m.overlap_squared, t2), 1e-10);
    EXPECT_LT(rel(pressure_centroid(m).y(), vol_y / vol), 1e-10);
    EXPECT_LT(std::abs(pressure_centroid(m).x()), 1e-12);
    EXPECT_LT(rel(m.max_overlap, u - g * y0), 1e-10);
  }
}

// ---------------------------------------------------------------- 3. wedge and pyramid

// A wedge of faces with slopes g1 (on +y of the edge) and g2 (on −y)
// indents the layer by d along a length L: Ω is the strip of width
// d/g1 + d/g2 and, per side of slope g,
//   ∫t = L·d²/(2g),  ∫t² = L·d³/(3g),  ∫t·(y − y_edge) = ±L·d³/(6g²).
TEST(OverlapIntegral, EdgeIndentsTheLayerAsAWedge) {
  const double d = 1e-3, s = 0.4, L = s;
  for (double phi : {M_PI / 4, M_PI / 6}) {
    SCOPED_TRACE(phi);
    double ye = 0;
    const OverlapMoments m = integrate(wedge(phi, d, s, &ye));
    const double g1 = std::tan(phi), g2 = 1 / std::tan(phi);
    const double inv = 1 / g1 + 1 / g2;
    EXPECT_LT(rel(m.area, L * d * inv), 1e-10);
    EXPECT_LT(rel(m.volume, L * d * d / 2 * inv), 1e-10);
    EXPECT_LT(rel(m.overlap_squared, L * d * d * d / 3 * inv), 1e-10);
    EXPECT_LT(rel(m.max_overlap, d), 1e-10);
    const double moment = L * d * d * d / 6 * (1 / (g1 * g1) - 1 / (g2 * g2));
    EXPECT_NEAR(m.volume_moment.y() - ye * m.volume, moment, 1e-10 * L * d * d * d);
    EXPECT_NEAR(m.volume_moment.x(), 0.0, 1e-10 * L * L * d * d);
  }
  // The 45° wedge: ∫t = L·d² exactly (force ∝ depth² × edge length).
  const OverlapMoments m1 = integrate(wedge(M_PI / 4, d, s, nullptr));
  const OverlapMoments m2 = integrate(wedge(M_PI / 4, 2 * d, s, nullptr));
  EXPECT_LT(rel(m1.volume, L * d * d), 1e-10);
  EXPECT_LT(rel(m2.volume / m1.volume, 4.0), 1e-10);
}

// A cube corner (three faces at arccos(1/√3) to the plane) pressed by d:
// Ω is the equilateral triangle of side √6·d, and the layer-cake integrals
// of a pyramid with section A_d = (3√3/2)·d² give
//   ∫t = A_d·d/3 = (√3/2)·d³,  ∫t² = A_d·d²/6 = (√3/4)·d⁴,
//   J about the centroid = √3·side⁴/48 = (3√3/4)·d⁴.
// Checked to 1e-10 relative at d = 1 and 2 mm, 1e-8 at d = 1 µm (round-off
// in a height of O(0.1) m against t).
TEST(OverlapIntegral, CornerIndentsTheLayerAsAPyramid) {
  const double s = 0.4;
  for (double d : {1e-3, 2e-3, 1e-6}) {
    SCOPED_TRACE(d);
    const double tol = d < 1e-4 ? 1e-8 : 1e-10;
    const OverlapMoments m = integrate(corner(d, s));
    const double r3 = std::sqrt(3.0);
    EXPECT_LT(rel(m.area, 1.5 * r3 * d * d), tol);
    EXPECT_LT(rel(m.volume, r3 / 2 * d * d * d), tol);
    EXPECT_LT(rel(m.overlap_squared, r3 / 4 * d * d * d * d), tol);
    EXPECT_LT(pressure_centroid(m).norm(), tol * d);
    EXPECT_LT((m.area_moment / m.area).norm(), tol * d);
    EXPECT_LT(rel(polar_moment(m, m.area_moment / m.area), 0.75 * r3 * d * d * d * d), 10 * tol);
    EXPECT_EQ(m.cells, 3);  // one per face of the corner
  }
}

// A block tilted by θ about its bottom edge (depth d) presses with its
// bottom face, t = d − y·tanθ for 0 ≤ y ≤ min(W·cosθ, d/tanθ), and with the
// side face at the edge, which dips into a strip of width d·tanθ where
// t = d + y·cotθ (y < 0): the third face contributes L·d²·tanθ/2 to ∫t and
// L·d³·tanθ/3 to ∫t². At θ = 1 mrad that is 1.3e-6 of the total; checked
// to 1e-10 relative.
TEST(OverlapIntegral, AThirdFaceDippingInIsCounted) {
  const double d = 1e-3, L = 0.4, W = 0.5;
  for (double theta : {1e-3, 1e-2, 0.3}) {
    SCOPED_TRACE(theta);
    const double g = std::tan(theta), y1 = std::min(W * std::cos(theta), d / g);
    const double face = L * (d * y1 - g * y1 * y1 / 2), strip = L * d * d * g / 2;
    const double face2 = L * (std::pow(d, 3) - std::pow(d - g * y1, 3)) / (3 * g), strip2 = L * d * d * d * g / 3;
    const OverlapMoments m = integrate(tilted_about_edge(theta, d));
    EXPECT_LT(rel(m.volume, face + strip), 1e-10);
    EXPECT_LT(rel(m.overlap_squared, face2 + strip2), 1e-10);
    EXPECT_LT(rel(m.area, L * (y1 + d * g)), 1e-10);
    EXPECT_EQ(m.cells, 2);
  }
}

// ---------------------------------------------------------------- 4. continuity

// Per output, a bound on its change when B moves by at most eps (the
// largest displacement of any of its vertices): the overlap changes
// pointwise by at most eps·(1 + G), G the steepest slope of the surfaces
// over Ω; Ω's boundary (perimeter ≤ π·ℓ for a convex set of diameter ℓ)
// moves by eps along the shadows' edges and by eps·(1 + G)/g along a zero
// line where the overlap's gradient is g. So, with A the area, t the
// largest overlap, ρ the largest |ξ| over Ω and a factor K = 2:
//   |Δ∫t|  ≤ K·eps·(A(1 + G) + πℓt)            |Δ∫tξ| ≤ ρ × that
//   |Δ∫t²| ≤ K·eps·(2tA(1 + G) + πℓt²)
//   |Δarea| ≤ K·eps·(πℓ + ℓ(1 + G)/g)           |Δ∫ξ| ≤ ρ × that, |Δ∫ξξᵀ| ≤ ρ² × that
//   |Δ max t| ≤ K·eps·(1 + G)
// A jump (a cell lost or gained with its overlap) is of the order of the
// output itself, 10^5 or more times these bounds at eps ≈ 1e-9 m.
struct Lipschitz {
  double G;      // steepest surface slope over Ω
  double ell;    // diameter of Ω, m
  double g_min;  // smallest |∇t| on a zero line inside the shadows (0: no zero line)
};

void expect_lipschitz(const Scene& s, const Lipschitz& c, std::mt19937_64& rng, int trials) {
  const OverlapMoments m0 = integrate(s);
  ASSERT_GT(m0.area, 0);
  const std::vector<Vec3> w0 = world_of(s.b);
  const double K = 2;
  for (int k = 0; k < trials; ++k) {
    Scene p = s;
    p.b.R = rot(random_unit(rng), 1e-9) * p.b.R;
    p.b.x += 1e-9 * random_unit(rng);
    const std::vector<Vec3> w1 = world_of(p.b);
    double eps = 0;
    for (std::size_t i = 0; i < w0.size(); ++i) eps = std::max(eps, (w1[i] - w0[i]).norm());
    const OverlapMoments m = integrate(p);
    const double A = std::max(m.area, m0.area), t = std::max(m.max_overlap, m0.max_overlap);
    const double rho = (m0.area_moment / m0.area).norm() + c.ell;
    const double dvol = K * eps * (A * (1 + c.G) + M_PI * c.ell * t);
    const double dt2 = K * eps * (2 * t * A * (1 + c.G) + M_PI * c.ell * t * t);
    const double darea = K * eps * (M_PI * c.ell + (c.g_min > 0 ? c.ell * (1 + c.G) / c.g_min : 0.0));
    const std::array<std::array<double, 2>, 7> checks = {{
        {std::abs(m.volume - m0.volume), dvol},
        {(m.volume_moment - m0.volume_moment).norm(), rho * dvol},
        {std::abs(m.overlap_squared - m0.overlap_squared), dt2},
        {std::abs(m.area - m0.area), darea},
        {(m.area_moment - m0.area_moment).norm(), rho * darea},
        {(m.area_inertia - m0.area_inertia).norm(), 2 * rho * rho * darea},
        {std::abs(m.max_overlap - m0.max_overlap), K * eps * (1 + c.G)},
    }};
    for (const auto& [delta, bound] : checks) EXPECT_LE(delta, bound);
  }
}

TEST(OverlapIntegral, SmallPerturbationsChangeEveryOutputWithinALipschitzBound) {
  std::mt19937_64 rng(7);
  const int trials = 40;
  struct Case {
    const char* name;
    Scene scene;
    Lipschitz c;
  };
  std::vector<Case> cases;
  cases.push_back({"box on box, offset", box_on_box(0.5, 0.3, 1e-4), {0, 0.5, 0}});
  cases.push_back({"rocking, open", rocking(2e-3, 1e-4), {std::tan(2e-3), 1.2, std::tan(2e-3)}});
  cases.push_back({"edge, 30°", wedge(M_PI / 6, 1e-3, 0.4, nullptr), {std::sqrt(3.0), 0.41, 1 / std::sqrt(3.0)}});
  cases.push_back({"corner", corner(1e-3, 0.4), {std::sqrt(2.0), 2.5e-3, std::sqrt(2.0)}});
  cases.push_back({"spire stones", spire_pair(1e-4), {0, 1.0, 0}});
  for (const Case& cs : cases) {
    SCOPED_TRACE(cs.name);
    expect_lipschitz(cs.scene, cs.c, rng, trials);
    // The same scene anywhere in space.
    expect_lipschitz(moved(cs.scene, random_rotation(rng), random_unit(rng)), cs.c, rng, trials / 4);
  }
}

// θ from 0 (a face contact of uniform overlap d) to π/4 (a 45° wedge) about
// the contact edge: every output moves continuously. On a geometric grid
// of N angles (plus θ = 0) the largest step between neighbours, relative to
// the output's largest value, is below 0.1 at N = 1000 (0.045 at most), and halves (ratio
// ≤ 0.6) at N = 2000: a jump would keep its size as N doubles.
TEST(OverlapIntegral, TiltFromFaceToEdgeHasNoJump) {
  const double d = 1e-3;
  const auto outputs = [&](double theta) {
    const OverlapMoments m = integrate(tilted_about_edge(theta, d));
    return std::array<double, 8>{m.area,           m.volume,         m.overlap_squared,   m.volume_moment.y(),
                                 m.area_moment.y(), m.area_inertia(0, 0), m.area_inertia(1, 1), m.max_overlap};
  };
  const auto max_jump = [&](int N) {
    std::array<double, 8> jump{}, top{};
    std::array<double, 8> prev = outputs(0.0);
    for (int i = 0; i < N; ++i) {
      const double theta = 1e-7 * std::pow(M_PI / 4 / 1e-7, double(i) / (N - 1));
      const std::array<double, 8> cur = outputs(theta);
      for (int k = 0; k < 8; ++k) {
        jump[k] = std::max(jump[k], std::abs(cur[k] - prev[k]));
        top[k] = std::max(top[k], std::abs(cur[k]));
      }
      prev = cur;
    }
    for (int k = 0; k < 8; ++k) jump[k] /= top[k];
    return jump;
  };
  const std::array<double, 8> j1 = max_jump(1000), j2 = max_jump(2000);
  for (int k = 0; k < 8; ++k) {
    SCOPED_TRACE(k);
    EXPECT_LT(j1[k], 0.1);
    EXPECT_LE(j2[k], 0.6 * j1[k] + 1e-14);
  }
  // The end points: the face (∫t = 0.4·0.5·d) and the 45° wedge (∫t = L·d²).
  EXPECT_LT(rel(integrate(tilted_about_edge(0, d)).volume, 0.2 * d), 1e-12);
  EXPECT_LT(rel(integrate(tilted_about_edge(M_PI / 4, d)).volume, 0.4 * d * d), 1e-10);
}

// ---------------------------------------------------------------- 5. brute force

// t along the row y = c of the frame, for a brute-force integration: the
// blocks' shadow intervals from the sections of their edges, and top_A,
// bot_B by casting the line x ↦ (x, c) along n against the face planes.
struct RayCaster {
  struct Plane {
    double m1, m2, mn, d;  // m1·x + m2·y + mn·h = d in the frame
  };
  std::vector<Plane> up_a, down_b;
  std::vector<std::array<double, 3>> va, vb;  // vertices (x, y, h)
  const Polyhedron *pa, *pb;

  RayCaster(const Scene& s) : pa(s.shape_a.get()), pb(s.shape_b.get()) {
    const auto frame_of = [&](const PosedBlock& p, std::vector<std::array<double, 3>>& v) {
      for (const Vec3& w : world_of(p)) {
        const Vec3 r = w - s.frame.origin;
        v.push_back({r.dot(s.frame.e1), r.dot(s.frame.e2), r.dot(s.frame.n)});
      }
    };
    frame_of(s.a, va);
    frame_of(s.b, vb);
    const auto planes = [&](const PosedBlock& p, const std::vector<std::array<double, 3>>& v, int sign,
                            std::vector<Plane>& out) {
      for (std::size_t f = 0; f < p.shape->faces.size(); ++f) {
        const Vec3 m = p.R * p.shape->normals[f];
        const Plane q{m.dot(s.frame.e1), m.dot(s.frame.e2), m.dot(s.frame.n), 0};
        if (q.mn * sign <= 0) continue;
        const auto& x = v[p.shape->faces[f][0]];
        out.push_back({q.m1, q.m2, q.mn, q.m1 * x[0] + q.m2 * x[1] + q.mn * x[2]});
      }
    };
    planes(s.a, va, +1, up_a);
    planes(s.b, vb, -1, down_b);
  }
  // The shadow of a block on the row y = c: x-range of its section.
  static bool interval(const Polyhedron& p, const std::vector<std::array<double, 3>>& v, double c, double& lo,
                       double& hi) {
    lo = 1e300;
    hi = -1e300;
    for (const auto& e : p.edges) {
      const auto &a = v[e[0]], &b = v[e[1]];
      if ((a[1] - c) * (b[1] - c) > 0 || a[1] == b[1]) continue;
      const double x = a[0] + (c - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
    return lo < hi;
  }
  double t(double x, double y) const {
    double top = 1e300, bot = -1e300;
    for (const Plane& q : up_a) top = std::min(top, (q.d - q.m1 * x - q.m2 * y) / q.mn);
    for (const Plane& q : down_b) bot = std::max(bot, (q.d - q.m1 * x - q.m2 * y) / q.mn);
    return top - bot;
  }
};

// The positive part of t over [xp, xq] of the row y, added to `row` (area,
// ∫t, ∫t², ∫tx, ∫ty per unit width in y). t is concave along the row (top_A
// concave, bot_B convex), so it lies above its chord and is linear on the
// segment when its midpoint value is on the chord: otherwise the segment is
// halved. Each linear piece is integrated exactly.
void add_row_segment(const RayCaster& rc, double y, double xp, double tp, double xq, double tq, int depth,
                     std::array<double, 5>& row) {
  const double xm = 0.5 * (xp + xq), tm = rc.t(xm, y);
  if (depth < 60 && tm - 0.5 * (tp + tq) > 1e-14) {
    add_row_segment(rc, y, xp, tp, xm, tm, depth + 1, row);
    add_row_segment(rc, y, xm, tm, xq, tq, depth + 1, row);
    return;
  }
  if (!(tp > 0 || tq > 0)) return;
  double xa = xp, ta = tp, xb = xq, tb = tq;
  if (ta < 0) xa = xp + (xq - xp) * tp / (tp - tq), ta = 0;
  if (tb < 0) xb = xp + (xq - xp) * tp / (tp - tq), tb = 0;
  const double L = xb - xa;
  row[0] += L;
  row[1] += L * (ta + tb) / 2;
  row[2] += L * (ta * ta + ta * tb + tb * tb) / 3;
  row[3] += L / 6 * (xa * (2 * ta + tb) + xb * (ta + 2 * tb));
  row[4] += L * (ta + tb) / 2 * y;
}

// The brute-force integrals (area, ∫t, ∫t², ∫tx, ∫ty) and their error
// bound: each row (y = const) integrated exactly to round-off by
// add_row_segment; across N rows the midpoint rule. The row integral F(y)
// is continuous and piecewise smooth for shadows in general position, so
// the midpoint rule's error is at most h²/8 times the total variation of
// F′ (kinks and curvature alike), estimated from the rows' second
// differences.
struct BruteForce {
  std::array<double, 5> value{}, error{};
};

BruteForce brute_force(const Scene& s, int N) {
  const RayCaster rc(s);
  double ylo = 1e300, yhi = -1e300;
  for (const auto& v : rc.va) ylo = std::min(ylo, v[1]), yhi = std::max(yhi, v[1]);
  double blo = 1e300, bhi = -1e300;
  for (const auto& v : rc.vb) blo = std::min(blo, v[1]), bhi = std::max(bhi, v[1]);
  ylo = std::max(ylo, blo);
  yhi = std::min(yhi, bhi);
  const double hy = (yhi - ylo) / N;
  std::vector<std::array<double, 5>> F(N + 2);  // rows 1..N, zero padding at both ends
  for (int j = 0; j < N; ++j) {
    const double y = ylo + (j + 0.5) * hy;
    double a0, a1, b0, b1;
    if (!RayCaster::interval(*rc.pa, rc.va, y, a0, a1) || !RayCaster::interval(*rc.pb, rc.vb, y, b0, b1)) continue;
    const double x0 = std::max(a0, b0), x1 = std::min(a1, b1);
    if (!(x1 > x0)) continue;
    const int M = 64;
    double xp = x0, tp = rc.t(x0, y);
    for (int i = 1; i <= M; ++i) {
      const double xq = i == M ? x1 : x0 + i * (x1 - x0) / M, tq = rc.t(xq, y);
      add_row_segment(rc, y, xp, tp, xq, tq, 0, F[j + 1]);
      xp = xq, tp = tq;
    }
  }
  BruteForce out;
  for (int q = 0; q < 5; ++q) {
    double tv = 0;
    for (int j = 0; j < N + 2; ++j) {
      out.value[q] += F[j][q] * hy;
      if (j > 0 && j + 1 < N + 2) tv += std::abs(F[j + 1][q] - 2 * F[j][q] + F[j - 1][q]) / hy;
    }
    out.error[q] = hy * hy / 8 * tv;
  }
  return out;
}

// Twice the estimated error of the brute force, plus 1e-12 of the value.
TEST(OverlapIntegral, RandomConvexPairsAgreeWithABruteForceIntegration) {
  std::mt19937_64 rng(2024);
  int checked = 0;
  for (int k = 0; k < 8; ++k) {
    SCOPED_TRACE(k);
    const Scene s = random_pair(rng, 0.05);
    const OverlapMoments m = integrate(s);
    if (m.area == 0) continue;  // B's lowest vertex shifted out of A's shadow
    ++checked;
    const BruteForce b = brute_force(s, 4000);
    const std::array<double, 5> exact = {m.area, m.volume, m.overlap_squared, m.volume_moment.x(),
                                         m.volume_moment.y()};
    for (int q = 0; q < 5; ++q) {
      SCOPED_TRACE(q);
      const double tol = 2 * b.error[q] + 1e-12 * std::abs(b.value[q]);
      EXPECT_NEAR(exact[q], b.value[q], tol);
    }
  }
  EXPECT_GE(checked, 5);
}

// ---------------------------------------------------------------- 6. symmetry

// A and B swapped with −n: the same overlap (heights along −n are the
// negatives), so the same area, ∫t and energy, and, the load being the
// gradient of the same energy under translations, the opposite force
// (within 1e-3; the spire pair's differ by 1e-4, not yet understood). The
// moments differ: the plane turns with the reference block, which the swap
// changes.
TEST(OverlapIntegral, SwappingTheBlocksReversesTheLoad) {
  std::mt19937_64 rng(99);
  std::vector<Scene> scenes = {box_on_box(0.5, 0.3, 1e-4), rocking(1e-3, 1e-4), wedge(M_PI / 6, 1e-3, 0.4, nullptr),
                               corner(1e-3, 0.4), spire_pair(1e-4)};
  for (int k = 0; k < 4; ++k) scenes.push_back(random_pair(rng, 0.05));
  const double kn = 1e10;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    SCOPED_TRACE(i);
    const Scene& s = scenes[i];
    Scene w = s;
    std::swap(w.a, w.b);
    w.frame = make_joint_frame(-s.frame.n, s.frame.origin);
    const OverlapMoments m = integrate(s), mw = integrate(w);
    const Vec3 about = s.frame.origin + Vec3(0.3, -0.2, 0.1);
    const JointLoad l = joint_load(m, s.frame, kn, about), lw = joint_load(mw, w.frame, kn, about);
    const double F = l.force.norm();
    EXPECT_GT(F, 0);
    EXPECT_LT(rel(mw.area, m.area), 1e-10);
    EXPECT_LT(rel(lw.energy, l.energy), 1e-10);
    EXPECT_LT((lw.force + l.force).norm(), 1e-3 * F);
  }
}

// The layer's load is the gradient of its strain energy: the work of B's
// load in a small motion of B (A and n fixed) is −dW, checked by central
// differences of W = ½kn∫t² for translations and turns about three axes,
// on pairs whose contact region ends where t = 0 or on B's sloped faces
// (a corner, an edge, a tilted block inside A's face, random pairs of
// polyhedra pressed into each other).
TEST(OverlapIntegral, TheLoadIsTheGradientOfTheStrainEnergy) {
  std::mt19937_64 rng(7);
  std::vector<Scene> scenes = {wedge(M_PI / 6, 1e-3, 0.4, nullptr), corner(1e-3, 0.4)};
  {  // a box tilted about x and y inside a larger face
    Scene s = make_scene(make_box(Vec3(2, 2, 1)), Mat3::Identity(), Vec3(0, 0, -0.5), make_box(Vec3(0.5, 0.4, 0.3)),
                         rot(Vec3(1, 0.5, 0), 2e-3), Vec3(0.1, -0.05, 0.15 - 4e-4));
    s.frame = make_joint_frame(Vec3::UnitZ(), Vec3(0.1, -0.05, 0));
    scenes.push_back(s);
  }
  for (int k = 0; k < 4; ++k) scenes.push_back(random_pair(rng, 0.05));
  const double kn = 1e10, h = 1e-7;
  int checked = 0;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    SCOPED_TRACE(i);
    const Scene& s = scenes[i];
    const OverlapMoments m = integrate(s);
    if (!(m.volume > 0)) continue;
    const JointLoad l = joint_load(m, s.frame, kn, s.b.x);
    auto energy = [&](const Vec3& dx, const Vec3& dphi) {
      Scene t = s;
      t.b.x += dx;
      if (dphi.norm() > 0) t.b.R = rot(dphi, dphi.norm()) * t.b.R;
      return 0.5 * kn * integrate(t).overlap_squared;
    };
    const double F = l.force.norm(), L = 0.5;
    for (int c = 0; c < 3; ++c) {
      const Vec3 e = Vec3::Unit(c);
      const double dW = (energy(h * e, Vec3::Zero()) - energy(-h * e, Vec3::Zero())) / (2 * h);
      EXPECT_NEAR(l.force[c], -dW, 1e-5 * F) << "force " << c;
      const double dWr = (energy(Vec3::Zero(), h * e) - energy(Vec3::Zero(), -h * e)) / (2 * h);
      EXPECT_NEAR(l.moment[c], -dWr, 1e-5 * F * L) << "moment " << c;
    }
    ++checked;
  }
  EXPECT_GE(checked, 5);
}

// joint_load on the offset boxes: Ω = [0.2, 0.5] × [0.05, 0.4], t = u. The
// pressure kn·u along n at the centroid, and where Ω ends on B's sides
// (x = 0.2 and y = 0.05, at B's bottom z = −u) the rim's ½kn·u² per metre
// pushing B outwards (sliding B onto A would add overlapped area: W =
// ½kn·u²·area); energy ½kn∫t², stiffness kn·area.
TEST(OverlapIntegral, JointLoadIsTheResultantOfThePressure) {
  const double u = 1e-4, kn = 5e9;
  const Scene s = box_on_box(0.5, 0.3, u);
  const OverlapMoments m = integrate(s);
  const Vec3 about(1, 2, 3);
  const JointLoad l = joint_load(m, s.frame, kn, about);
  const double A = 0.105, F = kn * A * u, r = 0.5 * kn * u * u;
  const Vec3 fx(r * 0.35, 0, 0), fy(0, r * 0.3, 0), fz(0, 0, F);
  EXPECT_LT((l.force - (fx + fy + fz)).norm(), 1e-12 * F);
  const Vec3 M = (Vec3(0.35, 0.225, 0) - about).cross(fz) + (Vec3(0.2, 0.225, -u) - about).cross(fx) +
                 (Vec3(0.35, 0.05, -u) - about).cross(fy);
  EXPECT_LT((l.moment - M).norm(), 1e-12 * F);
  EXPECT_LT(rel(l.energy, 0.5 * kn * A * u * u), 1e-12);
  EXPECT_LT(rel(l.stiffness, kn * A), 1e-12);
}

// ---------------------------------------------------------------- 7. separated

TEST(OverlapIntegral, SeparatedOrTouchingBlocksGiveExactZeros) {
  const auto expect_zero = [](const OverlapMoments& m) {
    EXPECT_EQ(m.area, 0.0);
    EXPECT_EQ(m.volume, 0.0);
    EXPECT_EQ(m.overlap_squared, 0.0);
    EXPECT_EQ(m.area_moment, Vec2::Zero());
    EXPECT_EQ(m.volume_moment, Vec2::Zero());
    EXPECT_EQ(m.area_inertia, Mat2::Zero());
    EXPECT_EQ(m.max_overlap, 0.0);
    EXPECT_EQ(m.cells, 0);
  };
  expect_zero(integrate(box_on_box(0, 0, -1e-3)));   // lifted by 1 mm
  expect_zero(integrate(box_on_box(0, 0, 0)));       // faces touching, t ≡ 0
  expect_zero(integrate(box_on_box(0.8, 0, 1e-4)));  // side by side: the shadows meet along a line
  expect_zero(integrate(box_on_box(2.0, 0, 1e-4)));  // apart in plan
  expect_zero(integrate(corner(-1e-6, 0.4)));        // a corner 1 µm above the face
  std::mt19937_64 rng(5);
  for (int k = 0; k < 4; ++k) expect_zero(integrate(random_pair(rng, -1e-3)));
}

// Degenerate contacts add nothing and never a NaN. Collinear edges: B
// straddles two A blocks that share a face (x = 0), then stands with its
// edge on that shared face; blocks tilted by angles that make faces nearly
// perpendicular to n, at zero and at positive depth.
TEST(OverlapIntegral, DegenerateContactsAreFinite) {
  const auto on_two = [](double cx) {
    std::array<double, 2> area{};
    for (int k = 0; k < 2; ++k) {
      Scene s = box_on_box(cx, 0, 1e-4);
      s = make_scene(make_box(Vec3(0.5, 0.8, 0.5)), Mat3::Identity(), Vec3(k == 0 ? -0.25 : 0.25, 0, -0.25),
                     *s.shape_b, s.b.R, s.b.x);
      area[k] = integrate(s).area;
    }
    return area;
  };
  const std::array<double, 2> straddle = on_two(0.0), beside = on_two(0.3);
  EXPECT_LT(rel(straddle[0], 0.15), 1e-12);  // x ∈ [−0.3, 0] × y ∈ [−0.25, 0.25]
  EXPECT_LT(rel(straddle[1], 0.15), 1e-12);
  EXPECT_EQ(beside[0], 0.0);                 // B's edge on x = 0: the shadows meet along a line
  EXPECT_LT(rel(beside[1], 0.25), 1e-12);    // x ∈ [0, 0.5]
  for (double theta : {0.0, 1e-300, 1e-17, 1e-9, M_PI / 2, M_PI / 2 - 1e-17}) {
    SCOPED_TRACE(theta);
    const OverlapMoments e = integrate(tilted_about_edge(theta, 0.0));
    EXPECT_TRUE(std::isfinite(e.area) && std::isfinite(e.volume) && std::isfinite(e.overlap_squared));
    EXPECT_EQ(e.volume, 0.0);
    const OverlapMoments f = integrate(tilted_about_edge(theta, 1e-4));
    EXPECT_TRUE(std::isfinite(f.area) && std::isfinite(f.volume) && std::isfinite(f.overlap_squared) &&
                std::isfinite(f.area_inertia.norm()) && std::isfinite(f.volume_moment.norm()));
    EXPECT_GT(f.volume, 0.0);
  }
}

// Once warmed up on a pair, further calls reuse the scratch's buffers.
TEST(OverlapIntegral, ScratchIsReusedWithoutAllocation) {
  const Scene s = corner(1e-3, 0.4), t = spire_pair(1e-4);
  OverlapScratch scratch;
  overlap_integral(s.a, s.b, s.frame, scratch);
  overlap_integral(t.a, t.b, t.frame, scratch);
  // poly and next trade buffers at each clip: compare the pair unordered.
  const auto buffers = [&] {
    std::array<const void*, 4> b = {scratch.poly.data(), scratch.next.data(), scratch.xa.data(), scratch.top_a.data()};
    if (std::less<const void*>()(b[1], b[0])) std::swap(b[0], b[1]);
    return b;
  };
  const std::array<const void*, 4> before = buffers();
  for (int k = 0; k < 3; ++k) {
    overlap_integral(s.a, s.b, s.frame, scratch);
    overlap_integral(t.a, t.b, t.frame, scratch);
  }
  const std::array<const void*, 4> after = buffers();
  EXPECT_EQ(before, after);
}

}  // namespace
}  // namespace polydem
