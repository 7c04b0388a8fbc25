#include "io/ensemble_tables.hpp"

#include "io/sweep_tables.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace polydem {

namespace {

std::string cell(double x) { return csv_number(x); }

Json number_or_null(double x) { return std::isfinite(x) ? Json(x) : Json(); }

}  // namespace

std::string replicas_csv(const std::vector<ReplicaRow>& rows) {
  std::string csv =
      "replica,seed,friction_angle_shift_deg,normal_stiffness_factor,shear_stiffness_factor,time_shift_s,"
      "largest_initial_speed_m_s,status,collapse_mode";
  for (const EnsembleQuantity& q : ensemble_quantities()) csv += std::string(",") + q.name;
  csv += ",dislodged_blocks,steps,exit_code,point\n";
  for (const ReplicaRow& r : rows) {
    const EnsembleDraw& d = r.drawn;
    csv += fmt::format("{},{},{},{},{},{},{},{},{}", r.replica, r.seed, cell(d.friction_angle_shift),
                       cell(d.normal_stiffness_factor), cell(d.shear_stiffness_factor), cell(d.time_shift),
                       cell(d.largest_initial_speed), r.result.status, r.result.collapse_mode);
    for (const EnsembleQuantity& q : ensemble_quantities()) {
      csv += ',';
      csv += cell(q.of(r.result));
    }
    csv += fmt::format(",{},{},{},{}\n", r.result.dislodged, r.result.steps, r.result.exit_code, r.id);
  }
  return csv;
}

std::string ensemble_csv(const std::vector<std::string>& keys, const std::vector<EnsemblePoint>& points,
                         bool fractions) {
  // One column per status any point saw, so that every row has the same.
  std::set<std::string> statuses;
  for (const EnsemblePoint& p : points)
    for (const auto& [status, n] : p.outcome.status_counts) statuses.insert(status);
  std::string csv;
  for (const auto& key : keys) csv += key + ",";
  csv += "replicas";
  for (const auto& status : statuses) csv += fmt::format(",n_{}", status);
  csv += ",n_mode_I,n_mode_II";
  for (const EnsembleQuantity& q : ensemble_quantities())
    csv += fmt::format(",{0}_n,{0}_p16,{0}_median,{0}_p84", q.name);
  if (fractions) {
    csv += ",judged";
    for (const BandOutcome& o : band_outcomes()) csv += fmt::format(",p_{}", o.name);
  }
  csv += "\n";
  for (const EnsemblePoint& p : points) {
    for (const auto& key : keys) csv += fmt::format("{},", cell(value_of(p.point, key)));
    csv += std::to_string(p.outcome.replicas);
    for (const auto& status : statuses) {
      long n = 0;
      for (const auto& [s, count] : p.outcome.status_counts)
        if (s == status) n = count;
      csv += fmt::format(",{}", n);
    }
    csv += fmt::format(",{},{}", p.outcome.mode_I, p.outcome.mode_II);
    for (const Distribution& d : p.outcome.quantities)
      csv += fmt::format(",{},{},{},{}", d.n, cell(d.p16), cell(d.median), cell(d.p84));
    if (fractions) {
      csv += fmt::format(",{}", p.fractions.judged);
      for (double x : p.fractions.p) {
        csv += ',';
        csv += cell(x);
      }
    }
    csv += "\n";
  }
  return csv;
}

std::string bands_csv(const std::vector<std::string>& column_keys, const std::string& axis_key,
                      const std::vector<ColumnBands>& bands) {
  std::string csv;
  for (const auto& key : column_keys) csv += key + ",";
  csv += fmt::format("outcome,status,{0}_16,{0}_50,{0}_84,beta,{0}_below,{0}_above,{0}_falls_back,runs,reached,"
                     "undetermined,failed,largest_gap\n",
                     axis_key);
  for (const ColumnBands& c : bands)
    for (const OutcomeBand& b : c.outcomes) {
      for (const auto& key : column_keys) csv += cell(value_of(c.column, key)) + ",";
      csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", b.outcome, b.status, cell(b.at16),
                         cell(b.at50), cell(b.at84), cell(b.beta), cell(b.below), cell(b.above),
                         cell(b.falls_back), b.runs, b.reached, b.undetermined, b.failed, cell(b.largest_gap));
    }
  return csv;
}

std::string courses_csv(const std::vector<std::string>& keys, const std::vector<EnsemblePoint>& points) {
  if (std::none_of(points.begin(), points.end(), [](const EnsemblePoint& p) { return !p.outcome.courses.empty(); }))
    return {};
  std::string csv;
  for (const auto& key : keys) csv += key + ",";
  csv += "course,level_m,bed_joints,vertical_joints";
  for (const CourseQuantity& q : course_quantities()) csv += fmt::format(",{0}_n,{0}_p16,{0}_median,{0}_p84", q.name);
  csv += "\n";
  for (const EnsemblePoint& p : points)
    for (std::size_t k = 0; k < p.outcome.courses.size(); ++k) {
      const CourseDistribution& c = p.outcome.courses[k];
      for (const auto& key : keys) csv += cell(value_of(p.point, key)) + ",";
      csv += fmt::format("{},{},{},{}", k, cell(c.level), c.bed_joints, c.vertical_joints);
      for (const Distribution& d : c.quantities)
        csv += fmt::format(",{},{},{},{}", d.n, cell(d.p16), cell(d.median), cell(d.p84));
      csv += "\n";
    }
  return csv;
}

Json outcome_json(const EnsembleOutcome& o) {
  Json j = Json::object();
  j.set("replicas", static_cast<std::int64_t>(o.replicas));
  Json counts = Json::object();
  for (const auto& [status, n] : o.status_counts) counts.set(status, static_cast<std::int64_t>(n));
  j.set("status_counts", std::move(counts));
  j.set("collapse_modes", Json::object()
                              .set("I", static_cast<std::int64_t>(o.mode_I))
                              .set("II", static_cast<std::int64_t>(o.mode_II)));
  Json qs = Json::object();
  const auto quantities = ensemble_quantities();
  for (std::size_t i = 0; i < quantities.size() && i < o.quantities.size(); ++i) {
    const Distribution& d = o.quantities[i];
    qs.set(quantities[i].name, Json::object()
                                   .set("n", static_cast<std::int64_t>(d.n))
                                   .set("p16", number_or_null(d.p16))
                                   .set("median", number_or_null(d.median))
                                   .set("p84", number_or_null(d.p84)));
  }
  j.set("distributions", std::move(qs));
  return j;
}

std::vector<EnsemblePoint> ensemble_points(const std::vector<std::string>& keys,
                                           const std::vector<std::pair<SweepPoint, PointResult>>& rows) {
  std::map<std::vector<double>, std::vector<const std::pair<SweepPoint, PointResult>*>> groups;
  for (const auto& row : rows) {
    std::vector<double> at;
    for (const auto& key : keys) at.push_back(value_of(row.first, key));
    groups[at].push_back(&row);
  }
  std::vector<EnsemblePoint> out;
  for (const auto& [at, members] : groups) {
    EnsemblePoint p;
    for (std::size_t k = 0; k < keys.size(); ++k) p.point.values.emplace_back(keys[k], at[k]);
    std::vector<PointResult> results;
    for (const auto* m : members) results.push_back(m->second);
    p.outcome = summarise_ensemble(results);
    p.fractions = outcome_fractions(results);
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace polydem
