// Ensembles: N replicas of one deck, each perturbed as little as an engineer
// would still call "the same structure", and the distribution of what they do.
//
// A masonry structure under strong motion is chaotic: a rocking body's
// impacts, a stone's slip and the opening of a joint turn on differences far
// below what anyone knows of the structure, so one run is one sample. An
// ensemble runs the deck N times with seeded perturbations of the values
// nobody knows to that precision ([ensemble] in docs/deck.md, the reasons in
// docs/ensembles.md):
//   - every joint law's friction angle  φ + δφ, δφ uniform in ±friction_angle;
//   - its normal and shear stiffness   kn·(1 + εn), ks·(1 + εs), each ε
//     uniform in ±stiffness (one draw each, for every law);
//   - each free block's initial velocity: a direction uniform on the sphere,
//     a speed uniform in [0, velocity), added to the deck's;
//   - the ground motion's start time   t0 + u·time_shift·Δ, u uniform in
//     [0, 1), Δ the record's sample step (its duration over its intervals)
//     or sample_step for pulses, ramps and constants; every component by the
//     same shift (one earthquake).
// Replica 0 is the deck as written; the reader drops the [[check]]s of
// replicas k > 0 (they test the deck as written against its theory). Replica k of seed S draws from its own
// stream, analytical::RandomStream(mix_seed(S, k)), in the order above
// (friction, kn, ks, shift, then three numbers per free block in deck
// order), so it is the same on every machine and does not depend on which
// other replicas run or where.
//
// What an ensemble reports (summarise_ensemble): the count of each
// assessment status and collapse mode, and per outcome the median and the
// 16th and 84th percentiles (Hyndman & Fan type 7: linear interpolation
// between order statistics at (n − 1)q, numpy's default) over the replicas
// that measured it; runs that ended unstable or in error are counted but
// measure nothing.
#pragma once

#include "core/scene_spec.hpp"
#include "studies/point_result.hpp"

#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace polydem {

// Replica `replica` of `seed` with the sizes of spec.ensemble: what was
// drawn and the initial velocity added to each block (zero unless free).
struct Perturbation {
  EnsembleDraw drawn;
  std::vector<Vec3> velocity;  // per block of spec.blocks
};
Perturbation draw_perturbation(const SceneSpec& spec, long replica, std::uint64_t seed);
void apply_perturbation(SceneSpec& spec, const Perturbation& p);

// Δ: the sample step the ground motion's shift is a fraction of.
double motion_sample_step(const SceneSpec& spec);

// The key of a replica's override and the sweep axis of an ensemble.
inline constexpr const char* kReplicaKey = "ensemble.replica";
inline constexpr const char* kSeedKey = "ensemble.seed";

struct Distribution {
  long n = 0;  // replicas that measured it
  double p16 = std::numeric_limits<double>::quiet_NaN();
  double median = std::numeric_limits<double>::quiet_NaN();
  double p84 = std::numeric_limits<double>::quiet_NaN();
};
// NaN values are left out; n = 0 gives NaNs.
Distribution distribution(std::vector<double> values);

// An outcome of a run as the ensemble reads it from its PointResult (NaN:
// not measured by that run).
struct EnsembleQuantity {
  const char* name;  // column stem, e.g. "peak_tip_displacement_m"
  double (*of)(const PointResult&);
};
std::span<const EnsembleQuantity> ensemble_quantities();

// A course's walking over the replicas (output.walking; run/walking.hpp):
// the distribution of each of its figures, as course_quantities() names them.
struct CourseDistribution {
  double level = 0;  // m, the course's bed level at t = 0
  int bed_joints = 0, vertical_joints = 0;
  std::vector<Distribution> quantities;
};
struct CourseQuantity {
  const char* name;  // column stem, e.g. "residual_vertical_mean_m"
  double (*of)(const CourseWalking&);
};
std::span<const CourseQuantity> course_quantities();

struct EnsembleOutcome {
  long replicas = 0;
  std::vector<std::pair<std::string, long>> status_counts;  // by status, alphabetical
  long mode_I = 0, mode_II = 0;                              // collapses by mode
  std::vector<Distribution> quantities;                      // as ensemble_quantities()
  // Per course from the bottom, over the replicas that measured it with the
  // first such replica's courses (every replica has the same initial mesh).
  std::vector<CourseDistribution> courses;
};
EnsembleOutcome summarise_ensemble(const std::vector<PointResult>& replicas);

}  // namespace polydem
