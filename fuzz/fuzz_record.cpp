// libFuzzer targets: the ground-motion record readers of
// io/ground_motion_record.hpp. Built twice from this file:
//   polydem_fuzz_at2          parse_at2()         (PEER NGA .AT2 text)
//   polydem_fuzz_csv_record   parse_csv_record()  (two columns time, acceleration)
// (POLYDEM_FUZZ_CSV selects the second).
//
// Contract under test: any text either gives a record or throws RecordError
// ("FILE:LINE: what"); any std::exception counts as a clear error. A record
// that is returned must keep the header's promises (same length of time and
// acceleration, times strictly increasing, every value finite, dt > 0);
// a broken promise aborts with a message, as does a crash, a sanitizer report or a hang.
#include "io/ground_motion_record.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

namespace {

constexpr std::size_t kMaxInput = 64 * 1024;

// A broken promise: say which, then abort (libFuzzer saves the input).
[[noreturn]] void broken(const char* what) {
  std::fprintf(stderr, "polydem_fuzz: record returned with %s\n", what);
  std::abort();
}

void check(const polydem::GroundMotionRecord& r) {
  if (r.time.size() != r.acceleration.size()) broken("time and acceleration of different lengths");
  if (!(r.dt > 0) || !std::isfinite(r.dt)) broken("dt not positive and finite");
  for (std::size_t i = 0; i < r.time.size(); ++i) {
    if (!std::isfinite(r.time[i])) broken("a non-finite time");
    if (!std::isfinite(r.acceleration[i])) broken("a non-finite acceleration");
    if (i > 0 && !(r.time[i] > r.time[i - 1])) broken("times not strictly increasing");
  }
  // The consumers: interpolation before, at, inside and after the record.
  double sum = polydem::peak_acceleration(r);
  if (!r.time.empty()) {
    const double t0 = r.time.front(), t1 = r.time.back();
    for (const double t : {t0 - 1.0, t0, 0.5 * t0 + 0.5 * t1, t1, t1 + 1.0}) sum += polydem::sample(r, t);
  }
  if (!std::isfinite(sum)) broken("sample() or peak_acceleration() not finite");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > kMaxInput) return -1;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
#ifdef POLYDEM_FUZZ_CSV
    check(polydem::parse_csv_record(text, "fuzz.csv"));
#else
    check(polydem::parse_at2(text, "fuzz.AT2"));
#endif
  } catch (const std::exception&) {
    // A clear error: accepted.
  }
  return 0;
}
