#include "apps/collapse_command.hpp"
#include "core/units.hpp"

#include "apps/run_command.hpp"
#include "apps/scene_runner.hpp"
#include "io/atomic_file.hpp"
#include "io/deck.hpp"
#include "io/json.hpp"

#include <fmt/core.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <numbers>

namespace polydem {

namespace {


struct Trial {
  double acceleration_g = 0;
  bool collapsed = false;
  double wall_seconds = 0;
  Assessment assessment;
};

class Runner {
 public:
  Runner(const CollapseOptions& o) : o_(o) {}

  SceneSpec spec(const std::vector<std::string>& extra) const {
    std::vector<std::string> all = o_.overrides;
    all.insert(all.end(), extra.begin(), extra.end());
    return o_.use_default ? parse_deck(default_deck_text(), "<built-in default deck>", all)
                          : read_deck(o_.deck_path, all);
  }

  static std::string direction_override(double deg) {
    const double a = deg * std::numbers::pi / 180.0;
    return fmt::format("ground_motion.direction=[{:.17g}, {:.17g}, 0.0]", std::cos(a), std::sin(a));
  }

  Trial constant(double deg, double a_g) {
    const SceneSpec s = spec({"ground_motion.kind=constant", fmt::format("ground_motion.acceleration_g={:.17g}", a_g),
                              fmt::format("ground_motion.rise_time={:.17g}", o_.rise_time), direction_override(deg),
                              fmt::format("simulation.end_time={:.17g}", o_.rise_time + o_.hold_time),
                              "assessment.stop_on_collapse=true", "output.energies=false", "output.histories=[]"});
    RunControl c;
    c.threads = o_.threads;
    const RunReport r = run_scene(s, c);
    ++runs_;
    Trial t{a_g, r.assessment.status == "collapsed", r.wall_seconds, r.assessment};
    if (!o_.quiet)
      std::cerr << fmt::format("  direction {:6.1f} deg  a = {:.4f} g  {:<9}  {} steps  {:.1f} s\n", deg, a_g,
                               r.assessment.status, r.steps, r.wall_seconds);
    return t;
  }

  Trial ramp(double deg) {
    const double a_max = 1.2 * o_.high_g;
    const SceneSpec s = spec({"ground_motion.kind=ramp", fmt::format("ground_motion.rate_g={:.17g}", o_.ramp_rate_g),
                              direction_override(deg), fmt::format("simulation.end_time={:.17g}", a_max / o_.ramp_rate_g),
                              // a slow ramp starts at rest: it must not stop as "settled"
                              "simulation.settle_velocity=0",
                              "assessment.stop_on_collapse=true", "output.energies=false", "output.histories=[]"});
    RunControl c;
    c.threads = o_.threads;
    const RunReport r = run_scene(s, c);
    ++runs_;
    Trial t{r.assessment.damage_time >= 0 ? r.assessment.ground_acceleration_at_damage / kGravity : NAN,
            r.assessment.status == "collapsed", r.wall_seconds, r.assessment};
    if (!o_.quiet)
      std::cerr << fmt::format("  direction {:6.1f} deg  ramp {:.3f} g/s: mechanism at {:.4f} g  {}  {:.1f} s\n", deg,
                               o_.ramp_rate_g, t.acceleration_g, r.assessment.status, r.wall_seconds);
    return t;
  }

  int runs() const { return runs_; }

 private:
  const CollapseOptions& o_;
  int runs_ = 0;
};

Json crack_json(const Assessment& a) {
  Json j = Json::object();
  j.set("collapse_mode", a.collapse_mode);
  j.set("moved_blocks", static_cast<int>(a.moved_blocks.size()));
  j.set("opened_joints", a.opened_joints);
  j.set("crack_angle_deg", a.crack_angle_deg >= 0 ? Json(a.crack_angle_deg) : Json());
  j.set("crack_lowest_z_m", a.crack_angle_deg >= 0 ? Json(a.crack_low_z) : Json());
  j.set("crack_highest_z_m", a.crack_angle_deg >= 0 ? Json(a.crack_high_z) : Json());
  Json names = Json::array();
  for (const auto& n : a.moved_blocks) names.push_back(n);
  j.set("moved_block_names", std::move(names));
  return j;
}

}  // namespace

int collapse_command(const CollapseOptions& o) {
  Runner runner(o);
  try {
    (void)runner.spec({});  // bad input fails here, before any run
  } catch (const std::exception& e) {
    std::cerr << "polydem: error: " << e.what() << "\n";
    return exit_bad_input;
  }
  Json out = Json::object();
  out.set("deck", o.use_default ? std::string("<built-in default deck>") : o.deck_path);
  out.set("method", o.method);
  out.set("tolerance_g", o.tolerance_g);
  Json results = Json::array();
  struct Row {
    double deg, bisect, bisect_wall, ramp, ramp_wall;
    int runs;
    double beta;
  };
  std::vector<Row> rows;
  try {
    for (double deg : o.directions_deg) {
      Json d = Json::object();
      d.set("direction_deg", deg);
      Row row{deg, NAN, 0, NAN, 0, 0, -1};
      if (o.method == "bisection" || o.method == "both") {
        const int runs0 = runner.runs();
        Trial lo = runner.constant(deg, o.low_g);
        Trial hi = runner.constant(deg, o.high_g);
        double wall = lo.wall_seconds + hi.wall_seconds;
        Json b = Json::object();
        if (lo.collapsed || !hi.collapsed) {
          b.set("error", fmt::format("the bracket [{}, {}] g does not contain the collapse acceleration "
                                     "(collapsed at low: {}, at high: {})",
                                     o.low_g, o.high_g, lo.collapsed, hi.collapsed));
        } else {
          Trial last_collapse = hi;
          while (hi.acceleration_g - lo.acceleration_g > o.tolerance_g) {
            Trial mid = runner.constant(deg, 0.5 * (lo.acceleration_g + hi.acceleration_g));
            wall += mid.wall_seconds;
            if (mid.collapsed) {
              hi = mid;
              last_collapse = mid;
            } else {
              lo = mid;
            }
          }
          row.bisect = 0.5 * (lo.acceleration_g + hi.acceleration_g);
          row.beta = last_collapse.assessment.crack_angle_deg;
          b.set("collapse_acceleration_g", row.bisect);
          b.set("bracket_g", Json(std::vector<double>{lo.acceleration_g, hi.acceleration_g}));
          b.set("crack", crack_json(last_collapse.assessment));
        }
        row.bisect_wall = wall;
        row.runs = runner.runs() - runs0;
        b.set("runs", row.runs);
        b.set("wall_seconds", wall);
        d.set("bisection", std::move(b));
      }
      if (o.method == "ramp" || o.method == "both") {
        const Trial t = runner.ramp(deg);
        row.ramp = t.acceleration_g;
        row.ramp_wall = t.wall_seconds;
        Json r = Json::object();
        r.set("rate_g_per_s", o.ramp_rate_g);
        r.set("collapse_acceleration_g", std::isfinite(t.acceleration_g) ? Json(t.acceleration_g) : Json());
        r.set("wall_seconds", t.wall_seconds);
        r.set("crack", crack_json(t.assessment));
        d.set("ramp", std::move(r));
        if (row.beta < 0) row.beta = t.assessment.crack_angle_deg;
      }
      rows.push_back(row);
      results.push_back(std::move(d));
    }
  } catch (const InstabilityError& e) {
    std::cerr << "polydem: stopped: " << e.what() << "\n";
    return exit_instability;
  } catch (const std::exception& e) {
    std::cerr << "polydem: error: " << e.what() << "\n";
    return exit_bad_input;
  }
  out.set("directions", std::move(results));
  double lowest = INFINITY;
  for (const Row& r : rows) {
    if (std::isfinite(r.bisect)) lowest = std::min(lowest, r.bisect);
    else if (std::isfinite(r.ramp)) lowest = std::min(lowest, r.ramp);
  }
  out.set("collapse_acceleration_g", std::isfinite(lowest) ? Json(lowest) : Json());
  std::filesystem::create_directories(o.out_dir);
  write_file_atomic(o.out_dir + "/collapse.json", out.dump(2) + "\n");

  std::cout << fmt::format("{:>14} {:>16} {:>6} {:>10} {:>16} {:>10} {:>10}\n", "direction_deg", "bisection_g", "runs",
                           "wall_s", "ramp_g", "wall_s", "crack_deg");
  for (const Row& r : rows)
    std::cout << fmt::format("{:>14.1f} {:>16.4f} {:>6} {:>10.1f} {:>16.4f} {:>10.1f} {:>10.1f}\n", r.deg, r.bisect,
                             r.runs, r.bisect_wall, r.ramp, r.ramp_wall, r.beta);
  std::cout << "results in " << o.out_dir << "/collapse.json\n";
  return exit_success;
}

}  // namespace polydem
