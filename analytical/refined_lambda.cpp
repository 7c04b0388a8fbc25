#include "analytical/refined_lambda.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace polydem::analytical {

namespace {

constexpr double kPi = 3.14159265358979323846;

struct BlockData {
  double mass = 0.0;
  Vec3 centroid = Vec3::Zero();
  bool moves = false;  // not the base
  const std::vector<Vec3>* vertices = nullptr;
};

// What every mechanism of one direction shares.
struct Frame {
  Vec3 d = Vec3::Zero();  // unit horizontal load direction
  double p_d = 0.0;       // d·pivot
  double z_p = 0.0;       // pivot height
  std::vector<char> pivot_block;
  std::vector<double> w_face;  // 0..1 per face 0..7 (stepped family)
};

std::vector<BlockData> block_data(const SpireModel& model, double density) {
  std::vector<BlockData> out;
  out.reserve(model.blocks.size());
  bool any = false;
  for (const auto& b : model.blocks) {
    const MassProperties mp = mass_properties(b.shape);
    BlockData bd;
    bd.mass = density * mp.volume;
    bd.centroid = mp.centroid;
    bd.moves = b.kind != BlockKind::base;
    bd.vertices = &b.shape.vertices;
    any = any || bd.moves;
    out.push_back(bd);
  }
  if (!any) throw std::invalid_argument("refined_lambda: the model has no free block");
  return out;
}

double wrap_abs(double a) {  // |a| wrapped to [0, π]
  a = std::fmod(std::fabs(a), 2.0 * kPi);
  return a > kPi ? 2.0 * kPi - a : a;
}

Frame make_frame(const SpireModel& model, const LoadDirection& dir) {
  Frame f;
  f.d = Vec3(std::cos(dir.azimuth), std::sin(dir.azimuth), 0.0);
  // Bottom of the free blocks and its extreme point in d.
  double z_min = std::numeric_limits<double>::infinity();
  double extent = 0.0;
  for (const auto& b : model.blocks) {
    if (b.kind == BlockKind::base) continue;
    for (const Vec3& v : b.shape.vertices) {
      z_min = std::min(z_min, v.z());
      extent = std::max(extent, v.norm());
    }
  }
  const double tol = 1e-9 * std::max(extent, 1.0) + 1e-9;
  f.z_p = z_min;
  f.p_d = -std::numeric_limits<double>::infinity();
  for (const auto& b : model.blocks) {
    if (b.kind == BlockKind::base) continue;
    for (const Vec3& v : b.shape.vertices)
      if (v.z() <= z_min + tol) f.p_d = std::max(f.p_d, f.d.dot(v));
  }
  // Pivot blocks: a bottom vertex on the pivot axis (relative tolerance: the
  // corner of a face-normal direction is exact, round-off only).
  const double ptol = 1e-7 * std::max(extent, 1.0);
  f.pivot_block.assign(model.blocks.size(), 0);
  for (std::size_t i = 0; i < model.blocks.size(); ++i) {
    const auto& b = model.blocks[i];
    if (b.kind == BlockKind::base) continue;
    for (const Vec3& v : b.shape.vertices)
      if (v.z() <= z_min + ptol && f.d.dot(v) >= f.p_d - ptol) f.pivot_block[i] = 1;
  }
  // Angular distance of each face from the pivot face(s), scaled to [0, 1].
  std::vector<double> delta(8);
  for (int k = 0; k < 8; ++k) delta[k] = wrap_abs(k * kPi / 4.0 - dir.azimuth);
  const double dmin = *std::min_element(delta.begin(), delta.end());
  f.w_face.resize(8);
  for (int k = 0; k < 8; ++k) f.w_face[k] = std::clamp((delta[k] - dmin) / (kPi - dmin), 0.0, 1.0);
  return f;
}

// Fills moments, mass, centroid and λ from m.blocks.
void evaluate(Mechanism& m, const std::vector<BlockData>& data, const Frame& f, double g) {
  double mass = 0.0, restoring = 0.0, overturning = 0.0;
  Vec3 first = Vec3::Zero();
  bool pivot = false;
  for (std::size_t i : m.blocks) {
    const BlockData& b = data[i];
    mass += b.mass;
    first += b.mass * b.centroid;
    restoring += b.mass * g * (f.p_d - f.d.dot(b.centroid));
    overturning += b.mass * g * (b.centroid.z() - f.z_p);
    pivot = pivot || f.pivot_block[i];
  }
  m.mass = mass;
  m.centroid = mass > 0.0 ? Vec3(first / mass) : Vec3::Zero();
  m.pivot = Vec3(f.p_d * f.d.x(), f.p_d * f.d.y(), f.z_p);
  m.restoring_moment = restoring;
  m.overturning_moment = overturning;
  m.admissible = pivot && mass > 0.0 && overturning > 0.0;
  m.lambda = m.admissible ? restoring / overturning : std::numeric_limits<double>::quiet_NaN();
}

double point_beta(const Vec3& x, const Frame& f) { return std::atan2(x.z() - f.z_p, f.p_d - f.d.dot(x)); }

// The β below which the block is in the part: its centroid's (plane), or its
// highest vertex's (plane_cover: the block is in as soon as any of it is
// above the plane). Points on the pivot axis itself do not count.
double block_beta(const BlockData& b, const Frame& f, CrackFamily family) {
  if (family != CrackFamily::plane_cover) return point_beta(b.centroid, f);
  double best = 0.0;
  for (const Vec3& v : *b.vertices) {
    const double h = v.z() - f.z_p, l = f.p_d - f.d.dot(v);
    if (h * h + l * l <= 1e-18) continue;
    best = std::max(best, std::atan2(h, l));
  }
  return best;
}

std::vector<int> stepped_courses(const Frame& f, int n, int n_courses) {
  std::vector<int> c(8);
  for (int k = 0; k < 8; ++k) c[k] = std::min(n_courses, static_cast<int>(std::lround(n * f.w_face[k])));
  return c;
}

Mechanism stepped(const SpireModel& model, const std::vector<BlockData>& data, const Frame& f,
                  const LoadDirection& dir, int n, double g) {
  Mechanism m;
  m.family = CrackFamily::stepped;
  m.direction = dir;
  m.trailing_course = n;
  m.face_course = stepped_courses(f, n, model.n_courses);
  for (std::size_t i = 0; i < model.blocks.size(); ++i) {
    const auto& b = model.blocks[i];
    if (!data[i].moves) continue;
    const bool in = (b.face >= 0 && b.face < 8) ? b.course >= m.face_course[b.face] : true;
    if (in) m.blocks.push_back(i);
  }
  evaluate(m, data, f, g);
  return m;
}

bool better(const Mechanism& a, const Mechanism& b) {  // a governs over b
  if (!a.admissible) return false;
  if (!b.admissible) return true;
  return a.lambda < b.lambda;
}

}  // namespace

const char* to_string(CrackFamily f) {
  switch (f) {
    case CrackFamily::plane: return "plane";
    case CrackFamily::plane_cover: return "plane-cover";
    case CrackFamily::stepped: return "stepped";
  }
  return "?";
}

std::vector<LoadDirection> spire_load_directions() {
  std::vector<LoadDirection> out;
  for (int k = 0; k < 8; ++k) out.push_back({"face " + std::to_string(k), k * kPi / 4.0});
  for (int k = 0; k < 8; ++k)
    out.push_back({"corner " + std::to_string(k) + "/" + std::to_string((k + 1) % 8), (k + 0.5) * kPi / 4.0});
  return out;
}

Mechanism plane_crack_mechanism(const SpireModel& model, double density, const LoadDirection& direction,
                                double beta, CrackFamily family, double g) {
  if (family == CrackFamily::stepped) throw std::invalid_argument("plane_crack_mechanism: not a plane family");
  const auto data = block_data(model, density);
  const Frame f = make_frame(model, direction);
  Mechanism m;
  m.family = family;
  m.direction = direction;
  m.beta_low = m.beta_high = beta;
  for (std::size_t i = 0; i < data.size(); ++i)
    if (data[i].moves && block_beta(data[i], f, family) > beta) m.blocks.push_back(i);
  evaluate(m, data, f, g);
  return m;
}

Mechanism stepped_crack_mechanism(const SpireModel& model, double density, const LoadDirection& direction,
                                  int trailing_course, double g) {
  const auto data = block_data(model, density);
  const Frame f = make_frame(model, direction);
  return stepped(model, data, f, direction, trailing_course, g);
}

RefinedLambdaResult refined_lambda(const SpireModel& model, double density, const RefinedLambdaOptions& options) {
  if (!(density > 0.0)) throw std::invalid_argument("refined_lambda: density must be > 0");
  const auto data = block_data(model, density);
  const auto directions = options.directions.empty() ? spire_load_directions() : options.directions;
  const double g = options.g;
  RefinedLambdaResult res;
  for (const auto& b : data)
    if (b.moves) res.total_mass += b.mass;

  for (const auto& dir : directions) {
    const Frame f = make_frame(model, dir);

    for (const CrackFamily family : {CrackFamily::plane, CrackFamily::plane_cover}) {
      // Plane family: blocks by β_i, largest first; every prefix (ties kept
      // together) is the part above the planes with β between the next
      // distinct β_i and this one.
      std::vector<std::size_t> order;
      std::vector<double> beta(data.size(), 0.0);
      for (std::size_t i = 0; i < data.size(); ++i)
        if (data[i].moves) {
          order.push_back(i);
          beta[i] = block_beta(data[i], f, family);
        }
      std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return beta[a] > beta[b]; });
      Mechanism best_plane;
      best_plane.family = family;
      best_plane.direction = dir;
      double restoring = 0.0, overturning = 0.0;
      bool pivot = false;
      std::size_t best_end = 0;
      double best_lambda = std::numeric_limits<double>::infinity();
      double best_lo = 0.0, best_hi = 0.0;
      for (std::size_t k = 0; k < order.size();) {
        std::size_t e = k;
        const double bk = beta[order[k]];
        while (e < order.size() && std::fabs(beta[order[e]] - bk) <= 1e-12) {
          const std::size_t i = order[e];
          restoring += data[i].mass * (f.p_d - f.d.dot(data[i].centroid));
          overturning += data[i].mass * (data[i].centroid.z() - f.z_p);
          pivot = pivot || f.pivot_block[i];
          ++e;
        }
        ++res.candidates;
        if (pivot && overturning > 0.0) {
          const double lam = restoring / overturning;
          if (lam < best_lambda) {
            best_lambda = lam;
            best_end = e;
            best_hi = bk;
            best_lo = e < order.size() ? beta[order[e]] : 0.0;
          }
        }
        k = e;
      }
      if (best_end > 0) {
        best_plane.blocks.assign(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(best_end));
        std::sort(best_plane.blocks.begin(), best_plane.blocks.end());
        best_plane.beta_low = best_lo;
        best_plane.beta_high = best_hi;
        evaluate(best_plane, data, f, g);
      } else {
        best_plane.lambda = std::numeric_limits<double>::quiet_NaN();
      }
      (family == CrackFamily::plane ? res.plane : res.plane_cover).push_back(best_plane);
    }

    // Stepped family.
    Mechanism best_step;
    best_step.lambda = std::numeric_limits<double>::quiet_NaN();
    // n beyond n_courses: the thresholds are capped at the top course, so
    // faces leave the part whole (the front face(s) and the tip stay).
    for (int n = 0; n <= 4 * model.n_courses; ++n) {
      Mechanism m = stepped(model, data, f, dir, n, g);
      ++res.candidates;
      if (better(m, best_step)) best_step = std::move(m);
    }
    res.stepped.push_back(best_step);
  }

  bool first = true;
  for (const auto* list : {&res.plane, &res.plane_cover, &res.stepped})
    for (const auto& m : *list)
      if (first || better(m, res.governing)) {
        if (!m.admissible) continue;
        res.governing = m;
        first = false;
      }
  return res;
}

}  // namespace polydem::analytical
