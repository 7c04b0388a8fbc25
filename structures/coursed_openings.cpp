// The face-plane work shared by the wall and tower builders (see the header).
#include "structures/coursed_openings.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace polydem::masonry {

namespace {

constexpr double kPi = std::numbers::pi;

std::string num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// Distance of z above the bed joint below it (0 on a joint).
double above_bed(double z, double ch) {
  const double k = std::floor(z / ch + 1e-9);
  return std::max(0.0, z - k * ch);
}

}  // namespace

void force_joint(std::vector<Segment>& segs, double x, double min_len, double tol) {
  for (std::size_t i = 0; i < segs.size(); ++i) {
    Segment& g = segs[i];
    if (std::abs(g.u0 - x) <= tol || std::abs(g.u1 - x) <= tol) {
      // Already a joint: make it exact.
      if (std::abs(g.u0 - x) <= tol && i > 0) g.u0 = x, segs[i - 1].u1 = x;
      if (std::abs(g.u1 - x) <= tol && i + 1 < segs.size()) g.u1 = x, segs[i + 1].u0 = x;
      return;
    }
    if (!(g.u0 < x && x < g.u1)) continue;
    const double left = x - g.u0, right = g.u1 - x;
    const bool can_left = i > 0, can_right = i + 1 < segs.size();
    if (left < min_len && can_left && (right >= min_len || left <= right || !can_right)) {
      g.u0 = x, segs[i - 1].u1 = x;
    } else if (right < min_len && can_right) {
      g.u1 = x, segs[i + 1].u0 = x;
    } else {
      Segment second = g;
      g.u1 = x;
      second.u0 = x;
      segs.insert(segs.begin() + static_cast<long>(i) + 1, second);
    }
    return;
  }
}

Opening make_opening(double position, double sill, double width, double height, bool arch, double extent,
                     int voussoirs, int courses, double ch) {
  Opening g;
  g.a = position;
  g.b = position + width;
  g.sill = sill;
  g.top = sill + height;
  g.arch = arch;
  g.radius = 0.5 * width;
  g.centre = position + g.radius;
  g.head = arch ? g.top - g.radius : g.top;
  g.voussoirs = voussoirs;
  g.zone_a = g.a - extent;
  g.zone_b = g.b + extent;
  const double tol = 1e-9 * ch;
  for (int c = 0; c < courses; ++c) {
    const double z1 = (c + 1) * ch;
    if (g.head_lo < 0 && z1 > g.head + tol) g.head_lo = c;
    if (g.head_lo >= 0 && z1 >= g.top + 0.5 * ch - tol) {
      g.head_hi = c;
      break;
    }
  }
  if (g.head_hi >= 0) g.head_top = (g.head_hi + 1) * ch;
  return g;
}

double opening_area(const Opening& o) {
  double area = (o.b - o.a) * (o.head - o.sill);
  if (o.arch) area += 0.5 * o.voussoirs * o.radius * o.radius * std::sin(kPi / o.voussoirs);
  return area;
}

std::vector<LevelProblem> level_problems(const Opening& g, double height, double ch, double wall_height) {
  std::vector<LevelProblem> out;
  if (g.head_hi < 0)
    out.push_back({"height", "the head at z = " + num(g.top) + " leaves less than half a course (" + num(0.5 * ch) +
                                 " m) of wall above it for the " + (g.arch ? "voussoirs" : "lintel") +
                                 " (wall height " + num(wall_height) + "): the opening cuts the top course"});
  const double ds = above_bed(g.sill, ch);
  if (!(ds < 1e-9 * ch || ds >= kSliver * ch * (1 - 1e-9)))
    out.push_back({"sill", "is " + num(ds) +
                               " m above a bed joint: the piece under it would be thinner than a quarter course (" +
                               num(kSliver * ch) + " m); put the sill on a bed joint (" + num(g.sill - ds) +
                               ") or higher"});
  const double dh = above_bed(g.head, ch);
  if (!(dh < 1e-9 * ch || dh >= kSliver * ch * (1 - 1e-9)))
    out.push_back({"height", std::string("puts the ") + (g.arch ? "springing" : "head") + " at z = " + num(g.head) +
                                 ", " + num(dh) +
                                 " m above a bed joint: the pieces beside the opening would be thinner than a quarter "
                                 "course (" +
                                 num(kSliver * ch) + " m); make it " + num(height - dh) + " or at least " +
                                 num(height - dh + kSliver * ch)});
  return out;
}

void fit_course(std::vector<Segment>& segs, const Opening& g, int c, double z0, double z1, double ch, double min_len,
                double tol, int jamb_kind) {
  const bool beside = z0 < g.head - 1e-9 * ch && z1 > g.sill + 1e-9 * ch;
  const bool head_course = c >= g.head_lo && c <= g.head_hi;
  if (head_course) {
    force_joint(segs, g.zone_a, min_len, tol);
    force_joint(segs, g.zone_b, min_len, tol);
    // One jamb segment between the head's ends.
    std::vector<Segment> merged;
    bool jamb_added = false;
    for (const auto& seg : segs) {
      if (seg.u0 >= g.zone_a - tol && seg.u1 <= g.zone_b + tol) {
        if (!jamb_added) merged.push_back({g.zone_a, g.zone_b, true, jamb_kind});
        jamb_added = true;
      } else {
        merged.push_back(seg);
      }
    }
    segs = merged;
  } else if (beside) {
    force_joint(segs, g.a, min_len, tol);
    force_joint(segs, g.b, min_len, tol);
  }
}

std::vector<Rect> cut_by_openings(const Rect& unit, const std::vector<Opening>& openings, double ch, double tol,
                                  bool& cut) {
  std::vector<Rect> rects = {unit};
  cut = false;
  for (const auto& g : openings) {
    const bool meets = unit.u0 < g.zone_b - tol && unit.u1 > g.zone_a + tol && unit.z0 < g.head_top - 1e-9 * ch &&
                       unit.z1 > g.sill + 1e-9 * ch;
    if (!meets) continue;
    cut = true;
    std::vector<Rect> next;
    for (const Rect& r : rects) {
      const Rect regions[] = {{r.u0, std::min(r.u1, g.a), r.z0, std::min(r.z1, g.head)},
                              {std::max(r.u0, g.a), std::min(r.u1, g.b), r.z0, std::min(r.z1, g.sill)},
                              {std::max(r.u0, g.b), r.u1, r.z0, std::min(r.z1, g.head)}};
      for (const Rect& q : regions)
        if (q.u1 - q.u0 > tol && q.z1 - q.z0 > 1e-9 * ch) next.push_back(q);
    }
    rects = next;
  }
  return rects;
}

std::vector<HalfPlane> voussoir(const Opening& g, int j, Vec2& interior) {
  const int n = g.voussoirs;
  const double a0 = kPi - kPi * j / n, a1 = kPi - kPi * (j + 1) / n;
  // Directions of the radial joints, exact at the springings (π and 0).
  auto dir = [n](double a, int k) {
    if (k == 0) return Vec2(-1, 0);
    if (k == n) return Vec2(1, 0);
    return Vec2(std::cos(a), std::sin(a));
  };
  auto intrados = [&](int k) {
    if (k == 0) return Vec2(g.a, g.head);
    if (k == n) return Vec2(g.b, g.head);
    const Vec2 d = dir(kPi - kPi * k / n, k);
    return Vec2(g.centre + g.radius * d.x(), g.head + g.radius * d.y());
  };
  const Vec2 d0 = dir(a0, j), d1 = dir(a1, j + 1);
  const Vec2 C(g.centre, g.head);
  std::vector<HalfPlane> out;
  // Keep the polar angle about C within [a1, a0]: n0 points from the ray at
  // a0 towards smaller angles, n1 from the ray at a1 towards larger ones;
  // keep n·(x - C) >= 0.
  const Vec2 n0(d0.y(), -d0.x()), n1(-d1.y(), d1.x());
  out.push_back({-n0.x(), -n0.y(), -n0.dot(C)});
  out.push_back({-n1.x(), -n1.y(), -n1.dot(C)});
  // Outside the intrados chord (its normal away from C: the chords run clockwise).
  const Vec2 P0 = intrados(j), P1 = intrados(j + 1);
  const Vec2 t = P1 - P0;
  const Vec2 up(-t.y(), t.x());
  out.push_back({-up.x(), -up.y(), -up.dot(P0)});
  out.push_back({-1, 0, -g.zone_a});
  out.push_back({1, 0, g.zone_b});
  out.push_back({0, 1, g.head_top});
  const double am = 0.5 * (a0 + a1);
  const double reach = std::min(g.zone_b - g.b, g.head_top - g.top);
  const double r = g.radius + 0.5 * reach;
  interior = Vec2(g.centre + r * std::cos(am), g.head + r * std::sin(am));
  return out;
}

std::vector<Vec2> clip(const std::vector<Vec2>& poly, const Line& l) {
  std::vector<Vec2> out;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& p = poly[i];
    const Vec2& q = poly[(i + 1) % n];
    const double fp = l.a.dot(p) - l.d, fq = l.a.dot(q) - l.d;
    if (fp <= 0) out.push_back(p);
    if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0)) out.push_back(p + (fp / (fp - fq)) * (q - p));
  }
  return out;
}

std::vector<Vec2> cleaned(const std::vector<Vec2>& poly, double tol) {
  std::vector<Vec2> p;
  for (const auto& v : poly)
    if (p.empty() || (v - p.back()).norm() > tol) p.push_back(v);
  while (p.size() > 1 && (p.front() - p.back()).norm() <= tol) p.pop_back();
  bool changed = true;
  while (changed && p.size() >= 3) {
    changed = false;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec2& a = p[(i + p.size() - 1) % p.size()];
      const Vec2& b = p[i];
      const Vec2& c = p[(i + 1) % p.size()];
      const Vec2 u = b - a, w = c - b;
      if (std::abs(u.x() * w.y() - u.y() * w.x()) <= tol * (u.norm() + w.norm())) {
        p.erase(p.begin() + static_cast<long>(i));
        changed = true;
        break;
      }
    }
  }
  return p;
}

}  // namespace polydem::masonry
