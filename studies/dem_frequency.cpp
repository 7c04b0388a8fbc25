#include "studies/dem_frequency.hpp"
#include "core/units.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analytical/beam_modes.hpp"
#include "contact/joint_law.hpp"
#include "core/blocks.hpp"
#include "run/run_scene.hpp"
#include "structures/generator_specs.hpp"

namespace polydem {

namespace {

constexpr double kPi = 3.14159265358979323846;

// |Σ w_k u_k e^{-iωt_k}| with Hann weights over [t_0, t_end] and trapezoid
// spacing weights.
double fourier_amplitude(const std::vector<double>& t, const std::vector<double>& u, double f) {
  const std::size_t n = t.size();
  const double t0 = t.front(), T = t.back() - t.front();
  const double w = 2.0 * kPi * f;
  double re = 0.0, im = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double dt = 0.5 * ((k + 1 < n ? t[k + 1] : t[k]) - (k > 0 ? t[k - 1] : t[k]));
    const double hann = 0.5 - 0.5 * std::cos(2.0 * kPi * (t[k] - t0) / T);
    const double a = hann * dt * u[k];
    re += a * std::cos(w * t[k]);
    im -= a * std::sin(w * t[k]);
  }
  return std::hypot(re, im);
}

}  // namespace

double fourier_peak_hz(const std::vector<double>& t, const std::vector<double>& u, double f_min, double f_max) {
  if (t.size() < 8 || t.size() != u.size() || !(t.back() > t.front())) return 0.0;
  double mean = 0.0;
  for (double v : u) mean += v;
  mean /= static_cast<double>(u.size());
  std::vector<double> c(u.size());
  for (std::size_t k = 0; k < u.size(); ++k) c[k] = u[k] - mean;
  // Scan at a quarter of the resolution 1/T, then golden section on the
  // bracket around the largest value.
  const double T = t.back() - t.front();
  const double df = 0.25 / T;
  double best_f = f_min, best_a = -1.0;
  for (double f = f_min; f <= f_max; f += df) {
    const double a = fourier_amplitude(t, c, f);
    if (a > best_a) {
      best_a = a;
      best_f = f;
    }
  }
  double lo = std::max(f_min, best_f - df), hi = std::min(f_max, best_f + df);
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = hi - r * (hi - lo), x2 = lo + r * (hi - lo);
  double a1 = fourier_amplitude(t, c, x1), a2 = fourier_amplitude(t, c, x2);
  for (int it = 0; it < 60 && hi - lo > 1e-9 * best_f; ++it) {
    if (a1 > a2) {
      hi = x2;
      x2 = x1;
      a2 = a1;
      x1 = hi - r * (hi - lo);
      a1 = fourier_amplitude(t, c, x1);
    } else {
      lo = x1;
      x1 = x2;
      a1 = a2;
      x2 = lo + r * (hi - lo);
      a2 = fourier_amplitude(t, c, x2);
    }
  }
  return 0.5 * (lo + hi);
}

double zero_crossing_hz(const std::vector<double>& t, const std::vector<double>& u, int* crossings) {
  if (crossings) *crossings = 0;
  if (t.size() < 3 || t.size() != u.size()) return 0.0;
  double mean = 0.0;
  for (double v : u) mean += v;
  mean /= static_cast<double>(u.size());
  std::vector<double> tc;
  for (std::size_t k = 1; k < u.size(); ++k) {
    const double a = u[k - 1] - mean, b = u[k] - mean;
    if ((a < 0.0 && b >= 0.0) || (a > 0.0 && b <= 0.0)) tc.push_back(t[k - 1] + (t[k] - t[k - 1]) * a / (a - b));
  }
  if (crossings) *crossings = static_cast<int>(tc.size());
  if (tc.size() < 3) return 0.0;
  return static_cast<double>(tc.size() - 1) / (2.0 * (tc.back() - tc.front()));
}

std::string spire_tip_block(const SceneSpec& scene) {
  for (const auto& b : scene.blocks)
    if (b.name == "tip" && b.motion == BlockMotion::free) return b.name;
  std::string best;
  double top = -1e300;
  for (const auto& b : scene.blocks) {
    if (b.motion != BlockMotion::free) continue;
    const double c = mass_properties(b.shape).centroid.z();
    if (c > top) {
      top = c;
      best = b.name;
    }
  }
  return best;
}

double spire_joint_normal_stiffness(const SceneSpec& scene) {
  const Blocks blocks = build_blocks(scene.blocks);
  const JointLaws laws = make_joint_laws(blocks, scene.joint, scene.joint_pairs);
  std::vector<char> free(static_cast<std::size_t>(blocks.count), 0);
  for (int i = 0; i < blocks.count; ++i) free[static_cast<std::size_t>(i)] = blocks.is_free(i) ? 1 : 0;
  const std::vector<int> acting = acting_laws(laws, free);
  const double kn = laws.laws[static_cast<std::size_t>(acting.at(0))].kn;
  for (const int k : acting)
    if (laws.laws[static_cast<std::size_t>(k)].kn != kn)
      throw std::runtime_error(
          "dem-frequency: the spire's joints have different normal stiffnesses ([[joint]] between); the beam "
          "estimate needs one");
  return kn;
}

DemFrequencyResult measure_dem_frequency(SceneSpec scene, const DemFrequencyOptions& o) {
  const SpireSpec* spire = spire_of(scene.generators);
  if (!spire) throw std::runtime_error("dem-frequency: the deck has no [spire]");
  if (!(o.duration > 0.0) || !(o.pulse_period > 0.0) || !(o.history_interval > 0.0) || o.settle_time < 0.0)
    throw std::runtime_error("dem-frequency: duration, pulse period and interval must be > 0, settle time >= 0");
  DemFrequencyResult res;
  res.tip = spire_tip_block(scene);
  if (res.tip.empty()) throw std::runtime_error("dem-frequency: no free block to monitor");
  const double g = scene.simulation.gravity.norm() > 0 ? scene.simulation.gravity.norm() : kGravity;

  // The beam estimate.
  const SpireModel model = build_spire(*spire);
  res.kn = spire_joint_normal_stiffness(scene);
  res.course_height = model.course_height;
  res.E_eq = res.kn * res.course_height;
  res.density = 2600.0;
  for (const auto& b : scene.blocks)
    if (b.name == res.tip) res.density = b.density;
  res.wall_thickness = spire->wall_thickness;
  res.outer_apothem = spire->base_inradius + 0.5 * spire->wall_thickness;
  res.height = spire->height;
  res.Omega1 = analytical::tapered_cantilever_omegas(1).at(0);
  res.section = analytical::hollow_octagon_section(res.outer_apothem, res.wall_thickness, res.density, res.E_eq);
  res.f_beam_hz = analytical::natural_frequency_hz(res.Omega1, res.section.mass_per_height,
                                                   res.section.bending_stiffness, res.height);

  // The run.
  const Vec3 dir(std::cos(o.azimuth), std::sin(o.azimuth), 0.0);
  scene.ground_motion = GroundMotionSpec{};
  scene.ground_motion.kind = GroundMotionKind::sine_pulse;
  scene.ground_motion.applied_as = GroundMotionApplication::body_force;
  scene.ground_motion.direction = dir;
  scene.ground_motion.start_time = o.settle_time;
  scene.ground_motion.acceleration = o.pulse_g * g;
  scene.ground_motion.period = o.pulse_period;
  if (!o.keep_damping) {
    scene.joint.damping = 0.0;
    for (JointPairSpec& p : scene.joint_pairs) p.joint.damping = 0.0;  // every law's ([[joint]] between)
  }
  const double t_free = o.settle_time + o.pulse_period;
  scene.simulation.end_time = t_free + o.duration;
  scene.simulation.settle_velocity = 0.0;
  scene.simulation.settle_time = 0.0;
  if (o.threads > 0) scene.simulation.threads = o.threads;
  scene.output = OutputSpec{};
  scene.output.history_interval = o.history_interval;
  scene.output.histories = {HistorySpec{res.tip, "position"}};
  scene.output.energies = false;
  scene.assessment.stop_on_collapse = false;
  scene.checks.clear();

  RunControl control;
  control.threads = o.threads;
  const RunReport rep = run_scene(scene, control);
  res.status = rep.status;
  res.unstable = rep.unstable;
  res.instability = rep.instability;
  res.steps = rep.steps;
  res.time_step = rep.time_step;
  res.wall_seconds = rep.wall_seconds;
  res.end_time = rep.end_time;
  res.blocks = rep.blocks;

  const auto& h = rep.histories;
  const std::size_t nc = h.columns.size();
  int cx = -1, cy = -1;
  for (std::size_t c = 0; c < nc; ++c) {
    if (h.columns[c] == res.tip + ".position.x") cx = static_cast<int>(c);
    if (h.columns[c] == res.tip + ".position.y") cy = static_cast<int>(c);
  }
  if (cx < 0 || cy < 0 || h.row_count() == 0) throw std::runtime_error("dem-frequency: no history of the tip recorded");
  // Displacement along the pulse relative to the position just before it.
  double ref = 0.0;
  bool have_ref = false;
  for (std::size_t r = 0; r < h.row_count(); ++r) {
    const double t = h.rows[r * nc];
    const double along = dir.x() * h.rows[r * nc + cx] + dir.y() * h.rows[r * nc + cy];
    if (t <= o.settle_time || !have_ref) {
      ref = along;
      have_ref = true;
    }
    if (t >= t_free) {
      res.t.push_back(t);
      res.u.push_back(along - ref);
    }
  }
  res.samples = static_cast<int>(res.t.size());
  for (double v : res.u) res.amplitude_m = std::max(res.amplitude_m, std::fabs(v));
  if (res.samples >= 8) {
    res.window_s = res.t.back() - res.t.front();
    res.f_fourier_hz = fourier_peak_hz(res.t, res.u, o.f_min, o.f_max);
    res.f_zero_crossing_hz = zero_crossing_hz(res.t, res.u, &res.zero_crossings);
  }
  res.ratio_to_beam = res.f_beam_hz > 0 ? res.f_fourier_hz / res.f_beam_hz : 0.0;
  return res;
}

}  // namespace polydem
