#include "analytical/rocking_cases.hpp"

#include <stdexcept>

namespace polydem::analytical {

const char* to_string(BodyShape s) {
  switch (s) {
    case BodyShape::block: return "block";
    case BodyShape::shell: return "shell";
    case BodyShape::cone: return "cone";
    case BodyShape::cracked: return "cracked";
  }
  return "?";
}

const char* to_string(LoadKind k) {
  switch (k) {
    case LoadKind::pulse: return "pulse";
    case LoadKind::constant: return "constant";
    case LoadKind::record: return "record";
  }
  return "?";
}

std::optional<BodyShape> body_shape_named(const std::string& name) {
  for (const BodyShape s : {BodyShape::block, BodyShape::shell, BodyShape::cone, BodyShape::cracked})
    if (name == to_string(s)) return s;
  return std::nullopt;
}

std::optional<LoadKind> load_kind_named(const std::string& name) {
  for (const LoadKind k : {LoadKind::pulse, LoadKind::constant, LoadKind::record})
    if (name == to_string(k)) return k;
  return std::nullopt;
}

RockingBody rocking_body(const BodySpec& s, double g) {
  switch (s.shape) {
    case BodyShape::block: return rectangular_block(s.b, s.h, 1.0, g);
    case BodyShape::shell: return conical_shell(s.r_b, s.H, 1.0, g);
    case BodyShape::cone: return solid_cone(s.r_b, s.H, 1.0, g);
    case BodyShape::cracked:
      return cracked_spire_body(SpireGeometry{s.H, s.r_b, s.tip, s.thickness, s.density}, s.H_bar.value_or(s.tip), g);
  }
  throw std::invalid_argument("rocking_body: unknown shape");
}

GroundMotion ground_motion(const LoadSpec& load, double g) {
  switch (load.kind) {
    case LoadKind::pulse: return sine_pulse_ground_motion(load.a_p * g, load.T_p);
    case LoadKind::constant: return constant_ground_motion(load.a * g);
    case LoadKind::record: {
      std::vector<double> a;
      a.reserve(load.record.size());
      for (double a_g : load.record) a.push_back(a_g * g);
      return sampled_ground_motion(load.record_dt, std::move(a));
    }
  }
  throw std::invalid_argument("ground_motion: unknown load");
}

RockingResponse rocking_response(const RockingCase& c) {
  RockingOptions options = c.options;
  options.record_history = true;
  RockingResponse r;
  r.body = rocking_body(c.body, options.g);
  r.result = simulate_rocking(r.body, ground_motion(c.load, options.g), options);
  return r;
}

std::vector<RockingSample> samples_every(const std::vector<RockingSample>& history, double every) {
  std::vector<RockingSample> kept;
  double next = 0.0;
  for (const RockingSample& s : history) {
    if (s.t + 1e-12 < next && &s != &history.back()) continue;
    next = s.t + every;
    kept.push_back(s);
  }
  return kept;
}

CollapseDiagram pulse_collapse_diagram(const CollapseDiagramCase& c) {
  if (c.T_p_count < 1) throw std::invalid_argument("pulse_collapse_diagram: need T_p_count >= 1");
  const int n = c.T_p_count;
  std::vector<double> periods;
  for (int i = 0; i < n; ++i) periods.push_back(n == 1 ? c.T_p_min : c.T_p_min + (c.T_p_max - c.T_p_min) * i / (n - 1));
  CollapseDiagram d;
  d.body = rocking_body(c.body, c.scan.g);
  d.columns = collapse_diagram(d.body, periods, c.scan);
  return d;
}

}  // namespace polydem::analytical
