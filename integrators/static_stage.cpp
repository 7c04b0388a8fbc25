#include "integrators/static_stage.hpp"

#include "integrators/critical_time_step.hpp"

#include <algorithm>
#include <cmath>

namespace polydem {

StaticStage start_static_stage(const Blocks& blocks, const ContactSet& contacts, const JointLaws& laws,
                               const JointLaw& step_law, const SimulationSpec& sim, double dt, double local_damping,
                               const Vec3& load, bool density_scaling) {
  StaticStage s;
  s.active = true;
  s.local_damping = local_damping;
  s.load = load;
  s.scaled_inv_mass = blocks.props.inv_mass;
  s.scaled_inv_inertia = blocks.props.inv_principal_inertia;
  // Local damping can raise a force to (1 + α) times itself (the header):
  // every block (1 + α) times heavier keeps the step's margin.
  const double amplification = 1.0 + std::max(0.0, local_damping);
  double top = 0;
  std::vector<double> w;
  if (density_scaling) {
    // Each block's highest frequency, on all its faces or on the joints it
    // has now, whichever is higher; the step was chosen for the highest of all.
    w = block_frequencies(blocks, step_law);
    const std::vector<double> wc = block_frequencies_from_contacts(blocks, contacts, laws);
    for (int i : blocks.free_blocks) {
      w[i] = std::max(w[i], wc[i]);
      top = std::max(top, w[i]);
    }
    // Under the joint bound the step may allow less than √2·top (each joint
    // counted once beside a fixed block or a stiffer stone), but blocks
    // scaled to one frequency count every joint twice: scale them to ω/√2 of
    // the highest ω the step allows (blocks above it become heavier).
    if (sim.time_step_bound == StepBound::joint)
      top = std::min(top, highest_frequency_for_step(dt, step_law.beta, sim.safety_factor, sim.damping_scheme) /
                              std::sqrt(2.0));
  }
  for (int i : blocks.free_blocks) {
    double f = 1.0 / amplification;  // the inverse mass factor
    if (top > 0 && w[i] > 0) f *= (top / w[i]) * (top / w[i]);
    s.scaled_inv_mass[i] *= f;
    s.scaled_inv_inertia[i] *= f;
  }
  return s;
}

}  // namespace polydem
