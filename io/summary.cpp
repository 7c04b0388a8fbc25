#include "io/summary.hpp"

#include "core/units.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5_results.hpp"

#include <filesystem>

#ifndef POLYDEM_VERSION
#define POLYDEM_VERSION "0.1.0"
#endif

#include <algorithm>
#include <limits>

namespace polydem {

namespace {

struct GroupTotals {
  std::string name;
  int blocks = 0;
  double mass = 0;  // kg, ρ·V of each block as the run built it
  int dislodged = 0;
  double dislodged_mass = 0;  // kg
};

// Per group, in the order of its first block: the count and the mass, and
// of them the blocks the assessment found dislodged.
std::vector<GroupTotals> group_totals(const std::vector<BlockSpec>& blocks, const std::vector<std::string>& dislodged) {
  std::vector<GroupTotals> out;
  for (const BlockSpec& b : blocks) {
    if (b.group.empty()) continue;
    auto it = std::find_if(out.begin(), out.end(), [&](const GroupTotals& g) { return g.name == b.group; });
    if (it == out.end()) {
      out.push_back({b.group, 0, 0.0});
      it = out.end() - 1;
    }
    ++it->blocks;
    const double m = b.density * mass_properties(b.shape).volume;
    it->mass += m;
    if (std::find(dislodged.begin(), dislodged.end(), b.name) != dislodged.end()) {
      ++it->dislodged;
      it->dislodged_mass += m;
    }
  }
  return out;
}

double number_or(const Json* j, double fallback) {
  return (j && (j->type() == Json::Type::Number || j->type() == Json::Type::Integer)) ? j->as_number() : fallback;
}

std::string string_or(const Json* j, const std::string& fallback) {
  return (j && j->type() == Json::Type::String) ? j->as_string() : fallback;
}

void write_table(ResultsFile& f, const std::string& group, const HistoryTable& t) {
  const std::size_t rows = t.row_count(), cols = t.columns.size();
  for (std::size_t c = 0; c < cols; ++c) {
    std::vector<double> col(rows);
    for (std::size_t r = 0; r < rows; ++r) col[r] = t.rows[r * cols + c];
    f.write_vector(group + "/" + t.columns[c], col, t.units[c]);
  }
}

}  // namespace

void set_crack(Json& j, const Assessment& a) {
  j.set("moved_blocks", static_cast<int>(a.moved_blocks.size()));
  j.set("opened_joints", a.opened_joints);
  j.set("crack_angle_deg", a.crack_angle_deg >= 0 ? Json(a.crack_angle_deg) : Json());
  j.set("crack_lowest_z_m", a.crack_angle_deg >= 0 ? Json(a.crack_low_z) : Json());
  j.set("crack_highest_z_m", a.crack_angle_deg >= 0 ? Json(a.crack_high_z) : Json());
}

Json profile_json(const RunProfile& p) {
  Json j = Json::object();
  const double total = p.total > 0 ? p.total : 1.0;
  for (const auto& [name, seconds] : {std::pair<const char*, double>{"setup", p.setup},
                                      {"equilibrium", p.equilibrium},
                                      {"detection", p.detection},
                                      {"patch", p.patch},
                                      {"joint_law", p.joint_law},
                                      {"gather_update", p.gather_update},
                                      {"guard", p.guard},
                                      {"output", p.output}}) {
    Json stage = Json::object();
    stage.set("seconds", seconds);
    stage.set("fraction", seconds / total);
    j.set(name, std::move(stage));
  }
  j.set("total_seconds", p.total);
  j.set("steps", p.steps);
  j.set("microseconds_per_step", p.steps > 0 ? 1e6 * (p.total - p.setup - p.equilibrium) / p.steps : 0.0);
  Json t = Json::object();
  t.set("given", p.threads_given);
  t.set("probes", p.thread_probes);
  t.set("switches", p.thread_switches);
  t.set("stall_drops", p.thread_stall_drops);
  t.set("steps_on_one", p.steps_on_one_thread);
  j.set("threads", std::move(t));
  return j;
}

Json summary_json(const SceneSpec& spec, const RunReport& r, int threads) {
  Json s = Json::object();
  s.set("polydem_version", POLYDEM_VERSION);
  s.set("deck", spec.deck_path);
  s.set("status", r.status);
  if (r.unstable) {
    s.set("instability", r.instability);
    s.set("last_good_time_s", r.last_good_time);
  }
  s.set("settled", r.settled);
  s.set("warnings", Json(spec.warnings));
  if (r.equilibrium.ran) {
    Json e = Json::object();
    e.set("steps", r.equilibrium.steps);
    e.set("unbalanced_force_ratio", r.equilibrium.ratio);
    e.set("ratio_tolerance", spec.equilibrium.ratio);
    e.set("local_damping", spec.equilibrium.local_damping);
    e.set("density_scaling", spec.equilibrium.density_scaling);
    e.set("wall_seconds", r.equilibrium.wall_seconds);
    e.set("max_displacement_m", r.equilibrium.max_displacement);
    e.set("max_displacement_block", r.equilibrium.max_displacement_block);
    s.set("equilibrium", std::move(e));
  }
  if (spec.ensemble.given) {
    // The replica of an ensemble this run is, and what it drew (docs/ensembles.md).
    const EnsembleSpec& en = spec.ensemble;
    Json e = Json::object();
    e.set("replica", static_cast<std::int64_t>(en.replica));
    e.set("seed", static_cast<std::int64_t>(en.seed));
    e.set("friction_angle_shift_deg", en.drawn.friction_angle_shift);
    e.set("normal_stiffness_factor", en.drawn.normal_stiffness_factor);
    e.set("shear_stiffness_factor", en.drawn.shear_stiffness_factor);
    e.set("time_shift_s", en.drawn.time_shift);
    e.set("largest_initial_speed_m_s", en.drawn.largest_initial_speed);
    s.set("ensemble", std::move(e));
  }
  const Assessment& a = r.assessment;
  Json as = Json::object();
  as.set("collapse_mode", a.collapse_mode);
  as.set("collapse_reason", a.collapse_reason);
  as.set("collapse_time_s", a.collapse_time >= 0 ? Json(a.collapse_time) : Json());
  as.set("damage_time_s", a.damage_time >= 0 ? Json(a.damage_time) : Json());
  // Under a rising load this is the acceleration at which the mechanism formed.
  as.set("ground_acceleration_at_damage_g",
         a.damage_time >= 0 ? Json(a.ground_acceleration_at_damage / kGravity) : Json());
  as.set("peak_displacement_m", a.peak_displacement);
  as.set("peak_displacement_block", a.peak_displacement_block);
  as.set("max_residual_displacement_m", a.max_residual_displacement);
  as.set("monitor_block", a.monitor_block);
  as.set("monitor_peak_displacement_m", a.monitor_peak_displacement);
  as.set("monitor_residual_displacement_m", a.monitor_residual_displacement);
  as.set("monitor_past_no_return", a.monitor_past_no_return);
  as.set("fastest_speed_m_s", a.fastest_speed);
  as.set("fastest_block", a.fastest_block);
  as.set("moving_speed_limit_m_s", a.moving_speed_limit);
  as.set("stones_lost", a.stones_lost());
  set_crack(as, a);
  Json dis = Json::object();
  dis.set("count", a.stones_lost());
  dis.set("mass_kg", a.dislodged_mass);
  dis.set("mass_fraction", a.dislodged_mass_fraction);
  dis.set("lowest_z_m", a.dislodged_blocks.empty() ? Json() : Json(a.dislodged_low_z));
  dis.set("highest_z_m", a.dislodged_blocks.empty() ? Json() : Json(a.dislodged_high_z));
  dis.set("blocks", Json(a.dislodged_blocks));
  dis.set("fallen_count", static_cast<int>(a.fallen_blocks.size()));
  dis.set("fallen_mass_fraction", a.fallen_mass_fraction);
  dis.set("fallen_blocks", Json(a.fallen_blocks));
  as.set("dislodged", std::move(dis));
  s.set("assessment", std::move(as));
  if (!r.walking.bed_joint.empty() || !r.walking.vertical_joint.empty()) {
    Json w = Json::object();
    w.set("residual_bed_opening_m", r.walking.bed_opening);
    w.set("residual_bed_joint", r.walking.bed_joint);
    w.set("residual_vertical_opening_m", r.walking.vertical_opening);
    w.set("residual_vertical_joint", r.walking.vertical_joint);
    w.set("max_bed_opening_m", r.walking.max_bed_opening);
    w.set("max_vertical_opening_m", r.walking.max_vertical_opening);
    Json courses = Json::array();
    for (const CourseWalking& c : r.walking.courses) {
      Json j = Json::object();
      j.set("level_m", c.level);
      j.set("bed_joints", c.bed_joints);
      j.set("vertical_joints", c.vertical_joints);
      j.set("residual_bed_mean_m", c.bed_mean);
      j.set("residual_bed_largest_m", c.bed_largest);
      j.set("residual_vertical_mean_m", c.vertical_mean);
      j.set("residual_vertical_largest_m", c.vertical_largest);
      j.set("max_bed_m", c.peak_bed);
      j.set("max_vertical_m", c.peak_vertical);
      courses.push_back(std::move(j));
    }
    w.set("courses", std::move(courses));
    s.set("walking", std::move(w));
  }
  s.set("checks_passed", r.all_checks_passed());
  s.set("end_time_s", r.end_time);
  s.set("steps", r.steps);
  s.set("time_step_s", r.time_step);
  s.set("initial_time_step_s", r.initial_time_step);
  s.set("time_step_reductions", r.time_step_reductions);
  s.set("critical_time_step_s", r.critical.critical);
  s.set("highest_frequency_rad_s", r.critical.omega_max);
  s.set("damping_ratio_at_highest_frequency", r.critical.damping_ratio);
  s.set("time_step_set_by", r.time_step_set_by);
  s.set("time_step_bound", spec.simulation.time_step_bound == StepBound::joint ? "joint" : "block");
  s.set("time_step_block", r.time_step_block);
  s.set("damping_scheme", spec.simulation.damping_scheme == DampingScheme::split ? "split" : "explicit");
  s.set("joint_model", spec.simulation.joint_model == JointModel::overlap ? "overlap" : "subcontacts");
  s.set("damping_split_fraction", r.damping_split_fraction);
  s.set("contact_margin_m", r.margin);
  s.set("detection_travel_m", r.detection_travel);
  s.set("detection_trigger", pair_by_pair(spec.simulation) ? "pair" : "scene");
  const JointSampling sampling = joint_sampling_of(spec.simulation);
  s.set("joint_sampling", sampling == JointSampling::step   ? "step"
                          : sampling == JointSampling::clip ? "clip"
                                                            : "detection");
  s.set("blocks", r.blocks);
  s.set("free_blocks", r.free_blocks);
  const std::vector<GroupTotals> groups = group_totals(spec.blocks, r.assessment.dislodged_blocks);
  if (!groups.empty()) {
    Json gs = Json::array();
    for (const GroupTotals& g : groups) {
      Json j = Json::object();
      j.set("name", g.name);
      j.set("blocks", g.blocks);
      j.set("mass_kg", g.mass);
      // The group's own collapse measure: its blocks the assessment found
      // dislodged (ending beyond assessment.collapse_displacement from their
      // place), and their fraction of the group's mass.
      j.set("dislodged_blocks", g.dislodged);
      j.set("dislodged_mass_fraction", g.mass > 0 ? g.dislodged_mass / g.mass : 0.0);
      gs.push_back(std::move(j));
    }
    s.set("groups", std::move(gs));
  }
  s.set("contact_detections", r.detections);
  if (pair_by_pair(spec.simulation)) s.set("pairs_resampled", r.pairs_resampled);
  if (sampling == JointSampling::clip) s.set("pairs_clipped", r.pairs_clipped);
  s.set("subcontact_updates", r.subcontact_updates);
  if (r.checkpoints > 0) {
    Json c = Json::object();
    c.set("written", r.checkpoints);
    c.set("state_bytes", r.checkpoint_bytes);
    c.set("wall_seconds", r.checkpoint_wall_seconds);
    s.set("checkpoints", std::move(c));
  }
  s.set("threads", threads);
  s.set("wall_seconds", r.wall_seconds);
  s.set("subcontact_updates_per_second", r.wall_seconds > 0 ? r.subcontact_updates / r.wall_seconds : 0.0);
  s.set("profile", profile_json(r.profile));
  Json e = Json::object();
  e.set("kinetic_J", r.energy.kinetic);
  e.set("gravitational_J", r.energy.gravitational);
  e.set("strain_J", r.energy.strain);
  e.set("slip_dissipation_J", r.energy.slip);
  e.set("damping_dissipation_J", r.energy.damping);
  e.set("load_work_J", r.energy.load_work);
  e.set("numerical_J", r.numerical_energy());
  e.set("numerical_of_dissipation", r.numerical_fraction_of_dissipation());
  e.set("numerical_at_detections_J", r.numerical_at_detections);
  e.set("balance_J", r.energy.balance);
  e.set("put_in_J", r.energy_reference);
  s.set("energy", std::move(e));
  s.set("energy_balance_error", r.energy_balance_error);
  Json checks = Json::array();
  for (const CheckResult& c : r.checks) {
    Json j = Json::object();
    j.set("name", c.name);
    j.set("measured", c.measured);
    j.set("expected", c.expected);
    j.set("tolerance", c.tolerance);
    j.set("unit", c.unit);
    j.set("passed", c.passed);
    j.set("note", c.note);
    checks.push_back(std::move(j));
  }
  s.set("checks", std::move(checks));
  return s;
}

void write_summary(const std::string& dir, const SceneSpec& spec, const RunReport& report, int threads) {
  std::filesystem::create_directories(dir);
  write_file_atomic(dir + "/summary.json", summary_json(spec, report, threads).dump(2) + "\n");
}

PointResult point_result_from_summary(const std::string& text, const std::string& what) {
  constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  const Json s = Json::parse(text, what);
  PointResult r;
  r.status = string_or(s.find("status"), "");
  if (r.status.empty()) throw std::runtime_error(what + ": no status");
  if (s.find("instability")) {
    r.status = "unstable";
    r.message = string_or(s.find("instability"), "");
    r.exit_code = 3;  // polydem run's exit code for an unstable run
  }
  if (const Json* a = s.find("assessment")) {
    r.collapse_mode = string_or(a->find("collapse_mode"), "");
    r.peak_tip_displacement = number_or(a->find("monitor_peak_displacement_m"), 0);
    // A summary of an earlier version names the peak max_displacement_m.
    const Json* peak = a->find("peak_displacement_m");
    r.peak_displacement = number_or(peak ? peak : a->find("max_displacement_m"), 0);
    r.residual_displacement = number_or(a->find("max_residual_displacement_m"), 0);
    r.collapse_time = number_or(a->find("collapse_time_s"), -1);
    r.damage_time = number_or(a->find("damage_time_s"), -1);
    if (const Json* d = a->find("dislodged")) r.dislodged = static_cast<int>(number_or(d->find("count"), 0));
    r.ground_acceleration_at_damage_g = number_or(a->find("ground_acceleration_at_damage_g"), kNone);
  }
  if (const Json* w = s.find("walking")) {
    r.max_bed_opening = number_or(w->find("max_bed_opening_m"), kNone);
    r.max_vertical_opening = number_or(w->find("max_vertical_opening_m"), kNone);
    r.residual_bed_opening = number_or(w->find("residual_bed_opening_m"), kNone);
    r.residual_vertical_opening = number_or(w->find("residual_vertical_opening_m"), kNone);
    if (const Json* cs = w->find("courses"); cs && cs->type() == Json::Type::Array) {
      for (std::size_t k = 0; k < cs->size(); ++k) {
        const Json& j = cs->at(k);
        CourseWalking c;
        c.level = number_or(j.find("level_m"), kNone);
        c.bed_joints = static_cast<int>(number_or(j.find("bed_joints"), 0));
        c.vertical_joints = static_cast<int>(number_or(j.find("vertical_joints"), 0));
        c.bed_mean = number_or(j.find("residual_bed_mean_m"), kNone);
        c.bed_largest = number_or(j.find("residual_bed_largest_m"), kNone);
        c.vertical_mean = number_or(j.find("residual_vertical_mean_m"), kNone);
        c.vertical_largest = number_or(j.find("residual_vertical_largest_m"), kNone);
        c.peak_bed = number_or(j.find("max_bed_m"), kNone);
        c.peak_vertical = number_or(j.find("max_vertical_m"), kNone);
        r.courses.push_back(c);
      }
    }
  }
  r.wall_seconds = number_or(s.find("wall_seconds"), 0);
  r.steps = static_cast<long>(number_or(s.find("steps"), 0));
  return r;
}

PointResult read_point_result(const std::string& dir) {
  const std::string path = dir + "/summary.json";
  if (!std::filesystem::exists(path)) return {};
  try {
    return point_result_from_summary(read_file_text(path), path);
  } catch (const std::exception&) {
    return {};  // damaged: run the point again
  }
}

void write_results_h5(const std::string& path, const SceneSpec& spec, const RunReport& report) {
  ResultsFile h5(path);
  h5.write_string("/deck", spec.deck_text);
  h5.write_attribute("/deck", "path", spec.deck_path);
  h5.write_attribute("/deck", "polydem_version", POLYDEM_VERSION);
  if (report.histories.columns.size() > 1) write_table(h5, "/histories", report.histories);
  if (!report.energies.columns.empty()) write_table(h5, "/energies", report.energies);
  // The blocks' names and groups (the VTK snapshots' `group` cell field is
  // the index into /blocks/group_names, -1 for a block without a group).
  std::vector<std::string> names, groups, group_names;
  for (const BlockSpec& b : spec.blocks) {
    names.push_back(b.name);
    groups.push_back(b.group);
    if (!b.group.empty() && std::find(group_names.begin(), group_names.end(), b.group) == group_names.end())
      group_names.push_back(b.group);
  }
  if (!names.empty()) {
    h5.write_strings("/blocks/name", names);
    h5.write_strings("/blocks/group", groups);
    if (!group_names.empty()) h5.write_strings("/blocks/group_names", group_names);
  }
  h5.commit();
}

}  // namespace polydem
