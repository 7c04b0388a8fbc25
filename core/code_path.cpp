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

bool wide_lanes_available() {
#if defined(POLYDEM_LANES_AVX2) && !defined(__AVX__) && !defined(__FMA__)
  // __builtin_cpu_supports asks the OS too (XCR0 keeps the AVX-512 state).
  static const bool wide =
      lanes_available() && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl");
  return wide;
#else
  return false;
#endif
}

namespace {

bool environment_says(std::string_view value) {
  const char* e = std::getenv("POLYDEM_CODE_PATH");
  return e && std::string_view(e) == value;
}

}  // namespace

bool use_lanes(CodePath path) {
  if (path == CodePath::portable) return false;
  if (path == CodePath::lanes || path == CodePath::lanes_avx2) return lanes_available();
  static const bool automatic = lanes_available() && !environment_says("portable");
  return automatic;
}

bool use_wide_lanes(CodePath path) {
  if (path == CodePath::lanes) return wide_lanes_available();
  if (path != CodePath::automatic) return false;
  static const bool automatic = use_lanes(CodePath::automatic) && wide_lanes_available() && !environment_says("avx2");
  return automatic;
}

}  // namespace polydem
