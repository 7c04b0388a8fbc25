// `polydem ida`: incremental dynamic analysis of a deck under the records of
// a suite (studies/ida.hpp), or a multiple-stripe analysis, run on local
// worker processes or MPI ranks as `polydem sweep` runs its points.
//
//   polydem ida suite.toml examples/spire/tip_pulse.toml --im pga
//       --tolerance 0.02 --max-runs 10 --out out/tip_ida --jobs 2
//   polydem ida suite.toml DECK --im sa --period 0.8 --stripes 0.1,0.2,0.4
//
// Each run is `polydem run DECK --set ground_motion={the record}
// --set ground_motion.scale=F ...` into DIR/points/<id>; the tables
// (DIR/ida.csv, capacities.csv, ida.json; io/ida_tables.hpp) are written at
// the end, the two tables after each round of a hunt-and-fill too. With --resume the runs whose summary is on disk are not run
// again; without it a DIR that holds an analysis's results is refused.
#pragma once

#include <string>
#include <vector>

namespace polydem {

struct IdaOptions {
  std::string suite_path;
  std::string deck_path;
  bool use_default = false;
  std::string out_dir = "out/ida";
  // As typed; checked by ida_command (a bad value names its option).
  std::string im = "pga";     // pga | sa
  std::string period;         // T₁, s (with --im sa)
  std::string damping = "0.05";
  std::string hunt;           // FIRST:STEP:GROWTH of the hunt, g; empty: 0.05:0.05:0.05
  std::string tolerance = "0.01";
  std::string max_runs = "12";
  std::string stripes;        // IM1,IM2,...: a multiple-stripe analysis
  std::string scales;         // F1,F2,...: every record at these scale factors
  int jobs = 0;               // local worker processes (0: cores / threads)
  int threads = 1;            // OpenMP threads per run
  std::vector<std::string> overrides;
  bool resume = false;
  bool quiet = false;
  std::string executable;  // polydem binary for local workers (tests); default: this one
};

int ida_command(const IdaOptions& options);

}  // namespace polydem
