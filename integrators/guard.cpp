#include "integrators/guard.hpp"

#include "geometry/cut.hpp"

#include <algorithm>
#include <sstream>
#include <string>

namespace polydem {

void Guard::restart(const BlockState& state) {
  energy_reference = mechanical0 = 0;
  energy_started = false;
  last_good = state;
  last_good_time = 0;
  last_good_step = 0;
}

void save_block_state(ByteWriter& w, const BlockState& s) {
  w.put(s.position);
  w.put(s.orientation);
  w.put(s.rotation);
  w.put(s.velocity);
  w.put(s.angular_momentum);
  w.put(s.angular_velocity);
  w.put(s.contact_force);
  w.put(s.contact_torque);
}

void load_block_state(ByteReader& r, BlockState& s, std::size_t n) {
  r.get_sized(s.position, n, "block state position");
  r.get_sized(s.orientation, n, "block state orientation");
  r.get_sized(s.rotation, n, "block state rotation");
  r.get_sized(s.velocity, n, "block state velocity");
  r.get_sized(s.angular_momentum, n, "block state angular_momentum");
  r.get_sized(s.angular_velocity, n, "block state angular_velocity");
  r.get_sized(s.contact_force, n, "block state contact_force");
  r.get_sized(s.contact_torque, n, "block state contact_torque");
}

void Guard::save(ByteWriter& w) const {
  w.put(energy_reference);
  w.put(mechanical0);
  w.put(energy_started);
  save_block_state(w, last_good);
  w.put(last_good_time);
  w.put(last_good_step);
}

void Guard::load(ByteReader& r, std::size_t n) {
  r.get(energy_reference);
  r.get(mechanical0);
  r.get(energy_started);
  load_block_state(r, last_good, n);
  r.get(last_good_time);
  r.get(last_good_step);
}

void check_health(Guard& g, const Blocks& blocks, const ContactSet& contacts, double margin, const EnergyLedger& e,
                  const Vec3& gravity, long step, double time, double dt) {
  const auto& st = blocks.state;
  auto stop = [&](const std::string& cause) {
    std::ostringstream msg;
    msg << "numerical instability at step " << step << " (t = " << time << " s, time step " << dt
        << " s): " << cause << "; the last good state is from step " << g.last_good_step << " (t = "
        << g.last_good_time << " s)";
    throw InstabilityError(msg.str());
  };
  for (int i : blocks.free_blocks) {
    if (st.position[i].allFinite() && st.velocity[i].allFinite() && st.angular_momentum[i].allFinite()) continue;
    stop("block '" + blocks.props.name[i] + "' has a non-finite position or velocity");
  }
  // Penetration: a joint overlapping by a fair fraction of the smaller
  // block's size is no longer a contact but blocks passing through each
  // other. A hard impact sinks a joint by about v·sqrt(m/(kn·A)), a few mm for
  // a stone falling metres onto a corner: more than the margin, which is
  // therefore not the limit (only its floor).
  // What is judged is the blocks' true overlap, the penetration depth: the
  // least distance one block must move to leave the other (the separating
  // axes of both blocks' faces and edges, geometry/cut.hpp). The joint's
  // own measure screens the pairs first, since it is at least as deep where
  // the blocks truly overlap: the largest overlap over the region along the
  // joint's plane (overlap model) or a subcontact's depth below it. Neither
  // is the overlap once the plane no longer faces the contact: two stones
  // side by side on a plane kept from a bed joint they have tipped off show
  // the height of the face they share as a sliver of "overlap" along the
  // old plane, and are only touching.
  const auto& sub = contacts.sub;
  const auto& size = blocks.props.size;
  auto judge = [&](int ref, int inc, double overlap) {
    const double smaller = std::min(size[ref], size[inc]);
    const double limit = std::max(margin, g.penetration_limit * smaller);
    if (overlap <= limit) return;
    const double depth = penetration_depth(world_shape(blocks, ref), world_shape(blocks, inc));
    if (depth <= limit) return;
    std::ostringstream what;
    what << "blocks '" << blocks.props.name[ref] << "' and '" << blocks.props.name[inc] << "' overlap by "
         << depth << " m, beyond the penetration limit " << limit << " m (" << 100 * g.penetration_limit
         << " % of the smaller block's size, at least the contact margin)";
    stop(what.str());
  };
  if (contacts.pair_joints_in_use()) {
    for (std::size_t q = 0; q < contacts.pairs.size(); ++q) {
      const ContactPair& cp = contacts.pairs[q];
      const int r = contacts.joints.ref_block[q];
      judge(r, r == cp.a ? cp.b : cp.a, contacts.joints.overlap[q]);
    }
  } else {
    // Each pair once, by its deepest subcontact: the depth is the pair's.
    for (const ContactPair& cp : contacts.pairs) {
      if (cp.count == 0) continue;
      const auto first = static_cast<std::size_t>(cp.first), end = first + static_cast<std::size_t>(cp.count);
      std::size_t deepest = first;
      for (std::size_t s = first + 1; s < end; ++s)
        if (sub.geometric_overlap(s) > sub.geometric_overlap(deepest)) deepest = s;
      judge(sub.ref_block[deepest], sub.inc_block[deepest], sub.geometric_overlap(deepest));
    }
  }
  const double mechanical = e.kinetic + e.gravitational + e.strain - e.load_work;
  if (!g.energy_started) {
    g.mechanical0 = mechanical;
    g.energy_started = true;
  }
  g.energy_reference = std::max(g.energy_reference, energy_in_play(e));
  // A floor so that a scene at rest (all energies ~0) is not judged on noise.
  double floor = 0;
  for (int i : blocks.free_blocks) floor += blocks.props.mass[i] * gravity.norm() * 1e-6;
  const double growth = mechanical - g.mechanical0;
  if (growth > g.energy_growth_limit * std::max(g.energy_reference, floor) && growth > floor) {
    std::ostringstream what;
    what << "the mechanical energy grew by " << growth << " J beyond the work of the loads ("
         << 100 * growth / g.energy_reference << " % of the energy in play)";
    stop(what.str());
  }
  g.last_good = st;
  g.last_good_time = time;
  g.last_good_step = step;
}

}  // namespace polydem
