#pragma once
// What the stochastic ground-motion model (synthetic_ground_motion.hpp)
// promises for fixed parameters, computed from the model instead of
// sampled: the target a suite of records is checked against.
//
// For fixed parameters a record is linear in its noise, a = Σᵢ uᵢ gᵢ
// (for_each_unit_record), with the uᵢ independent standard normals. So
// anything linear in the record is a zero-mean Gaussian process whose
// variance is exactly the sum of squares of its values on the gᵢ:
//
// - the expected Arias intensity, π/(2g) ∫ E[a²] dt, with E[a²(t)] =
//   Σᵢ gᵢ²(t) (post-filter included, trapezoidal like record_measures), and
//   where its cumulative curve reaches 5, 45 and 95 %;
// - the response u(t) of a linear oscillator (period T, damping ξ) and its
//   velocity u̇(t): each gᵢ is stepped through the exact piecewise-linear
//   step of response_spectrum.hpp, giving σ_u²(t), σ_u̇²(t) and their
//   covariance at every sample, without sampling error.
//
// The peak. The spectrum's ordinate is max |u| over the record, whose
// distribution has no closed form even for a Gaussian u. It is taken from
// a first-passage approximation: the probability that |u| stays below b is
// exp(−∫ α(b, t) dt), α the rate of first crossings of ±b.
//
// - Poisson (Rice): every crossing is independent. For a Gaussian (u, u̇)
//   with correlation ρ (non-zero while the variance changes), crossings of
//   +b upward and of −b downward together happen at
//     α_P = 2 φ(r) s [φ(η) + η Φ(η)] / σ_u,
//     r = b/σ_u, s = σ_u̇ √(1 − ρ²), η = ρ r / √(1 − ρ²)
//   (Rice 1944; for ρ = 0 it is 2 ν₀ e^{−r²/2}, ν₀ = σ_u̇/(2π σ_u)).
//   A narrow-band response crosses in clumps, one per envelope excursion,
//   so Poisson overstates the rate and the peak.
// - Vanmarcke (1975): the crossings that start an envelope excursion,
//     α_V = α_P (1 − e^{−√(π/2) δ_e r}) / (1 − e^{−r²/2}),  δ_e = δ^1.2,
//   with δ = √(1 − λ₁²/(λ₀λ₂)) the spectral bandwidth of u, λ_k the
//   spectral moments. δ is that of the stationary response to the filter
//   frozen at ω_f(t) (and the post-filter): |H_f|² |H_hp|² |H_osc|², whose
//   moments are integrated numerically; the frozen spectrum is a fair
//   description because ω_f drifts slowly against the oscillator's period.
//
// The median peak b₅₀ solves ∫ α(b, t) dt = ln 2; the target median
// pseudo-spectral acceleration is ω² b₅₀. Vanmarcke's law is the target;
// its 16 and 84 % points give the dispersion of the peak (what a suite's
// sample median is compared with, through the sampling error of a median).
// The Poisson median is kept beside it as the upper bound.
//
// Accuracy. The variances are exact to rounding; the approximation is the
// first passage alone. Against suites of 2000 records for the median
// parameters of three scenarios (M 5.2-7.5, R 10-50 km), with two seeds
// (tests/analytical/synthetic_target_slow_test.cpp, docs/fragility.md),
// the suites' sample median PSa is 0.974 to 1.060 times Vanmarcke's from
// 0.1 to 2 s (low by up to 6 % near 0.2 s, where the response is
// narrowest), and 0.81 to 0.98 times Poisson's. The dispersion agrees with
// the suites' standard deviation of ln PSa within 0.015. Cost: one
// oscillator pass per noise sample and period, O(n²) in the record's
// samples (about 0.1 s per period for a 30 s record at 0.01 s).

#include "analytical/synthetic_ground_motion.hpp"

#include <vector>

namespace polydem::analytical {

struct SyntheticTarget {
  // E[I_a] [m/s] and the times [s] where the expected cumulative Arias
  // intensity reaches 5, 45 and 95 % of it (D5-95 = t95 − t5).
  double arias_intensity = 0.0;
  double t5 = 0.0, t45 = 0.0, t95 = 0.0, d5_95 = 0.0;
  double damping = 0.05;
  std::vector<double> period;                       // T [s], as asked
  std::vector<double> median_pseudo_acceleration;   // ω² b₅₀, Vanmarcke [m/s²]
  std::vector<double> poisson_median_pseudo_acceleration;  // ω² b₅₀, Poisson
  std::vector<double> dispersion;                   // (ln b₈₄ − ln b₁₆)/2, Vanmarcke
  std::vector<double> rms_pseudo_acceleration;      // ω² max_t σ_u(t)
  std::vector<double> bandwidth;                    // δ at t_mid
};

// The targets for parameters `p` simulated with options `o` (the same
// checks as simulate_record), at `periods` (each > 0) for damping ξ in
// (0, 1). Throws std::invalid_argument on a bad period or damping.
SyntheticTarget synthetic_target(const SyntheticMotionParameters& p, const SyntheticOptions& o,
                                 const std::vector<double>& periods, double damping = 0.05);

}  // namespace polydem::analytical
