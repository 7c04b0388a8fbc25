// The threads of one run: the caller's (the command line's --threads), else
// the deck's simulation.threads, else OpenMP's default (OMP_NUM_THREADS or
// the cores). OpenMP's count is a setting of the calling thread that
// outlives a run, so it is set only while the run works (ScopedThreads) and
// put back after: a deck asking for one thread does not leave the next run
// in the same process (Python, in-process sweeps) on one.
#pragma once

#include "core/scene_spec.hpp"

#include <omp.h>

namespace polydem {

inline int run_threads(int caller, const SceneSpec& spec) {
  return caller > 0 ? caller : spec.simulation.threads;
}

class ScopedThreads {
 public:
  explicit ScopedThreads(int threads) : saved_(omp_get_max_threads()) {
    if (threads > 0) omp_set_num_threads(threads);
  }
  ~ScopedThreads() { omp_set_num_threads(saved_); }
  ScopedThreads(const ScopedThreads&) = delete;
  ScopedThreads& operator=(const ScopedThreads&) = delete;

 private:
  int saved_;
};

}  // namespace polydem
