// The arch generator: voussoir volumes against closed forms computed here
// (the polygonal ring: n · ½ sin(β/n) ((R+t)² − R²)), the supports' against
// their polygons' areas, no overlaps (a separating face plane for every pair),
// every joint shared face to face, symmetry, placement, and the spec errors.
#include "structures/arch.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace polydem {
namespace {

constexpr double kPi = std::numbers::pi;

double volume(const Polyhedron& p) { return mass_properties(p).volume; }

double total(const ArchModel& m, BlockKind kind) {
  double v = 0;
  for (const auto& b : m.blocks)
    if (b.kind == kind) v += volume(b.shape);
  return v;
}

int count(const ArchModel& m, BlockKind kind) {
  int c = 0;
  for (const auto& b : m.blocks) c += b.kind == kind;
  return c;
}

// A face plane of a with every vertex of b on or outside it.
bool separated_by_a_face(const Polyhedron& a, const Polyhedron& b, double tol) {
  for (std::size_t f = 0; f < a.faces.size(); ++f) {
    bool all_out = true;
    for (const Vec3& v : b.vertices)
      if (a.normals[f].dot(v) - a.offsets[f] < -tol) {
        all_out = false;
        break;
      }
    if (all_out) return true;
  }
  return false;
}

// Convex prisms of one extrusion direction overlap iff no face plane of
// either separates them (the separating axes of two such prisms are their
// faces' normals): every pair must be separated.
void expect_no_overlap(const ArchModel& m) {
  const double tol = 1e-9;
  for (std::size_t i = 0; i < m.blocks.size(); ++i)
    for (std::size_t j = i + 1; j < m.blocks.size(); ++j)
      EXPECT_TRUE(separated_by_a_face(m.blocks[i].shape, m.blocks[j].shape, tol) ||
                  separated_by_a_face(m.blocks[j].shape, m.blocks[i].shape, tol))
          << m.blocks[i].name << " overlaps " << m.blocks[j].name;
}

// Area of the face of a lying on the plane of a face of b with the opposite
// normal (their shared joint), 0 if none.
double shared_face_area(const Polyhedron& a, const Polyhedron& b) {
  double best = 0;
  for (std::size_t f = 0; f < a.faces.size(); ++f)
    for (std::size_t g = 0; g < b.faces.size(); ++g)
      if (a.normals[f].dot(b.normals[g]) < -1 + 1e-12 && std::abs(a.offsets[f] + b.offsets[g]) < 1e-12)
        best = std::max(best, face_area(a, static_cast<int>(f)));
  return best;
}

// The polygonal ring of a circular arch: n voussoirs of angle β/n.
double ring_area(double R, double t, double beta, int n) {
  return n * 0.5 * std::sin(beta / n) * ((R + t) * (R + t) - R * R);
}
// An odd ring of a vault: n − 1 whole voussoirs and two halves.
double odd_ring_area(double R, double t, double beta, int n) {
  return (n - 1) * 0.5 * std::sin(beta / n) * ((R + t) * (R + t) - R * R) +
         2 * 0.5 * std::sin(beta / (2 * n)) * ((R + t) * (R + t) - R * R);
}

TEST(Arch, SemicircleVoussoirsFillThePolygonalRing) {
  ArchSpec s;
  s.radius = 2.0;
  s.thickness = 0.3;
  s.depth = 0.8;
  s.voussoirs = 9;
  const ArchModel m = build_arch(s);
  EXPECT_EQ(count(m, BlockKind::voussoir), 9);
  EXPECT_EQ(count(m, BlockKind::abutment), 2);
  EXPECT_EQ(m.blocks.size(), 11u);
  EXPECT_NEAR(m.profile.span, 4.0, 1e-12);
  EXPECT_NEAR(m.profile.rise, 2.0, 1e-12);
  const double expected = ring_area(2.0, 0.3, kPi, 9) * 0.8;
  EXPECT_NEAR(total(m, BlockKind::voussoir), expected, 1e-9 * expected);
  // The abutments: pier_width (2 t) by pier_height (span/2), flat on top.
  const double abut = 2 * (0.6 * 2.0 * 0.8);
  EXPECT_NEAR(total(m, BlockKind::abutment), abut, 1e-9 * abut);
  for (const auto& b : m.blocks) EXPECT_NO_THROW(validate(b.shape)) << b.name;
  expect_no_overlap(m);
  // Neighbours share their whole joint: t by the depth.
  for (int i = 0; i + 1 < 9; ++i)
    EXPECT_NEAR(shared_face_area(m.blocks[i].shape, m.blocks[i + 1].shape), 0.3 * 0.8, 1e-9) << i;
  EXPECT_NEAR(shared_face_area(m.blocks[0].shape, m.blocks[9].shape), 0.3 * 0.8, 1e-9);   // left springing
  EXPECT_NEAR(shared_face_area(m.blocks[8].shape, m.blocks[10].shape), 0.3 * 0.8, 1e-9);  // right springing
  // Mirror symmetry x -> −x, to the last bit: voussoir i and n−1−i.
  for (int i = 0; i < 9; ++i) {
    const auto& a = m.blocks[i].shape;
    const auto& b = m.blocks[8 - i].shape;
    for (const Vec3& v : a.vertices) {
      const Vec3 w(-v.x(), v.y(), v.z());
      EXPECT_TRUE(std::any_of(b.vertices.begin(), b.vertices.end(), [&](const Vec3& u) { return u == w; }))
          << "voussoir " << i;
    }
  }
  EXPECT_EQ(m.blocks[0].name, "voussoir00");
  EXPECT_EQ(m.blocks[9].name, "abutment0");
  EXPECT_EQ(m.blocks[10].name, "abutment1");
}

TEST(Arch, EveryEmbraceAndShapeIsExact) {
  struct Case {
    ArchShape shape;
    double embrace, span, rise, pointedness;
    int n;
    ArchSupports supports;
  };
  const Case cases[] = {
      {ArchShape::circular, 180, 4, 0, 1, 3, ArchSupports::abutments},
      {ArchShape::circular, 120, 4, 0, 1, 7, ArchSupports::piers},
      {ArchShape::circular, 60, 4, 0, 1, 5, ArchSupports::abutments},
      {ArchShape::circular, 250, 4, 0, 1, 12, ArchSupports::abutments},
      {ArchShape::circular, 359, 1, 0, 1, 40, ArchSupports::abutments},
      {ArchShape::segmental, 0, 4, 1, 1, 9, ArchSupports::piers},
      {ArchShape::pointed, 0, 4, 0, 1, 8, ArchSupports::base},
      {ArchShape::pointed, 0, 4, 0, 1, 9, ArchSupports::piers},
      {ArchShape::pointed, 0, 4, 0, 0.3, 10, ArchSupports::abutments},
      {ArchShape::pointed, 0, 4, 0, 2, 11, ArchSupports::abutments},
  };
  for (const Case& c : cases) {
    ArchSpec s;
    s.shape = c.shape;
    s.embrace = c.embrace;
    s.span = c.span;
    s.rise = c.rise;
    s.pointedness = c.pointedness;
    s.voussoirs = c.n;
    s.supports = c.supports;
    s.thickness = 0.25;
    s.depth = 0.6;
    SCOPED_TRACE("shape " + std::to_string(static_cast<int>(c.shape)) + " n " + std::to_string(c.n) + " embrace " +
                 std::to_string(c.embrace));
    const ArchModel m = build_arch(s);
    const ArchProfile& p = m.profile;
    EXPECT_EQ(count(m, BlockKind::voussoir), c.n);
    double expected = 0;
    if (c.shape == ArchShape::pointed) {
      // The outline through the joints' ends, by the shoelace formula.
      std::vector<Vec2> outline;
      for (int j = 0; j <= c.n; ++j) outline.push_back(arch_joint(s, p, j).intrados);
      for (int j = c.n; j >= 0; --j) outline.push_back(arch_joint(s, p, j).extrados);
      double a = 0;
      for (std::size_t i = 0; i < outline.size(); ++i) {
        const Vec2& u = outline[i];
        const Vec2& v = outline[(i + 1) % outline.size()];
        a += u.x() * v.y() - u.y() * v.x();
      }
      expected = 0.5 * a * s.depth;
      // The apex: the two arcs meet at x = 0, height √(R² − c²).
      const double cc = c.pointedness * c.span / 2, R = c.span / 2 + cc;
      EXPECT_NEAR(p.rise, std::sqrt(R * R - cc * cc), 1e-12);
    } else {
      const double beta = c.shape == ArchShape::segmental ? 4 * std::atan(2 * c.rise / c.span) : c.embrace * kPi / 180;
      const double R = c.shape == ArchShape::segmental ? (c.span * c.span / 4 + c.rise * c.rise) / (2 * c.rise)
                                                       : c.span / (2 * std::sin(beta / 2));
      EXPECT_NEAR(p.radius, R, 1e-12 * R);
      expected = ring_area(R, 0.25, beta, c.n) * s.depth;
    }
    EXPECT_NEAR(total(m, BlockKind::voussoir), expected, 1e-9 * expected);
    expect_no_overlap(m);
    // The end supports' top course: pier_width by its height, plus the
    // skewback's part above the springing line, less the springing joint's
    // triangle (w · t sin θ0 − ½ t² cos θ0 sin θ0).
    if (c.supports != ArchSupports::base) {
      const double th = p.springing_angle, t = 0.25;
      const double w = m.pier_width, h = m.pier_height;
      const double one = (w * h + w * t * std::sin(th) - 0.5 * t * t * std::cos(th) * std::sin(th)) * s.depth;
      const BlockKind k = c.supports == ArchSupports::piers ? BlockKind::pier : BlockKind::abutment;
      EXPECT_NEAR(total(m, k), 2 * one, 1e-9 * one);
    }
  }
}

TEST(Arch, VaultRingsAreStaggeredByHalfAVoussoir) {
  ArchSpec s;
  s.radius = 3.0;
  s.thickness = 0.4;
  s.voussoirs = 7;
  s.rings = 4;
  s.depth = 2.0;
  s.supports = ArchSupports::piers;
  s.pier_courses = 3;
  s.pier_height = 2.4;
  const ArchModel m = build_arch(s);
  // Rings 0 and 2: 7 voussoirs; rings 1 and 3: 8 (a half at each springing).
  EXPECT_EQ(count(m, BlockKind::voussoir), 7 + 8 + 7 + 8);
  EXPECT_EQ(count(m, BlockKind::pier), 2 * 3);
  EXPECT_EQ(count(m, BlockKind::base), 1);
  const double even = ring_area(3.0, 0.4, kPi, 7) * 0.5, odd = odd_ring_area(3.0, 0.4, kPi, 7) * 0.5;
  EXPECT_NEAR(total(m, BlockKind::voussoir), 2 * even + 2 * odd, 1e-9 * (even + odd));
  ASSERT_EQ(m.ring_area.size(), 4u);
  EXPECT_NEAR(m.ring_area[1] * 0.5, odd, 1e-9 * odd);
  // Piers: 2 × (w = 0.8) × 2.4 × 2.0, flat topped.
  EXPECT_NEAR(total(m, BlockKind::pier), 2 * 0.8 * 2.4 * 2.0, 1e-9);
  expect_no_overlap(m);
  // No joint runs through two neighbouring rings: the smallest block is half
  // a voussoir (never a sliver).
  double smallest = 1e300, largest = 0;
  for (const auto& b : m.blocks)
    if (b.kind == BlockKind::voussoir) {
      smallest = std::min(smallest, volume(b.shape));
      largest = std::max(largest, volume(b.shape));
    }
  EXPECT_GT(smallest, 0.49 * largest);
  EXPECT_EQ(m.blocks[7].name, "ring1_voussoir00");
  EXPECT_EQ(m.blocks[7].ring, 1);
  EXPECT_EQ(m.blocks[30].name, "pier0_course0");
}

TEST(Arch, ArcadeSharesItsInteriorPiers) {
  ArchSpec s;
  s.span = 3.0;
  s.thickness = 0.3;
  s.voussoirs = 9;
  s.spans = 2;
  s.supports = ArchSupports::piers;
  s.pier_width = 0.8;
  s.pier_height = 2.0;
  const ArchModel m = build_arch(s);
  EXPECT_EQ(count(m, BlockKind::voussoir), 18);
  EXPECT_EQ(count(m, BlockKind::pier), 3);
  EXPECT_NEAR(total(m, BlockKind::pier), 3 * 0.8 * 2.0 * 1.0, 1e-9);
  expect_no_overlap(m);
  // The middle pier carries the right springing of span 0 and the left of span 1.
  const Polyhedron* middle = nullptr;
  for (const auto& b : m.blocks)
    if (b.name == "pier1") middle = &b.shape;
  ASSERT_NE(middle, nullptr);
  EXPECT_NEAR(shared_face_area(m.blocks[8].shape, *middle), 0.3, 1e-9);
  EXPECT_NEAR(shared_face_area(m.blocks[9].shape, *middle), 0.3, 1e-9);
  EXPECT_EQ(m.blocks[9].name, "span1_voussoir00");
  // On one fixed base: the arches spring from the slab, pier_width apart.
  ArchSpec on_base = s;
  on_base.supports = ArchSupports::base;
  const ArchModel b = build_arch(on_base);
  EXPECT_EQ(count(b, BlockKind::base), 1);
  EXPECT_EQ(b.blocks.size(), 18u + 1);
  expect_no_overlap(b);
  EXPECT_NEAR(shared_face_area(b.blocks[8].shape, b.blocks[18].shape), 0.3, 1e-9);
  EXPECT_NEAR(shared_face_area(b.blocks[9].shape, b.blocks[18].shape), 0.3, 1e-9);
  // Segmental spans: the middle pier's top is a ridge of two skewbacks.
  s.shape = ArchShape::segmental;
  s.rise = 0.8;
  const ArchModel seg = build_arch(s);
  expect_no_overlap(seg);
  const double th = seg.profile.springing_angle, t = 0.3;
  const double interior = (0.8 * 2.0 + 0.8 * t * std::sin(th) - t * t * std::cos(th) * std::sin(th)) * 1.0;
  for (const auto& b : seg.blocks) {
    if (b.name == "pier1") {
      EXPECT_NEAR(volume(b.shape), interior, 1e-9 * interior);
    }
  }
}

TEST(Arch, PlacedAtItsOriginAlongItsDirection) {
  ArchSpec s;
  s.span = 4.0;
  s.thickness = 0.3;
  s.depth = 1.0;
  s.origin = Vec3(10, 20, 5);
  s.direction = Vec3(0, 2, 0);  // the span along +y
  const ArchModel m = build_arch(s);
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const auto& b : m.blocks)
    if (b.kind == BlockKind::voussoir)
      for (const Vec3& v : b.shape.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  EXPECT_NEAR(lo.y(), 20 - 2.3, 1e-12);
  EXPECT_NEAR(hi.y(), 20 + 2.3, 1e-12);
  EXPECT_NEAR(lo.x(), 10 - 0.5, 1e-12);
  EXPECT_NEAR(hi.x(), 10 + 0.5, 1e-12);
  EXPECT_NEAR(lo.z(), 5, 1e-12);
  EXPECT_NEAR(hi.z(), 5 + 2.3 * std::cos(kPi / 18), 1e-12);  // the keystone's flat extrados chord
}

void expect_spec_error(const ArchSpec& s, const std::string& field, const std::string& fragment) {
  try {
    build_arch(s);
    ADD_FAILURE() << "accepted; expected an error on " << field;
  } catch (const ArchSpecError& e) {
    EXPECT_EQ(e.field, field) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(Arch, BadSpecsNameTheirField) {
  ArchSpec s;
  s.span = 4;
  auto with = [&](auto change) {
    ArchSpec c = s;
    change(c);
    return c;
  };
  expect_spec_error(with([](ArchSpec& c) { c.voussoirs = 2; }), "voussoirs", "[3, 1000]");
  expect_spec_error(with([](ArchSpec& c) { c.thickness = 2.5; }), "thickness", "less than the intrados radius");
  expect_spec_error(with([](ArchSpec& c) { c.embrace = 360; }), "embrace", "(0, 360)");
  expect_spec_error(with([](ArchSpec& c) { c.embrace = 0; }), "embrace", "(0, 360)");
  expect_spec_error(with([](ArchSpec& c) { c.radius = 2; }), "radius", "not both");
  expect_spec_error(with([](ArchSpec& c) { c.shape = ArchShape::pointed, c.pointedness = 2.5; }), "pointedness",
                    "(0, 2]");
  expect_spec_error(with([](ArchSpec& c) { c.shape = ArchShape::pointed, c.pointedness = 0; }), "pointedness",
                    "(0, 2]");
  expect_spec_error(with([](ArchSpec& c) { c.shape = ArchShape::segmental, c.rise = 2; }), "rise", "span/2");
  expect_spec_error(with([](ArchSpec& c) { c.embrace = 120, c.supports = ArchSupports::base; }), "supports",
                    "horizontal springing");
  expect_spec_error(with([](ArchSpec& c) { c.embrace = 240, c.supports = ArchSupports::piers; }), "supports",
                    "horseshoe");
  expect_spec_error(with([](ArchSpec& c) { c.embrace = 240, c.pier_width = 1; }), "pier_width", "leave pier_width");
  expect_spec_error(with([](ArchSpec& c) { c.pier_width = 0.2; }), "pier_width", "at least");
  expect_spec_error(with([](ArchSpec& c) { c.spans = 2, c.pier_width = 0.5; }), "pier_width", "interior pier");
  expect_spec_error(with([](ArchSpec& c) { c.rings = 0; }), "rings", "[1, 200]");
  expect_spec_error(with([](ArchSpec& c) { c.direction = Vec3(0, 0, 1); }), "direction", "horizontal");
  expect_spec_error(with([](ArchSpec& c) { c.voussoirs = 999, c.rings = 10; }), "voussoirs", "at most 5000");
  expect_spec_error(with([](ArchSpec& c) { c.embrace = 300, c.pier_height = 0.1, c.thickness = 0.4; }),
                    "pier_height", "below the springing joint");
}

}  // namespace
}  // namespace polydem
