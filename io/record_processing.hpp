// What may be done to a record after it is read and before a run or a
// spectrum uses it: a polynomial baseline correction and the time scaling of
// a reduced-scale model. Both are off unless a deck, a suite or the spectrum
// command asks for them (docs/records.md, "Baseline correction" and "Time
// scaling").
#pragma once

#include <vector>

namespace polydem {

// Polynomial baseline correction (Boore 2001's least-squares fit of the
// displacement, the scheme of SeismoSignal's "baseline correction order").
// A small offset in an accelerogram (an instrument's zero, a digitising
// error) integrates into a velocity that drifts and a displacement that
// grows like t²: the ground "walks away". The record is integrated exactly
// (piecewise-linear acceleration, from rest at its first sample) to the
// displacement u(t); the polynomial p(τ) = Σ c_k τ^k, k = 2 … order + 2,
// τ = (t − t₀)/(t_end − t₀), is fitted to u by least squares over the
// samples; its second derivative, a polynomial of degree `order` in t, is
// subtracted from the acceleration. The fit starts at τ² so the corrected
// record still starts from rest (no jump in velocity or displacement).
// order in [0, 4]: 0 removes a constant offset, 1 a linear drift, 2 a
// quadratic one. Throws std::invalid_argument for another order or a record
// of fewer than order + 2 samples.
void correct_baseline(std::vector<double>& time, std::vector<double>& acceleration, int order);

// The record's displacement from rest at each sample, integrating the
// piecewise-linear acceleration exactly (the scheme the correction fits).
std::vector<double> record_displacement(const std::vector<double>& time, const std::vector<double>& acceleration);

// Time scaling for a reduced-scale model under the same gravity (a shaking
// table model at length scale λ = model / prototype, Froude similitude):
// accelerations unchanged, times multiplied by √λ. λ > 0.
void scale_record_time(std::vector<double>& time, double length_scale);

// The largest baseline order accepted.
inline constexpr int kMaxBaselineOrder = 4;

}  // namespace polydem
