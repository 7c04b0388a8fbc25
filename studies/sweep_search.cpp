#include "studies/sweep_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace polydem {

long SearchAxis::lattice_points() const {
  return std::max(1L, std::lround((stop - start) / resolution)) + 1;
}

double SearchAxis::value(long k) const { return lattice_value(start, stop, k, lattice_points()); }

SearchAxis parse_search_axis(const std::string& arg, double resolution) {
  const SweepAxis a = parse_axis(arg, "--search");
  if (arg.find(':') == std::string::npos || a.values.size() < 2)
    throw std::invalid_argument("--search " + arg + ": give a range START:STOP:N with N >= 2 coarse points");
  SearchAxis s;
  s.key = a.key;
  s.start = a.values.front();
  s.stop = a.values.back();
  s.coarse = static_cast<long>(a.values.size());
  if (!(resolution > 0))
    throw std::invalid_argument("--resolution must be positive (the bracket width to bisect down to)");
  s.resolution = resolution;
  if (s.lattice_points() < s.coarse)
    throw std::invalid_argument("--search " + arg + ": the coarse scan is already finer than --resolution");
  if (s.lattice_points() > 1000000)
    throw std::invalid_argument("--resolution: more than a million lattice points along " + s.key);
  return s;
}

namespace {

struct Column {
  std::map<long, PointResult> runs;             // by lattice index
  std::vector<std::pair<long, long>> open;      // intervals still to bisect
};

}  // namespace

SearchReport boundary_search(const std::vector<SweepPoint>& outer, const SearchAxis& axis, const BatchRunner& run) {
  const long last = axis.lattice_points() - 1;
  std::vector<Column> columns(outer.size());
  SearchReport report;
  report.full_grid = static_cast<long>(outer.size()) * (last + 1);

  // Runs (column, lattice index) pairs as one batch.
  auto evaluate = [&](const std::vector<std::pair<std::size_t, long>>& todo) {
    std::vector<SweepPoint> batch;
    for (const auto& [c, k] : todo) batch.push_back(outer[c].with(axis.key, axis.value(k)));
    const std::vector<PointResult> results = run(batch);
    for (std::size_t i = 0; i < todo.size(); ++i) columns[todo[i].first].runs[todo[i].second] = results[i];
    report.runs += static_cast<long>(todo.size());
    ++report.rounds;
  };

  std::vector<long> coarse;
  for (long i = 0; i < axis.coarse; ++i) {
    const long k = axis.coarse == 1 ? 0 : std::lround(static_cast<double>(i) * last / (axis.coarse - 1));
    if (coarse.empty() || coarse.back() != k) coarse.push_back(k);
  }
  std::vector<std::pair<std::size_t, long>> todo;
  for (std::size_t c = 0; c < columns.size(); ++c)
    for (long k : coarse) todo.emplace_back(c, k);
  evaluate(todo);
  for (Column& col : columns)
    for (std::size_t i = 0; i + 1 < coarse.size(); ++i)
      if (col.runs[coarse[i]].klass() != col.runs[coarse[i + 1]].klass()) col.open.emplace_back(coarse[i], coarse[i + 1]);

  for (;;) {
    todo.clear();
    for (std::size_t c = 0; c < columns.size(); ++c)
      for (const auto& [lo, hi] : columns[c].open)
        if (hi - lo > 1) todo.emplace_back(c, lo + (hi - lo) / 2);
    if (todo.empty()) break;
    evaluate(todo);
    for (Column& col : columns) {
      std::vector<std::pair<long, long>> next;
      for (const auto& [lo, hi] : col.open) {
        if (hi - lo <= 1) {
          next.emplace_back(lo, hi);
          continue;
        }
        const long mid = lo + (hi - lo) / 2;
        const std::string a = col.runs[lo].klass(), m = col.runs[mid].klass(), b = col.runs[hi].klass();
        if (m == a) {
          next.emplace_back(mid, hi);
        } else if (m == b) {
          next.emplace_back(lo, mid);
        } else {  // a third class: both halves hold a change
          next.emplace_back(lo, mid);
          next.emplace_back(mid, hi);
        }
      }
      col.open = std::move(next);
    }
  }

  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t c = 0; c < columns.size(); ++c) {
    Column& col = columns[c];
    ColumnResult out;
    out.outer = outer[c];
    for (const auto& [k, r] : col.runs) {
      out.runs.emplace_back(axis.value(k), r);
      out.wall_seconds += r.wall_seconds;
    }
    std::sort(col.open.begin(), col.open.end());
    for (const auto& [lo, hi] : col.open)
      out.transitions.push_back({axis.value(lo), axis.value(hi), col.runs[lo].klass(), col.runs[hi].klass()});
    // Thresholds: the first run (in lattice order) that is not intact / that
    // collapsed. With every change bracketed to one lattice step, that run's
    // neighbour below is of the other class.
    out.damage_threshold = out.stones_threshold = out.collapse_threshold = nan;
    for (const auto& [k, r] : col.runs) {
      if (std::isnan(out.damage_threshold) && r.klass() != "intact") out.damage_threshold = axis.value(k);
      if (std::isnan(out.stones_threshold) && (r.dislodged > 0 || r.status == "collapsed"))
        out.stones_threshold = axis.value(k);
      if (std::isnan(out.collapse_threshold) && r.status == "collapsed") {
        out.collapse_threshold = axis.value(k);
        out.collapse_mode = r.collapse_mode;
      }
    }
    report.columns.push_back(std::move(out));
  }
  return report;
}

}  // namespace polydem
