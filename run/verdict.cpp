#include "run/verdict.hpp"

#include "core/units.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace polydem {

namespace {

// A length in the unit an engineer reads it in: µm, mm or m, 3 digits.
std::string length(double m) {
  const double a = std::abs(m);
  if (a > 0 && a < 1e-3) return fmt::format("{:.3g} µm", 1e6 * m);
  if (a < 1) return fmt::format("{:.3g} mm", 1e3 * m);
  return fmt::format("{:.3g} m", m);
}

std::string energy(double joules) {
  const double a = std::abs(joules);
  if (a < 1e3) return fmt::format("{:.3g} J", joules);
  if (a < 1e6) return fmt::format("{:.3g} kJ", 1e-3 * joules);
  return fmt::format("{:.3g} MJ", 1e-6 * joules);
}

// "at 0.218 g (t = 2.18 s)" under a ground motion, "at t = 2.18 s" without.
std::string moment(const SceneSpec& spec, double time, double ground_acceleration) {
  if (spec.ground_motion.kind == GroundMotionKind::none && spec.ground_motion.components.empty())
    return fmt::format("at t = {:.3g} s", time);
  return fmt::format("at {:.3g} g (t = {:.3g} s)", ground_acceleration / kGravity, time);
}

// ", 15 joints cracked at z = 0.00-0.77 m" (the crack the assessment found:
// joints of the initial mesh that opened or slid, run/crack.hpp).
std::string crack(const Assessment& a) {
  if (a.opened_joints == 0) return "";
  if (a.crack_angle_deg < 0) return fmt::format(", {} joint cracked", a.opened_joints);
  // Heights within half a centimetre of zero print as 0.00, not -0.00.
  const auto cm = [](double z) { return std::abs(z) < 0.005 ? 0.0 : z; };
  return fmt::format(", {} joints cracked at z = {:.2f}-{:.2f} m", a.opened_joints, cm(a.crack_low_z),
                     cm(a.crack_high_z));
}

// "peak displacement 534 mm (tip), 5.0 mm at the end"
std::string displacements(const Assessment& a) {
  return fmt::format("peak displacement {} ({}), {} at the end", length(a.peak_displacement),
                     a.peak_displacement_block.empty() ? "no free block" : a.peak_displacement_block,
                     length(a.max_residual_displacement));
}

// ": the tip past its point of no return" when that decided the collapse.
std::string reason(const Assessment& a) {
  if (a.collapse_reason != "point of no return") return "";
  return fmt::format("; {} past its point of no return", a.monitor_block);
}

std::string status_line(const SceneSpec& spec, const RunReport& r) {
  const Assessment& a = r.assessment;
  const std::string when = a.damage_time >= 0 ? moment(spec, a.damage_time, a.ground_acceleration_at_damage) : "";
  const std::string first_moved =
      when.empty() ? "" : fmt::format("the first block moved {} {}", length(spec.assessment.damage_displacement), when);
  if (a.status == "collapsed")
    return fmt::format("collapsed (Mode {}) at t = {:.3g} s: the mechanism formed {}{}{}", a.collapse_mode,
                       a.collapse_time, when.empty() ? "at the start" : when, crack(a), reason(a));
  if (a.status == "undetermined")
    return fmt::format("undetermined (run longer): {} still moves at {:.3g} m/s at t = {:.3g} s (over {:.3g} m/s); {}",
                       a.fastest_block, a.fastest_speed, r.end_time, a.moving_speed_limit, displacements(a));
  if (a.status == "damaged")
    return fmt::format("damaged: {}{}{}{}", first_moved, first_moved.empty() ? "" : "; ", displacements(a), crack(a));
  return fmt::format("intact: {}{}{}", displacements(a), first_moved.empty() ? "" : "; ", first_moved);
}

// The groups the lost blocks belong to, in the deck's order, each with how
// many of its blocks were lost: "course18 (16 of 16), tip"; at most four named.
std::string fallen_groups(const SceneSpec& spec, const std::vector<std::string>& fallen) {
  struct Count {
    std::string name;
    int blocks = 0, fell = 0;
  };
  std::unordered_map<std::string, bool> is_fallen;
  for (const std::string& n : fallen) is_fallen[n] = true;
  std::vector<Count> groups;
  for (const BlockSpec& b : spec.blocks) {
    if (b.group.empty()) continue;
    auto it = std::find_if(groups.begin(), groups.end(), [&](const Count& c) { return c.name == b.group; });
    if (it == groups.end()) it = groups.insert(groups.end(), Count{b.group});
    ++it->blocks;
    if (is_fallen.count(b.name)) ++it->fell;
  }
  std::string out;
  int named = 0, more = 0;
  for (const Count& c : groups) {
    if (c.fell == 0) continue;
    if (named == 4) {
      ++more;
      continue;
    }
    out += (named++ ? ", " : ": ") + c.name;
    if (c.blocks > 1) out += fmt::format(" ({} of {})", c.fell, c.blocks);
  }
  if (more > 0) out += fmt::format(" and {} more group{}", more, more > 1 ? "s" : "");
  return out;
}

std::string lost_line(const SceneSpec& spec, const RunReport& r) {
  const Assessment& a = r.assessment;
  if (a.dislodged_blocks.empty())
    return fmt::format("lost: nothing (no block ends more than {} from its place)",
                       length(spec.assessment.collapse_displacement));
  const std::string from = a.dislodged_high_z - a.dislodged_low_z < 0.005
                               ? fmt::format("z = {:.2f} m", a.dislodged_low_z)
                               : fmt::format("z = {:.2f}-{:.2f} m", a.dislodged_low_z, a.dislodged_high_z);
  return fmt::format("lost: {} of {} block{} ({} fell), {:.3g} % of the free mass, from {}{}",
                     a.dislodged_blocks.size(), r.free_blocks, r.free_blocks == 1 ? "" : "s", a.fallen_blocks.size(),
                     100 * a.dislodged_mass_fraction, from, fallen_groups(spec, a.dislodged_blocks));
}

std::string energy_line(const RunReport& r) {
  const double slip = r.energy.slip - r.energy_start.slip, damping = r.energy.damping - r.energy_start.damping;
  const double put_in = r.energy_reference;
  return fmt::format("energy: {} put in, {} dissipated (slip {}, damping {}); numerical {} ({:.2g} % of the energy "
                     "put in)",
                     energy(put_in), energy(slip + damping), energy(slip), energy(damping), energy(r.numerical_energy()),
                     put_in > 0 ? 100 * r.numerical_energy() / put_in : 0.0);
}

}  // namespace

std::vector<std::string> verdict_lines(const SceneSpec& spec, const RunReport& report) {
  if (report.unstable) return {};
  return {status_line(spec, report), lost_line(spec, report), energy_line(report)};
}

}  // namespace polydem
