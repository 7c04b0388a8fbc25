// Through the collapse (issue 15): falling stones hitting others are not an
// instability. Shared by collapse_test.cpp (stones dropped from 5 m, default
// suite) and collapse_slow_test.cpp (a 50-block tower toppling to rest,
// `slow` label). Each scene is a deck generated as text (extreme_cases.hpp's
// helpers) and stepped here directly, so that every step's deepest joint
// overlap and the energy ledger every 64 steps are seen, not only the
// samples a run records:
//   - the run reaches its end time (no guard stop);
//   - the ledger's balance (kinetic + gravitational + strain + slip +
//     damping − load work) stays within the case's tolerance of its start,
//     relative to the largest energy in play;
//   - the deepest overlap of any joint over the whole run stays below a
//     fraction of the smaller block's size;
//   - the case's own check on the final state (at rest, on top).
#pragma once

#include "extreme_cases.hpp"
#include "run/setup.hpp"

#include <chrono>
#include <memory>

namespace polydem::collapse {

using extreme::box;
using extreme::Header;
using extreme::header;
using extreme::kG;

struct Outcome {
  bool stopped = false;
  std::string message;
  double time = 0;
  long steps = 0;
  double wall = 0;
  double balance_error = 0;    // max |balance − balance(0)| / reference
  double reference = 0;        // J, largest energy in play
  double deepest = 0;          // m, deepest overlap of any joint at any step
  double deepest_fraction = 0;  // of the smaller block's size
  int detections = 0;
  // J: the normal strain detections added by re-sampling the joints (the
  // sum of the steps in which the ledger's resampled_normal fell); held at
  // zero since the hold (contact/joint_law.hpp), but for round-off.
  double resampled_added = 0;
  std::unique_ptr<Simulation> sim;
};

inline Outcome run(const std::string& deck, const std::string& name) {
  const SceneSpec spec = parse_deck(deck, name + ".toml");
  RunSetup setup;
  Outcome o;
  o.sim = build_simulation(spec, setup);
  Simulation& s = *o.sim;
  const auto& size = s.blocks().props.size;
  const double balance0 = s.energies().balance;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    while (s.time() < spec.simulation.end_time) {
      const double resampled_before = s.contacts().resampled_normal_energy;
      s.step();
      o.resampled_added += std::max(0.0, resampled_before - s.contacts().resampled_normal_energy);
      const auto& sub = s.contacts().sub;
      for (std::size_t k = 0; k < sub.size(); ++k) {
        const double overlap = sub.geometric_overlap(k);  // the blocks', crush included
        if (overlap <= o.deepest) continue;
        o.deepest = overlap;
        o.deepest_fraction = overlap / std::min(size[sub.ref_block[k]], size[sub.inc_block[k]]);
      }
      if (s.steps() % 64 == 0) {
        const EnergyLedger e = s.energies();
        o.reference = std::max(o.reference, energy_in_play(e));
        if (o.reference > 0)
          o.balance_error = std::max(o.balance_error, std::abs(e.balance - balance0) / o.reference);
      }
    }
  } catch (const InstabilityError& e) {
    o.stopped = true;
    o.message = e.what();
  }
  o.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  o.time = s.time();
  o.steps = s.steps();
  o.detections = s.contacts().detections;
  return o;
}

inline void print(const std::string& name, const Outcome& o) {
  char buf[512];
  std::snprintf(buf, sizeof buf, "| %s | %.3g | %ld | %d | %.2f | %.3g | %.3g mm (%.2g %%) | %.3g J | %s |",
                name.c_str(), o.time, o.steps, o.detections, o.wall, o.balance_error, 1e3 * o.deepest,
                100 * o.deepest_fraction, o.resampled_added, o.stopped ? o.message.c_str() : "end time");
  std::cout << "COLLAPSE_ROW " << buf << std::endl;
}

// The block's lowest corner, z.
inline double lowest_z(const Blocks& b, int i) {
  double z = 1e300;
  for (std::size_t v = 0; v < b.props.local_shape[i].vertices.size(); ++v)
    z = std::min(z, world_vertex(b, i, static_cast<int>(v)).z());
  return z;
}

// --- a stone dropped from 5 m ------------------------------------------------
//
// A 0.5 m cube (325 kg) released at rest with its lowest edge or corner 5 m
// above its target: the fixed base (top z = 0) or a 4 x 4 x 0.5 m stone
// resting on the base (a wide slab: tumbling off it is not the point). It
// hits at 9.9 m/s on an edge (turned 40 deg about x) or a corner (40 deg about x, then 30 deg about y), off balance so that it
// cannot stand on the edge or corner it lands on; it bounces, tumbles and
// must come to rest on a face on top of its target. Joint as the extreme
// cases (98 GPa/m, phi = 30 deg) with damping beta = 2e-4 s, so that the
// bounces die out within the run (xi ~ 0.4 on the corner mode). The contact
// margin is 1 mm (0.2 % of the stone's size, as 3 mm is of the spire's
// stones), below what the impact sinks the joint: the guard must not take
// the impact for an instability.
enum class Target { base, stone };
enum class Landing { edge, corner };

inline std::string drop_deck(Target target, Landing landing, double end_time) {
  Header h;
  h.end_time = end_time;
  h.damping = 2e-4;
  std::string deck = header(h);
  deck.insert(deck.find("[joint]"), "contact_margin = 1e-3\n");
  deck += extreme::base(8);
  double top = 0;
  if (target == Target::stone) {
    deck += box("target", {4, 4, 0.5}, {0, 0, 0.25});
    top = 0.5;
  }
  const double rx = 40, ry = landing == Landing::edge ? 0.0 : 30.0;
  // The deck's rotation is R = Ry·Rx about the centroid: the lowest corner.
  const double k = std::acos(-1.0) / 180;
  const Mat3 R = (Eigen::AngleAxisd(ry * k, Vec3::UnitY()) * Eigen::AngleAxisd(rx * k, Vec3::UnitX())).toRotationMatrix();
  double half = 0;
  for (int c = 0; c < 8; ++c) {
    const Vec3 v(c & 1 ? 0.25 : -0.25, c & 2 ? 0.25 : -0.25, c & 4 ? 0.25 : -0.25);
    half = std::max(half, -(R * v).z());
  }
  std::ostringstream rot;
  rot << "rotation = [" << rx << ", " << ry << ", 0]\n";
  deck += box("stone", {0.5, 0.5, 0.5}, {0.05, 0.03, top + 5 + half}, 2600, rot.str());
  return deck;
}

}  // namespace polydem::collapse
