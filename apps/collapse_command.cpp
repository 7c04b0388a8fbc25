#include "apps/collapse_command.hpp"

#include "apps/run_command.hpp"
#include "io/collapse_results.hpp"
#include "io/deck.hpp"

#include <fmt/core.h>

#include <cmath>
#include <filesystem>
#include <iostream>

namespace polydem {

int collapse_command(const CollapseOptions& o) {
  SceneSpec scene;
  try {  // bad input fails here, before any run
    scene = o.use_default ? parse_deck(default_deck_text(), kDefaultDeckName, o.overrides)
                          : read_deck(o.deck_path, o.overrides);
  } catch (const std::exception& e) {
    std::cerr << "polydem: error: " << e.what() << "\n";
    return exit_bad_input;
  }
  CollapseSearchOptions so;
  so.low_g = o.low_g;
  so.high_g = o.high_g;
  so.tolerance_g = o.tolerance_g;
  so.rise_time = o.rise_time;
  so.hold_time = o.hold_time;
  so.ramp_rate_g = o.ramp_rate_g;
  so.static_increments = o.static_increments;
  so.static_ratio = o.static_ratio;
  so.static_max_steps = o.static_max_steps;
  so.density_scaling = o.density_scaling;
  so.threads = o.threads;
  TrialObserver print;
  if (!o.quiet)
    print = [&o](const char* method, const CollapseTrial& t) {
      if (std::string(method) == "ramp")
        std::cerr << fmt::format("  direction {:6.1f} deg  ramp {:.3f} g/s: mechanism at {:.4f} g  {}  {:.1f} s\n",
                                 t.direction_deg, o.ramp_rate_g, t.acceleration_g, t.assessment.status,
                                 t.wall_seconds);
      else
        std::cerr << fmt::format("  direction {:6.1f} deg  a = {:.4f} g  {:<9}  {} steps  {:.1f} s\n",
                                 t.direction_deg, t.acceleration_g, t.assessment.status, t.steps, t.wall_seconds);
    };

  CollapseStudy study;
  study.deck = o.use_default ? std::string(kDefaultDeckName) : o.deck_path;
  study.method = o.method;
  study.tolerance_g = o.tolerance_g;
  study.ramp_rate_g = o.ramp_rate_g;
  try {
    for (double deg : o.directions_deg) {
      CollapseDirection d;
      d.direction_deg = deg;
      if (o.method == "bisection" || o.method == "both") d.bisection = bisect_collapse(scene, deg, so, print);
      if (o.method == "static") d.bisection = bisect_collapse_static(scene, deg, so, print);
      if (o.method == "ramp" || o.method == "both") d.ramp = ramp_collapse(scene, deg, so, print);
      study.directions.push_back(std::move(d));
    }
  } catch (const InstabilityError& e) {
    std::cerr << "polydem: stopped: " << e.what() << "\n";
    return exit_instability;
  } catch (const SceneError& e) {
    std::cerr << "polydem: error: " << locate_scene_error(e, scene) << "\n";
    return exit_bad_input;
  } catch (const std::exception& e) {
    std::cerr << "polydem: error: " << e.what() << "\n";
    return exit_bad_input;
  }
  std::filesystem::create_directories(o.out_dir);
  write_collapse_json(o.out_dir + "/collapse.json", study);

  std::cout << fmt::format("{:>14} {:>16} {:>6} {:>10} {:>16} {:>10} {:>10}\n", "direction_deg", "bisection_g", "runs",
                           "wall_s", "ramp_g", "wall_s", "crack_deg");
  for (const CollapseDirection& d : study.directions) {
    const bool bisected = d.bisection && d.bisection->error.empty();
    double crack = bisected ? d.bisection->last_collapse.assessment.crack_angle_deg : -1;
    if (crack < 0 && d.ramp) crack = d.ramp->assessment.crack_angle_deg;
    std::cout << fmt::format("{:>14.1f} {:>16.4f} {:>6} {:>10.1f} {:>16.4f} {:>10.1f} {:>10.1f}\n", d.direction_deg,
                             bisected ? d.bisection->collapse_g : NAN, d.bisection ? d.bisection->runs : 0,
                             d.bisection ? d.bisection->wall_seconds : 0.0, d.ramp ? d.ramp->acceleration_g : NAN,
                             d.ramp ? d.ramp->wall_seconds : 0.0, crack);
  }
  for (const CollapseDirection& d : study.directions)
    if (d.bisection && !d.bisection->error.empty())
      std::cerr << fmt::format("polydem: direction {:.1f} deg: {}\n", d.direction_deg, d.bisection->error);
  std::cout << "results in " << o.out_dir << "/collapse.json\n";
  return exit_success;
}

}  // namespace polydem
