#include "io/analytic_report.hpp"

#include "structures/generator_specs.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

namespace polydem {

namespace pa = analytical;

namespace {

// printf's %g to `prec` digits; "-" for NaN and infinities.
std::string num(double v, int prec = 6) {
  if (!std::isfinite(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", prec, v);
  return buf;
}

std::string body_description(const pa::BodySpec& s) {
  switch (s.shape) {
    case pa::BodyShape::block:
      return "rectangular block, half-width b = " + num(s.b) + " m, half-height h = " + num(s.h) + " m";
    case pa::BodyShape::shell:
    case pa::BodyShape::cone:
      return (s.shape == pa::BodyShape::shell ? "conical shell (eq. 8)" : "solid cone") + std::string(", r_b = ") +
             num(s.r_b) + " m, H = " + num(s.H) + " m";
    case pa::BodyShape::cracked:
      return "cracked spire, H_bar = " + num(s.H_bar.value_or(s.tip)) + " m (H = " + num(s.H) + " m, r_b = " +
             num(s.r_b) + " m, solid tip " + num(s.tip) + " m, wall " + num(s.thickness) + " m)";
  }
  return "";
}

void report_body(std::ostream& out, const pa::BodySpec& s, const pa::RockingBody& b) {
  out << "  body     " << body_description(s) << "\n"
      << "           R = " << num(b.R) << " m, alpha = " << num(b.alpha) << " rad, I0/M = " << num(b.I0 / b.mass)
      << " m2, p = " << num(b.p) << " rad/s, c (eq. 10) = " << num(b.restitution)
      << ", uplift at tan(alpha) = " << num(std::tan(b.alpha)) << " g\n";
}

std::string load_description(const pa::LoadSpec& l) {
  switch (l.kind) {
    case pa::LoadKind::pulse: return "one-sine pulse a_p = " + num(l.a_p) + " g, T_p = " + num(l.T_p) + " s";
    case pa::LoadKind::constant: return "constant a = " + num(l.a) + " g";
    case pa::LoadKind::record:
      return "record " + l.record_name + (l.record_shifted ? " (record shifted to start at t = 0)" : "");
  }
  return "";
}

std::string crack_text(const pa::Mechanism& m) {
  char buf[200];
  if (m.family != pa::CrackFamily::stepped) {
    std::snprintf(buf, sizeof buf, "beta in (%.2f, %.2f] deg", m.beta_low * 180.0 / std::numbers::pi,
                  m.beta_high * 180.0 / std::numbers::pi);
    return buf;
  }
  std::string s = "trailing course " + std::to_string(m.trailing_course) + ", first course per face";
  for (std::size_t k = 0; k < m.face_course.size(); ++k) {
    s += k ? ',' : ' ';
    s += std::to_string(m.face_course[k]);
  }
  return s;
}

std::string mechanism_text(const LimitAnalysisResult& r) {
  if (r.status == LimitStatus::failed && r.primal_residual + r.dual_residual > 0) {
    std::ostringstream s;
    s << "failed: the solution misses the check (equilibrium residual " << num(r.primal_residual, 3)
      << ", mechanism residual " << num(r.dual_residual, 3) << ", limit 1e-5)";
    return s.str();
  }
  if (r.status != LimitStatus::optimal) return to_string(r.status);
  const auto& m = r.mechanism;
  std::ostringstream s;
  s << m.blocks_moving << " blocks (" << num(m.mass_moving, 5) << " kg) moving; interfaces opening " << m.opening
    << " (" << m.opening_bed << " bed), sliding " << m.sliding << " (" << m.sliding_bed << " bed)";
  return s.str();
}

}  // namespace

void report_cone_overturning(std::ostream& out, const pa::ConeOverturning& r, bool h_c_given) {
  out << "static overturning of a conical shell (paper eq. 1-2)\n"
      << "  inputs   r_b = " << num(r.r_b) << " m, H = " << num(r.H) << " m\n"
      << "  eq. 1    lambda = 3 r_b / H                 = " << num(r.lambda_eq1) << " g\n";
  if (h_c_given) out << "  eq. 2    lambda at h_c = " << num(r.h_c) << " m      = " << num(r.lambda_at_h_c) << " g\n";
  out << "  eq. 2    governing lambda (min over h_c)  = " << num(r.governing.lambda) << " g at h_c = "
      << num(r.governing.h_c) << " m\n";
}

void report_spire_beam(std::ostream& out, const pa::SpireBeamModes& r) {
  const pa::SpireBeam& b = r.beam;
  out << "tapered cantilever m = (1-y/H) m_b, EI = (1-y/H)^3 EI_b (paper eq. 3-6)\n"
      << "  inputs   H = " << num(b.H) << " m, r_b = " << num(b.r_b) << " m (" << pa::to_string(b.section)
      << "), t = " << num(b.thickness) << " m, E = " << num(b.E) << " Pa, density = " << num(b.density) << " kg/m3\n"
      << "  base     m_b = " << num(r.section.mass_per_height) << " kg/m, I_b = " << num(r.section.second_moment)
      << " m4, EI_b = " << num(r.section.bending_stiffness) << " N m2\n"
      << "  mode  Omega_n      f_n [Hz]\n";
  for (std::size_t i = 0; i < r.modes.size(); ++i) {
    char line[128];
    std::snprintf(line, sizeof line, "  %4zu  %-11.6g  %.6g\n", i + 1, r.modes[i].Omega, r.modes[i].f_hz);
    out << line;
  }
  out << "  Rayleigh (eq. 5-6): k_min = " << num(r.rayleigh.k) << ", Omega = " << num(r.rayleigh.Omega)
      << ", f = " << num(r.rayleigh_f_hz) << " Hz\n";
}

void report_rocking(std::ostream& out, const pa::RockingCase& c, const pa::RockingResponse& r, double every) {
  const pa::RockingOptions& ro = c.options;
  const pa::RockingResult& x = r.result;
  out << "rocking on a rigid base (paper eq. 7" << (ro.form == pa::RockingForm::linearised ? "/9" : "")
      << ", restitution eq. 10)\n";
  report_body(out, c.body, r.body);
  out << "  load     " << load_description(c.load) << "\n"
      << "  step     RK4 dt = " << num(ro.dt) << " s, t_end = " << num(ro.t_end) << " s, c used = "
      << num(ro.restitution.value_or(r.body.restitution)) << "\n"
      << "  result   uplift " << (x.uplifted ? "at t = " + num(x.t_uplift) + " s" : std::string("never")) << ", "
      << x.impacts << " impacts, max |theta| = " << num(x.max_abs_theta) << " rad ("
      << num(x.max_abs_theta / r.body.alpha, 4) << " alpha), "
      << (x.overturned ? "OVERTURNED (" + std::string(pa::to_string(x.mode)) + ") at t = " + num(x.t_overturn) + " s"
                       : std::string("no overturning"))
      << ", stopped at t = " << num(x.t_final) << " s\n"
      << "  t [s]        theta [rad]     omega [rad/s]   a_g [g]\n";
  for (const pa::RockingSample& s : pa::samples_every(x.history, every)) {
    char line[160];
    std::snprintf(line, sizeof line, "  %-11.5f  %-14.6e  %-14.6e  %.5f\n", s.t, s.theta, s.omega, s.a_g / ro.g);
    out << line;
  }
}

void report_collapse_diagram(std::ostream& out, const pa::CollapseDiagramCase& c, const pa::CollapseDiagram& r) {
  out << "collapse diagram for one-sine pulses a_p sin(2 pi t / T_p) (Zhang & Makris 2001)\n";
  report_body(out, c.body, r.body);
  out << "  scan     a_p from tan(alpha) to " << num(c.scan.a_max_g) << " g, " << c.scan.coarse_points
      << " points, transitions to " << num(c.scan.tolerance_g) << " g\n"
      << "  T_p [s]   w_p/p    min collapse [g]  Mode II from [g]  Mode I regions [g]\n";
  for (const pa::CollapseColumn& col : r.columns) {
    std::ostringstream intervals;  // (not string + chains: g++ 12 warns falsely on them at -O2)
    for (const auto& [lo, hi] : col.mode1_intervals) intervals << '[' << num(lo, 4) << ", " << num(hi, 4) << "] ";
    const std::string m1 = intervals.str();
    char line[200];
    std::snprintf(line, sizeof line, "  %-8.4g  %-7.4g  %-16s  %-16s  %s\n", col.T_p, col.omega_ratio,
                  num(col.min_collapse_g, 5).c_str(), num(col.mode2_boundary_g, 5).c_str(),
                  m1.empty() ? "-" : m1.c_str());
    out << line;
  }
}

void report_cracked_spire(std::ostream& out, const pa::CrackedSpireCurve& r) {
  const pa::SpireGeometry& s = r.spire;
  out << "p of the spire cracked just below its solid tip, vs cracked height H_bar (paper Fig. 7a)\n"
      << "  inputs   H = " << num(s.H) << " m, r_b = " << num(s.r_b) << " m, solid tip " << num(s.tip_height)
      << " m, wall " << num(s.wall_thickness) << " m, density " << num(s.density) << " kg/m3, g = " << num(r.g)
      << " m/s2\n"
      << "  H_bar [m]  p [rad/s]  mass [kg]    R [m]     alpha [rad]\n";
  for (const pa::CrackedSpirePoint& p : r.points) {
    char line[160];
    std::snprintf(line, sizeof line, "  %-9.4f  %-9.5f  %-11.5g  %-8.5f  %.5f\n", p.H_bar, p.body.p, p.body.mass,
                  p.body.R, p.body.alpha);
    out << line;
  }
  out << "  max p = " << num(r.p_max.p) << " rad/s at H_bar = " << num(r.p_max.H_bar) << " m\n";
}

void report_spire_lambda(std::ostream& out, const SpireLambda& r) {
  const pa::RefinedLambdaResult& x = r.refined;
  out << "refined static lambda on the block model (rigid part above a crack, pivot on the base)\n"
      << "  spire    " << r.deck << ": H = " << num(r.height) << " m, r_b = " << num(r.base_inradius)
      << " m (mid-wall apothem), " << r.blocks << " blocks, " << r.courses << " courses, " << r.windows
      << " windows, density " << num(r.density) << " kg/m3, free mass " << num(x.total_mass) << " kg\n"
      << "  direction = of the equivalent static force; the pivot is the base edge/corner that way\n"
      << "  direction    family       lambda     blocks  mass [kg]   crack\n";
  for (std::size_t i = 0; i < x.plane.size(); ++i)
    for (const pa::Mechanism* m : {&x.plane[i], &x.plane_cover[i], &x.stepped[i]}) {
      char line[320];
      std::snprintf(line, sizeof line, "  %-11s  %-11s  %-9.5f  %-6zu  %-10.1f  %s\n", m->direction.name.c_str(),
                    pa::to_string(m->family), m->lambda, m->blocks.size(), m->mass, crack_text(*m).c_str());
      out << line;
    }
  out << "  eq. 1 lambda = " << num(r.lambda_eq1) << ", eq. 2 governing = " << num(r.eq2.lambda)
      << " (r_b, H of the spire)\n"
      << "  refined lambda = " << num(x.governing.lambda) << ": " << x.governing.direction.name << ", "
      << pa::to_string(x.governing.family) << " crack, " << crack_text(x.governing) << ", "
      << x.governing.blocks.size() << " blocks, " << num(x.governing.mass) << " kg (" << x.candidates
      << " mechanisms evaluated)\n";
}

void report_dem_frequency(std::ostream& out, const SceneSpec& scene, const DemFrequencyOptions& d,
                          const DemFrequencyResult& r) {
  out << "first natural frequency of the block model, DEM free vibration against eq. 4\n"
      << "  spire    " << scene.deck_path << ": " << r.blocks << " blocks, "
      << spire_windows(scene.generators) << " windows, tip block '" << r.tip << "'\n"
      << "  run      gravity, joint damping " << (d.keep_damping ? num(scene.joint.damping) : std::string("0"))
      << " s, sine pulse " << num(d.pulse_g) << " g x " << num(d.pulse_period) << " s at t = " << num(d.settle_time)
      << " s, free vibration " << num(d.duration) << " s; " << r.steps << " steps of " << num(r.time_step) << " s, "
      << num(r.wall_seconds, 3) << " s wall, status " << r.status
      << (r.unstable ? " (UNSTABLE: " + r.instability + ")" : std::string()) << "\n"
      << "  DEM      tip amplitude " << num(r.amplitude_m) << " m; f = " << num(r.f_fourier_hz)
      << " Hz (Fourier peak), " << num(r.f_zero_crossing_hz) << " Hz (" << r.zero_crossings << " zero crossings)\n"
      << "  beam     E_eq = kn h = " << num(r.kn) << " Pa/m x " << num(r.course_height) << " m = " << num(r.E_eq)
      << " Pa; hollow octagon a_out = " << num(r.outer_apothem) << " m, t = " << num(r.wall_thickness)
      << " m: m_b = " << num(r.section.mass_per_height) << " kg/m, EI_b = " << num(r.section.bending_stiffness)
      << " N m2; Omega1 = " << num(r.Omega1) << ", H = " << num(r.height) << " m: f = " << num(r.f_beam_hz)
      << " Hz\n"
      << "  ratio    DEM / beam = " << num(r.ratio_to_beam, 4) << "\n";
}

void report_limit_study(std::ostream& out, const LimitStudy& study, bool interfaces) {
  const LimitModel& model = study.model;
  const std::vector<FrictionPyramid>& pyramids = study.options.pyramids;
  const LimitAnalysisResult& first = study.cases.front().results.front();
  out << "limit analysis of the block model: rigid blocks, no tension, Coulomb friction (docs/analytical.md 7)\n"
      << "  deck     " << study.deck << ": " << model.mass.size() << " blocks (" << study.free_blocks << " free), "
      << model.interfaces.size() << " interfaces touching at t = 0, " << model.vertices
      << " patch vertices; blocks and initial mesh in " << num(model.detection_seconds, 3) << " s\n"
      << "  LP       " << study.options.pyramid_sides << "-sided friction pyramid at every vertex (generators), GLPK "
      << to_string(study.options.method) << "; " << first.rows << " rows, " << first.columns << " columns, "
      << first.nonzeros << " nonzeros\n"
      << "  load     lambda m |g| horizontally along the direction's azimuth from +x (the static equivalent of\n"
      << "           a ground acceleration -lambda g the opposite way), on the dead load m g\n"
      << "  bound    circumscribed pyramid: an upper bound on any lambda at which the blocks can stand in their\n"
      << "           initial geometry; inscribed: below the exact cone's value (the two bracket it)\n";
  out << "  dir [deg]  phi [deg]";
  for (const auto p : pyramids) out << (p == FrictionPyramid::circumscribed ? "  lambda circ." : "  lambda inscr.");
  out << "  solve [s]  mechanism (" << to_string(pyramids.front()) << ")\n";
  for (const LimitCase& c : study.cases) {
    char line[96];
    std::snprintf(line, sizeof line, "  %-9.4g  %-9.4g", c.direction_deg, c.friction_angle_deg);
    out << line;
    double t = 0;
    for (const auto& r : c.results) {
      std::snprintf(line, sizeof line, "  %-12.6g", r.lambda);
      out << line << (pyramids.size() > 1 && &r == &c.results.back() ? " " : "");
      t += r.build_seconds + r.solve_seconds;
    }
    std::snprintf(line, sizeof line, "  %-9.3f", t);
    out << line << "  " << mechanism_text(c.results.front()) << "\n";
  }
  if (!interfaces) return;
  for (const LimitCase& c : study.cases) {
    const LimitAnalysisResult& r = c.results.front();
    if (r.status != LimitStatus::optimal) continue;
    out << "  interfaces moving at direction " << num(c.direction_deg) << " deg, phi " << num(c.friction_angle_deg)
        << " deg (" << to_string(pyramids.front()) << "):\n";
    for (std::size_t q = 0; q < r.mechanism.motion.size(); ++q) {
      if (r.mechanism.motion[q] == InterfaceMotion::closed) continue;
      const LimitInterface& f = model.interfaces[q];
      out << "    " << model.names[f.ref] << " | " << model.names[f.inc] << "  " << (f.bed ? "bed" : "vertical")
          << "  " << to_string(r.mechanism.motion[q]) << "\n";
    }
  }
}

void report_thinnest_arch_heading(std::ostream& out, const ThinnestArchOptions& o) {
  out << "thinnest semicircular arch under self-weight (limit-analysis LP, phi = " << num(o.friction_angle_deg)
      << " deg): t/R, R the centre-line radius; Milankovitch (continuous): 0.1075\n"
      << "  voussoirs   t/R        vs 0.1075   trials   seconds\n";
}

void report_thinnest_arch(std::ostream& out, const ThinnestArch& a) {
  char line[160];
  if (a.stands_however_thin())
    std::snprintf(line, sizeof line, "  %9d   < 0.001    (stands however thin)\n", a.voussoirs);
  else
    std::snprintf(line, sizeof line, "  %9d   %.6f   %+7.2f %%   %6d   %7.2f\n", a.voussoirs, a.bracket.threshold(),
                  100.0 * (a.bracket.threshold() / 0.1075 - 1.0), a.bracket.trials, a.seconds);
  out << line << std::flush;
}

}  // namespace polydem
