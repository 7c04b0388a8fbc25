#include "io/analytic_results.hpp"

#include "io/atomic_file.hpp"
#include "structures/generator_specs.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace polydem {

namespace pa = analytical;

namespace {

Json xyz(const Vec3& v) { return Json(std::vector<double>{v.x(), v.y(), v.z()}); }

Json ints(const std::vector<int>& xs) {
  Json a = Json::array();
  for (int x : xs) a.push_back(x);
  return a;
}

// The body as given.
Json body_spec_json(const pa::BodySpec& b) {
  Json j = Json::object().set("kind", pa::to_string(b.shape));
  switch (b.shape) {
    case pa::BodyShape::block: return j.set("b_m", b.b).set("h_m", b.h);
    case pa::BodyShape::shell:
    case pa::BodyShape::cone: return j.set("r_b_m", b.r_b).set("H_m", b.H);
    case pa::BodyShape::cracked:
      return j.set("H_bar_m", b.H_bar.value_or(b.tip))
          .set("H_m", b.H)
          .set("r_b_m", b.r_b)
          .set("tip_m", b.tip)
          .set("thickness_m", b.thickness)
          .set("density_kg_m3", b.density);
  }
  return j;
}

// What eq. 7-10 take of it.
Json body_properties_json(const pa::RockingBody& b) {
  return Json::object()
      .set("R_m", b.R)
      .set("alpha_rad", b.alpha)
      .set("p_rad_s", b.p)
      .set("I0_over_M_m2", b.I0 / b.mass)
      .set("restitution", b.restitution)
      .set("uplift_g", std::tan(b.alpha));
}

Json load_json(const pa::LoadSpec& l) {
  Json j = Json::object().set("kind", pa::to_string(l.kind));
  switch (l.kind) {
    case pa::LoadKind::pulse: return j.set("a_p_g", l.a_p).set("T_p_s", l.T_p);
    case pa::LoadKind::constant: return j.set("a_g", l.a);
    case pa::LoadKind::record: return j.set("file", l.record_name);
  }
  return j;
}

Json mechanism_json(const pa::Mechanism& m) {
  Json j = Json::object()
               .set("direction", m.direction.name)
               .set("azimuth_rad", m.direction.azimuth)
               .set("family", pa::to_string(m.family))
               .set("lambda", m.lambda)
               .set("blocks", m.blocks.size())
               .set("mass_kg", m.mass)
               .set("centroid_m", xyz(m.centroid))
               .set("pivot_m", xyz(m.pivot));
  if (m.family != pa::CrackFamily::stepped)
    return j.set("beta_low_rad", m.beta_low).set("beta_high_rad", m.beta_high);
  return j.set("trailing_course", m.trailing_course).set("face_course", ints(m.face_course));
}

Json mechanisms_json(const std::vector<pa::Mechanism>& ms) {
  Json a = Json::array();
  for (const pa::Mechanism& m : ms) a.push_back(mechanism_json(m));
  return a;
}

Json limit_mechanism_json(const LimitModel& model, const LimitMechanism& m) {
  Json moving = Json::array();
  for (std::size_t i = 0; i < m.moving.size(); ++i)
    if (m.moving[i])
      moving.push_back(Json::object()
                           .set("name", model.names[i])
                           .set("speed", m.speed[i])
                           .set("velocity", xyz(m.velocity[i]))
                           .set("angular_velocity", xyz(m.angular_velocity[i])));
  Json interfaces = Json::array();
  for (std::size_t q = 0; q < m.motion.size(); ++q) {
    if (m.motion[q] == InterfaceMotion::closed) continue;
    const LimitInterface& f = model.interfaces[q];
    interfaces.push_back(Json::object()
                             .set("blocks", Json(std::vector<std::string>{model.names[f.ref], model.names[f.inc]}))
                             .set("bed", f.bed)
                             .set("motion", to_string(m.motion[q]))
                             .set("normal", xyz(f.normal)));
  }
  return Json::object()
      .set("blocks_moving", m.blocks_moving)
      .set("mass_moving_kg", m.mass_moving)
      .set("opening", m.opening)
      .set("opening_bed", m.opening_bed)
      .set("sliding", m.sliding)
      .set("sliding_bed", m.sliding_bed)
      .set("moving_blocks", std::move(moving))
      .set("interfaces", std::move(interfaces));
}

Json limit_result_json(const LimitModel& model, const LimitAnalysisResult& r) {
  Json j = Json::object()
               .set("status", to_string(r.status))
               .set("lambda", r.lambda)
               .set("generator_mu", r.generator_mu)
               .set("rows", r.rows)
               .set("columns", r.columns)
               .set("nonzeros", r.nonzeros)
               .set("build_s", r.build_seconds)
               .set("solve_s", r.solve_seconds)
               .set("primal_residual", r.primal_residual)
               .set("dual_residual", r.dual_residual);
  if (r.status == LimitStatus::optimal) j.set("mechanism", limit_mechanism_json(model, r.mechanism));
  return j;
}

}  // namespace

Json cone_overturning_json(const pa::ConeOverturning& r) {
  return Json::object()
      .set("model", "lambda")
      .set("inputs", Json::object().set("r_b_m", r.r_b).set("H_m", r.H).set("h_c_m", r.h_c))
      .set("lambda_eq1", r.lambda_eq1)
      .set("lambda_eq2_at_h_c", r.lambda_at_h_c)
      .set("lambda_eq2_governing", r.governing.lambda)
      .set("h_c_governing_m", r.governing.h_c);
}

Json spire_beam_json(const pa::SpireBeamModes& r) {
  const pa::SpireBeam& b = r.beam;
  Json modes = Json::array();
  for (std::size_t i = 0; i < r.modes.size(); ++i)
    modes.push_back(Json::object().set("n", i + 1).set("Omega", r.modes[i].Omega).set("f_Hz", r.modes[i].f_hz));
  return Json::object()
      .set("model", "beam")
      .set("inputs", Json::object()
                         .set("H_m", b.H)
                         .set("r_b_m", b.r_b)
                         .set("thickness_m", b.thickness)
                         .set("E_Pa", b.E)
                         .set("density_kg_m3", b.density)
                         .set("section", pa::to_string(b.section)))
      .set("m_b_kg_m", r.section.mass_per_height)
      .set("I_b_m4", r.section.second_moment)
      .set("EI_b_Nm2", r.section.bending_stiffness)
      .set("modes", std::move(modes))
      .set("rayleigh",
           Json::object().set("k_min", r.rayleigh.k).set("Omega", r.rayleigh.Omega).set("f_Hz", r.rayleigh_f_hz));
}

Json rocking_json(const pa::RockingCase& c, const pa::RockingResponse& r, double every) {
  const pa::RockingResult& x = r.result;
  const double g = c.options.g;
  Json history = Json::array();
  for (const pa::RockingSample& s : pa::samples_every(x.history, every))
    history.push_back(Json(std::vector<double>{s.t, s.theta, s.omega, s.a_g / g}));
  return Json::object()
      .set("model", "rocking")
      .set("body", body_spec_json(c.body))
      .set("properties", body_properties_json(r.body))
      .set("load", load_json(c.load))
      .set("form", c.options.form == pa::RockingForm::linearised ? "eq9" : "eq7")
      .set("dt_s", c.options.dt)
      .set("uplifted", x.uplifted)
      .set("t_uplift_s", x.uplifted ? Json(x.t_uplift) : Json())
      .set("overturned", x.overturned)
      .set("mode", pa::to_string(x.mode))
      .set("t_overturn_s", x.overturned ? Json(x.t_overturn) : Json())
      .set("impacts", x.impacts)
      .set("max_abs_theta_rad", x.max_abs_theta)
      .set("t_final_s", x.t_final)
      .set("impact_times_s", Json(x.impact_times))
      .set("history", std::move(history))
      .set("history_columns", Json(std::vector<std::string>{"t_s", "theta_rad", "omega_rad_s", "a_g_g"}));
}

Json collapse_diagram_json(const pa::CollapseDiagramCase& c, const pa::CollapseDiagram& r) {
  Json columns = Json::array();
  for (const pa::CollapseColumn& col : r.columns) {
    Json intervals = Json::array();
    for (const auto& [lo, hi] : col.mode1_intervals) intervals.push_back(Json(std::vector<double>{lo, hi}));
    Json transitions = Json::array();
    for (const pa::CollapseTransition& t : col.transitions)
      transitions.push_back(
          Json::object().set("a_g", t.a_g).set("below", pa::to_string(t.below)).set("above", pa::to_string(t.above)));
    columns.push_back(Json::object()
                          .set("T_p_s", col.T_p)
                          .set("omega_p_over_p", col.omega_ratio)
                          .set("min_collapse_g", col.min_collapse_g)
                          .set("mode2_boundary_g", col.mode2_boundary_g)
                          .set("mode1_intervals_g", std::move(intervals))
                          .set("transitions", std::move(transitions)));
  }
  return Json::object()
      .set("model", "collapse-diagram")
      .set("body", body_spec_json(c.body))
      .set("properties", body_properties_json(r.body))
      .set("a_max_g", c.scan.a_max_g)
      .set("tolerance_g", c.scan.tolerance_g)
      .set("columns", std::move(columns));
}

Json cracked_spire_json(const pa::CrackedSpireCurve& r) {
  const pa::SpireGeometry& s = r.spire;
  Json curve = Json::array();
  for (const pa::CrackedSpirePoint& p : r.points)
    curve.push_back(Json::object()
                        .set("H_bar_m", p.H_bar)
                        .set("p_rad_s", p.body.p)
                        .set("mass_kg", p.body.mass)
                        .set("R_m", p.body.R)
                        .set("alpha_rad", p.body.alpha));
  return Json::object()
      .set("model", "cracked-cone-p")
      .set("inputs", Json::object()
                         .set("H_m", s.H)
                         .set("r_b_m", s.r_b)
                         .set("tip_m", s.tip_height)
                         .set("thickness_m", s.wall_thickness)
                         .set("density_kg_m3", s.density))
      .set("p_max_rad_s", r.p_max.p)
      .set("H_bar_at_p_max_m", r.p_max.H_bar)
      .set("curve", std::move(curve));
}

Json spire_lambda_json(const SpireLambda& r) {
  return Json::object()
      .set("model", "refined-lambda")
      .set("deck", r.deck)
      .set("blocks", r.blocks)
      .set("courses", r.courses)
      .set("windows", r.windows)
      .set("density_kg_m3", r.density)
      .set("total_mass_kg", r.refined.total_mass)
      .set("candidates", r.refined.candidates)
      .set("lambda_eq1", r.lambda_eq1)
      .set("lambda_eq2", r.eq2.lambda)
      .set("lambda_refined", r.refined.governing.lambda)
      .set("governing", mechanism_json(r.refined.governing))
      .set("plane", mechanisms_json(r.refined.plane))
      .set("plane_cover", mechanisms_json(r.refined.plane_cover))
      .set("stepped", mechanisms_json(r.refined.stepped));
}

Json dem_frequency_json(const SceneSpec& scene, const DemFrequencyOptions& o, const DemFrequencyResult& r) {
  return Json::object()
      .set("model", "dem-frequency")
      .set("deck", scene.deck_path)
      .set("tip", r.tip)
      .set("blocks", r.blocks)
      .set("windows", spire_windows(scene.generators))
      .set("damping_s", o.keep_damping ? scene.joint.damping : 0.0)
      .set("pulse_g", o.pulse_g)
      .set("pulse_period_s", o.pulse_period)
      .set("settle_s", o.settle_time)
      .set("duration_s", o.duration)
      .set("status", r.status)
      .set("unstable", r.unstable)
      .set("steps", r.steps)
      .set("time_step_s", r.time_step)
      .set("wall_s", r.wall_seconds)
      .set("samples", r.samples)
      .set("amplitude_m", r.amplitude_m)
      .set("f_dem_fourier_Hz", r.f_fourier_hz)
      .set("f_dem_zero_crossing_Hz", r.f_zero_crossing_hz)
      .set("zero_crossings", r.zero_crossings)
      .set("kn_Pa_m", r.kn)
      .set("course_height_m", r.course_height)
      .set("E_eq_Pa", r.E_eq)
      .set("outer_apothem_m", r.outer_apothem)
      .set("thickness_m", r.wall_thickness)
      .set("m_b_kg_m", r.section.mass_per_height)
      .set("EI_b_Nm2", r.section.bending_stiffness)
      .set("Omega1", r.Omega1)
      .set("f_beam_Hz", r.f_beam_hz)
      .set("ratio_dem_to_beam", r.ratio_to_beam);
}

Json limit_study_json(const LimitStudy& study) {
  const LimitModel& m = study.model;
  Json cases = Json::array();
  for (const LimitCase& c : study.cases) {
    Json j = Json::object().set("direction_deg", c.direction_deg).set("friction_angle_deg", c.friction_angle_deg);
    for (std::size_t k = 0; k < c.results.size(); ++k)
      j.set(to_string(study.options.pyramids[k]), limit_result_json(m, c.results[k]));
    cases.push_back(std::move(j));
  }
  return Json::object()
      .set("model", "limit-lp")
      .set("deck", study.deck)
      .set("blocks", m.mass.size())
      .set("free_blocks", study.free_blocks)
      .set("interfaces", m.interfaces.size())
      .set("vertices", m.vertices)
      .set("pyramid_sides", study.options.pyramid_sides)
      .set("method", to_string(study.options.method))
      .set("initial_mesh_s", m.detection_seconds)
      .set("cases", std::move(cases));
}

Json thinnest_arch_json(const ThinnestArchOptions& options, const std::vector<ThinnestArch>& arches) {
  Json cases = Json::array();
  for (const ThinnestArch& a : arches)
    cases.push_back(Json::object()
                        .set("voussoirs", a.voussoirs)
                        .set("t_over_R", a.bracket.threshold())
                        .set("falls", a.bracket.falls)
                        .set("stands", a.bracket.stands)
                        .set("trials", a.bracket.trials)
                        .set("seconds", a.seconds));
  return Json::object()
      .set("model", "arch-thickness")
      .set("phi_deg", options.friction_angle_deg)
      .set("cases", std::move(cases));
}

void write_dem_frequency_csv(const std::string& path, const DemFrequencyResult& r) {
  std::string text = "t_s,u_m\n";
  char line[96];
  for (std::size_t i = 0; i < r.t.size(); ++i) {
    std::snprintf(line, sizeof line, "%.9g,%.9g\n", r.t[i], r.u[i]);
    text += line;
  }
  try {
    write_file_atomic(path, text);
  } catch (const std::exception&) {
    throw std::runtime_error("cannot write " + path);
  }
}

}  // namespace polydem
