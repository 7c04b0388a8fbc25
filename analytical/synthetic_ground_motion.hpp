#pragma once
// Synthetic ground motions for an earthquake scenario: the site-based
// stochastic model of Rezaeian & Der Kiureghian (2010, "Simulation of
// synthetic ground motions for specified earthquake and site
// characteristics", Earthquake Engng Struct. Dyn. 39:1155-1180), written
// from the paper's equations (docs/fragility.md, "Synthetic records").
//
// The model. An acceleration history is white noise w(τ) passed through a
// linear filter whose frequency changes with time, then modulated:
//
//   x(t) = q(t) Σᵢ sᵢ(t) uᵢ,   sᵢ(t) = h(t − tᵢ; tᵢ) / √(Σⱼ h²(t − tⱼ; tⱼ))
//   h(t − τ; τ) = ω_f(τ)/√(1−ζ_f²) e^{−ζ_f ω_f(τ)(t−τ)} sin(ω_f(τ)√(1−ζ_f²)(t−τ)),  t ≥ τ
//   ω_f(τ) = ω_mid + ω′ (τ − t_mid)
//   q(t) = α₁ t^{α₂−1} e^{−α₃ t}
//
// with uᵢ independent standard normals at tᵢ = i Δt. The normalisation
// makes the variance of x(t) exactly q²(t), so q alone sets the evolving
// intensity and the filter alone the frequency content: the filter is an
// oscillator's displacement response to a unit impulse (×ω²), whose output
// crosses zero upwards ω_f/2π times a second. q² is, up to a factor, a
// gamma density of shape 2α₂ − 1 and rate 2α₃, so the expected cumulative
// Arias intensity is a gamma CDF: the parameters (I_a, D5-95, t_mid) fix
// α₁, α₂, α₃ (modulating_function). A high-pass post-filter, a critically
// damped oscillator ü + 2ω_c u̇ + ω_c² u = x whose ü is the record (f_c =
// ω_c/2π = 0.2 Hz), removes the drift of velocity and displacement.
//
// The six parameters (I_a, D5-95, t_mid, ω_mid/2π, ω′/2π, ζ_f) are random:
// each maps to a standard normal νᵢ = Φ⁻¹(Fᵢ(θᵢ)) through its fitted
// marginal Fᵢ; the νᵢ are regressions on the faulting style F, magnitude
// M, rupture distance R and V_s30 plus correlated normal errors (the
// paper's predictive equations, their coefficients, standard deviations
// and correlations, in synthetic_ground_motion.cpp).

#include "analytical/probability.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace polydem::analytical {

// The scenario: moment magnitude, closest distance to the rupture R_rup
// [km], V_s30 [m/s], and the faulting style (F = 0 strike-slip, 1 reverse).
struct EarthquakeScenario {
  double magnitude = 6.5;
  double distance = 20.0;
  double vs30 = 760.0;
  bool reverse = false;
};

// The model's six parameters.
struct SyntheticMotionParameters {
  double arias_intensity = 0.0;  // I_a = π/(2g) ∫ a² dt [m/s]
  double d5_95 = 0.0;            // significant duration, 5 % to 95 % of I_a [s]
  double t_mid = 0.0;            // time at 45 % of I_a [s]
  double f_mid = 0.0;            // filter frequency at t_mid, ω_mid/2π [Hz]
  double f_slope = 0.0;          // its rate of change, ω′/2π [Hz/s]
  double zeta_f = 0.0;           // filter damping ratio
};

// q(t) = α₁ t^{α₂−1} e^{−α₃ t}, in m/s² (α₁ carries the unit).
struct ModulatingFunction {
  double alpha1 = 0.0, alpha2 = 0.0, alpha3 = 0.0;
  double shape() const { return 2.0 * alpha2 - 1.0; }  // of the gamma law of q²
  double rate() const { return 2.0 * alpha3; }
};

// α₁, α₂, α₃ such that the expected I_a, D5-95 and t_mid are the
// parameters'; g converts I_a to ∫q² dt = 2 g I_a / π. Throws
// std::invalid_argument when D5-95 / t_mid ≥ 4.92: then α₂ ≤ 1 and q(0)
// would not vanish (the shape would be below 1).
ModulatingFunction modulating_function(const SyntheticMotionParameters& p, double g);

// The parameters at the regressions' means (every error zero): the
// scenario's median motion. Throws std::invalid_argument unless M, R and
// V_s30 are > 0.
SyntheticMotionParameters median_parameters(const EarthquakeScenario& s);

// One draw of the six parameters with the paper's correlated errors
// (inter- and intra-event together: the scenario is a design scenario, not
// one recorded event). A draw whose modulating function does not exist
// (D5-95 / t_mid ≥ 4.92) is drawn again from the same stream (2-3 % of
// the draws for ordinary scenarios; after 1000 failed draws it throws
// std::invalid_argument).
SyntheticMotionParameters sample_parameters(const EarthquakeScenario& s, RandomStream& rs);

struct SyntheticOptions {
  double dt = 0.01;             // sampling step [s]
  double high_pass = 0.2;       // f_c of the post-filter [Hz]; 0: none
  double min_frequency = 0.3;   // floor of ω_f/2π when ω′ drives it down [Hz]
  double energy_end = 0.999;    // the noise stops where q² has given this share of I_a
  double tail = 5.0;            // then the post-filter rings down this long [s]
  double g = 9.80665;           // for I_a [m/s²]
};

struct SyntheticRecord {
  std::string name;
  std::uint64_t seed = 0;               // of its RandomStream
  SyntheticMotionParameters parameters;  // the targets it was drawn for
  double dt = 0.0;
  std::vector<double> acceleration;      // m/s², sample i at t = i dt
};

// One record for given parameters, drawing its noise from `rs`.
SyntheticRecord simulate_record(const SyntheticMotionParameters& p, const SyntheticOptions& o, RandomStream& rs);

// The record taken apart: for fixed parameters it is linear in its noise,
//   acceleration = Σᵢ uᵢ gᵢ,
// uᵢ the standard normals in the order simulate_record draws them and gᵢ
// the record it makes with uᵢ = 1 and every other u zero, post-filter
// included. Calls visit(i, gᵢ) for i = 0, 1, …, with gᵢ[j] the sample
// i + j (the samples before i are zero) up to the record's end; returns
// the record's length. Anything linear in the record then has its exact
// variance Σᵢ (its value on gᵢ)²: the expected Arias intensity, an
// oscillator's response (synthetic_target.hpp). Same checks as
// simulate_record.
std::size_t for_each_unit_record(const SyntheticMotionParameters& p, const SyntheticOptions& o,
                                 const std::function<void(std::size_t, const std::vector<double>&)>& visit);

// `count` records for the scenario. Record i (0-based) is named
// "<prefix>_<i+1, zero-padded>" and draws its parameters, then its noise,
// from RandomStream(mix_seed(seed, i)): the same (scenario, seed, i)
// gives the same record whatever the count.
std::vector<SyntheticRecord> synthetic_suite(const EarthquakeScenario& s, int count, std::uint64_t seed,
                                             const SyntheticOptions& o, const std::string& prefix = "synthetic");

// What the model's targets are checked against, measured on a record.
struct RecordMeasures {
  double arias_intensity = 0.0;    // [m/s], trapezoidal ∫ a² dt
  double t5 = 0.0, t45 = 0.0, t95 = 0.0;  // times at 5, 45, 95 % of it [s]
  double d5_95 = 0.0;               // t95 − t5 [s]
  double pga = 0.0;                 // [m/s²]
  double pgv = 0.0;                 // [m/s], trapezoidal velocity
  double residual_velocity = 0.0;   // velocity at the end [m/s]
};
RecordMeasures record_measures(double dt, const std::vector<double>& a, double g = 9.80665);

// Zero-level up-crossings of a in [t0, t1] (sign changes from < 0 to ≥ 0
// between samples there).
int upcrossings(double dt, const std::vector<double>& a, double t0, double t1);

}  // namespace polydem::analytical
