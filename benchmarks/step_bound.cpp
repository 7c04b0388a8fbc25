// How much step the automatic time step leaves on the table: for each deck,
// the joints of its first detection (as a run builds them), the bounds of
// the highest frequency a run can take (critical_time_step.hpp: the
// all-faces estimate a run starts from, the block bound √2·max ω_b and the
// joint bound of simulation.time_step_bound = "joint") and the assembled
// system's exact highest frequency (integrators/joint_modes.hpp), each with
// the step it would give (the deck's β and safety factor) against the step a
// run with the default bound takes, and the blocks the top mode lives in.
// Dense eigenvalues: seconds for a few hundred blocks; decks with more than
// max_joint_mode_blocks free blocks are reported as too large.
//
//   polydem_step_bound [DECK...]     (default examples/spire/earthquake.toml)
#include "integrators/critical_time_step.hpp"
#include "integrators/joint_modes.hpp"
#include "io/deck.hpp"
#include "run/setup.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <numeric>
#include <string>
#include <vector>

using namespace polydem;

int main(int argc, char** argv) {
  std::vector<std::string> decks(argv + 1, argv + argc);
  if (decks.empty()) decks.push_back(std::string(POLYDEM_SOURCE_DIR) + "/examples/spire/earthquake.toml");
  std::printf("| deck | free blocks | subcontacts | bound | ω (rad/s) | ξ | step (s) | step / run's |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  int status = 0;
  std::vector<std::string> notes;  // the top modes, printed under the table
  for (const std::string& path : decks) {
    try {
      // Built with the default bound: its step after the first detection is
      // the one each row is compared with.
      SceneSpec spec = read_deck(path);
      spec.simulation.time_step_bound = StepBound::block;
      RunSetup setup;
      const std::unique_ptr<Simulation> sim = build_simulation(spec, setup);
      const JointLaws& laws = sim->joint_laws();
      const double beta = sim->step_law().beta;
      const double sf = spec.simulation.safety_factor;
      const auto t0 = std::chrono::steady_clock::now();
      const JointModes m = joint_modes(sim->blocks(), sim->contacts(), laws);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const std::string name = path.substr(path.find_last_of('/') + 1);
      const double run_step = sim->dt();
      const CriticalStep joint_bound =
          critical_time_step_from_contacts(sim->blocks(), sim->contacts(), laws, beta, sf, 0, 1, StepBound::joint);
      const struct {
        const char* label;
        double omega;
      } rows[] = {{"all faces (the start)", setup.critical.omega_max},
                  {"block (√2·max ω_b)", m.block_bound},
                  {"joint (time_step_bound = \"joint\")", joint_bound.omega_max},
                  {"exact", m.omega_max}};
      for (const auto& r : rows) {
        const CriticalStep c = critical_step_for(r.omega, beta, sf);
        std::printf("| %s | %zu | %zu | %s | %.4e | %.3f | %.4e | %.3f |\n", name.c_str(), sim->blocks().free_blocks.size(),
                    sim->contacts().sub.size(), r.label, r.omega, c.damping_ratio, c.chosen, c.chosen / run_step);
      }
      // The top mode's blocks, largest share first.
      std::vector<int> order(m.share.size());
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(), [&](int a, int b) { return m.share[a] > m.share[b] || (m.share[a] == m.share[b] && a < b); });
      char line[256];
      std::snprintf(line, sizeof line, "- %s (eigenvalues in %.1f s): the top mode in", name.c_str(), seconds);
      std::string note = line;
      double shown = 0;
      for (std::size_t k = 0; k < order.size() && k < 6; ++k) {
        const int i = order[k];
        std::snprintf(line, sizeof line, " %s (%.2f, %.1f kg),", sim->blocks().props.name[i].c_str(), m.share[i],
                      sim->blocks().props.mass[i]);
        note += line;
        shown += m.share[i];
      }
      std::snprintf(line, sizeof line, " %.2f of it in these", shown);
      notes.push_back(note + line);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s: %s\n", path.c_str(), e.what());
      status = 1;
    }
  }
  std::printf("\n");
  for (const std::string& n : notes) std::printf("%s\n", n.c_str());
  return status;
}
