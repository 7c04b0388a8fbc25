#include "io/run_outputs.hpp"

#include "io/summary.hpp"
#include "io/vtk.hpp"

#include <filesystem>

namespace polydem {

void write_run_outputs(const std::string& dir, const SceneSpec& spec, const RunReport& report, int threads) {
  std::filesystem::create_directories(dir);
  write_results_h5(dir + "/results.h5", spec, report);
  if (report.unstable) write_vtu(dir + "/last_good_state.vtu", report.final_shapes);
  write_summary(dir, spec, report, threads);
}

}  // namespace polydem
