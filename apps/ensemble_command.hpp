// `polydem ensemble`: N replicas of one deck, each with seeded perturbations
// that leave it "the same structure" (studies/ensemble.hpp), run on local
// worker processes or MPI ranks as `polydem sweep` runs its points, and the
// distribution of their outcomes.
//
//   polydem ensemble examples/spire/tip_pulse.toml --replicas 20 --seed 7
//       --out out/tip_ensemble --jobs 2
//
// Replica k is `polydem run DECK --set ensemble.seed=S --set
// ensemble.replica=k` into DIR/points/<id>; the tables (DIR/replicas.csv,
// ensemble.csv, ensemble.json; io/ensemble_tables.hpp) are written at the
// end. With --resume the replicas whose summary is on disk are not run
// again; without it a DIR that holds an ensemble's results is refused.
#pragma once

#include <string>
#include <vector>

namespace polydem {

struct EnsembleOptions {
  std::string deck_path;
  bool use_default = false;
  std::string out_dir = "out/ensemble";
  std::string replicas;  // N, as typed (checked here: an integer in [1, 1e6])
  std::string seed;      // S, as typed; empty: the deck's ensemble.seed (default 1)
  int jobs = 0;          // local worker processes (0: cores / threads)
  int threads = 1;       // OpenMP threads per run
  std::vector<std::string> overrides;
  bool resume = false;
  bool quiet = false;
  std::string executable;  // polydem binary for local workers (tests); default: this one
};

int ensemble_command(const EnsembleOptions& options);

}  // namespace polydem
