// The Coulomb joint law, per subcontact (compression positive).
//
// For a subcontact of tributary area A with normal overlap u_n and relative
// shear velocity v_s of the incident block over the reference block:
//   normal:  F_n = kn·A·u_n, no tension unless still bonded (then ≥ −σ_t·A);
//   shear:   F_s ← Q·F_s − ks·A·v_s·dt: the stored force first turns with
//            the joint (Q, below) and is projected onto the current plane,
//            then increments; capped at c·A + F_n·tan φ (slip: the cap is
//            the force, the excess displacement is dissipated, the bond is
//            lost), F_n the spring's force as in 3DEC or, with [joint]
//            friction_normal_force = "total", the spring's and the normal
//            dashpot's (below) where the joint closes, F_n + β·kn·A·u̇_n:
//            at the onset of an impact the dashpot's force is several
//            times the spring's (ξ ≈ 0.8 on the spire), so the two
//            choices differ in how far stones slide at each impact. With
//            "total" the shear dashpot is within the bound too: the joint
//            slips when the spring's trial alone, or the spring's trial
//            and the shear dashpot together, exceed the cap (the dashpot
//            is then off, and the spring keeps its trial up to the cap; a
//            bond is lost as on any slip), so the whole tangential force
//            never exceeds tan φ times the whole normal force. Explicit
//            damping only: the split scheme applies part of the dashpots
//            after the law, beyond any cap;
//   damping: stiffness-proportional, β·kn·A·u̇_n and β·ks·A·v_s, only while
//            the joint is closed (and, in shear, not slipping) — Rayleigh
//            damping of the joint springs as in 3DEC, Table 1's β.
// The total normal force never pulls an unbonded joint together: damping on
// an opening joint is cut at zero force.
// Velocities are at t − dt/2 and positions at t (leapfrog), so u_n and F_s
// are at t.
//
// The joint's spin. The stored shear force is a vector in the joint plane;
// between two steps the plane turns with the reference block, which
// carries the normal, and the joint twists about its normal. Q is the
// rotation by θ = dt·(ω_r + ½((ω_c − ω_r)·n)·n): the reference block's
// rotation over the step (exact: the integrator turns it by ω_r·dt), with
// the twist about the normal taken as the mean of the two blocks' spins
// (the standard incremental update, as PFC and 3DEC). A pair turning as one
// rigid body carries its shear round with it; without Q the force stayed
// fixed in space while the joint turned under it, and projecting onto the
// new plane kept only the tilt (shortening the force by O(θ²) a step).
//
// The dashpot's work. The force F_d(t) computed from the velocity at
// t − dt/2 acts on the blocks from the velocity update at t: over the step
// the integrator moves the joint by dt·v(t), with v(t) the centred velocity,
// the mean of v(t − dt/2) and v(t + dt/2), and the kinetic energy changes by
// exactly dt·F·v(t). So the dissipation is dt·F_d(t)·u̇(t) with the centred
// relative velocity: half booked when the force is computed (with the
// velocity it came from), half at the next step (with the velocity that
// step reads, t + dt/2), the force kept in Subcontacts::damping_force in
// between. Booking it all with the lagged velocity would be first order in
// ξ·ω·dt: across a stiff overdamped impact, where the velocity changes by a
// large fraction in one step, it over-counts the dissipation by percents
// (docs/contact.md).
#pragma once

#include "contact/joint_law_kernels.hpp"
#include "contact/subcontacts.hpp"
#include "core/code_path.hpp"
#include "core/blocks.hpp"
#include "core/scene_spec.hpp"

#include <cstdint>
#include <vector>

namespace polydem {


JointLaw make_joint_law(const JointSpec& spec);

// The laws of a scene's joints, a table by pair of block groups ([[joint]]
// with `between`). laws[0] is the default ([joint]); a joint between blocks
// a and b takes laws[pair_law[block_slot[a]·slots + block_slot[b]]], with
// slot 0 for blocks without a group and 1 + the group's index otherwise. A
// scene with one law is a table of one: one slot, every block in it. Built
// once per run (make_joint_laws) and handed to everything that reads a
// joint's stiffness or strength: the joint law, detection, the time step,
// the checks.
struct JointLaws {
  std::vector<JointLaw> laws;
  int slots = 1;
  std::vector<int> block_slot;  // per block
  std::vector<int> pair_law;    // slots × slots, symmetric

  const JointLaw& between(int a, int b) const {
    return laws[static_cast<std::size_t>(pair_law[static_cast<std::size_t>(block_slot[a] * slots + block_slot[b])])];
  }
  // True when some law bonds new joints (JointLaw::bonds).
  bool any_bonds() const;
};

// The laws of a scene: the default, then one per [[joint]] `between` whose two
// groups both exist among the blocks (an entry for a group without blocks acts
// on no joint and is left out). Block groups: Blocks::props.group.
JointLaws make_joint_laws(const Blocks& blocks, const JointSpec& default_joint,
                          const std::vector<JointPairSpec>& pairs);

// Every joint among `blocks` blocks under one law.
JointLaws uniform_joint_laws(const JointLaw& law, int blocks);

// The laws (indices into laws.laws, ascending) that some joint among the
// blocks marked in `among` (per block; empty: every block) can take: the
// law of every pair of groups present among them (a group with itself when
// it has two blocks there); the default alone when no two blocks are.
std::vector<int> acting_laws(const JointLaws& laws, const std::vector<char>& among = {});

// The stiffest law that can act, for the time step: the largest kn, ks and
// damping β over the laws some pair of the blocks' groups uses (the default
// only if some pair falls to it); its friction and strength are the first
// acting law's.
JointLaw stiffest_law(const JointLaws& laws);

// The split damping scheme (integrators/split_damping.hpp): the joint law
// applies the part `explicit_part` = 1 − θ of every dashpot, and writes each
// subcontact's DashpotState into `dashpot` (when not null) for the pass that
// applies the rest after the velocity update (apply_dashpot_rest). The
// default is the explicit scheme: the whole dashpot, nothing written.
using lanes::DashpotState;
using lanes::kNormalDashpot;
using lanes::kShearDashpot;
struct SplitPart {
  double explicit_part = 1.0;
  std::uint8_t* dashpot = nullptr;  // one per subcontact
};

// The forces of the subcontacts of pairs [pair_begin, pair_end) into their
// slots (sub.force, point, overlap, normal_force, ...), each pair under its
// own law (JointLaws::between). The pair's common plane and the two blocks'
// motion are loaded once. `path` (core/code_path.hpp): the kernel's lane
// type (joint_law_kernels.hpp); the same bits on every one.
void compute_pair_forces(const JointLaws& laws, const BlockState& state, const std::vector<ContactPair>& pairs,
                         Subcontacts& sub, double dt, std::size_t pair_begin, std::size_t pair_end,
                         CodePath path = CodePath::automatic, const SplitPart& split = {});

// The split scheme's second part, pairs [pair_begin, pair_end): each
// subcontact whose DashpotState says its dashpots act takes the rest θ of
// them from the relative velocity of `velocity_next`, `omega_next` (every
// block's velocities after the step's forces, before the blocks move) at its
// point, normal and shear as in the law, the normal force still never
// pulling an unbonded joint together. Each normal part goes into its
// subcontact's normal force, each force into `rest_force` (one per
// subcontact, zero where no dashpot acts: what a record of the joint's
// force adds to the law's); `rest` (one per pair) receives the pair's sum:
// the rest force on the incident block and its moment about each block's
// centroid, which the blocks gather pair by pair onto the law's force (a
// quarter of the entries of a gather by subcontact). Its work is booked
// block by block (Simulation: the rest's force and moment at the blocks'
// centred velocities, the same sum as at the subcontacts'). `path` as the
// law's.
void apply_dashpot_rest(const JointLaws& laws, double theta, const BlockState& state,
                        const std::vector<Vec3>& velocity_next, const std::vector<Vec3>& omega_next,
                        const std::vector<ContactPair>& pairs, const std::uint8_t* dashpot, Subcontacts& sub,
                        std::vector<lanes::PairRest>& rest, Vec3Array& rest_force, std::size_t pair_begin,
                        std::size_t pair_end, CodePath path = CodePath::automatic);

// Books the second half of the last step's dashpot work of every
// subcontact with the relative velocity at its point now (the state's
// velocities, t + dt/2 of that step), and clears the pending force. Called
// before a detection replaces the subcontacts.
void settle_damping_work(const BlockState& state, Subcontacts& sub, double dt);

// Normal strain energy Σ ½·kn·A·u_n² of the subcontacts closed or bonded,
// with u_n evaluated at the blocks' current pose (their body-fixed plane and
// point), J. Detection compares it before and after it re-samples the joints.
double normal_strain_energy_now(const JointLaws& laws, const BlockState& state, const Subcontacts& sub,
                                int threads = 1);
// The same over subcontacts [first, last), serial.
double normal_strain_energy_now(const JointLaws& laws, const BlockState& state, const Subcontacts& sub, int first,
                                int last);
// The dashpot work still owed by subcontacts [first, last) (settle_damping_work).
void settle_damping_work(const BlockState& state, Subcontacts& sub, double dt, int first, int last);

// Re-sampling must not make normal strain. A detection re-clips every joint
// at the pose it finds: the points and tributary areas of a pair's new
// subcontacts differ from the previous ones', and ½·kn·A·u_n² with them,
// while nothing has moved. Usually by little (a crossing appears, a corner's
// fan area changes); but a corner that ploughed into its neighbour while
// the clip gave it a sliver (an area of 1e-4 m², barely resisting) and is
// then found deep under a full polygon would have its whole depth priced at
// once: 61 kJ from one detection in the spire's 1.0 g pulse run, enough to
// throw stones tens of metres (docs/contact.md). So, for each pair found
// again, when its new subcontacts would hold more normal strain at this pose
// than its previous ones, the pair's plane is moved back by the depth δ ≥ 0
// at which they hold exactly as much: Σ ½·kn·A·(u_n − δ)₊² = E_previous (a
// corner crushed by δ, the joint's stiffness from then on its full kn·A).
// The shift lives in the subcontacts' body-fixed plane (ref_offset_local),
// so the step pays nothing for it; the next detection re-clips from the
// geometry and finds the shift again if it is still needed. A re-sampling
// that lowers the strain is left alone (the ledger books what it removed).
// Pairs with a bonded subcontact are left alone too (tension: the strain
// is not monotone in δ), and only the previous compression counts (a broken
// bond's tension is not handed on as compression). A pair found for the first time held no strain:
// if it is found already overlapping (a corner the clip kept outside the
// reference face until it was in: 1.1 and 2.5 kJ in the 1.0 g run), it
// starts at zero force. Only the first detection's pairs (t = 0, the
// structure as built) start from the geometry.
// `sampled` (when given): these pairs of `contacts` alone (ascending), the
// rest having been taken over whole, left alone.
void hold_normal_strain(const JointLaws& laws, const BlockState& state, const ContactSet& old, ContactSet& contacts,
                        int threads = 1, const std::vector<int>* sampled = nullptr);

// Elastic strain energy stored in the joints, J.
double joint_strain_energy(const JointLaws& laws, const Subcontacts& sub);

// Shear strain energy Σ |F_s|²/(2·ks·A) with each subcontact's own ks, J.
double shear_strain_energy(const JointLaws& laws, const Subcontacts& sub);
// The same over subcontacts [first, last).
double shear_strain_energy(const JointLaws& laws, const Subcontacts& sub, int first, int last);

}  // namespace polydem
