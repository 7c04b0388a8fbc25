#include "io/analytic_inputs.hpp"

#include "io/deck.hpp"
#include "io/ground_motion_record.hpp"
#include "structures/generator_specs.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace polydem {

SceneSpec analytic_scene(const std::string& deck, bool no_windows) {
  std::vector<std::string> overrides;
  if (no_windows) overrides.push_back("spire.window_faces=[]");
  return deck.empty() ? parse_deck("[spire]\n", kDefaultSpireName, overrides) : read_deck(deck, overrides);
}

SceneSpec analytic_spire_scene(const std::string& deck, bool no_windows) {
  SceneSpec s = analytic_scene(deck, no_windows);
  if (!spire_of(s.generators)) throw std::runtime_error("the deck " + deck + " has no [spire]");
  return s;
}

SceneSpec unit_semicircular_arch(int voussoirs, double t_over_R) {
  std::ostringstream d;
  d.precision(17);
  d << "[[arch]]\nradius = " << 1.0 - 0.5 * t_over_R << "\nthickness = " << t_over_R << "\nvoussoirs = " << voussoirs
    << "\ndepth = 1\nsupports = \"base\"\n";
  return parse_deck(d.str(), "<arch-thickness>");
}

UniformRecord read_uniform_record(const std::string& path) {
  const GroundMotionRecord rec = read_record(path);
  UniformRecord r;
  r.dt = rec.time[1] - rec.time[0];
  for (std::size_t i = 1; i < rec.time.size(); ++i)
    if (!(std::abs(rec.time[i] - rec.time[i - 1] - r.dt) <= 1e-6 * r.dt))
      throw RecordError(path, 0, "time step must be uniform (the rocking models sample the record every dt)");
  r.acceleration.reserve(rec.acceleration.size());
  for (double a : rec.acceleration) r.acceleration.push_back(a / kRecordG);
  r.shifted = rec.time.front() != 0.0;
  return r;
}

analytical::LoadSpec record_load(const std::string& path) {
  const UniformRecord r = read_uniform_record(path);
  analytical::LoadSpec l;
  l.kind = analytical::LoadKind::record;
  l.record_dt = r.dt;
  l.record = r.acceleration;
  l.record_name = path;
  l.record_shifted = r.shifted;
  return l;
}

}  // namespace polydem
