// Whether the AVX2 lanes can run here (see joint_law_lanes.hpp). Compiled
// without -mavx2: it is what decides whether the kernel may be called.
#include "contact/joint_law_lanes.hpp"

#include <cstdlib>

namespace polydem::lanes {

#ifdef POLYDEM_LANES_AVX2
bool available() { return __builtin_cpu_supports("avx2"); }
#else
bool available() { return false; }
void pair_law(const PairFrame&, const LawConstants&, const SubcontactArrays&, std::size_t, std::size_t) {
  std::abort();  // never called: available() is false
}
#endif

}  // namespace polydem::lanes
