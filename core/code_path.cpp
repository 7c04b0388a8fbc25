#include "core/code_path.hpp"

#include <cstdlib>
#include <string_view>

namespace polydem {

bool lanes_available() {
#ifdef POLYDEM_LANES_AVX2
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
#else
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
