#include "studies/limit_analysis.hpp"

#include "run/joint_mesh.hpp"
#include "run/setup.hpp"

#include <glpk.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace polydem {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// A unit vector perpendicular to n.
Vec3 any_perpendicular(const Vec3& n) {
  const Vec3 a = std::abs(n.x()) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  return (a - a.dot(n) * n).normalized();
}

// The first tangent of an interface: d projected on the joint plane, else
// "up" projected, else any perpendicular.
Vec3 first_tangent(const Vec3& n, const Vec3& d, const Vec3& up) {
  for (const Vec3& v : {d, up}) {
    const Vec3 t = v - v.dot(n) * n;
    if (t.norm() > 1e-9) return t.normalized();
  }
  return any_perpendicular(n);
}

// The extreme points of a planar patch (normal n): a vertex inside the
// convex hull of the others, or within 1e-9 of the patch's size of one of
// its edges (collinear points of the clipped polygon, repeated points), is
// a convex combination of them and adds nothing but a degenerate column.
// Andrew's monotone chain in the plane's coordinates.
std::vector<Vec3> extreme_points(const std::vector<Vec3>& points, const Vec3& n) {
  if (points.size() <= 1) return points;
  const Vec3 t1 = any_perpendicular(n), t2 = n.cross(t1);
  struct P {
    double u, v;
    int i;
  };
  std::vector<P> q;
  double size = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    q.push_back({points[i].dot(t1), points[i].dot(t2), static_cast<int>(i)});
    size = std::max(size, (points[i] - points[0]).norm());
  }
  const double eps = 1e-9 * size * size;
  std::sort(q.begin(), q.end(), [](const P& a, const P& b) { return a.u < b.u || (a.u == b.u && a.v < b.v); });
  const auto cross = [](const P& o, const P& a, const P& b) {
    return (a.u - o.u) * (b.v - o.v) - (a.v - o.v) * (b.u - o.u);
  };
  std::vector<P> hull;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t start = hull.size();
    for (std::size_t k = 0; k < q.size(); ++k) {
      const P& c = pass == 0 ? q[k] : q[q.size() - 1 - k];
      while (hull.size() >= start + 2 && cross(hull[hull.size() - 2], hull.back(), c) <= eps) hull.pop_back();
      hull.push_back(c);
    }
    hull.pop_back();  // the last point of each chain starts the other
  }
  std::vector<Vec3> out;
  for (const P& h : hull) {
    const Vec3& p = points[h.i];
    bool repeated = false;
    for (const Vec3& o : out) repeated = repeated || (o - p).norm() <= 1e-9 * size;
    if (!repeated) out.push_back(p);
  }
  return out;
}

// The sparse matrix in GLPK's 1-based triplets (index 0 unused). Every
// entry is of order 1 (forces over the weight, moments over weight times
// length): one below 1e-13 is round-off (cos π/2 = 6e-17) and is dropped.
// Kept, it wrecks GLPK's geometric-mean scaling of its row and column, and
// the simplex reported wrong optima (a box's λ = 0, or unbounded), which the
// a posteriori check below then catches.
struct Triplets {
  std::vector<int> row{0}, col{0};
  std::vector<double> value{0.0};
  void add(int r, int c, double v) {
    if (std::abs(v) < 1e-13) return;
    row.push_back(r);
    col.push_back(c);
    value.push_back(v);
  }
  int size() const { return static_cast<int>(value.size()) - 1; }
};

struct GlpkProblem {
  glp_prob* lp = glp_create_prob();
  ~GlpkProblem() { glp_delete_prob(lp); }
};

// GLPK prints through its own terminal hook; silence it while we solve.
struct QuietGlpk {
  int previous = glp_term_out(GLP_OFF);
  ~QuietGlpk() { glp_term_out(previous); }
};

// The a posteriori check's tolerance (relative). GLPK's interior-point
// solutions balance the blocks to about 1e-6 of the weight (its own
// stopping test is on scaled residuals); a wrong optimum of the simplex
// misses by orders of magnitude more (the tiny-entry failures above).
constexpr double kCheckTolerance = 1e-5;
// λ is boxed in [−cap, cap] rather than free: GLPK's interior-point method
// loses its way on the free column (on the spire it stopped with "numerical
// instability" at a gap of 1e-5; boxed, it converges to 1e-8 in 57
// iterations), and a box tells an unbounded problem from an infeasible one.
// λ at the cap is reported as unbounded: no mechanism below 100 g.
constexpr double kLambdaCap = 100.0;

}  // namespace

const char* to_string(FrictionPyramid p) { return p == FrictionPyramid::inscribed ? "inscribed" : "circumscribed"; }
const char* to_string(LpMethod m) { return m == LpMethod::simplex ? "simplex" : "interior-point"; }
const char* to_string(InterfaceMotion m) {
  switch (m) {
    case InterfaceMotion::closed: return "closed";
    case InterfaceMotion::opening: return "opening";
    case InterfaceMotion::sliding: return "sliding";
  }
  return "?";
}
const char* to_string(LimitStatus s) {
  switch (s) {
    case LimitStatus::optimal: return "optimal";
    case LimitStatus::unbounded: return "unbounded";
    case LimitStatus::infeasible: return "infeasible";
    case LimitStatus::failed: return "failed";
  }
  return "?";
}

LimitModel limit_model(const SceneSpec& scene) {
  const auto t0 = std::chrono::steady_clock::now();
  if (!(scene.simulation.gravity.norm() > 0.0))
    throw std::invalid_argument("simulation.gravity is zero: the limit analysis needs a dead load");
  RunSetup setup;
  const std::unique_ptr<Simulation> sim = build_simulation(scene, setup);
  const Blocks& b = sim->blocks();
  const Vec3 up = -scene.simulation.gravity.normalized();
  const JointMesh mesh = JointMesh::from_contacts(*sim, up, scene.simulation.overlap_tolerance);

  LimitModel m;
  m.gravity = scene.simulation.gravity;
  m.names = b.props.name;
  m.mass = b.props.mass;
  m.radius = b.props.radius;
  m.centroid = b.state.position;
  m.free.resize(b.count);
  for (int i = 0; i < b.count; ++i) m.free[i] = b.is_free(i) ? 1 : 0;
  if (std::none_of(m.free.begin(), m.free.end(), [](char f) { return f != 0; }))
    throw std::invalid_argument("the scene has no free block");
  for (const InitialJoint& j : mesh.joints) {
    LimitInterface f;
    f.ref = j.ref;
    f.inc = j.inc;
    const Mat3& Rr = b.state.rotation[j.ref];
    const Mat3& Rc = b.state.rotation[j.inc];
    f.normal = (Rr * j.normal_local).normalized();
    const double offset = j.offset_local + f.normal.dot(b.state.position[j.ref]);
    f.bed = j.bed;
    std::vector<Vec3> corners;
    for (int k = j.first; k < j.first + j.count; ++k) {
      const Vec3 p = Rc * mesh.corners[k] + b.state.position[j.inc];
      corners.push_back(p - (f.normal.dot(p) - offset) * f.normal);
    }
    f.vertices = extreme_points(corners, f.normal);
    m.vertices += static_cast<int>(f.vertices.size());
    m.redundant_vertices += j.count - static_cast<int>(f.vertices.size());
    m.interfaces.push_back(std::move(f));
  }
  m.detection_seconds = seconds_since(t0);
  return m;
}

LimitAnalysisResult limit_analysis(const LimitModel& model, const LimitAnalysisOptions& o) {
  const auto t_build = std::chrono::steady_clock::now();
  if (!(o.friction_angle_deg >= 0.0 && o.friction_angle_deg < 90.0))
    throw std::invalid_argument("friction angle must be in [0, 90) degrees");
  if (o.pyramid_sides < 3 || o.pyramid_sides > 360) throw std::invalid_argument("pyramid sides must be in [3, 360]");
  const double g_norm = model.gravity.norm();
  if (!(g_norm > 0.0)) throw std::invalid_argument("gravity is zero: the limit analysis needs a dead load");
  const Vec3 up = -model.gravity / g_norm;
  Vec3 d = o.direction - o.direction.dot(up) * up;
  if (!(d.norm() > 1e-9 * std::max(1.0, o.direction.norm())))
    throw std::invalid_argument("direction has no horizontal part (it is parallel to gravity)");
  d.normalize();

  LimitAnalysisResult r;
  r.friction_angle_deg = o.friction_angle_deg;
  r.direction = d;
  const int k = o.pyramid_sides;
  const double mu = std::tan(o.friction_angle_deg * std::numbers::pi / 180.0);
  const bool circ = o.pyramid == FrictionPyramid::circumscribed;
  r.generator_mu = circ ? mu / std::cos(std::numbers::pi / k) : mu;
  const double theta0 = o.pyramid_rotation + (circ ? std::numbers::pi / k : 0.0);
  // Without friction the pyramid is the normal alone.
  const int rays = mu > 0.0 ? k : 1;

  // Rows: 6 per free block, numbered in block order (1-based for GLPK).
  const int nb = static_cast<int>(model.mass.size());
  std::vector<int> row_of(nb, -1);
  int rows = 0;
  double weight = 0, length = 0;
  for (int i = 0; i < nb; ++i)
    if (model.free[i]) {
      row_of[i] = rows + 1;
      rows += 6;
      weight += model.mass[i] * g_norm;
      length += model.radius[i];
    }
  if (rows == 0) throw std::invalid_argument("the model has no free block");
  length /= rows / 6;
  std::vector<char> touched(nb, 0);
  for (const LimitInterface& f : model.interfaces) touched[f.ref] = touched[f.inc] = 1;
  for (int i = 0; i < nb; ++i)
    if (model.free[i] && !touched[i]) {
      std::ostringstream s;
      s << "block '" << model.names[i] << "' touches no other block at t = 0: it cannot be in equilibrium";
      throw std::invalid_argument(s.str());
    }

  // Columns: 1 = λ, then the generators, vertex by vertex.
  Triplets a;
  for (int i = 0; i < nb; ++i)
    if (model.free[i]) {
      const Vec3 load = model.mass[i] * g_norm * d / weight;
      for (int c = 0; c < 3; ++c) a.add(row_of[i] + c, 1, load[c]);
    }
  int col = 1;
  std::vector<Vec3> gen(rays);
  for (const LimitInterface& f : model.interfaces) {
    const Vec3 t1 = first_tangent(f.normal, d, up);
    const Vec3 t2 = f.normal.cross(t1);
    for (int j = 0; j < rays; ++j) {
      const double th = theta0 + 2.0 * std::numbers::pi * j / k;
      gen[j] = f.normal + (rays > 1 ? r.generator_mu : 0.0) * (std::cos(th) * t1 + std::sin(th) * t2);
    }
    for (const Vec3& p : f.vertices)
      for (int j = 0; j < rays; ++j) {
        ++col;
        for (const auto& [block, sign] : {std::pair{f.inc, 1.0}, std::pair{f.ref, -1.0}}) {
          if (row_of[block] < 0) continue;
          const Vec3 force = sign * gen[j];
          const Vec3 moment = (p - model.centroid[block]).cross(force) / length;
          for (int c = 0; c < 3; ++c) {
            a.add(row_of[block] + c, col, force[c]);
            a.add(row_of[block] + 3 + c, col, moment[c]);
          }
        }
      }
  }
  r.rows = rows;
  r.columns = col;
  r.nonzeros = a.size();

  GlpkProblem p;
  glp_set_obj_dir(p.lp, GLP_MAX);
  glp_add_rows(p.lp, rows);
  for (int i = 0; i < nb; ++i)
    if (model.free[i]) {
      const Vec3 dead = -model.mass[i] * model.gravity / weight;  // Σ f + λ·load = −m g
      for (int c = 0; c < 6; ++c) {
        const double rhs = c < 3 ? dead[c] : 0.0;
        glp_set_row_bnds(p.lp, row_of[i] + c, GLP_FX, rhs, rhs);
      }
    }
  glp_add_cols(p.lp, col);
  glp_set_col_bnds(p.lp, 1, GLP_DB, -kLambdaCap, kLambdaCap);
  glp_set_obj_coef(p.lp, 1, 1.0);
  for (int c = 2; c <= col; ++c) glp_set_col_bnds(p.lp, c, GLP_LO, 0.0, 0.0);
  glp_load_matrix(p.lp, a.size(), a.row.data(), a.col.data(), a.value.data());
  r.build_seconds = seconds_since(t_build);
  if (!o.lp_file.empty()) {
    QuietGlpk quiet;
    if (glp_write_mps(p.lp, GLP_MPS_FILE, nullptr, o.lp_file.c_str()) != 0)
      throw std::runtime_error("cannot write the LP to " + o.lp_file);
  }

  const auto t_solve = std::chrono::steady_clock::now();
  std::vector<double> dual(rows + 1, 0.0), primal(col + 1, 0.0);
  {
    QuietGlpk quiet;
    if (o.method == LpMethod::simplex) {
      glp_scale_prob(p.lp, GLP_SF_AUTO);
      glp_adv_basis(p.lp, 0);
      glp_smcp parm;
      glp_init_smcp(&parm);
      parm.msg_lev = GLP_MSG_OFF;
      const int rc = glp_simplex(p.lp, &parm);
      const int st = rc == 0 ? glp_get_status(p.lp) : GLP_UNDEF;
      if (st == GLP_OPT) {
        r.status = LimitStatus::optimal;
        r.lambda = glp_get_obj_val(p.lp);
        for (int i = 1; i <= rows; ++i) dual[i] = glp_get_row_dual(p.lp, i);
        for (int c = 1; c <= col; ++c) primal[c] = glp_get_col_prim(p.lp, c);
      } else if (st == GLP_NOFEAS) {
        r.status = LimitStatus::infeasible;
      }
    } else {
      // GLPK's interior point now and then stops on "numerical instability"
      // (the spire at φ = 20°, 1 solve in 20): another ordering of the
      // normal equations, then a tighter box on λ, usually gets through.
      for (const auto& [ordering, cap] : {std::pair{GLP_ORD_AMD, kLambdaCap}, std::pair{GLP_ORD_SYMAMD, kLambdaCap},
                                         std::pair{GLP_ORD_AMD, kLambdaCap / 10}, std::pair{GLP_ORD_SYMAMD, kLambdaCap / 10}}) {
        glp_set_col_bnds(p.lp, 1, GLP_DB, -cap, cap);
        glp_iptcp parm;
        glp_init_iptcp(&parm);
        parm.msg_lev = GLP_MSG_OFF;
        parm.ord_alg = ordering;
        const int rc = glp_interior(p.lp, &parm);
        const int st = rc == 0 ? glp_ipt_status(p.lp) : GLP_UNDEF;
        ++r.attempts;
        if (st == GLP_OPT) {
          r.status = LimitStatus::optimal;
          r.lambda = glp_ipt_obj_val(p.lp);
          if (r.lambda >= cap * (1.0 - 1e-9)) r.lambda = kLambdaCap;  // at the box: unbounded (below)
          for (int i = 1; i <= rows; ++i) dual[i] = glp_ipt_row_dual(p.lp, i);
          for (int c = 1; c <= col; ++c) primal[c] = glp_ipt_col_prim(p.lp, c);
          break;
        }
        if (rc == GLP_ENOFEAS || st == GLP_NOFEAS) {
          r.status = LimitStatus::infeasible;
          break;
        }
      }
    }
  }
  r.solve_seconds = seconds_since(t_solve);
  if (r.status == LimitStatus::optimal && r.lambda >= kLambdaCap * (1.0 - 1e-9)) {
    r.status = LimitStatus::unbounded;
    r.lambda = std::numeric_limits<double>::infinity();
  }
  if (r.status != LimitStatus::optimal) return r;

  // A posteriori check with our own matrix, not the solver's: the forces
  // balance every block (residual over the free weight), none is negative,
  // and the duals are a mechanism (every generator's power ≥ 0, the load's
  // = 1, over the largest dual) whose work against gravity is λ.
  std::vector<double> residual(rows + 1, 0.0), power(col + 1, 0.0);
  for (int e = 1; e <= a.size(); ++e) {
    residual[a.row[e]] += a.value[e] * primal[a.col[e]];
    power[a.col[e]] += a.value[e] * dual[a.row[e]];
  }
  double dual_scale = 0, dead_work = 0;
  for (int i = 1; i <= rows; ++i) {
    residual[i] -= glp_get_row_lb(p.lp, i);
    r.primal_residual = std::max(r.primal_residual, std::abs(residual[i]));
    dual_scale = std::max(dual_scale, std::abs(dual[i]));
    dead_work += glp_get_row_lb(p.lp, i) * dual[i];
  }
  for (int c = 2; c <= col; ++c) r.primal_residual = std::max(r.primal_residual, -primal[c]);
  r.dual_residual = std::abs(power[1] - 1.0);
  for (int c = 2; c <= col; ++c) r.dual_residual = std::max(r.dual_residual, -power[c] / dual_scale);
  r.dual_residual = std::max(r.dual_residual, std::abs(dead_work - r.lambda) / std::max(1.0, std::abs(r.lambda)));
  if (!(r.primal_residual <= kCheckTolerance && r.dual_residual <= kCheckTolerance)) {
    r.status = LimitStatus::failed;
    r.lambda = std::numeric_limits<double>::quiet_NaN();
    return r;
  }

  // The mechanism: v = the force rows' duals, ω = the moment rows' over the
  // moment scale (the generator's dual constraint is g·Δu(p) ≥ 0).
  LimitMechanism& m = r.mechanism;
  m.velocity.assign(nb, Vec3::Zero());
  m.angular_velocity.assign(nb, Vec3::Zero());
  m.moving.assign(nb, 0);
  m.speed.assign(nb, 0.0);
  double top = 0;
  for (int i = 0; i < nb; ++i)
    if (model.free[i]) {
      m.velocity[i] = Vec3(dual[row_of[i]], dual[row_of[i] + 1], dual[row_of[i] + 2]);
      m.angular_velocity[i] = Vec3(dual[row_of[i] + 3], dual[row_of[i] + 4], dual[row_of[i] + 5]) / length;
      top = std::max(top, m.velocity[i].norm() + m.angular_velocity[i].norm() * model.radius[i]);
    }
  if (top > 0)
    for (int i = 0; i < nb; ++i) {
      m.velocity[i] /= top;
      m.angular_velocity[i] /= top;
      m.speed[i] = m.velocity[i].norm() + m.angular_velocity[i].norm() * model.radius[i];
      if (m.speed[i] > o.motion_tolerance) {
        m.moving[i] = 1;
        ++m.blocks_moving;
        m.mass_moving += model.mass[i];
      }
    }
  const auto speed_at = [&](int i, const Vec3& p) -> Vec3 {
    return m.velocity[i] + m.angular_velocity[i].cross(p - model.centroid[i]);
  };
  for (const LimitInterface& f : model.interfaces) {
    double vn = 0, vt = 0;
    for (const Vec3& p : f.vertices) {
      const Vec3 du = speed_at(f.inc, p) - speed_at(f.ref, p);
      const double n = du.dot(f.normal);
      vn = std::max(vn, n);
      vt = std::max(vt, (du - n * f.normal).norm());
    }
    InterfaceMotion im = InterfaceMotion::closed;
    if (vt > o.motion_tolerance) im = InterfaceMotion::sliding;
    else if (vn > o.motion_tolerance) im = InterfaceMotion::opening;
    m.motion.push_back(im);
    if (im == InterfaceMotion::sliding) {
      ++m.sliding;
      m.sliding_bed += f.bed;
    } else if (im == InterfaceMotion::opening) {
      ++m.opening;
      m.opening_bed += f.bed;
    }
  }
  return r;
}

}  // namespace polydem
