// Joint damping in two parts: what the step's stiffness-proportional
// dashpots cost the time step, and how the split scheme takes most of it
// back (simulation.damping_scheme = "split").
//
// The explicit scheme (polydem's default, and 3DEC's) computes each
// subcontact's dashpot force c·v_rel from the velocities at t − dt/2, with
// the spring. Mode by mode (C = β·K keeps each mode's damping ratio
// ξ = β·ω/2) the velocity update is v₊ = (1 − X)·v₋ − dt·ω²·x, X = 2ξ·ω·dt,
// stable while ω·dt ≤ 2(√(1 + ξ²) − ξ): at the spire's stiffest stones
// (ξ = 0.83) the dashpots halve the springs' step.
//
// The split scheme computes the dashpot in two parts. The joint law applies
// (1 − θ) of it from the velocities at t − dt/2, as the explicit one; after the
// velocity update, before the blocks move, a second pass over the
// subcontacts applies the remaining θ from the updated velocities (each
// block's velocity after the step's forces, `v_t`), and the blocks move with
// the corrected velocity. Per mode, with a = 1 − (1 − θ)·X and b = 1 − θ·X:
//
//     v₊ = b·(a·v₋ − dt·ω²·x),   x₊ = x + dt·v₊
//
// whose amplification matrix has trace 1 + ab − b·w² and determinant ab
// (w = ω·dt). Both roots lie in the unit circle (Jury) if and only if
//
//     b ≥ 0,   |ab| ≤ 1,   2 + 2ab − b·w² ≥ 0.
//
// To first order in dt the force is the same dashpot, c·v at the step's
// time, so the scheme converges to the same model as the explicit one; the
// second pass costs a relative velocity and a gather per subcontact, about
// two fifths of a step (docs/benchmarks.md, "The spire").
//
// What is proved here. A step dt is stable for every mode of frequency
// ω ≤ ω_max whose damping is at most the proportional one at its
// frequency, c ≤ β·ω² (a dashpot switched off while its joint slips or opens
// only lowers it): X ≤ 2Ξ·w²/W with Ξ = β·ω_max/2 and W = ω_max·dt. For a
// given X the last condition is hardest at the largest w, w = W, and the
// other two do not depend on w; so the step is stable when, for every X in
// [0, 2Ξ·W], b ≥ 0, |ab| ≤ 1 and 2 + 2ab − b·W² ≥ 0. Each is a quadratic in X
// (ab = 1 − X + θ(1 − θ)·X²), checked exactly at its ends and its vertex
// (split_damping_stable). For each Ξ the fraction θ is the one of 0.01, 0.02,
// …, 0.50 allowing the largest W (split_damping), W found by bisection and
// taken from the stable side. Undamped (Ξ = 0) W = 2, the springs' limit;
// at the spire's Ξ = 0.83 W = 1.88 with θ = 0.32, against the explicit
// 0.94: twice the step. Modes are decoupled when C = β·K with one β for
// every joint; the scheme is not proved for several laws with different β
// or dashpots that switch within a step, which scripts/damping_stability.py
// measures on random spring-dashpot networks instead (docs/benchmarks.md).
#pragma once

namespace polydem {

// Stable steps of the split scheme for one damping ratio Ξ at the highest
// frequency: the fraction θ applied after the velocity update and the
// largest ω_max·dt (before the safety factor) it allows.
struct SplitDamping {
  double fraction = 0.5;  // θ
  double limit = 2.0;     // W = ω_max·dt
};

// The scheme is stable at W = ω_max·dt with the fraction θ for every mode
// at or below ω_max damped at most proportionally (the header).
bool split_damping_stable(double W, double xi_max, double theta);

// The best fraction of 0.01 … 0.50 for ξ_max and its step limit.
SplitDamping split_damping(double xi_max);

// The explicit scheme's limit 2(√(1 + ξ²) − ξ), for comparison.
double explicit_damping_limit(double xi_max);

}  // namespace polydem
