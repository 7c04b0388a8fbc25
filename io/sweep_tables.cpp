#include "io/sweep_tables.hpp"

#include "io/atomic_file.hpp"
#include "io/hdf5_results.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#ifndef POLYDEM_VERSION
#define POLYDEM_VERSION "0.1.0"
#endif

namespace polydem {
namespace {

std::string cell(double x) { return csv_number(x); }

constexpr const char* kDeckUnit = "as the deck key (docs/deck.md)";

}  // namespace

std::string csv_number(double x) { return std::isfinite(x) ? value_text(x) : std::string(); }

std::string transitions_text(const std::vector<Transition>& transitions) {
  std::string out;
  for (const Transition& t : transitions) {
    if (!out.empty()) out += ';';
    out += value_text(t.above) + ":" + t.from + ">" + t.to;
  }
  return out;
}

void write_sweep_tables(const std::string& out_dir, const SweepTables& t) {
  std::filesystem::create_directories(out_dir);
  std::vector<const SweepRow*> rows;
  for (const SweepRow& r : t.rows) rows.push_back(&r);
  std::stable_sort(rows.begin(), rows.end(), [&](const SweepRow* a, const SweepRow* b) {
    for (const auto& key : t.keys) {
      const double x = value_of(a->point, key), y = value_of(b->point, key);
      if (x != y) return x < y;
    }
    return false;
  });
  const auto none = [](double x, bool valid) { return valid ? x : std::numeric_limits<double>::quiet_NaN(); };

  std::string csv;
  for (const auto& key : t.keys) csv += key + ",";
  csv += "status,collapse_mode,peak_tip_displacement_m,peak_displacement_m,residual_displacement_m,collapse_time_s,"
         "run_wall_seconds,steps,exit_code,point,dislodged_blocks\n";
  for (const SweepRow* r : rows) {
    for (const auto& key : t.keys) csv += cell(value_of(r->point, key)) + ",";
    const PointResult& p = r->result;
    csv += fmt::format("{},{},{},{},{},{},{},{},{},{}\n", p.status, p.collapse_mode, cell(p.peak_tip_displacement),
                       cell(p.peak_displacement), cell(p.residual_displacement),
                       cell(none(p.collapse_time, p.collapse_time >= 0)), cell(p.wall_seconds), p.steps, p.exit_code,
                       r->id);
    csv.pop_back();
    csv += fmt::format(",{}\n", p.dislodged);
  }
  write_file_atomic(out_dir + "/sweep.csv", csv);

  ResultsFile h5(out_dir + "/sweep.h5");
  h5.write_string("/deck", t.deck_text);
  h5.write_attribute("/deck", "path", t.deck_path);
  h5.write_attribute("/deck", "polydem_version", POLYDEM_VERSION);
  for (const auto& key : t.keys) {
    std::vector<double> v;
    for (const SweepRow* r : rows) v.push_back(value_of(r->point, key));
    h5.write_vector("/points/" + key, v, kDeckUnit);
  }
  auto column = [&](const std::string& name, const std::string& unit, auto get) {
    std::vector<double> v;
    for (const SweepRow* r : rows) v.push_back(get(r->result));
    h5.write_vector("/points/" + name, v, unit);
  };
  auto strings = [&](const std::string& name, auto get) {
    std::vector<std::string> v;
    for (const SweepRow* r : rows) v.push_back(get(*r));
    h5.write_strings("/points/" + name, v);
  };
  strings("status", [](const SweepRow& r) { return r.result.status; });
  strings("collapse_mode", [](const SweepRow& r) { return r.result.collapse_mode; });
  strings("point", [](const SweepRow& r) { return r.id; });
  column("peak_tip_displacement", "m", [](const PointResult& p) { return p.peak_tip_displacement; });
  column("peak_displacement", "m", [](const PointResult& p) { return p.peak_displacement; });
  column("residual_displacement", "m", [](const PointResult& p) { return p.residual_displacement; });
  column("collapse_time", "s", [&](const PointResult& p) { return none(p.collapse_time, p.collapse_time >= 0); });
  column("run_wall_seconds", "s", [](const PointResult& p) { return p.wall_seconds; });
  column("steps", "1", [](const PointResult& p) { return static_cast<double>(p.steps); });
  column("exit_code", "1", [](const PointResult& p) { return static_cast<double>(p.exit_code); });
  h5.write_attribute("/points", "keys", fmt::format("{}", fmt::join(t.keys, " ")));

  if (t.search && t.axis) {
    const SearchReport& s = *t.search;
    const std::string& key = t.axis->key;
    std::vector<std::string> outer_keys(t.keys.begin(), t.keys.end() - 1);
    std::string b;
    for (const auto& k : outer_keys) b += k + ",";
    b += fmt::format("damage_{0},collapse_{0},collapse_mode,transitions,runs,run_wall_seconds,stones_lost_{0}\n", key);
    for (const ColumnResult& c : s.columns) {
      for (const auto& k : outer_keys) b += cell(value_of(c.outer, k)) + ",";
      b += fmt::format("{},{},{},{},{},{},{}\n", cell(c.damage_threshold), cell(c.collapse_threshold), c.collapse_mode,
                       transitions_text(c.transitions), c.runs.size(), cell(c.wall_seconds),
                       cell(c.stones_threshold));
    }
    write_file_atomic(out_dir + "/boundaries.csv", b);
    for (const auto& k : outer_keys) {
      std::vector<double> v;
      for (const ColumnResult& c : s.columns) v.push_back(value_of(c.outer, k));
      h5.write_vector("/boundaries/" + k, v, kDeckUnit);
    }
    std::vector<double> dmg, stones, col, runs, wall;
    std::vector<std::string> mode, trans;
    for (const ColumnResult& c : s.columns) {
      dmg.push_back(c.damage_threshold);
      stones.push_back(c.stones_threshold);
      col.push_back(c.collapse_threshold);
      runs.push_back(static_cast<double>(c.runs.size()));
      wall.push_back(c.wall_seconds);
      mode.push_back(c.collapse_mode);
      trans.push_back(transitions_text(c.transitions));
    }
    h5.write_vector("/boundaries/damage_threshold", dmg, kDeckUnit);
    h5.write_vector("/boundaries/stones_lost_threshold", stones, kDeckUnit);
    h5.write_vector("/boundaries/collapse_threshold", col, kDeckUnit);
    h5.write_strings("/boundaries/collapse_mode", mode);
    h5.write_strings("/boundaries/transitions", trans);
    h5.write_vector("/boundaries/runs", runs, "1");
    h5.write_vector("/boundaries/run_wall_seconds", wall, "s");
    h5.write_attribute("/boundaries", "search_key", key);
    h5.write_attribute("/boundaries", "resolution", (t.axis->stop - t.axis->start) / (t.axis->lattice_points() - 1));
    h5.write_attribute("/boundaries", "runs", static_cast<double>(s.runs));
    h5.write_attribute("/boundaries", "full_grid_runs", static_cast<double>(s.full_grid));
  }
  h5.commit();
}

}  // namespace polydem
