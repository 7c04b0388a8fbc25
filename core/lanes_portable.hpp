// Four doubles at a time in plain C++: the lane type of the step's kernels
// on every machine without AVX2 (core/code_path.hpp). The interface of
// core/lanes_avx2.hpp, lane by lane: each function performs, in each lane,
// the one IEEE operation (or the fixed sequence) its AVX2 twin performs, so
// a kernel gives the same bits on either. Masks are lanes whose bits are all
// ones (true) or all zeros, as AVX2's comparisons make them; `pick` reads a
// mask's sign bit, as VBLENDVPD does.
#pragma once

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace polydem::simd_portable {

struct V {
  double l[4];
};

namespace detail {
inline std::uint64_t u(double x) { return std::bit_cast<std::uint64_t>(x); }
inline double d(std::uint64_t x) { return std::bit_cast<double>(x); }
inline double truth(bool c) { return d(c ? ~std::uint64_t{0} : 0); }
}  // namespace detail

#define POLYDEM_LANEWISE(expr)  \
  V r;                          \
  for (int k = 0; k < 4; ++k) { \
    r.l[k] = (expr);            \
  }                             \
  return r

static inline V zero() { return V{{0.0, 0.0, 0.0, 0.0}}; }
static inline V bc(double x) { return V{{x, x, x, x}}; }
static inline V add(V a, V b) { POLYDEM_LANEWISE(a.l[k] + b.l[k]); }
static inline V sub(V a, V b) { POLYDEM_LANEWISE(a.l[k] - b.l[k]); }
static inline V mul(V a, V b) { POLYDEM_LANEWISE(a.l[k] * b.l[k]); }
static inline V div(V a, V b) { POLYDEM_LANEWISE(a.l[k] / b.l[k]); }
static inline V sqrt(V a) { POLYDEM_LANEWISE(std::sqrt(a.l[k])); }
static inline V neg(V a) { POLYDEM_LANEWISE(-a.l[k]); }
static inline V le(V a, V b) { POLYDEM_LANEWISE(detail::truth(a.l[k] <= b.l[k])); }
static inline V lt(V a, V b) { POLYDEM_LANEWISE(detail::truth(a.l[k] < b.l[k])); }
static inline V gt(V a, V b) { POLYDEM_LANEWISE(detail::truth(a.l[k] > b.l[k])); }
static inline V all_lanes(bool c) { return bc(detail::truth(c)); }
static inline V both(V a, V b) { POLYDEM_LANEWISE(detail::d(detail::u(a.l[k]) & detail::u(b.l[k]))); }
static inline V either(V a, V b) { POLYDEM_LANEWISE(detail::d(detail::u(a.l[k]) | detail::u(b.l[k]))); }
static inline V but_not(V a, V b) { POLYDEM_LANEWISE(detail::d(detail::u(a.l[k]) & ~detail::u(b.l[k]))); }
static inline V invert(V m) { POLYDEM_LANEWISE(detail::d(~detail::u(m.l[k]))); }
static inline V pick(V m, V a, V b) { POLYDEM_LANEWISE(std::signbit(m.l[k]) ? a.l[k] : b.l[k]); }
static inline int bits(V m) {
  int b = 0;
  for (int k = 0; k < 4; ++k) b |= (std::signbit(m.l[k]) ? 1 : 0) << k;
  return b;
}
// MAXPD(x, y) is (x > y) ? x : y and MINPD(x, y) (x < y) ? x : y, NaN and −0
// included: max_zero is MAXPD(0, a), min_of(a, b) MINPD(b, a), max_of(a, b)
// MAXPD(b, a), as in core/lanes_avx2.hpp.
static inline V max_zero(V a) { POLYDEM_LANEWISE(0.0 > a.l[k] ? 0.0 : a.l[k]); }
static inline V min_of(V a, V b) { POLYDEM_LANEWISE(b.l[k] < a.l[k] ? b.l[k] : a.l[k]); }
static inline V max_of(V a, V b) { POLYDEM_LANEWISE(b.l[k] > a.l[k] ? b.l[k] : a.l[k]); }
static inline V dot3(V ax, V ay, V az, V bx, V by, V bz) { return add(add(mul(ax, bx), mul(ay, by)), mul(az, bz)); }

static inline double lane(V v, int k) { return v.l[k]; }
static inline V with_lane(V v, int k, double x) {
  v.l[k] = x;
  return v;
}

struct Group {
  bool full;
  int count;
};
static inline Group group(std::size_t left) {
  Group g;
  g.count = left >= 4 ? 4 : static_cast<int>(left);
  g.full = g.count == 4;
  return g;
}
// Missing lanes read as 0, as a masked load's.
static inline V load(const double* p, const Group& g) { POLYDEM_LANEWISE(k < g.count ? p[k] : 0.0); }
static inline void store(double* p, V v, const Group& g) {
  for (int k = 0; k < g.count; ++k) p[k] = v.l[k];
}
static inline void store_xyz(double* p, V x, V y, V z, const Group& g) {
  for (int k = 0; k < g.count; ++k) {
    p[3 * k] = x.l[k];
    p[3 * k + 1] = y.l[k];
    p[3 * k + 2] = z.l[k];
  }
}
static inline std::uint32_t load_bytes(const std::uint8_t* p, const Group& g) {
  std::uint32_t bytes = 0;
  for (int k = 0; k < g.count; ++k) bytes |= static_cast<std::uint32_t>(p[k]) << (8 * k);
  return bytes;
}
static inline void store_bytes(std::uint8_t* p, std::uint32_t bytes, const Group& g) {
  for (int k = 0; k < g.count; ++k) p[k] = static_cast<std::uint8_t>(bytes >> (8 * k));
}
static inline V bytes_mask(std::uint32_t bytes, std::uint32_t bits) {
  POLYDEM_LANEWISE(detail::truth(((bytes >> (8 * k)) & bits & 0xFFu) != 0));
}
static inline std::uint32_t mask_bytes(V m) {
  std::uint32_t bytes = 0;
  for (int k = 0; k < 4; ++k) bytes |= (std::signbit(m.l[k]) ? 1u : 0u) << (8 * k);
  return bytes;
}

static inline void sum_lanes6(V a, V b, V c, V d, V e, V f, double out[6]) {
  const V* v[6] = {&a, &b, &c, &d, &e, &f};
  for (int i = 0; i < 6; ++i) out[i] = (v[i]->l[0] + v[i]->l[1]) + (v[i]->l[2] + v[i]->l[3]);
}

static inline V load3(const double* p) { return V{{p[0], p[1], p[2], 0.0}}; }
static inline void store3(double* p, V v) {
  p[0] = v.l[0];
  p[1] = v.l[1];
  p[2] = v.l[2];
}
static inline V yzx(V v) { return V{{v.l[1], v.l[2], v.l[0], v.l[3]}}; }

static inline V gather(const double* p, int width, int c, const int idx[4]) { POLYDEM_LANEWISE(p[width * idx[k] + c]); }
static inline void scatter(double* p, int width, int c, const int idx[4], V v) {
  for (int k = 0; k < 4; ++k) p[width * idx[k] + c] = v.l[k];
}

#undef POLYDEM_LANEWISE

}  // namespace polydem::simd_portable
