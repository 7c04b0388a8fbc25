#include "run/checks.hpp"

#include "run/scene_error.hpp"

#include "analytical/free_rocking.hpp"
#include "analytical/rocking_body.hpp"
#include "analytical/rocking_response.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace polydem {

namespace {

[[noreturn]] void fail(const SceneSpec& spec, const CheckSpec& c, const std::string& what) {
  throw SceneError("check.kind", "(" + c.kind + ")", c.deck_line, what);
}

CheckResult result(const CheckSpec& c, std::string unit, double measured, double expected, bool relative,
                   std::string note = {}) {
  CheckResult r;
  r.name = c.kind + (c.block.empty() ? "" : ":" + c.block);
  r.unit = std::move(unit);
  r.measured = measured;
  r.expected = std::isnan(c.expected) ? expected : c.expected;
  r.tolerance = c.tolerance;
  const double err = std::abs(measured - r.expected);
  r.passed = std::isfinite(measured) && (relative ? err <= c.tolerance * std::abs(r.expected) : err <= c.tolerance);
  r.note = std::move(note);
  return r;
}

Vec3 up_direction(const SceneSpec& spec) {
  const double g = spec.simulation.gravity.norm();
  return g > 0 ? Vec3(-spec.simulation.gravity / g) : Vec3(0, 0, 1);
}

int block_index(const SceneSpec& spec, const CheckSpec& c, const Simulation& sim, bool must_be_free = true) {
  const int i = sim.blocks().find(c.block);
  if (i < 0) fail(spec, c, "needs `block` naming a block of the deck");
  if (must_be_free && !sim.blocks().is_free(i)) fail(spec, c, "block '" + c.block + "' must be free");
  return i;
}

// ---- resting weight: the joints carry the block's weight ------------------
class RestingWeight : public CheckMonitor {
 public:
  RestingWeight(const CheckSpec& c, const SceneSpec& s, const Simulation& sim)
      : c_(c), up_(up_direction(s)), i_(block_index(s, c, sim)), g_(s.simulation.gravity.norm()) {}
  void observe(const Simulation&) override {}
  void save(ByteWriter&) const override {}
  void load(ByteReader&) override {}
  CheckResult finish(const Simulation& sim) override {
    const double carried = sim.blocks().state.contact_force[i_].dot(up_);
    return result(c_, "N", carried, sim.blocks().props.mass[i_] * g_, true,
                  "sum of the joint forces on the block along the vertical at the end");
  }

 private:
  CheckSpec c_;
  Vec3 up_;
  int i_;
  double g_;
};

// ---- no drift: the block stays where it was put ---------------------------
class NoDrift : public CheckMonitor {
 public:
  NoDrift(const CheckSpec& c, const SceneSpec& s, const Simulation& sim)
      : c_(c), i_(block_index(s, c, sim)), x0_(sim.blocks().state.position[i_]) {}
  void observe(const Simulation& sim) override {
    worst_ = std::max(worst_, (sim.blocks().state.position[i_] - x0_).norm());
  }
  CheckResult finish(const Simulation&) override {
    return result(c_, "m", worst_, 0.0, false, "largest displacement of the centroid during the run");
  }
  void save(ByteWriter& w) const override { w.put(worst_); }
  void load(ByteReader& r) override { r.get(worst_); }

 private:
  CheckSpec c_;
  int i_;
  Vec3 x0_;
  double worst_ = 0;
};

// ---- Coulomb slope: slide at g(sin θ − cos θ tan φ), or stick --------------
struct Slope {
  Vec3 down;      // unit, down the slope in the base plane
  double theta;   // rad
};
Slope slope_of(const SceneSpec& s) {
  const Vec3 g = s.simulation.gravity;
  const Vec3 along(g.x(), g.y(), 0.0);
  Slope sl;
  sl.theta = std::atan2(along.norm(), -g.z());
  sl.down = along.norm() > 0 ? Vec3(along.normalized()) : Vec3(1, 0, 0);
  return sl;
}

// The law of the joint block i stands on: the law between block i and the
// first block it touches that is not free (its base), or the default law if
// it touches none.
const JointLaw& base_joint_law(const Simulation& sim, int i) {
  const JointLaws& laws = sim.joint_laws();
  for (const ContactPair& p : sim.contacts().pairs) {
    const int other = p.a == i ? p.b : p.b == i ? p.a : -1;
    if (other >= 0 && !sim.blocks().is_free(other)) return laws.between(i, other);
  }
  return laws.laws[0];
}

class SlideAcceleration : public CheckMonitor {
 public:
  SlideAcceleration(const CheckSpec& c, const SceneSpec& s, const Simulation& sim)
      : c_(c), i_(block_index(s, c, sim)), slope_(slope_of(s)), g_(s.simulation.gravity.norm()),
        tan_phi_(base_joint_law(sim, i_).tan_phi), half_(0.5 * s.simulation.end_time) {}
  void observe(const Simulation& sim) override {
    const double t = sim.time() - sim.dt();  // time of the mid-step velocity
    const double v = sim.velocity_at_force_time(i_).dot(slope_.down);
    if (t >= half_ && !has_half_) {
      t1_ = t;
      v1_ = v;
      has_half_ = true;
    }
    t2_ = t;
    v2_ = v;
  }
  CheckResult finish(const Simulation&) override {
    const double a = has_half_ && t2_ > t1_ ? (v2_ - v1_) / (t2_ - t1_) : std::numeric_limits<double>::quiet_NaN();
    const double expected = g_ * (std::sin(slope_.theta) - std::cos(slope_.theta) * tan_phi_);
    return result(c_, "m/s^2", a, expected, true,
                  "mean acceleration down the slope over the second half of the run");
  }
  void save(ByteWriter& w) const override {
    w.put(has_half_);
    for (double x : {t1_, v1_, t2_, v2_}) w.put(x);
  }
  void load(ByteReader& r) override {
    r.get(has_half_);
    for (double* x : {&t1_, &v1_, &t2_, &v2_}) r.get(*x);
  }

 private:
  CheckSpec c_;
  int i_;
  Slope slope_;
  double g_, tan_phi_, half_;
  bool has_half_ = false;
  double t1_ = 0, v1_ = 0, t2_ = 0, v2_ = 0;
};

class Stick : public CheckMonitor {
 public:
  Stick(const CheckSpec& c, const SceneSpec& s, const Simulation& sim)
      : c_(c), i_(block_index(s, c, sim)), slope_(slope_of(s)), x0_(sim.blocks().state.position[i_]) {}
  void observe(const Simulation&) override {}
  void save(ByteWriter&) const override {}
  void load(ByteReader&) override {}
  CheckResult finish(const Simulation& sim) override {
    const double d = (sim.blocks().state.position[i_] - x0_).dot(slope_.down);
    return result(c_, "m", d, 0.0, false, "displacement down the slope at the end of the run");
  }

 private:
  CheckSpec c_;
  int i_;
  Slope slope_;
  Vec3 x0_;
};

// ---- rocking ---------------------------------------------------------------
// The rocking geometry of a block standing on its bottom face: the bottom
// face is the one most opposed to `up` at t = 0 (for a tilted block, the face
// it stands on when upright).
struct RockingGeometry {
  int bottom_face = 0;  // local face index
  Vec3 axis;            // world, rocking axis (θ > 0 rotates about it)
  double b = 0, h = 0, R = 0, alpha = 0, I0 = 0, p = 0, restitution = 0;
};

// Signed tilt of the block: the angle from −up to the bottom face normal,
// about `axis`.
double tilt(const Simulation& sim, int i, const RockingGeometry& rg, const Vec3& up) {
  const Vec3 n = sim.blocks().state.rotation[i] * sim.blocks().props.local_shape[i].normals[rg.bottom_face];
  const Vec3 down = -up;
  return std::atan2(down.cross(n).dot(rg.axis), down.dot(n));
}

RockingGeometry rocking_geometry(const Simulation& sim, int i, const Vec3& up, const Vec3& rock_dir, double g) {
  const Blocks& b = sim.blocks();
  const Polyhedron& shape = b.props.local_shape[i];
  const Mat3& R = b.state.rotation[i];
  RockingGeometry rg;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < shape.faces.size(); ++f) {
    const double c = (R * shape.normals[f]).dot(up);
    if (c < best) {
      best = c;
      rg.bottom_face = static_cast<int>(f);
    }
  }
  const Vec3 nb = shape.normals[rg.bottom_face];  // local, outward (down when upright)
  rg.h = shape.offsets[rg.bottom_face];           // centroid (origin) to the bottom plane
  // Rocking direction in the block's frame, in the bottom face's plane.
  Vec3 e = R.transpose() * rock_dir;
  e -= e.dot(nb) * nb;
  e.normalize();
  double bmax = 0;
  for (int v : shape.faces[rg.bottom_face]) bmax = std::max(bmax, std::abs(shape.vertices[v].dot(e)));
  rg.b = bmax;
  const Vec3 axis_local = nb.cross(e).normalized();
  rg.axis = R * axis_local;
  const Vec3 Ic = b.props.principal_inertia[i];
  const double I_axis = axis_local.dot(Ic.cwiseProduct(axis_local));
  const double m = b.props.mass[i];
  rg.R = std::hypot(rg.b, rg.h);
  rg.alpha = std::atan2(rg.b, rg.h);
  rg.I0 = I_axis + m * rg.R * rg.R;
  rg.p = std::sqrt(m * g * rg.R / rg.I0);
  rg.restitution = analytical::restitution_eq10(m, rg.R, rg.I0, rg.alpha);
  return rg;
}

class RockingOnset : public CheckMonitor {
 public:
  RockingOnset(const CheckSpec& c, const SceneSpec& s, const Simulation& sim)
      : c_(c), i_(block_index(s, c, sim)), g_(s.simulation.gravity.norm()) {
    if (!sim.ground_motion().active()) fail(s, c, "needs a [ground_motion] (a slow ramp)");
    const Vec3 up = up_direction(s);
    // The ground accelerates along d; the inertial force pushes the block to
    // −d, so it pivots on its edge furthest along −d: b is measured that way.
    const Vec3 d = sim.ground_motion().direction;
    rg_ = rocking_geometry(sim, i_, up, d, g_);
    // The heel has opened when its gap exceeds a thousandth of the elastic
    // compression under the block's own weight.
    threshold_ = 1e-3 * sim.blocks().props.mass[i_] * g_ /
                 (base_joint_law(sim, i_).kn * face_area(sim.blocks().props.local_shape[i_], rg_.bottom_face));
  }
  void observe(const Simulation& sim) override {
    if (found_) return;
    if (sim.largest_opening(i_) > threshold_) {
      found_ = true;
      const double t = sim.time() - sim.dt();
      onset_ = std::abs(sim.ground_motion().acceleration_at(t)) / g_;
    }
  }
  CheckResult finish(const Simulation&) override {
    return result(c_, "g", found_ ? onset_ : std::numeric_limits<double>::quiet_NaN(), rg_.b / rg_.h, true,
                  "ground acceleration (in g) when the heel first opens; expected b/h");
  }
  void save(ByteWriter& w) const override {
    w.put(found_);
    w.put(onset_);
  }
  void load(ByteReader& r) override {
    r.get(found_);
    r.get(onset_);
  }

 private:
  CheckSpec c_;
  int i_;
  double g_;
  RockingGeometry rg_;
  double threshold_ = 0;
  bool found_ = false;
  double onset_ = 0;
};

// Free rocking from a tilt: impacts are the sign changes of the tilt θ.
class FreeRocking : public CheckMonitor {
 public:
  FreeRocking(const CheckSpec& c, const SceneSpec& s, const Simulation& sim, bool restitution)
      : c_(c), i_(block_index(s, c, sim)), up_(up_direction(s)), g_(s.simulation.gravity.norm()),
        restitution_(restitution) {
    // Rocking direction: horizontal direction of the bottom face normal's tilt.
    const Blocks& b = sim.blocks();
    const Polyhedron& shape = b.props.local_shape[i_];
    int bottom = 0;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t f = 0; f < shape.faces.size(); ++f) {
      const double cc = (b.state.rotation[i_] * shape.normals[f]).dot(up_);
      if (cc < best) {
        best = cc;
        bottom = static_cast<int>(f);
      }
    }
    Vec3 n = b.state.rotation[i_] * shape.normals[bottom];
    Vec3 dir = n - n.dot(up_) * up_;
    if (dir.norm() < 1e-9) fail(s, c, "block '" + c.block + "' must start tilted");
    rg_ = rocking_geometry(sim, i_, up_, dir.normalized(), g_);
    theta0_ = std::abs(tilt(sim, i_, rg_, up_));
    peak_ = theta0_;
    last_theta_ = tilt(sim, i_, rg_, up_);
  }
  void observe(const Simulation& sim) override {
    const double theta = tilt(sim, i_, rg_, up_);
    if ((theta > 0) != (last_theta_ > 0) && theta != 0) {
      // Zero crossing of the tilt: an impact. The half-cycle before it closes.
      if (amplitudes_.empty()) first_impact_ = sim.time() - (theta / (theta - last_theta_)) * sim.dt();
      amplitudes_.push_back(peak_);
      peak_ = 0;
    }
    peak_ = std::max(peak_, std::abs(theta));
    last_theta_ = theta;
  }
  CheckResult finish(const Simulation&) override {
    if (!restitution_) {
      const double exact = analytical::free_rocking_time_to_impact(rg_.p, rg_.alpha, theta0_);
      std::ostringstream note;
      note << "time from release at " << theta0_ << " rad to the first impact; exact nonlinear eq. 7 (p = "
           << rg_.p << " rad/s, alpha = " << rg_.alpha << " rad)";
      return result(c_, "s", !amplitudes_.empty() ? first_impact_ : std::numeric_limits<double>::quiet_NaN(), exact, true,
                    note.str());
    }
    // Between impacts the block is a rigid body rocking freely, so the
    // energy integral of eq. 7 turns each half-cycle's amplitude into the
    // angular velocity at the impact: ω² = 2p²(cos(α − θ_max) − cos α). The
    // ratio across impact k compares the half-cycles on either side of it
    // (independent of how long the elastic impact lasts). Worst of the first
    // three impacts; later ones are small.
    auto omega = [&](double amplitude) {
      return rg_.p * std::sqrt(std::max(0.0, 2 * (std::cos(rg_.alpha - amplitude) - std::cos(rg_.alpha))));
    };
    double worst = std::numeric_limits<double>::quiet_NaN();
    std::ostringstream note;
    note << "omega after / omega before each impact, from the half-cycle amplitudes:";
    const std::size_t n = amplitudes_.size() >= 4 ? 3 : 0;
    for (std::size_t k = 0; k < n; ++k) {
      const double ratio = omega(amplitudes_[k + 1]) / omega(amplitudes_[k]);
      note << " " << ratio;
      if (std::isnan(worst) || std::abs(ratio - rg_.restitution) > std::abs(worst - rg_.restitution)) worst = ratio;
    }
    note << "; Housner/eq. 10 with alpha = " << rg_.alpha << " rad";
    return result(c_, "-", worst, rg_.restitution, true, note.str());
  }
  void save(ByteWriter& w) const override {
    for (double x : {theta0_, last_theta_, first_impact_, peak_}) w.put(x);
    w.put(amplitudes_);
  }
  void load(ByteReader& r) override {
    for (double* x : {&theta0_, &last_theta_, &first_impact_, &peak_}) r.get(*x);
    r.get(amplitudes_);
  }

 private:
  CheckSpec c_;
  int i_;
  Vec3 up_;
  double g_;
  bool restitution_;
  RockingGeometry rg_;
  double theta0_ = 0, last_theta_ = 0;
  double first_impact_ = 0;
  double peak_ = 0;
  std::vector<double> amplitudes_;  // largest |θ| of each half-cycle
};

// ---- energy ----------------------------------------------------------------
// Rocking under a one-sine ground pulse: the block's peak rotation about its
// rocking axis against Housner's rigid rocking body (eq. 7 with the impact
// of eq. 10, analytical/rocking_response.hpp) under the same pulse. The
// DEM's joints are stiff springs, not a rigid base, so the two agree to a
// few per cent, not to the integrator's accuracy.
class PulsePeakRotation : public CheckMonitor {
 public:
  PulsePeakRotation(const CheckSpec& c, const SceneSpec& s, const Simulation& sim)
      : c_(c), i_(block_index(s, c, sim)), g_(s.simulation.gravity.norm()) {
    const GroundMotionSpec& gm = s.ground_motion;
    if (gm.kind != GroundMotionKind::sine_pulse) fail(s, c, "needs a [ground_motion] of kind \"sine_pulse\"");
    if (gm.start_time != 0.0) fail(s, c, "needs the pulse to start at t = 0 (ground_motion.start_time = 0)");
    // The ground accelerates along d at first; the block pivots on its edge
    // furthest along −d (as for the onset).
    rg_ = rocking_geometry(sim, i_, up_direction(s), gm.direction, g_);
    q0_ = sim.blocks().initial_orientation[i_];
    const analytical::RockingBody body =
        analytical::make_rocking_body(sim.blocks().props.mass[i_], rg_.R, rg_.alpha, rg_.I0, g_);
    analytical::RockingOptions o;
    o.dt = 1e-4;
    o.t_end = s.simulation.end_time;
    o.g = g_;
    o.stop_when_safe = false;  // the peak comes in the free rocking after the pulse
    const analytical::RockingResult r =
        analytical::simulate_rocking(body, analytical::sine_pulse_ground_motion(gm.acceleration, gm.period), o);
    expected_ = r.max_abs_theta;
  }
  void observe(const Simulation& sim) override {
    const Eigen::AngleAxisd aa(sim.orientation_at_force_time(i_) * q0_.conjugate());
    double angle = aa.angle();
    if (angle > M_PI) angle -= 2 * M_PI;
    peak_ = std::max(peak_, std::abs(angle * aa.axis().dot(rg_.axis)));
  }
  CheckResult finish(const Simulation&) override {
    return result(c_, "rad", peak_, expected_, true,
                  "peak rotation about the rocking axis; expected: rigid rocking body (eq. 7, 10) under the pulse");
  }
  void save(ByteWriter& w) const override { w.put(peak_); }
  void load(ByteReader& r) override { r.get(peak_); }

 private:
  CheckSpec c_;
  int i_;
  double g_;
  RockingGeometry rg_;
  Quat q0_;
  double expected_ = 0, peak_ = 0;
};

// The same pulse against the rigid rocking body made of every free block
// together (a column of drums rocking as one piece on its base): mass,
// centroid and inertia summed over the free blocks, pivoting on the edge of
// `block`'s bottom face furthest along −d (`block` is the stack's lowest).
// Measured: `block`'s peak rotation about that edge.
class StackPulsePeakRotation : public CheckMonitor {
 public:
  StackPulsePeakRotation(const CheckSpec& c, const SceneSpec& s, const Simulation& sim)
      : c_(c), i_(block_index(s, c, sim)), g_(s.simulation.gravity.norm()) {
    const GroundMotionSpec& gm = s.ground_motion;
    if (gm.kind != GroundMotionKind::sine_pulse) fail(s, c, "needs a [ground_motion] of kind \"sine_pulse\"");
    if (gm.start_time != 0.0) fail(s, c, "needs the pulse to start at t = 0 (ground_motion.start_time = 0)");
    const Vec3 up = up_direction(s);
    rg_ = rocking_geometry(sim, i_, up, gm.direction, g_);
    const Blocks& b = sim.blocks();
    // The pivot: on the bottom plane, b along −e from the bottom block's
    // centroid's foot (e the rocking direction in that plane).
    const Vec3 nb = b.state.rotation[i_] * b.props.local_shape[i_].normals[rg_.bottom_face];
    const Vec3 e = nb.cross(rg_.axis).normalized() * -1.0;  // axis = nb × e
    const Vec3 foot = b.state.position[i_] + rg_.h * nb;
    const Vec3 pivot = foot - rg_.b * e;
    double m = 0, I = 0;
    Vec3 c_sum = Vec3::Zero();
    for (int k : b.free_blocks) {
      const double mk = b.props.mass[k];
      const Vec3 ax = b.state.rotation[k].transpose() * rg_.axis;
      const Vec3 r = b.state.position[k] - pivot;
      I += ax.dot(b.props.principal_inertia[k].cwiseProduct(ax)) + mk * (r - r.dot(rg_.axis) * rg_.axis).squaredNorm();
      m += mk;
      c_sum += mk * b.state.position[k];
    }
    const Vec3 rc = c_sum / m - pivot;
    const double height = rc.dot(-nb), lever = rc.dot(e);
    const double R = std::hypot(height, lever), alpha = std::atan2(lever, height);
    q0_ = b.initial_orientation[i_];
    const analytical::RockingBody body = analytical::make_rocking_body(m, R, alpha, I, g_);
    analytical::RockingOptions o;
    o.dt = 1e-4;
    o.t_end = s.simulation.end_time;
    o.g = g_;
    o.stop_when_safe = false;
    const analytical::RockingResult res =
        analytical::simulate_rocking(body, analytical::sine_pulse_ground_motion(gm.acceleration, gm.period), o);
    expected_ = res.max_abs_theta;
  }
  void observe(const Simulation& sim) override {
    const Eigen::AngleAxisd aa(sim.orientation_at_force_time(i_) * q0_.conjugate());
    double angle = aa.angle();
    if (angle > M_PI) angle -= 2 * M_PI;
    peak_ = std::max(peak_, std::abs(angle * aa.axis().dot(rg_.axis)));
  }
  CheckResult finish(const Simulation&) override {
    return result(c_, "rad", peak_, expected_, true,
                  "peak rotation about the rocking axis; expected: every free block as one rigid rocking body "
                  "(eq. 7, 10) under the pulse");
  }
  void save(ByteWriter& w) const override { w.put(peak_); }
  void load(ByteReader& r) override { r.get(peak_); }

 private:
  CheckSpec c_;
  int i_;
  double g_;
  RockingGeometry rg_;
  Quat q0_;
  double expected_ = 0, peak_ = 0;
};

class EnergyCheck : public CheckMonitor {
 public:
  EnergyCheck(const CheckSpec& c, bool conservation) : c_(c), conservation_(conservation) {}
  void observe(const Simulation& sim) override {
    // The ledger costs a pass over all blocks and subcontacts: sample it
    // every 8th step (and always at the start).
    if (!first_ && sim.steps() % 8 != 0) return;
    const EnergyLedger e = sim.energies();
    if (first_) {
      e0_ = e;
      first_ = false;
    }
    reference_ = std::max(reference_, energy_put_in(e, e0_));
    worst_drift_ = std::max(worst_drift_, std::abs(numerical_energy(e, e0_)));
    const double mech = e.kinetic + e.gravitational + e.strain - e.load_work;
    const double mech0 = e0_.kinetic + e0_.gravitational + e0_.strain - e0_.load_work;
    worst_growth_ = std::max(worst_growth_, mech - mech0);
  }
  CheckResult finish(const Simulation&) override {
    const double ref = reference_ > 0 ? reference_ : 1.0;
    if (conservation_)
      return result(c_, "-", worst_drift_ / ref, 0.0, false,
                    "largest |numerical| energy relative to the energy put in");
    CheckResult r = result(c_, "-", worst_growth_ / ref, 0.0, false,
                           "largest growth of kinetic+potential+strain energy beyond the load work, relative to the "
                           "energy put in");
    r.passed = worst_growth_ / ref <= c_.tolerance;
    return r;
  }
  void save(ByteWriter& w) const override {
    w.put(first_);
    for (double x : {e0_.kinetic, e0_.gravitational, e0_.strain, e0_.slip, e0_.damping, e0_.load_work, e0_.balance,
                     reference_, worst_drift_, worst_growth_})
      w.put(x);
  }
  void load(ByteReader& r) override {
    r.get(first_);
    for (double* x : {&e0_.kinetic, &e0_.gravitational, &e0_.strain, &e0_.slip, &e0_.damping, &e0_.load_work,
                      &e0_.balance, &reference_, &worst_drift_, &worst_growth_})
      r.get(*x);
  }

 private:
  CheckSpec c_;
  bool conservation_;
  bool first_ = true;
  EnergyLedger e0_;
  double reference_ = 0, worst_drift_ = 0, worst_growth_ = 0;
};

}  // namespace

std::unique_ptr<CheckMonitor> make_check(const CheckSpec& c, const SceneSpec& spec, const Simulation& sim) {
  if (c.kind == "resting_weight") return std::make_unique<RestingWeight>(c, spec, sim);
  if (c.kind == "no_drift") return std::make_unique<NoDrift>(c, spec, sim);
  if (c.kind == "slide_acceleration") return std::make_unique<SlideAcceleration>(c, spec, sim);
  if (c.kind == "stick") return std::make_unique<Stick>(c, spec, sim);
  if (c.kind == "rocking_onset") return std::make_unique<RockingOnset>(c, spec, sim);
  if (c.kind == "housner_restitution") return std::make_unique<FreeRocking>(c, spec, sim, true);
  if (c.kind == "rocking_first_impact") return std::make_unique<FreeRocking>(c, spec, sim, false);
  if (c.kind == "pulse_peak_rotation") return std::make_unique<PulsePeakRotation>(c, spec, sim);
  if (c.kind == "stack_pulse_peak_rotation") return std::make_unique<StackPulsePeakRotation>(c, spec, sim);
  if (c.kind == "energy_conservation") return std::make_unique<EnergyCheck>(c, true);
  if (c.kind == "energy_no_growth") return std::make_unique<EnergyCheck>(c, false);
  fail(spec, c, "unknown check kind");
}

}  // namespace polydem
