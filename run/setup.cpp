#include "run/setup.hpp"

#include "contact/detection.hpp"
#include "run/scene_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace polydem {

double automatic_margin(const Blocks& b) { return 0.02 * smallest_block_size(b); }

RunSetup choose_margin_and_step(const SceneSpec& spec, const Blocks& blocks, const JointLaws& laws) {
  RunSetup s;
  s.margin = spec.simulation.contact_margin > 0 ? spec.simulation.contact_margin : automatic_margin(blocks);
  // Time step: automatic, or the deck's if it is smaller.
  // The stiffest law that can act ([[joint]] `between`); one law: [joint].
  s.critical = critical_time_step(blocks, stiffest_law(laws), spec.simulation.safety_factor,
                                  spec.simulation.damping_scheme);
  double dt = s.critical.chosen;
  if (spec.simulation.time_step > 0) {
    if (s.critical.chosen > 0 && spec.simulation.time_step > s.critical.chosen) {
      std::ostringstream m;
      m << spec.simulation.time_step << " s exceeds the stable step " << s.critical.chosen << " s (critical "
        << s.critical.critical << " s times safety factor " << spec.simulation.safety_factor
        << "); a deck may only lower it";
      throw SceneError("simulation.time_step", "", 0, m.str());
    }
    dt = spec.simulation.time_step;
  }
  if (dt <= 0) dt = spec.simulation.end_time / 1000.0;  // nothing moves: any step will do
  s.time_step = dt;
  return s;
}

void check_initial_overlaps(const SceneSpec& spec, const Simulation& sim) {
  const ContactSet& cs = sim.contacts();
  for (std::size_t s = 0; s < cs.sub.size(); ++s) {
    if (cs.sub.geometric_overlap(s) <= spec.simulation.overlap_tolerance) continue;
    const int r = cs.sub.ref_block[s], c = cs.sub.inc_block[s];
    const auto& pr = sim.blocks().props;
    const int line = std::max(pr.deck_line[r], pr.deck_line[c]);
    const std::string& late = pr.deck_line[r] >= pr.deck_line[c] ? pr.name[r] : pr.name[c];
    const std::string& other = late == pr.name[r] ? pr.name[c] : pr.name[r];
    std::ostringstream m;
    m << "overlaps block '" << other << "' by " << cs.sub.geometric_overlap(s)
      << " m at the start (tolerance simulation.overlap_tolerance = " << spec.simulation.overlap_tolerance << " m)";
    throw SceneError("block", "('" + late + "')", line, m.str());
  }
}

std::unique_ptr<Simulation> build_simulation(const SceneSpec& spec, RunSetup& setup, ExtraGroundAcceleration extra) {
  // [[prescribe]] makes its blocks kinematic before they are built.
  std::vector<BlockSpec> specs;
  if (!spec.prescribed.empty()) {
    specs = spec.blocks;
    apply_prescriptions(specs, spec.prescribed);
  }
  const std::vector<BlockSpec>& block_specs = spec.prescribed.empty() ? spec.blocks : specs;
  Blocks blocks = build_blocks(block_specs);
  BlockLoads loads = resolve_loads(blocks, block_specs, spec.loads, spec.prescribed);
  JointLaws laws = make_joint_laws(blocks, spec.joint, spec.joint_pairs);
  setup = choose_margin_and_step(spec, blocks, laws);
  GroundMotion motion = spec.ground_motion.kind == GroundMotionKind::record
                            ? make_ground_motion(spec.ground_motion, spec.ground_motion.record_time,
                                                 spec.ground_motion.record_acceleration)
                            : make_ground_motion(spec.ground_motion);
  motion.extra = std::move(extra);
  auto sim = std::make_unique<Simulation>(std::move(blocks), spec.simulation, std::move(laws), std::move(motion),
                                          setup.margin, setup.time_step, true, std::move(loads));
  check_initial_overlaps(spec, *sim);
  return sim;
}

}  // namespace polydem
