#include "studies/ida.hpp"

#include "analytical/response_spectrum.hpp"
#include "core/units.hpp"
#include "studies/sweep_grid.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <stdexcept>

namespace polydem {

std::string IntensitySpec::name() const {
  if (measure == IntensityMeasure::pga) return "pga";
  return fmt::format("sa({} s, {} %)", value_text(period), value_text(damping * 100));
}

double record_intensity(const SuiteRecord& record, const IntensitySpec& im) {
  // The geometric mean over the horizontal components (one: its own IM).
  double log_sum = 0;
  int horizontal = 0;
  for (const SuiteComponent& c : record.components) {
    if (c.direction.z() != 0.0) continue;
    double x = 0;
    if (im.measure == IntensityMeasure::pga) {
      for (double a : c.acceleration) x = std::max(x, std::abs(a));
    } else {
      x = analytical::response_spectrum(c.time, c.acceleration, {im.period}, im.damping).pseudo_acceleration.at(0);
    }
    x *= c.scale / kRecordG;
    if (!(x > 0) || !std::isfinite(x))
      throw std::invalid_argument("record " + record.name + ": its " + im.name() + " is not > 0");
    log_sum += std::log(x);
    ++horizontal;
  }
  if (horizontal == 0)
    throw std::invalid_argument("record " + record.name +
                                ": no horizontal component (direction with z = 0), so no " + im.name());
  return horizontal == 1 ? std::exp(log_sum) : std::exp(log_sum / horizontal);
}

namespace {

// A TOML basic string.
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) < 0x20) {
      out += fmt::format("\\u{:04x}", static_cast<unsigned>(c));
      continue;
    }
    out += c;
  }
  return out + "\"";
}

std::string vector_text(const Vec3& v) {
  return fmt::format("[{}, {}, {}]", value_text(v.x()), value_text(v.y()), value_text(v.z()));
}

// One component's keys of the inline table (without its scale).
std::string component_keys(const SuiteComponent& c, const RecordSuite& suite, const GroundMotionSpec& deck) {
  std::string s = fmt::format("kind = \"record\", record = {}, direction = {}, start_time = {}", quoted(std::filesystem::absolute(c.record_path).lexically_normal().string()),
                              vector_text(c.direction), value_text(deck.start_time));
  if (suite.baseline_order >= 0) s += ", baseline_order = " + std::to_string(suite.baseline_order);
  if (suite.length_scale != 1.0) s += ", length_scale = " + value_text(suite.length_scale);
  return s;
}

double rounded(double x) { return std::stod(fmt::format("{:.12g}", x)); }

}  // namespace

std::string record_motion_override(const SuiteRecord& record, const RecordSuite& suite, const GroundMotionSpec& deck) {
  std::string s = "ground_motion = {" + component_keys(record.components.front(), suite, deck);
  s += ", applied_as = ";
  s += deck.applied_as == GroundMotionApplication::kinematic ? "\"kinematic\"" : "\"body_force\"";
  if (deck.tower_frequency > 0)
    s += ", tower_frequency = " + value_text(deck.tower_frequency) + ", tower_damping = " + value_text(deck.tower_damping);
  if (record.components.size() > 1) {
    s += ", component = [";
    for (std::size_t k = 1; k < record.components.size(); ++k)
      s += (k > 1 ? ", {" : "{") + component_keys(record.components[k], suite, deck) + "}";
    s += "]";
  }
  return s + "}";
}

SweepPoint record_point(const SuiteRecord& record, const std::string& motion_override, double factor) {
  SweepPoint p;
  p.fixed.push_back(motion_override);
  p.values.emplace_back("ground_motion.scale", factor * record.components.front().scale);
  for (std::size_t k = 1; k < record.components.size(); ++k)
    p.values.emplace_back("ground_motion.component[" + std::to_string(k) + "].scale",
                          factor * record.components[k].scale);
  return p;
}

std::string damage_state(const PointResult& r) {
  if (r.status == "collapsed") return "collapsed";
  if (r.status != "intact" && r.status != "damaged") return "undetermined";  // undetermined, unstable, error
  if (r.dislodged > 0) return "stones_lost";
  return r.status;
}

int damage_rank(const std::string& state) {
  if (state == "intact") return 0;
  if (state == "damaged") return 1;
  if (state == "stones_lost") return 2;
  if (state == "collapsed") return 3;
  return -1;
}

namespace {

// One record's search: its runs by IM and where it stands.
struct RecordSearch {
  enum class Phase { hunt, bracket, fill, done };
  Phase phase = Phase::hunt;
  std::map<double, IdaRun> runs;
  double last_hunt = 0;  // IM of the latest hunt run
  int hunt_steps = 0;
  double lo = 0, hi = 0;  // the collapse bracket

  double lowest_collapse() const {
    for (const auto& [im, run] : runs)
      if (run.state == "collapsed") return im;
    return std::numeric_limits<double>::quiet_NaN();
  }
};

IdaRecord summarise(const std::string& name, double record_im, const std::map<double, IdaRun>& runs) {
  IdaRecord out;
  out.name = name;
  out.record_im = record_im;
  for (const auto& [im, run] : runs) {
    out.runs.push_back(run);
    const int rank = damage_rank(run.state);
    if (rank < 0) ++out.undetermined;
    if (rank >= 1 && std::isnan(out.damage_im)) out.damage_im = im;
    if (rank >= 2 && std::isnan(out.stones_im)) out.stones_im = im;
    if (rank >= 3 && std::isnan(out.collapse_im)) out.collapse_im = im;
  }
  for (const auto& [im, run] : runs)
    if ((std::isnan(out.collapse_im) || im < out.collapse_im) && run.state != "collapsed") out.below_collapse_im = im;
  return out;
}

// The next IM of a record's search, or NaN when it is done.
double next_im(RecordSearch& s, const HuntAndFill& h) {
  using Phase = RecordSearch::Phase;
  const double none = std::numeric_limits<double>::quiet_NaN();
  if (static_cast<long>(s.runs.size()) >= h.max_runs) s.phase = Phase::done;
  double x = none;
  switch (s.phase) {
    case Phase::done:
      return none;
    case Phase::hunt:
      x = s.hunt_steps == 0 ? h.first : s.last_hunt + h.step + (s.hunt_steps - 1) * h.growth;
      break;
    case Phase::bracket:
      if (s.hi - s.lo > h.tolerance) {
        x = (s.lo + s.hi) / 2;
        break;
      }
      s.phase = Phase::fill;
      [[fallthrough]];
    case Phase::fill: {
      // The widest gap between the IMs run below the lowest collapse (and 0).
      const double top = s.lowest_collapse();
      double from = 0, widest = 0, at = 0;
      for (const auto& [im, run] : s.runs) {
        if (im > top) break;
        if (im - from > widest) {
          widest = im - from;
          at = from;
        }
        from = im;
      }
      if (widest <= h.tolerance) {
        s.phase = Phase::done;
        return none;
      }
      x = at + widest / 2;
      break;
    }
  }
  x = rounded(x);
  if (s.runs.count(x)) {  // the rounding met a run: nothing narrower to learn
    s.phase = Phase::done;
    return none;
  }
  return x;
}

// A finished run of the search moves it on.
void record_run(RecordSearch& s, double im, IdaRun run) {
  using Phase = RecordSearch::Phase;
  const bool collapsed = run.state == "collapsed";
  s.runs[im] = std::move(run);
  if (s.phase == Phase::hunt) {
    s.last_hunt = im;
    ++s.hunt_steps;
    if (collapsed) {
      s.phase = Phase::bracket;
      s.hi = im;
      s.lo = 0;
      for (const auto& [x, r] : s.runs)
        if (x < im && r.state != "collapsed") s.lo = x;
    }
  } else if (s.phase == Phase::bracket) {
    (collapsed ? s.hi : s.lo) = im;
  }
}

void check_names(const std::vector<std::string>& names, const std::vector<double>& record_ims) {
  if (names.size() != record_ims.size()) throw std::invalid_argument("one IM per record");
  for (double x : record_ims)
    if (!(x > 0) || !std::isfinite(x)) throw std::invalid_argument("every record's IM must be > 0");
}

}  // namespace

IdaReport hunt_and_fill(const std::vector<std::string>& names, const std::vector<double>& record_ims,
                        const HuntAndFill& h, const IdaPointOf& point_of, const BatchRunner& run,
                        const IdaProgress& after_round) {
  check_names(names, record_ims);
  for (const auto& [what, x] : {std::pair<const char*, double>{"first IM", h.first}, {"step", h.step},
                                {"tolerance", h.tolerance}})
    if (!(x > 0) || !std::isfinite(x)) throw std::invalid_argument(std::string("the hunt's ") + what + " must be > 0");
  if (!(h.growth >= 0) || !std::isfinite(h.growth)) throw std::invalid_argument("the hunt's growth must be >= 0");
  if (h.max_runs < 1) throw std::invalid_argument("max runs must be >= 1");

  std::vector<RecordSearch> searches(names.size());
  IdaReport report;
  const auto summarise_all = [&]() {
    report.records.clear();
    for (std::size_t r = 0; r < searches.size(); ++r)
      report.records.push_back(summarise(names[r], record_ims[r], searches[r].runs));
  };
  for (;;) {
    std::vector<std::pair<std::size_t, double>> todo;
    for (std::size_t r = 0; r < searches.size(); ++r) {
      const double x = next_im(searches[r], h);
      if (!std::isnan(x)) todo.emplace_back(r, x);
    }
    if (todo.empty()) break;
    std::vector<SweepPoint> batch;
    for (const auto& [r, x] : todo) batch.push_back(point_of(r, x, x / record_ims[r]));
    const std::vector<PointResult> results = run(batch);
    for (std::size_t i = 0; i < todo.size(); ++i) {
      const auto [r, x] = todo[i];
      record_run(searches[r], x, IdaRun{x, x / record_ims[r], results[i], damage_state(results[i])});
    }
    report.runs += static_cast<long>(todo.size());
    ++report.rounds;
    if (after_round) {
      summarise_all();
      after_round(report);
    }
  }
  summarise_all();
  return report;
}

IdaReport run_stripes(const std::vector<std::string>& names, const std::vector<double>& record_ims,
                      const std::vector<double>& levels, bool factors, const IdaPointOf& point_of,
                      const BatchRunner& run) {
  check_names(names, record_ims);
  if (levels.empty()) throw std::invalid_argument("no stripes");
  for (double x : levels)
    if (!(x > 0) || !std::isfinite(x)) throw std::invalid_argument("every stripe must be > 0");
  std::vector<SweepPoint> batch;
  std::vector<std::pair<double, double>> at;  // im, factor
  for (std::size_t r = 0; r < names.size(); ++r)
    for (double x : levels) {
      const double im = factors ? x * record_ims[r] : x;
      const double factor = factors ? x : x / record_ims[r];
      batch.push_back(point_of(r, im, factor));
      at.emplace_back(im, factor);
    }
  const std::vector<PointResult> results = run(batch);
  IdaReport report;
  report.runs = static_cast<long>(batch.size());
  report.rounds = 1;
  std::size_t i = 0;
  for (std::size_t r = 0; r < names.size(); ++r) {
    std::map<double, IdaRun> runs;
    for (std::size_t k = 0; k < levels.size(); ++k, ++i)
      runs[at[i].first] = IdaRun{at[i].first, at[i].second, results[i], damage_state(results[i])};
    report.records.push_back(summarise(names[r], record_ims[r], runs));
  }
  return report;
}

}  // namespace polydem
