// The Coulomb joint law, one subcontact at a time (compression positive).
//
// For a subcontact of tributary area A with normal overlap u_n and relative
// shear velocity v_s of the incident block over the reference block:
//   normal:  F_n = kn·A·u_n, no tension unless still bonded (then ≥ −σ_t·A);
//   shear:   F_s ← F_s − ks·A·v_s·dt, F_s first rotated into the current
//            plane; capped at c·A + F_n·tan φ (slip: the cap is the force, the
//            excess displacement is dissipated, the bond is lost);
//   damping: stiffness-proportional, β·kn·A·u̇_n and β·ks·A·v_s, only while
//            the joint is closed (and, in shear, not slipping) — Rayleigh
//            damping of the joint springs as in 3DEC, Table 1's β.
// The total normal force never pulls an unbonded joint together: damping on
// an opening joint is cut at zero force.
// Velocities are at t − dt/2 and positions at t (leapfrog), so u_n and F_s
// are at t and the dissipation increments are exact for the step.
#pragma once

#include "contact/subcontacts.hpp"
#include "core/blocks.hpp"
#include "core/scene_spec.hpp"

namespace polydem {

struct JointLaw {
  double kn = 0, ks = 0;  // Pa/m
  double tan_phi = 0;
  double cohesion = 0;          // Pa
  double tensile_strength = 0;  // Pa
  double beta = 0;              // s
};

JointLaw make_joint_law(const JointSpec& spec);

// Forces of subcontacts [begin, end) into their slots (sub.force/point/...).
void compute_joint_forces(const JointLaw& law, const BlockState& state, Subcontacts& sub, double dt,
                          std::size_t begin, std::size_t end);

// The same for the subcontacts of pairs [pair_begin, pair_end): the hot path.
// The pair's common plane and the two blocks' motion are loaded once.
void compute_pair_forces(const JointLaw& law, const BlockState& state, const std::vector<ContactPair>& pairs,
                         Subcontacts& sub, double dt, std::size_t pair_begin, std::size_t pair_end);

// Elastic strain energy stored in the joints, J.
double joint_strain_energy(const JointLaw& law, const Subcontacts& sub);

}  // namespace polydem
