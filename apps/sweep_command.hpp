// `polydem sweep`: a deck run over a grid of values of its keys, on local
// worker processes or across MPI ranks, resumable, with a boundary search
// that finds damage and collapse thresholds in far fewer runs than the full
// grid (paper Figures 5 and 7: one-sine pulses over a_p and T_p).
//
//   polydem sweep examples/spire/tip_pulse.toml --out out/tip
//       --vary ground_motion.period=0.5:2.0:7
//       --search ground_motion.acceleration_g=0.2:3.0:15 --resolution 0.01 --jobs 2
//
// Without --search the points are the full grid of the --vary axes. With it,
// each point of the --vary grid is a column along the --search key (see
// sweep_search.hpp). Finished points are kept in DIR/points and skipped when
// the same command runs again. Under `mpirun -np N` (polydem built with
// MPI) the points are spread over the ranks. With --replicas N every point
// of the grid is an ensemble of N replicas (docs/ensembles.md), and with
// --band-axis KEY the probabilities of damage, stones lost and collapse
// along KEY are fitted per column: their 16, 50 and 84 % intensities.
#pragma once

#include <string>
#include <vector>

namespace polydem {

struct SweepOptions {
  std::string deck_path;
  bool use_default = false;
  std::string out_dir = "out/sweep";
  std::vector<std::string> vary;     // KEY=START:STOP:N or KEY=V1,V2,...
  std::string search;                // KEY=START:STOP:N (coarse scan) or empty
  double resolution = 0;             // bisection stops at this bracket (with --search)
  int jobs = 0;                      // local worker processes (0: cores / threads)
  int threads = 1;                   // OpenMP threads per run
  std::vector<std::string> overrides;
  // Each point as an ensemble (studies/ensemble.hpp): N replicas, a last
  // axis ensemble.replica = 0..N-1, and DIR/ensembles.csv with each point's
  // class counts and percentiles. As typed; empty: none. Not with --search.
  std::string replicas;
  std::string seed;  // empty: the deck's ensemble.seed
  // With --replicas: one of the --vary keys, an intensity (values > 0). The
  // other --vary keys make the columns; DIR/bands.csv gets each column's
  // lognormal fit of damage, stones lost and collapse along it
  // (studies/ensemble_bands.hpp), and ensembles.csv the observed fractions.
  std::string band_axis;
  bool quiet = false;
  std::string executable;            // polydem binary for local workers (tests); default: this one
};

int sweep_command(const SweepOptions& options);

}  // namespace polydem
