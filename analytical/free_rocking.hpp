#pragma once
// Free rocking (a_g = 0) of a body released at rest at θ0 (0 < θ0 < α):
// the time to its first impact, exactly and in Housner's linearised form.

namespace polydem::analytical {

// Exact, eq. 7 with a_g = 0. Energy: θ̇² = 2p²(cos(α − θ0) − cos(α − θ)), so
//   T = ∫_0^θ0 dθ / (p √(2(cos(α − θ0) − cos(α − θ)))).
// The integrand blows up like (θ0 − θ)^{-1/2} at release; θ = θ0 − w² makes it
// smooth, and the difference of cosines is taken as 2 sin(a + w²/2) sin(w²/2)
// (a = α − θ0) so nothing cancels. Adaptive Simpson to ~1e-13 relative.
// p [rad/s], alpha and theta0 [rad]; returns seconds.
double free_rocking_time_to_impact(double p, double alpha, double theta0);

// Eq. 9 with a_g = 0: θ(t) = α − (α − θ0) cosh(p t), so
//   T = acosh(α / (α − θ0)) / p.
double free_rocking_time_to_impact_linear(double p, double alpha, double theta0);

// θ̇ just before the first impact (eq. 7, energy): −p √(2(cos(α − θ0) − cos α)).
double free_rocking_impact_velocity(double p, double alpha, double theta0);

}  // namespace polydem::analytical
