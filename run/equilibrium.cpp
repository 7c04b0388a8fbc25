#include "run/equilibrium.hpp"

#include "core/loads.hpp"
#include "run/scene_error.hpp"

#include <algorithm>
#include <chrono>
#include <sstream>

namespace polydem {

Unbalance largest_unbalance(const Simulation& sim, const Vec3& gravity) {
  const Blocks& b = sim.blocks();
  Unbalance u;
  if (b.free_blocks.empty() || !(gravity.norm() > 0)) return u;
  double applied = 0;
  for (int i : b.free_blocks) {
    // The static stage's loads: gravity alone (no ground motion).
    const Vec3 f = external_force(b.props, i, gravity, Vec3::Zero()) + b.state.contact_force[i];
    const double r = b.props.radius[i] > 0 ? b.props.radius[i] : 1.0;
    const double force = f.norm(), moment = b.state.contact_torque[i].norm() / r;
    if (std::max(force, moment) > u.value || u.block < 0) {
      u.block = i;
      u.value = std::max(force, moment);
      u.moment = moment > force;
    }
    applied += b.props.mass[i] * gravity.norm();
  }
  u.ratio = u.value / (applied / static_cast<double>(b.free_blocks.size()));
  return u;
}

double unbalanced_force_ratio(const Simulation& sim, const Vec3& gravity) {
  return largest_unbalance(sim, gravity).ratio;
}

EquilibriumReport solve_equilibrium(const EquilibriumSpec& spec, const Vec3& gravity, Simulation& sim) {
  const auto t0 = std::chrono::steady_clock::now();
  EquilibriumReport rep;
  rep.ran = true;
  const Blocks& b = sim.blocks();
  const std::vector<Vec3> start = b.state.position;
  int worst_block = -1;
  sim.begin_static_stage(spec.local_damping, gravity, spec.density_scaling);
  rep.ratio = unbalanced_force_ratio(sim, gravity);
  // Two steps in a row at the tolerance (header): a single one can be the
  // moment a swing's force passes through zero at its fastest.
  int steps_below = rep.ratio <= spec.ratio ? 1 : 0;
  while (steps_below < 2 && !(rep.steps == 0 && steps_below == 1)) {
    if (rep.steps >= spec.max_steps) {
      std::ostringstream m;
      m << "the static stage did not reach equilibrium in " << spec.max_steps
        << " steps (unbalanced-force ratio " << rep.ratio << ", tolerance equilibrium.ratio = " << spec.ratio
        << "); raise equilibrium.max_steps, or the scene has no equilibrium (a block sliding or toppling)";
      throw SceneError("equilibrium.max_steps", "", spec.deck_line, m.str());
    }
    sim.step();
    ++rep.steps;
    for (int i : b.free_blocks) {
      const double d = (b.state.position[i] - start[i]).norm();
      if (d > rep.max_displacement) {
        rep.max_displacement = d;
        worst_block = i;
      }
    }
    rep.ratio = unbalanced_force_ratio(sim, gravity);
    steps_below = rep.ratio <= spec.ratio ? steps_below + 1 : 0;
  }
  sim.end_static_stage();
  if (worst_block >= 0) rep.max_displacement_block = b.props.name[worst_block];
  rep.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return rep;
}

}  // namespace polydem
