// The column builder: base, plinth, drums and capital stacked on the axis;
// what each block is, and the polygon standing for the circle, is at the top
// of structures/column.hpp. Consecutive blocks share their bed planes exactly
// (the same z value ends one block and starts the next).
#include "structures/generator_text.hpp"
#include "structures/column.hpp"

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
  if (!ok) throw ColumnSpecError(field, what);
}

void require_non_negative(double v, const char* field, const char* zero_means) {
  require(std::isfinite(v) && v >= 0, field,
          "must be >= 0 (0: " + std::string(zero_means) + ") (got " + num(v) + ")");
}

std::vector<Vec2> polygon(int sides, double r) {
  std::vector<Vec2> p;
  for (int k = 0; k < sides; ++k) {
    const double a = (2.0 * k + 1.0) * kPi / sides;  // a side faces +x
    p.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return p;
}

std::vector<Vec2> square(double width) {
  const double h = 0.5 * width;
  return {{-h, -h}, {h, -h}, {h, h}, {-h, h}};
}

std::vector<Vec2> shifted(std::vector<Vec2> p, const Vec3& o) {
  for (Vec2& q : p) q += Vec2(o.x(), o.y());
  return p;
}

double plinth_width(const ColumnSpec& s) { return s.plinth_width > 0 ? s.plinth_width : 2.5 * s.radius; }
double capital_width(const ColumnSpec& s) { return s.capital_width > 0 ? s.capital_width : 2.5 * s.radius; }
double capital_height(const ColumnSpec& s) { return s.capital_height > 0 ? s.capital_height : s.radius; }

}  // namespace

void validate_column(const ColumnSpec& s) {
  require(s.drums >= 1 && s.drums <= 1000, "drums", "must be in [1, 1000] (got " + std::to_string(s.drums) + ")");
  require(std::isfinite(s.radius) && s.radius > 0, "radius", "must be > 0 and finite (got " + num(s.radius) + ")");
  require(s.radius <= 1e4, "radius", "must be at most 1e4 m (got " + num(s.radius) + ")");
  require(s.sides >= 4 && s.sides <= 128, "sides",
          "must be in [4, 128]: the drums' polygon stands for their circle (got " + std::to_string(s.sides) + ")");
  if (s.drum_heights.empty()) {
    require(std::isfinite(s.height) && s.height > 0, "height", "must be > 0 and finite (got " + num(s.height) + ")");
  } else {
    require(static_cast<int>(s.drum_heights.size()) == s.drums, "drum_heights",
            "must list one height per drum: drums = " + std::to_string(s.drums) + " (got " +
                std::to_string(s.drum_heights.size()) + ")");
    for (double h : s.drum_heights)
      require(std::isfinite(h) && h > 0, "drum_heights", "every drum height must be > 0 (got " + num(h) + ")");
  }
  const double shaft = s.drum_heights.empty() ? s.height : 0.0;
  const double smallest = s.drum_heights.empty() ? shaft / s.drums
                                                 : *std::min_element(s.drum_heights.begin(), s.drum_heights.end());
  const double total = s.drum_heights.empty() ? s.height : [&] {
    double h = 0;
    for (double d : s.drum_heights) h += d;
    return h;
  }();
  require(total <= 1e3 * s.radius && total <= 1e5, s.drum_heights.empty() ? "height" : "drum_heights",
          "gives a shaft " + num(total) + " m tall: at most 1000 radii and 100 km");
  require(smallest >= 1e-3 * s.radius, s.drum_heights.empty() ? "drums" : "drum_heights",
          "gives drums " + num(smallest) + " m tall: thinner than a thousandth of the radius");
  require_non_negative(s.plinth_height, "plinth_height", "no plinth");
  require_non_negative(s.plinth_width, "plinth_width", "2.5 radius");
  if (s.plinth_width > 0)
    require(s.plinth_height > 0, "plinth_width", "there is no plinth (plinth_height = 0)");
  if (s.plinth_height > 0)
    require(plinth_width(s) >= 2.0 * s.radius, "plinth_width",
            "must be at least the drums' diameter " + num(2.0 * s.radius) + " m (got " + num(plinth_width(s)) + ")");
  require_non_negative(s.capital_width, "capital_width", "2.5 radius");
  require_non_negative(s.capital_height, "capital_height", "the radius");
  if (s.capital == ColumnCapital::none) {
    require(s.capital_width == 0, "capital_width", "there is no capital (capital = \"none\")");
    require(s.capital_height == 0, "capital_height", "there is no capital (capital = \"none\")");
  }
  if (s.capital == ColumnCapital::frustum)
    require(std::abs(0.5 * capital_width(s) - s.radius) > 1e-6 * s.radius, "capital_width",
            "a frustum capital as wide as the shaft is one more drum (got " + num(capital_width(s)) + ")");
  require_non_negative(s.base_width, "base_width", "twice the widest block above it");
  for (const auto& [v, field] : {std::pair{s.plinth_height, "plinth_height"}, std::pair{s.plinth_width, "plinth_width"},
                                 std::pair{s.capital_width, "capital_width"}, std::pair{s.capital_height, "capital_height"},
                                 std::pair{s.base_width, "base_width"}, std::pair{s.base_thickness, "base_thickness"}})
    require(v <= 1e3 * s.radius, field, "must be at most 1000 radii (got " + num(v) + ")");
  require(std::isfinite(s.base_thickness) && s.base_thickness > 0, "base_thickness",
          "must be > 0 (the fixed base the column stands on) (got " + num(s.base_thickness) + ")");
  require(s.origin.allFinite(), "origin", "must be finite");
  if (s.base_width > 0) {
    const double under = s.plinth_height > 0 ? plinth_width(s) : 2.0 * s.radius;
    require(s.base_width >= under, "base_width",
            "must be at least as wide as the block standing on it, " + num(under) + " m (got " + num(s.base_width) +
                ")");
  }
}

ColumnModel build_column(const ColumnSpec& s) {
  validate_column(s);
  ColumnModel m;
  const Vec3& o = s.origin;
  double widest = 2.0 * s.radius;
  if (s.plinth_height > 0) widest = std::max(widest, plinth_width(s));
  if (s.capital != ColumnCapital::none) widest = std::max(widest, capital_width(s));
  const double base_width = s.base_width > 0 ? s.base_width : 2.0 * widest;

  auto add = [&](Polyhedron shape, BlockKind kind, int drum, std::string name) {
    GeneratedBlock b;
    b.shape = std::move(shape);
    b.kind = kind;
    b.index = drum;
    b.name = std::move(name);
    m.blocks.push_back(std::move(b));
  };
  add(make_prism(shifted(square(base_width), o), o.z() - s.base_thickness, o.z()), BlockKind::base, -1,
      "base");
  double z = o.z();
  if (s.plinth_height > 0) {
    const double z1 = z + s.plinth_height;
    add(make_prism(shifted(square(plinth_width(s)), o), z, z1), BlockKind::plinth, -1, "plinth");
    z = z1;
  }
  const std::vector<Vec2> section = shifted(polygon(s.sides, s.radius), o);
  m.drum_area = 0.5 * s.sides * s.radius * s.radius * std::sin(2.0 * kPi / s.sides);
  const double z_shaft = z;
  for (int i = 0; i < s.drums; ++i) {
    const double hi = s.drum_heights.empty() ? s.height / s.drums : s.drum_heights[i];
    m.drum_heights.push_back(hi);
    // The last drum ends exactly at the shaft's top when the height is split.
    const double z1 = s.drum_heights.empty() && i + 1 == s.drums ? z_shaft + s.height
                      : s.drum_heights.empty()                   ? z_shaft + (i + 1) * (s.height / s.drums)
                                                                 : z + hi;
    add(make_prism(section, z, z1), BlockKind::drum, i,
        "drum" + zero_padded(i, digits_for(std::max(10, s.drums - 1))));
    z = z1;
  }
  if (s.capital == ColumnCapital::abacus) {
    const double z1 = z + capital_height(s);
    add(make_prism(shifted(square(capital_width(s)), o), z, z1), BlockKind::capital, -1, "capital");
    z = z1;
  } else if (s.capital == ColumnCapital::frustum) {
    const double z1 = z + capital_height(s);
    std::vector<Vec3> pts;
    for (const Vec2& q : section) pts.emplace_back(q.x(), q.y(), z);
    for (const Vec2& q : shifted(polygon(s.sides, 0.5 * capital_width(s)), o)) pts.emplace_back(q.x(), q.y(), z1);
    add(convex_hull(pts), BlockKind::capital, -1, "capital");
    z = z1;
  }
  m.top = z - o.z();
  return m;
}

}  // namespace polydem
