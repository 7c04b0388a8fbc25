// Automatic critical time step for explicit central differences.
//
// For each free block we bound its highest natural frequency on its joints
// by assuming every face is in full contact (the most a block can carry):
// a face point at r (from the centroid) has the spring matrix
// D = kn·n nᵀ + ks·(I − n nᵀ) per unit area, and the block's 6×6 stiffness
// is ∫ [I, −[r]×]ᵀ D [I, −[r]×] dA over its faces (exact for polygons: the
// quadratic terms use each triangle's second moment). Its largest
// mass-normalised eigenvalue is ω_b². A joint between two free blocks can
// vibrate up to √2 faster than one block on a fixed neighbour, so
// ω = √2·max_b ω_b bounds the assembled blocks' highest frequency (proof and
// the exact frequency it bounds: joint_modes.hpp; 1.13-1.41 times it on the
// decks measured). The central-difference limit with stiffness-
// proportional damping ξ = β·ω/2 is dt = (2/ω)(√(1+ξ²) − ξ); the step used
// is that times the safety factor.
//
// The joint bound (simulation.time_step_bound = "joint", StepBound::joint)
// is tighter where the √2 is loose: a joint between free blocks a and b, with
// own parts A and B (each block's side of its spring, the other held),
// stores at most (1 + t)·xᵀAx + (1 + 1/t)·yᵀBy for any t > 0 (Young's
// inequality), so the assembled stiffness is at most the block-diagonal one
// in which block a counts that joint (1 + t) times and b (1 + 1/t) times. With
// t = g_b/g_a, the ratio of the blocks' own frequency bounds, a stiff small
// stone beside a heavy one counts its joint about once, not twice; a joint
// with a fixed or kinematic neighbour counts once (the block bound counts
// every joint twice). The highest eigenvalue over the weighted blocks bounds
// the assembled system's. At the first joints: 1.14× the block bound's step
// on the spire, 1.5× on the 8-drum column (a run of it 1.08×: the all-faces
// start caps both bounds), 0.995× on the semicircular arch (docs/benchmarks.md).
#pragma once

#include "contact/joint_law.hpp"
#include "contact/subcontacts.hpp"
#include "core/blocks.hpp"
#include "core/scene_spec.hpp"

#include <vector>

namespace polydem {

struct CriticalStep {
  double omega_max = 0;  // rad/s
  double damping_ratio = 0;  // ξ at omega_max
  double critical = 0;   // s, without safety factor
  double chosen = 0;     // s
  int governing_block = -1;
};

// `scheme`: the explicit dashpots' limit above, or the split scheme's
// W(ξ)/ω (split_damping.hpp), which allows up to the springs' 2/ω. Every
// function below takes it the same way.
// `stiffest`: the stiffest law that can act (stiffest_law): its kn and ks
// on every face, its β for the damping.
CriticalStep critical_time_step(const Blocks& blocks, const JointLaw& stiffest, double safety_factor,
                                DampingScheme scheme = DampingScheme::explicit_lagged);

// The step for a highest frequency ω (rad/s) found some other way (e.g.
// joint_modes.hpp): ξ = β·ω/2 with the dashpots' β (s), the limit and the
// chosen step as above; governing_block −1.
CriticalStep critical_step_for(double omega, double beta, double safety_factor,
                               DampingScheme scheme = DampingScheme::explicit_lagged);

// Its inverse: the highest frequency (rad/s) a chosen step `dt` allows with
// the dashpots' β and the safety factor. dt = sf·(2/ω)(√(1+ξ²) − ξ), ξ = βω/2
// gives ω = 2/√(c(c + 2β)), c = dt/sf. The split scheme's by bisection
// (the highest ω whose step allows dt, to 1e-13).
double highest_frequency_for_step(double dt, double beta, double safety_factor,
                                  DampingScheme scheme = DampingScheme::explicit_lagged);

// Each free block's ω_b of the same all-faces bound (rad/s, without the √2
// between free blocks; 0 for blocks that are not free). critical_time_step's
// omega_max is √2 times the largest. The static stage's density scaling
// (Simulation::begin_static_stage) sets every block's inertia so that its
// ω_b is that largest one over √(1 + α) (static_stage.hpp).
std::vector<double> block_frequencies(const Blocks& blocks, const JointLaw& stiffest);

// The same bound from the joints a block actually has: the subcontacts of
// the current detection (closed or still open within the margin, so every
// joint that can close before the next detection is counted), each a spring
// kn·A normal and ks·A tangential at its point. This is the stiffness of the
// discrete model itself (corner subcontacts included), usually well below the
// all-faces bound: spire stones never touch on their outer and inner faces.
// Blocks without subcontacts do not constrain it (they are in flight; a new
// joint is detected before it closes).
//
// `below` > 0 (a detection asking whether its joints need a step below the
// run's): blocks whose frequency bound (Gershgorin) allows `below` skip the
// eigenvalues. When the answer is yes (chosen < below) the result is the same
// as without it; when no, chosen ≥ below (or 0) and the governing block may
// not be the stiffest. 0: every block, the exact estimate. `threads` > 1:
// the blocks in parallel, the same result bit for bit.
//
// `bound`: StepBound::block (√2·max ω_b, above) or StepBound::joint (each
// joint shared by its blocks' stiffness, above); governing_block is the
// block whose weighted stiffness is highest.
//
// Each joint with its own law's kn and ks (JointLaws::between); `beta`: the
// dashpots' β the step is limited by (the stiffest law's, stiffest_law).
//
// `only` (StepBound::block): these blocks alone (ascending; those not free
// are passed over), the blocks whose joints a re-sampling pair by pair has
// just changed; the others' were checked when theirs last changed.
CriticalStep critical_time_step_from_contacts(const Blocks& blocks, const ContactSet& contacts, const JointLaws& laws,
                                              double beta, double safety_factor, double below = 0, int threads = 1,
                                              StepBound bound = StepBound::block,
                                              DampingScheme scheme = DampingScheme::explicit_lagged,
                                              const std::vector<int>* only = nullptr);

// Each free block's ω_b on the joints it has now (the subcontacts of the
// last detection, each law's kn and ks; 0 for blocks without joints). A
// block's subcontacts can be stiffer than its all-faces bound (a face's
// corners carry a quarter of it each: rocking on them is 3 times stiffer than
// on the spread face), so density scaling takes the larger of the two.
std::vector<double> block_frequencies_from_contacts(const Blocks& blocks, const ContactSet& contacts,
                                                    const JointLaws& laws);

}  // namespace polydem
