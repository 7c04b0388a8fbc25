#pragma once
// Elastic response spectra of a ground-acceleration record: the peak
// response of a damped single-degree-of-freedom oscillator
//   ü + 2ξω u̇ + ω² u = −a_g(t),   ω = 2π/T,
// starting at rest, over a range of periods T. The spectral displacement
// Sd(T) = max |u|, the pseudo-velocity PSV = ω Sd and the pseudo-acceleration
// PSA = ω² Sd (Chopra, Dynamics of Structures, ch. 6). PSA tends to the peak
// ground acceleration as T → 0 (the stiff oscillator moves with the ground).
//
// The record is piecewise linear between its samples (the solver samples it
// the same way, core/ground_motion.hpp), and each step is integrated exactly
// (Nigam & Jennings 1969): the state (u, u̇) at the step's end is a fixed
// linear map of the state at its start and of the two end accelerations,
//   x₁ = A x₀ + B [a₀, a₁],
// with A the damped free vibration over the step and B the response from
// rest to a unit acceleration at either end, both written out from the
// closed-form solution of the oscillator under a linear load. No step size
// limits the accuracy; the step only decides where the peak is looked for,
// so steps longer than T/20 are cut into equal substeps (the load stays
// linear inside them, so the response at each substep is exact too), and
// between substep points a peak is located on the cubic Hermite
// interpolant of u and u̇ (error ≈ (2π/20)⁴/384 ≈ 4e-5 of the peak). After
// the record the ground is at rest (a_g = 0, as the solver has it) and the
// free vibration is followed for one more period, which holds the peak of a
// long-period oscillator that the record's end leaves swinging.
//
// Units: those of the input (a_g in m/s² gives Sd in m, PSV in m/s, PSA in
// m/s²); times in s. Analytical is a standalone layer: plain vectors in and
// out, the record readers (io/ground_motion_record.hpp) stay outside.

#include <vector>

namespace polydem::analytical {

struct ResponseSpectrum {
  std::vector<double> period;        // T [s], as asked
  std::vector<double> displacement;  // Sd = max |u| [length]
  std::vector<double> pseudo_velocity;      // ω Sd
  std::vector<double> pseudo_acceleration;  // ω² Sd
  double damping = 0.05;             // ξ, fraction of critical
  double peak_ground_acceleration = 0.0;    // max |a_g| of the samples
};

// Spectra of the record a(t) (time strictly increasing, at least two
// samples, a the same length) at `periods` (each > 0) for damping ξ in
// [0, 1). Throws std::invalid_argument naming the first bad value.
ResponseSpectrum response_spectrum(const std::vector<double>& time, const std::vector<double>& acceleration,
                                   const std::vector<double>& periods, double damping = 0.05);

// The oscillator's relative displacement u(t) at the record's samples (the
// response history behind one spectral ordinate), from rest at time[0].
std::vector<double> oscillator_displacement(const std::vector<double>& time, const std::vector<double>& acceleration,
                                            double period, double damping);

// The exact step of the oscillator (ω = 2π/T, damping ξ < 1) over a step h
// under a ground acceleration varying linearly from a0 to a1:
//   (u, u̇)₁ = A (u, u̇)₀ + B (a0, a1).
// The step response_spectrum takes; also for linear maps of a record
// (synthetic_target.hpp).
struct OscillatorStep {
  double A[2][2] = {{0, 0}, {0, 0}};
  double B[2][2] = {{0, 0}, {0, 0}};
};
OscillatorStep oscillator_step(double h, double omega, double xi);

// The periods the spectrum command uses when given none: 0.01 s to 5 s, 100
// values evenly spaced in log T (s).
std::vector<double> default_spectrum_periods();

// A suite's spectra summarised per period, for ordinates that are lognormal
// across records (Baker 2015): the median exp(mean ln x) and the dispersion
// β = standard deviation of ln x (with n − 1; 0 for a single record). PSV,
// PSA and Sd differ by powers of ω at a fixed period, so their dispersions
// are equal and their medians are ω-multiples of one another.
struct SuiteSpectrum {
  std::vector<double> period;
  std::vector<double> median_displacement, median_pseudo_velocity, median_pseudo_acceleration;
  std::vector<double> dispersion;  // β of ln PSA (= of ln Sd, ln PSV)
  int records = 0;
};

// Every spectrum must have the same periods (throws std::invalid_argument
// otherwise, and for an empty list or a zero ordinate).
SuiteSpectrum suite_spectrum(const std::vector<ResponseSpectrum>& spectra);

}  // namespace polydem::analytical
