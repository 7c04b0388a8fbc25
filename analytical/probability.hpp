#pragma once
// The probability the fragility fit (fragility.hpp) and the stochastic
// ground-motion model (synthetic_ground_motion.hpp) share: the standard
// normal, gamma and beta distributions (CDF and quantile), a seeded random
// stream that gives the same numbers on every platform, and percentiles.
//
// Why not <random>'s distributions: std::normal_distribution and friends are
// implementation-defined (libstdc++, libc++ and MSVC give different numbers
// for the same engine), so a seed would not name one suite or one bootstrap.
// std::mt19937_64 itself is fully specified by the standard; everything on
// top of it here is written out: a 53-bit uniform and Box-Muller normals.

#include <cstdint>
#include <random>
#include <vector>

namespace polydem::analytical {

// Φ(x), the standard normal CDF, from erfc (accurate in both tails).
double normal_cdf(double x);
// ln Φ(x) and ln(1 − Φ(x)) without cancellation; −inf where they underflow.
double log_normal_cdf(double x);
double log_normal_sf(double x);
// Φ⁻¹(p) for 0 < p < 1 (Acklam's rational approximation, then one Halley
// step on erfc: relative error near 1e-15); ±inf at p = 0, 1.
double normal_quantile(double p);

// P(k, x) = γ(k, x) / Γ(k), the regularised lower incomplete gamma function
// (series below x = k + 1, Lentz's continued fraction above), k > 0, x ≥ 0.
double gamma_cdf(double k, double x);
// The x with P(k, x) = p (unit rate), by bisection in ln x to full precision.
double gamma_quantile(double k, double p);

// I_x(a, b), the regularised incomplete beta function (continued fraction),
// and the x in [0, 1] with I_x(a, b) = p (bisection).
double beta_cdf(double a, double b, double x);
double beta_quantile(double a, double b, double p);

// SplitMix64's finaliser: spreads a seed and an index into an engine seed,
// so that record i of a suite, or the bootstrap of state j, has its own
// stream (streams of adjacent seeds are unrelated).
std::uint64_t mix_seed(std::uint64_t seed, std::uint64_t index);

// A seeded stream of uniforms and standard normals: std::mt19937_64 seeded
// with one 64-bit value; uniform() = (engine() >> 11 + 0.5) / 2^53, in
// (0, 1); normal() by Box-Muller, using both values of each pair
// (√(−2 ln u1) cos 2πu2, then √(−2 ln u1) sin 2πu2).
class RandomStream {
 public:
  explicit RandomStream(std::uint64_t seed);
  double uniform();
  double normal();
  // An index in [0, n), n > 0: ⌊uniform() n⌋.
  std::size_t index(std::size_t n);

 private:
  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

// The q-quantile (0 ≤ q ≤ 1) of the values by linear interpolation between
// order statistics at (n − 1) q (Hyndman & Fan's type 7, numpy's default).
// `values` is sorted in place; empty gives NaN.
double percentile(std::vector<double>& values, double q);

}  // namespace polydem::analytical
