#include "core/code_path.hpp"

#include <cstdlib>
#include <string_view>

namespace polydem {

bool lanes_available() {
#if defined(POLYDEM_LANES_AVX2) && !defined(__AVX__) && !defined(__FMA__)
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
#else
  // No lanes in this build, or a build whose own code is compiled for AVX or
  // FMA (-march=native, say): there Eigen's packets and fused products
  // change the portable code's association, which the lanes repeat for
  // baseline x86-64, so the two would not give the same bits.
  return false;
#endif
}

bool use_lanes(CodePath path) {
  if (path == CodePath::portable) return false;
  if (path == CodePath::lanes) return lanes_available();
  static const bool automatic = [] {
    const char* e = std::getenv("POLYDEM_CODE_PATH");
    return lanes_available() && !(e && std::string_view(e) == "portable");
  }();
  return automatic;
}

}  // namespace polydem
