#include "core/loads.hpp"

#include <algorithm>

namespace polydem {

Vec3 ground_body_acceleration(const GroundMotion& motion, double t) {
  const bool body_force = motion.any_active() && motion.applied_as == GroundMotionApplication::body_force;
  const Vec3 a = body_force ? motion.acceleration_vector(t) : Vec3(Vec3::Zero());
  if (!motion.extra) return a;
  return a + motion.extra(t);
}

Vec3 table_value(const TimeTable& table, double t) {
  const auto& T = table.time;
  const auto& V = table.value;
  if (T.empty()) return Vec3(1.0, 0.0, 0.0);
  if (!(t > T.front())) return V.front();
  if (!(t < T.back())) return V.back();
  const std::size_t k = static_cast<std::size_t>(std::upper_bound(T.begin(), T.end(), t) - T.begin());  // T[k-1] <= t < T[k]
  const double w = (t - T[k - 1]) / (T[k] - T[k - 1]);
  return V[k - 1] + w * (V[k] - V[k - 1]);
}

std::vector<int> select_blocks(const std::vector<BlockSpec>& blocks, const std::vector<std::string>& names,
                               const std::vector<std::string>& groups) {
  std::vector<int> out;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const BlockSpec& b = blocks[i];
    const bool named = std::find(names.begin(), names.end(), b.name) != names.end();
    const bool grouped = !b.group.empty() && std::find(groups.begin(), groups.end(), b.group) != groups.end();
    if (named || grouped) out.push_back(static_cast<int>(i));
  }
  return out;
}

void apply_prescriptions(std::vector<BlockSpec>& blocks, const std::vector<PrescribeSpec>& prescribed) {
  for (const PrescribeSpec& p : prescribed) {
    for (int i : select_blocks(blocks, p.blocks, p.groups)) {
      BlockSpec& b = blocks[static_cast<std::size_t>(i)];
      b.motion = BlockMotion::kinematic;
      b.velocity = !p.displacement_table.empty() ? Vec3(Vec3::Zero())
                   : p.velocity_table.empty()     ? p.velocity
                                                  : table_value(p.velocity_table, 0.0);
      b.angular_velocity = p.angular_velocity;
    }
  }
}

BlockLoads resolve_loads(const Blocks& blocks, const std::vector<BlockSpec>& specs,
                         const std::vector<LoadSpec>& loads, const std::vector<PrescribeSpec>& prescribed) {
  BlockLoads out;
  for (const LoadSpec& l : loads) {
    for (int i : select_blocks(specs, l.blocks, l.groups)) {
      PointLoad p;
      p.block = i;
      p.force = l.force;
      p.moment = l.moment;
      p.at_point = l.at_point;
      if (l.at_point) p.arm_local = blocks.state.rotation[i].transpose() * (l.point - blocks.state.position[i]);
      p.factor = l.factor;
      out.loads.push_back(std::move(p));
    }
  }
  std::vector<int> which(specs.size(), -1);  // the last prescription of each block
  for (std::size_t k = 0; k < prescribed.size(); ++k)
    for (int i : select_blocks(specs, prescribed[k].blocks, prescribed[k].groups)) which[static_cast<std::size_t>(i)] = static_cast<int>(k);
  for (std::size_t i = 0; i < specs.size(); ++i) {
    if (which[i] < 0) continue;
    const PrescribeSpec& p = prescribed[static_cast<std::size_t>(which[i])];
    Prescription r;
    r.block = static_cast<int>(i);
    r.velocity = p.velocity;
    r.angular_velocity = p.angular_velocity;
    r.velocity_table = p.velocity_table;
    r.displacement_table = p.displacement_table;
    r.start = blocks.state.position[i];
    out.prescribed.push_back(std::move(r));
  }
  return out;
}

}  // namespace polydem
