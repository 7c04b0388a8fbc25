// The arch builder: the profile, the joints along it, a quadrilateral per
// voussoir, the supports' polygons; every block a right prism of its convex
// polygon (make_prism), turned and moved into place. What the blocks are
// and why is at the top of structures/arch.hpp.
//
// Exactness: neighbouring voussoirs are built from the very same joint
// points (a(s), e(s) computed once per joint and reused), so the joint is the
// same segment for both; the springing joints are the supports' top faces in
// the same way. The left half of the arch is computed, the right half is its
// mirror image (x -> −x, exact in floating point), so the arch is symmetric to
// the last bit.
#include "structures/generator_text.hpp"
#include "structures/arch.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace polydem {

namespace {

using generator_text::num;
using generator_text::zero_padded;
using generator_text::digits_for;

constexpr double kPi = std::numbers::pi;

void require(bool ok, const char* field, const std::string& what) {
  if (!ok) throw ArchSpecError(field, what);
}

void require_positive(double v, const char* field) {
  require(std::isfinite(v) && v > 0, field, "must be > 0 and finite (got " + num(v) + ")");
}

// Joint positions of ring r: whole voussoirs, or shifted by half of one.
std::vector<double> ring_joints(int n, int ring) {
  std::vector<double> s;
  if (ring % 2 == 0) {
    for (int j = 0; j <= n; ++j) s.push_back(j);
  } else {
    s.push_back(0.0);
    for (int j = 0; j < n; ++j) s.push_back(j + 0.5);
    s.push_back(n);
  }
  return s;
}

// Drops repeated points and points on the line through their neighbours, so
// make_prism sees only corners (a flat skewback continues the support's top).
std::vector<Vec2> corners_only(const std::vector<Vec2>& in, double tol) {
  std::vector<Vec2> p;
  for (const Vec2& q : in)
    if (p.empty() || (q - p.back()).norm() > tol) p.push_back(q);
  while (p.size() > 1 && (p.front() - p.back()).norm() <= tol) p.pop_back();
  bool changed = true;
  while (changed && p.size() > 3) {
    changed = false;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec2& a = p[(i + p.size() - 1) % p.size()];
      const Vec2& b = p[i];
      const Vec2& c = p[(i + 1) % p.size()];
      const Vec2 u = b - a, v = c - b;
      if (std::abs(u.x() * v.y() - u.y() * v.x()) <= tol * (u.norm() + v.norm()) && u.dot(v) > 0) {
        p.erase(p.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
        break;
      }
    }
  }
  return p;
}

double shoelace(const std::vector<Vec2>& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2& u = p[i];
    const Vec2& v = p[(i + 1) % p.size()];
    a += u.x() * v.y() - u.y() * v.x();
  }
  return 0.5 * a;
}

}  // namespace

ArchProfile arch_profile(const ArchSpec& s) {
  ArchProfile p;
  require(s.voussoirs >= 3 && s.voussoirs <= 1000, "voussoirs",
          "must be in [3, 1000] (got " + std::to_string(s.voussoirs) + ")");
  require_positive(s.thickness, "thickness");
  require_positive(s.depth, "depth");
  switch (s.shape) {
    case ArchShape::circular: {
      require(std::isfinite(s.embrace) && s.embrace > 0 && s.embrace < 360, "embrace",
              "must be in (0, 360) degrees (got " + num(s.embrace) + ")");
      require(s.span > 0 || s.radius > 0, "span", "missing: a circular arch needs span or radius");
      require(!(s.span > 0 && s.radius > 0), "radius",
              "give span or radius, not both (the embrace relates them: span = 2 radius sin(embrace/2))");
      p.embrace = s.embrace * kPi / 180.0;
      const double half_sin = std::sin(0.5 * p.embrace);
      if (s.radius > 0) {
        require_positive(s.radius, "radius");
        p.radius = s.radius;
        p.span = 2.0 * s.radius * half_sin;
      } else {
        require_positive(s.span, "span");
        p.span = s.span;
        p.radius = s.span / (2.0 * half_sin);
      }
      p.centre_z = -p.radius * std::cos(0.5 * p.embrace);
      p.rise = p.radius + p.centre_z;
      p.springing_angle = 0.5 * kPi - 0.5 * p.embrace;
      break;
    }
    case ArchShape::segmental: {
      require_positive(s.span, "span");
      require(std::isfinite(s.rise) && s.rise > 0 && s.rise < 0.5 * s.span, "rise",
              "must be in (0, span/2 = " + num(0.5 * s.span) +
                  ") for a segmental arch (a semicircle is shape = \"circular\") (got " + num(s.rise) + ")");
      p.span = s.span;
      p.rise = s.rise;
      p.radius = (0.25 * s.span * s.span + s.rise * s.rise) / (2.0 * s.rise);
      p.embrace = 4.0 * std::atan(2.0 * s.rise / s.span);
      p.centre_z = s.rise - p.radius;
      p.springing_angle = 0.5 * kPi - 0.5 * p.embrace;
      break;
    }
    case ArchShape::pointed: {
      require_positive(s.span, "span");
      require(std::isfinite(s.pointedness) && s.pointedness > 0 && s.pointedness <= 2, "pointedness",
              "must be in (0, 2]: the centres' offset over half the span (1: equilateral) (got " +
                  num(s.pointedness) + ")");
      p.span = s.span;
      p.centre_offset = s.pointedness * 0.5 * s.span;
      p.radius = 0.5 * s.span + p.centre_offset;
      p.embrace = std::acos(p.centre_offset / p.radius);
      p.rise = std::sqrt(p.radius * p.radius - p.centre_offset * p.centre_offset);
      p.springing_angle = 0;
      break;
    }
  }
  require(p.span >= 1e-3 && p.span <= 1e5, s.shape == ArchShape::circular && s.radius > 0 ? "radius" : "span",
          "gives a span of " + num(p.span) + " m: spans from 1 mm to 100 km");
  require(s.depth <= 1e5, "depth", "must be at most 1e5 m (got " + num(s.depth) + ")");
  require(s.thickness >= 1e-6 * p.radius, "thickness",
          "must be at least a millionth of the intrados radius " + num(p.radius) + " m (got " + num(s.thickness) + ")");
  require(s.thickness < p.radius, "thickness",
          "must be less than the intrados radius " + num(p.radius) + " m (got " + num(s.thickness) + ")");
  return p;
}

ArchJoint arch_joint(const ArchSpec& spec, const ArchProfile& p, double s) {
  const int n = spec.voussoirs;
  const double t = spec.thickness;
  if (2.0 * s > n) {  // the right half: the mirror image of the left
    ArchJoint j = arch_joint(spec, p, n - s);
    j.intrados.x() = -j.intrados.x();
    j.extrados.x() = -j.extrados.x();
    return j;
  }
  ArchJoint j;
  if (s == 0) {  // the springing: exactly on the springing line
    const double c = std::cos(p.springing_angle), sn = std::sin(p.springing_angle);
    j.intrados = Vec2(-0.5 * p.span, 0.0);
    j.extrados = j.intrados + t * Vec2(-c, sn);
    return j;
  }
  const bool crown = 2.0 * s == n;
  if (spec.shape == ArchShape::pointed) {
    const double c = p.centre_offset, R = p.radius;
    if (crown) {
      j.intrados = Vec2(0.0, p.rise);
      j.extrados = Vec2(0.0, std::sqrt((R + t) * (R + t) - c * c));
      return j;
    }
    const double phi = kPi - (2.0 * s / n) * p.embrace;
    j.intrados = Vec2(c + R * std::cos(phi), R * std::sin(phi));
    j.extrados = Vec2(c + (R + t) * std::cos(phi), (R + t) * std::sin(phi));
    return j;
  }
  const double th = 0.5 * kPi + 0.5 * p.embrace - s * p.embrace / n;
  const double R = p.radius;
  j.intrados = Vec2(R * std::cos(th), p.centre_z + R * std::sin(th));
  j.extrados = Vec2((R + t) * std::cos(th), p.centre_z + (R + t) * std::sin(th));
  if (crown) j.intrados.x() = j.extrados.x() = 0.0;
  return j;
}

ArchModel build_arch(const ArchSpec& s) {
  ArchModel model;
  const ArchProfile p = arch_profile(s);
  model.profile = p;
  const double t = s.thickness;
  require(s.rings >= 1 && s.rings <= 200, "rings", "must be in [1, 200] (got " + std::to_string(s.rings) + ")");
  require(s.spans >= 1 && s.spans <= 50, "spans", "must be in [1, 50] (got " + std::to_string(s.spans) + ")");
  require(s.pier_courses >= 1 && s.pier_courses <= 100, "pier_courses",
          "must be in [1, 100] (got " + std::to_string(s.pier_courses) + ")");
  require(s.origin.allFinite(), "origin", "must be finite");
  const Vec3 d(s.direction.x(), s.direction.y(), 0.0);
  require(s.direction.allFinite() && d.norm() > 1e-9 * std::max(1.0, s.direction.norm()), "direction",
          "must have a horizontal part (the span's direction); got a vertical or zero vector");
  const double blocks = static_cast<double>(s.spans) * s.rings * (s.voussoirs + 1) +
                        (s.spans + 1.0) * (s.supports == ArchSupports::piers ? s.pier_courses : 1);
  require(blocks <= 5000, "voussoirs",
          "with rings = " + std::to_string(s.rings) + " and spans = " + std::to_string(s.spans) + " gives about " +
              num(blocks) + " blocks (at most 5000)");

  const double cos0 = std::cos(p.springing_angle), sin0 = std::sin(p.springing_angle);
  const bool horseshoe = p.springing_angle < 0;
  const double joint_run = t * cos0;  // the springing joint's horizontal extent
  // Supports.
  require(std::isfinite(s.pier_width) && s.pier_width >= 0, "pier_width",
          "must be >= 0 (0: twice the thickness) (got " + num(s.pier_width) + ")");
  double w = s.pier_width > 0 ? s.pier_width : 2.0 * t;
  if (horseshoe) {
    require(s.supports == ArchSupports::abutments, "supports",
            "a horseshoe arch (embrace > 180) springs from abutments (supports = \"abutments\"): its springing "
            "joints lean inwards");
    require(s.spans == 1, "spans", "a horseshoe arch (embrace > 180) has one span");
    require(s.pier_width == 0, "pier_width",
            "a horseshoe arch's abutments are as wide as its springing joints, " + num(joint_run) +
                " m (leave pier_width out)");
    w = joint_run;
  } else {
    require(w >= joint_run * (1 - 1e-12), "pier_width",
            "must be at least the springing joint's horizontal run t cos(springing angle) = " + num(joint_run) +
                " m (got " + num(w) + ")");
    if (s.spans > 1)
      require(w >= 2.0 * joint_run * (1 - 1e-12), "pier_width",
              "an interior pier carries two springing joints: must be at least 2 t cos(springing angle) = " +
                  num(2.0 * joint_run) + " m (got " + num(w) + ")");
  }
  require(w <= 100.0 * (p.span + t), "pier_width", "must be at most 100 (span + thickness)");
  require(std::isfinite(s.pier_height) && s.pier_height >= 0, "pier_height",
          "must be >= 0 (0: half the span) (got " + num(s.pier_height) + ")");
  const double h = s.pier_height > 0 ? s.pier_height : 0.5 * p.span;
  const double below_springing = std::max(0.0, -t * sin0);  // a horseshoe's skewback dips below z = 0
  require(h / (s.supports == ArchSupports::piers ? s.pier_courses : 1) > below_springing * (1 + 1e-9), "pier_height",
          "the top course of a support must reach below the springing joint's lower end, " + num(below_springing) +
              " m under the springing line");
  require(h <= 1000.0 * (p.span + t), "pier_height", "must be at most 1000 (span + thickness)");
  require(std::isfinite(s.base_thickness) && s.base_thickness >= 0, "base_thickness",
          "must be >= 0 (0: the ring thickness) (got " + num(s.base_thickness) + ")");
  const double bt = s.base_thickness > 0 ? s.base_thickness : t;
  require(bt <= 1000.0 * (p.span + t), "base_thickness", "must be at most 1000 (span + thickness)");
  if (s.supports == ArchSupports::base)
    require(p.springing_angle == 0, "supports",
            "a fixed base (supports = \"base\") needs horizontal springing joints (a semicircular or pointed "
            "arch); this arch springs at " + num(p.springing_angle * 180 / kPi) +
                " degrees: use supports = \"abutments\" or \"piers\"");
  model.pier_width = w;
  model.pier_height = h;
  model.base_thickness = bt;

  // Local -> world.
  const Vec3 dx = d.normalized();
  Mat3 Rz;
  Rz.col(0) = dx;
  Rz.col(1) = Vec3(-dx.y(), dx.x(), 0.0);
  Rz.col(2) = Vec3(0, 0, 1);
  Mat3 M;  // prism (u, v, w) = local (x, z, -y)
  M.col(0) = Vec3(1, 0, 0);
  M.col(1) = Vec3(0, 0, 1);
  M.col(2) = Vec3(0, -1, 0);
  const Mat3 R = Rz * M;
  model.rotation = Rz;
  const double scale = p.span + 2 * t + 2 * w + h;
  const double tol = 1e-12 * scale;
  // A prism of the (x, z) polygon over y in [y0, y1], in world coordinates.
  auto prism = [&](const std::vector<Vec2>& poly, double y0, double y1) {
    return transformed(make_prism(poly, -y1, -y0), R, s.origin);
  };

  const int n = s.voussoirs;
  const double step = p.span + w;
  auto span_centre = [&](int j) { return (j - 0.5 * (s.spans - 1)) * step; };
  const bool many_spans = s.spans > 1, many_rings = s.rings > 1;

  // The joints of each ring (shared by every span: shifted copies).
  std::vector<std::vector<ArchJoint>> joints(std::min(s.rings, 2));
  for (int r = 0; r < static_cast<int>(joints.size()); ++r)
    for (double sj : ring_joints(n, r)) joints[r].push_back(arch_joint(s, p, sj));
  for (int r = 0; r < s.rings; ++r) {
    const auto& js = joints[r % 2];
    std::vector<Vec2> outline;
    for (const auto& j : js) outline.push_back(j.intrados);
    for (auto it = js.rbegin(); it != js.rend(); ++it) outline.push_back(it->extrados);
    model.ring_area.push_back(shoelace(outline));
  }

  for (int sp = 0; sp < s.spans; ++sp) {
    const Vec2 shift(span_centre(sp), 0.0);
    for (int r = 0; r < s.rings; ++r) {
      const double y0 = -0.5 * s.depth + r * s.depth / s.rings;
      const double y1 = r + 1 == s.rings ? 0.5 * s.depth : -0.5 * s.depth + (r + 1) * s.depth / s.rings;
      const auto& js = joints[r % 2];
      for (std::size_t i = 0; i + 1 < js.size(); ++i) {
        const std::vector<Vec2> quad = {js[i].intrados + shift, js[i + 1].intrados + shift,
                                        js[i + 1].extrados + shift, js[i].extrados + shift};
        GeneratedBlock b;
        try {
          b.shape = prism(quad, y0, y1);
        } catch (const GeometryError& e) {
          throw ArchSpecError("thickness", std::string("voussoir ") + std::to_string(i) +
                                                " is not a convex quadrilateral (" + e.what() + ")");
        }
        b.kind = BlockKind::voussoir;
        b.span = sp;
        b.ring = r;
        b.index = static_cast<int>(i);
        std::string name;
        if (many_spans) name += "span" + zero_padded(sp, digits_for(s.spans - 1)) + "_";
        if (many_rings) name += "ring" + zero_padded(r, digits_for(s.rings - 1)) + "_";
        name += "voussoir" + zero_padded(b.index, digits_for(std::max(10, n)));
        b.name = name;
        model.blocks.push_back(std::move(b));
      }
    }
  }

  // The supports, left to right.
  const ArchJoint left_spring = joints[0].front(), right_spring = joints[0].back();
  double x_min = 0, x_max = 0;
  for (int i = 0; i <= s.spans; ++i) {
    const bool has_right = i < s.spans, has_left = i > 0;  // the span it carries on that side
    const double xl = has_left ? span_centre(i - 1) + 0.5 * p.span : span_centre(0) - 0.5 * p.span - w;
    const double xr = has_right ? span_centre(i) - 0.5 * p.span : span_centre(s.spans - 1) + 0.5 * p.span + w;
    if (i == 0) x_min = xl;
    if (i == s.spans) x_max = xr;
    if (s.supports == ArchSupports::base) continue;
    const double ztop = t * sin0;  // the extrados springing point's height
    const bool pier = s.supports == ArchSupports::piers;
    const int courses = pier ? s.pier_courses : 1;
    for (int c = 0; c < courses; ++c) {
      const double zb = -h + c * h / courses;
      std::vector<Vec2> poly = {{xl, zb}, {xr, zb}};
      if (c + 1 < courses) {
        const double zt = -h + (c + 1) * h / courses;
        poly.push_back({xr, zt});
        poly.push_back({xl, zt});
      } else {
        if (has_right) {
          const Vec2 shift(span_centre(i), 0.0);
          poly.push_back(left_spring.intrados + shift);
          poly.push_back(left_spring.extrados + shift);
        } else {
          poly.push_back({xr, ztop});
        }
        if (has_left) {
          const Vec2 shift(span_centre(i - 1), 0.0);
          poly.push_back(right_spring.extrados + shift);
          poly.push_back(right_spring.intrados + shift);
        } else {
          poly.push_back({xl, ztop});
        }
      }
      GeneratedBlock b;
      try {
        b.shape = prism(corners_only(poly, tol), -0.5 * s.depth, 0.5 * s.depth);
      } catch (const GeometryError& e) {
        throw ArchSpecError("pier_width", std::string("support ") + std::to_string(i) +
                                              " cannot carry its springing joints (" + e.what() + ")");
      }
      b.kind = pier ? BlockKind::pier : BlockKind::abutment;
      b.index = i;
      b.course = pier ? c : -1;
      b.name = (pier ? "pier" : "abutment") + zero_padded(i, digits_for(s.spans));
      if (pier && courses > 1) b.name += "_course" + zero_padded(c, digits_for(courses - 1));
      model.blocks.push_back(std::move(b));
    }
  }
  if (s.supports != ArchSupports::abutments) {
    // Under everything it carries, overhanging by half a pier width.
    const double m = 0.5 * w;
    double lo = x_min, hi = x_max;
    double z0 = -bt, z1 = 0.0;
    if (s.supports == ArchSupports::piers) {
      z0 = -h - bt;
      z1 = -h;
    } else {
      lo = span_centre(0) + left_spring.extrados.x();
      hi = span_centre(s.spans - 1) + (-left_spring.extrados.x());
    }
    lo -= m;
    hi += m;
    GeneratedBlock b;
    b.shape = prism({{lo, z0}, {hi, z0}, {hi, z1}, {lo, z1}}, -0.5 * s.depth - m, 0.5 * s.depth + m);
    b.kind = BlockKind::base;
    b.name = "base";
    model.blocks.push_back(std::move(b));
  }
  return model;
}

}  // namespace polydem
