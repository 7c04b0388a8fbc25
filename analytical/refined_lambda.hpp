#pragma once
// Model 2 of issue 4: the static collapse multiplier λ on the real block
// geometry of the spire (structures/spire.hpp), refining eq. 1-2.
//
// A mechanism is a rigid set of whole blocks rotating about a pivot axis on
// the base under the self-weight and a horizontal body force λ·m·g in the
// load direction d (the equivalent static force of a ground acceleration
// −λ g d). The pivot axis is horizontal, perpendicular to d, through the
// extreme point of the spire's bottom bed in direction d (the outer bottom
// edge of the face whose normal is d, or the corner in a corner direction).
// Moment equilibrium about that axis:
//
//     λ = Σ m_i (p_d − d·c_i) / Σ m_i (c_z,i − z_p)
//
// (restoring lever over height of each centroid c_i; p_d = d·pivot, z_p its
// height). The result is the smallest λ over the candidate mechanisms: the
// value the paper calls the refined analytical model (3.2: λ = 0.168). It
// is not proved to bound the collapse multiplier of the block model either
// way: a part rotating rigidly about one base pivot leaves its neighbours
// across inclined joints (mitres, the stepped crack's risers), where the
// relative motion has a sliding component that the kinematic theorem's
// no-sliding assumption excludes and Coulomb friction resists; and the
// search tries only the families below. The DEM's threshold moves with the
// friction angle while this value cannot (README, "Analytical models against
// the DEM"): compare with the DEM, not as a bound.
//
// A mechanism is admissible only if it contains a pivot block (one touching
// the pivot axis): a part that does not reach the pivot would rotate while
// hanging off the blocks beneath it, and with separation allowed any such
// lift-off costs no work in the limit (λ → 0): not a collapse mode.
//
// Crack families (both searched exhaustively, per direction):
//   plane    the crack is the plane through the pivot axis inclined at β
//            from the horizontal, rising away from the pivot (towards −d);
//            the moving part is every block whose centroid lies above it.
//            β_i = atan2(c_z − z_p, p_d − d·c_i) is the angle at which block i
//            leaves the part, so the distinct parts are the blocks sorted by
//            β_i: every one of them is evaluated (no β grid).
//   plane-cover  the same planes, but a block is in the part as soon as any
//            of its vertices is above the plane (the crack passes beneath
//            every block the plane cuts). Near the pivot the centroid rule
//            drops the lowest front stones while the plane still cuts them,
//            which ends the plane family at a shallow β; this one runs up
//            to the plane tangent to the pivot face.
//   stepped  the crack follows the joints: on face f the moving part is the
//            blocks of course ≥ c_f, with c_f = round(n · w_f), w_f ∈ [0, 1]
//            the face's angular distance from the pivot face(s) around the
//            octagon (0 on the face(s) at the pivot, 1 on the face opposite),
//            and n = 0..4 n_courses the crack's course on the trailing side,
//            c_f capped at n_courses (past n_courses whole faces leave the
//            part, from the back). The front is cracked from the base (it
//            carries the pivot); the tip is always in the part. n = 0 is the
//            whole spire.
#include <string>
#include <vector>

#include "analytical/constants.hpp"
#include "structures/spire.hpp"

namespace polydem::analytical {

// A horizontal load direction: azimuth from +x, counter-clockwise.
struct LoadDirection {
  std::string name;      // "face 0" (the normal of face 0) or "corner 0/1"
  double azimuth = 0.0;  // rad
};

// The 16 directions: the 8 face normals and the 8 corner directions.
std::vector<LoadDirection> spire_load_directions();

enum class CrackFamily { plane, plane_cover, stepped };
const char* to_string(CrackFamily f);

struct Mechanism {
  CrackFamily family = CrackFamily::plane;
  LoadDirection direction;
  bool admissible = false;  // contains a pivot block
  double lambda = 0.0;      // restoring / overturning moment; NaN if not admissible
  // plane: the part is the set above the crack plane for every β in
  // (beta_low, beta_high] [rad]; beta_at = the β asked for (plane_crack_mechanism)
  double beta_low = 0.0, beta_high = 0.0;
  // stepped: the trailing course n and the first moving course per face 0..7
  int trailing_course = -1;
  std::vector<int> face_course;
  std::vector<std::size_t> blocks;  // indices into SpireModel::blocks
  double mass = 0.0;                // kg
  Vec3 centroid = Vec3::Zero();     // of the moving part, m
  Vec3 pivot = Vec3::Zero();        // a point of the pivot axis (on the axis line through d), m
  double restoring_moment = 0.0;    // Σ m g (p_d − d·c), N m
  double overturning_moment = 0.0;  // Σ m g (c_z − z_p) per unit λ, N m
};

struct RefinedLambdaOptions {
  double g = standard_gravity;                        // only scales the moments
  std::vector<LoadDirection> directions;   // empty: spire_load_directions()
};

struct RefinedLambdaResult {
  std::vector<Mechanism> plane;        // governing plane crack (centroid rule) per direction
  std::vector<Mechanism> plane_cover;  // governing plane crack (vertex rule) per direction
  std::vector<Mechanism> stepped;  // governing stepped crack per direction
  Mechanism governing;             // the smallest of all
  double total_mass = 0.0;         // of the free blocks (all but the base), kg
  int candidates = 0;              // mechanisms evaluated
};

// Every block has density `density` [kg/m³]. The base block (kind base) never
// moves. Throws std::invalid_argument for a model without free blocks.
RefinedLambdaResult refined_lambda(const SpireModel& model, double density, const RefinedLambdaOptions& options = {});

// One plane crack: the part above the plane of angle beta [rad] through the
// pivot of `direction` (family plane or plane_cover).
Mechanism plane_crack_mechanism(const SpireModel& model, double density, const LoadDirection& direction,
                                double beta, CrackFamily family = CrackFamily::plane, double g = standard_gravity);

// One stepped crack with trailing course n.
Mechanism stepped_crack_mechanism(const SpireModel& model, double density, const LoadDirection& direction,
                                  int trailing_course, double g = standard_gravity);

}  // namespace polydem::analytical
