#include "io/collapse_results.hpp"

#include "io/atomic_file.hpp"
#include "io/json.hpp"
#include "io/summary.hpp"

#include <cmath>

namespace polydem {

namespace {

Json crack_json(const Assessment& a) {
  Json j = Json::object();
  j.set("collapse_mode", a.collapse_mode);
  set_crack(j, a);
  j.set("moved_block_names", Json(a.moved_blocks));
  return j;
}

}  // namespace

double CollapseStudy::lowest_g() const {
  double lowest = INFINITY;
  for (const CollapseDirection& d : directions) {
    if (d.bisection && d.bisection->error.empty()) lowest = std::min(lowest, d.bisection->collapse_g);
    else if (d.ramp && std::isfinite(d.ramp->acceleration_g)) lowest = std::min(lowest, d.ramp->acceleration_g);
  }
  return std::isfinite(lowest) ? lowest : NAN;
}

void write_collapse_json(const std::string& path, const CollapseStudy& study) {
  Json out = Json::object();
  out.set("deck", study.deck);
  out.set("method", study.method);
  out.set("tolerance_g", study.tolerance_g);
  Json results = Json::array();
  for (const CollapseDirection& dir : study.directions) {
    Json d = Json::object();
    d.set("direction_deg", dir.direction_deg);
    if (dir.bisection) {
      const BisectionResult& r = *dir.bisection;
      Json b = Json::object();
      if (!r.error.empty()) {
        b.set("error", r.error);
        if (r.high_g > r.low_g) b.set("bracket_g", Json(std::vector<double>{r.low_g, r.high_g}));  // reached so far
      } else {
        b.set("collapse_acceleration_g", r.collapse_g);
        b.set("bracket_g", Json(std::vector<double>{r.low_g, r.high_g}));
        b.set("crack", crack_json(r.last_collapse.assessment));
      }
      b.set("runs", r.runs);
      b.set("wall_seconds", r.wall_seconds);
      d.set("bisection", std::move(b));
    }
    if (dir.ramp) {
      const CollapseTrial& t = *dir.ramp;
      Json r = Json::object();
      r.set("rate_g_per_s", study.ramp_rate_g);
      r.set("collapse_acceleration_g", std::isfinite(t.acceleration_g) ? Json(t.acceleration_g) : Json());
      r.set("wall_seconds", t.wall_seconds);
      r.set("crack", crack_json(t.assessment));
      d.set("ramp", std::move(r));
    }
    results.push_back(std::move(d));
  }
  out.set("directions", std::move(results));
  const double lowest = study.lowest_g();
  out.set("collapse_acceleration_g", std::isfinite(lowest) ? Json(lowest) : Json());
  write_file_atomic(path, out.dump(2) + "\n");
}

}  // namespace polydem
