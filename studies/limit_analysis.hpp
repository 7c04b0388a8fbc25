// Limit analysis of the block model: the largest horizontal body force that
// the blocks, as they sit at t = 0, can carry in equilibrium with joint
// forces that are compressive and within Coulomb's friction cone. The
// rigid-block equilibrium ("static") linear program of Livesley (1978),
// with friction as in Gilbert, Casapulla & Ahmed (2006).
//
// The model
//   Blocks are rigid. The interfaces are the joints of the initial mesh
//   (run/joint_mesh.hpp's JointMesh: every pair of blocks touching at t = 0
//   within simulation.overlap_tolerance, as polydem's own contact detection
//   finds them): each is a planar convex patch with a unit normal n (out of
//   the reference block, into the incident one) and its polygon's vertices
//   p_k (the subcontacts, projected on the reference plane; points within
//   1e-9 of the patch's size of the hull of the others, collinear or
//   repeated, are dropped as they add only degenerate columns). The joints
//   carry no tension and have no cohesion (the DEM's [joint] cohesion and
//   tensile strength are ignored: the LP is for dry masonry).
//
// Why vertex forces are enough
//   A no-tension distribution of normal stress over a convex polygon, with
//   the shear traction inside the friction cone at every point, has a
//   resultant (force and moment) that non-negative normal forces at the
//   vertices, each with its shear inside the same cone, reproduce exactly:
//   any point of the polygon is a convex combination of its vertices, so a
//   point force f at x = Σ w_k p_k equals the forces w_k f at the p_k in
//   force and in moment (Σ w_k p_k × f = x × f), and the cone is a convex
//   cone, so w_k f stays in it. The converse holds trivially. So the vertex
//   forces lose nothing; only the cone is replaced by a pyramid.
//
// Variables and constraints
//   At vertex k of an interface the force on the incident block is
//       f_k = Σ_j c_kj g_j,   g_j = n + μ_g (cos θ_j t1 + sin θ_j t2),   c_kj ≥ 0,
//   a non-negative combination of the pyramid's k edge rays (generators):
//   normal force Σ_j c_kj ≥ 0 and shear inside the pyramid. t1 is the
//   projection of the load direction d on the joint plane (where it has
//   one; else of "up", else any), t2 = n × t1, θ_j = θ_0 + 2πj/k.
//     inscribed     μ_g = μ = tan φ, θ_0 = 0: the edges lie on the cone; the
//                   pyramid is inside it, exact along d.
//     circumscribed μ_g = μ / cos(π/k), θ_0 = π/k: the faces touch the cone;
//                   it contains the cone, exact along d (a face's middle).
//   The reference block gets −f_k. Every free block i (fixed and kinematic
//   blocks are supports: no equation) is in equilibrium, force and moment
//   about its centroid c_i (6 rows):
//       Σ_k ±f_k + m_i g + λ m_i |g| d = 0,   Σ_k ±(p_k − c_i) × f_k = 0,
//   where g is the scene's gravity and d the unit horizontal direction of
//   the body force (perpendicular to g): λ m |g| d is the static equivalent
//   of a ground acceleration −λ |g| d. Maximise λ (a free variable). Rows are
//   divided by the free blocks' weight W (forces) and W times the mean
//   bounding radius (moments), the c by W.
//
// What the result bounds, and why
//   Statically admissible: a field of vertex forces in equilibrium with the
//   loads at λ, compressive and inside the cone. The LP's λ_cone (exact
//   cone) is the largest λ with such a field.
//   (1) If the rigid blocks, in their initial geometry, can be in
//       equilibrium at λ with joint forces obeying Coulomb's law without
//       tension or cohesion (the DEM's joint law with zero cohesion and
//       tensile strength, as in the spire's decks: its damping force
//       vanishes at rest, its elastic shear force is capped at μ times the
//       normal force, whatever the flow rule, and it acts at the patch
//       vertices, of which the LP keeps the extreme ones), that
//       field is statically admissible, so λ ≤ λ_cone. The circumscribed
//       pyramid contains the cone, so its field set is larger and
//       λ_circumscribed ≥ λ_cone: an upper bound on every λ at which the
//       block model in its initial geometry can stand. (For the DEM this
//       holds up to the change of geometry of its elastic joints, µm here;
//       a DEM run that settles at λ after its blocks have moved
//       millimetres stands on a geometry the LP did not see.)
//   (2) The inscribed pyramid lies inside the cone and contains the cone of
//       friction coefficient μ cos(π/k), so
//           λ_cone(μ cos π/k) ≤ λ_inscribed ≤ λ_cone(μ) ≤ λ_circumscribed ≤ λ_cone(μ / cos π/k).
//       The inscribed value is not a bound on the DEM: only a bracket, with
//       the circumscribed one, of the exact cone's value.
//   (3) Not a lower bound. The static theorem of plasticity (a statically
//       admissible field means the structure does not collapse) needs an
//       associated flow rule: friction that dilates at tan φ. The DEM's
//       Coulomb joint slides without dilatancy, and then the existence of an
//       admissible field does not make the structure stand (Drucker 1954):
//       the block model may collapse below λ_cone.
//   The LP's dual values are virtual velocities of the free blocks (force
//   rows: translation; moment rows: rotation times the moment scale) that
//   make the load do unit work, λ being the work done against gravity; the
//   dual constraint for each generator is g_j · Δu ≥ 0 at each vertex, Δu
//   the relative velocity of incident to reference block: the joint opens
//   or slides with dilatancy n·Δu ≥ μ_g |Δu_t| (over the pyramid). That is
//   the associative (dilatant) mechanism, the kinematic counterpart of the
//   LP, not a mechanism the DEM's joints follow exactly.
#pragma once

#include "core/scene_spec.hpp"

#include <limits>
#include <string>
#include <vector>

namespace polydem {

// One interface of the initial mesh, in world coordinates at t = 0.
struct LimitInterface {
  int ref = 0, inc = 0;          // reference and incident block
  Vec3 normal = Vec3::Zero();    // unit, out of ref into inc
  std::vector<Vec3> vertices;    // the patch's vertices, on the reference plane, m
  bool bed = false;              // normal within 45° of up (against gravity)
};

// The blocks and interfaces the LP is built on.
struct LimitModel {
  std::vector<std::string> names;
  std::vector<double> mass;        // kg
  std::vector<Vec3> centroid;      // m
  std::vector<double> radius;      // bounding radius about the centroid, m
  std::vector<char> free;          // 1: free; 0: fixed or kinematic (a support)
  Vec3 gravity = Vec3::Zero();     // m/s²
  std::vector<LimitInterface> interfaces;
  int vertices = 0;                // Σ over the interfaces
  int redundant_vertices = 0;      // patch points dropped: inside the hull of the others, or repeated
  double detection_seconds = 0;    // building the blocks and the first contact detection
};

// The blocks of the scene at t = 0 and the joints of its initial mesh
// (the blocks built as for a run, the first contact detection, the pairs
// touching within simulation.overlap_tolerance). Throws SceneError (as a
// run would) for blocks overlapping at t = 0, std::invalid_argument when
// gravity is zero or there is no free block.
LimitModel limit_model(const SceneSpec& scene);

enum class FrictionPyramid { inscribed, circumscribed };
const char* to_string(FrictionPyramid p);

// GLPK's interior-point method is the default: on the spire (2406 rows,
// 36k columns) it converges in about 60 iterations and 5 s, while its
// primal simplex, after some 35 000 iterations, cycles through "numerical
// instability" warnings on the degenerate vertices (many carry no force at
// the optimum) and did not finish in 15 minutes. The simplex is kept for
// small models (the tests compare the two).
enum class LpMethod { simplex, interior_point };
const char* to_string(LpMethod m);

struct LimitAnalysisOptions {
  double friction_angle_deg = 30.0;   // φ, degrees, in [0, 90)
  Vec3 direction{1.0, 0.0, 0.0};      // of the body force; its part perpendicular to gravity is used
  int pyramid_sides = 16;             // k ≥ 3 (16: the cone within 2 %)
  FrictionPyramid pyramid = FrictionPyramid::circumscribed;
  double pyramid_rotation = 0.0;      // rad, added to θ_0 (0: exact along d; tests use it)
  LpMethod method = LpMethod::interior_point;
  double motion_tolerance = 1e-4;     // relative to the fastest block: below it a velocity counts as zero
  std::string lp_file;                // when set, the LP is written there first (free MPS, GLPK's glp_write_mps)
};

enum class InterfaceMotion { closed, opening, sliding };
const char* to_string(InterfaceMotion m);

// The mechanism from the LP's dual values: virtual velocities of the free
// blocks (zero for supports), scaled so that the largest block speed
// |v| + |ω| r is 1. An interface slides if the relative velocity at one of
// its vertices has a tangential part above motion_tolerance (the dilatancy
// that comes with it is the associative rule's), opens if only a normal
// part (separation or a hinge), and is closed otherwise.
struct LimitMechanism {
  std::vector<Vec3> velocity, angular_velocity;  // per block
  std::vector<double> speed;                     // per block: |v| + |ω| r, the fastest 1
  std::vector<char> moving;                      // per block: speed above motion_tolerance
  std::vector<InterfaceMotion> motion;           // per interface
  int blocks_moving = 0;
  double mass_moving = 0;  // kg
  int opening = 0, sliding = 0;                  // interfaces
  int opening_bed = 0, sliding_bed = 0;          // of which bed joints
};

enum class LimitStatus { optimal, unbounded, infeasible, failed };
const char* to_string(LimitStatus s);

struct LimitAnalysisResult {
  LimitStatus status = LimitStatus::failed;
  // optimal: the multiplier; unbounded: +inf (λ reached the box the solver
  // is given, [−100, 100], or [−10, 10] on a retry: no mechanism below it);
  // infeasible or failed: NaN (the dead load alone has no admissible field).
  double lambda = std::numeric_limits<double>::quiet_NaN();
  double friction_angle_deg = 0;
  double generator_mu = 0;     // μ_g of the pyramid's edges
  Vec3 direction = Vec3::Zero();  // the unit horizontal d used
  LimitMechanism mechanism;    // when optimal
  // The solution checked against the matrix, when the solver says optimal:
  // the largest equilibrium residual over the free weight or negative force
  // (primal), and the largest violation of the mechanism's conditions (every
  // generator's power ≥ 0 and the load's = 1, relative to the largest dual;
  // its work against gravity = λ). Above 1e-5 the status is `failed`.
  double primal_residual = 0, dual_residual = 0;
  int attempts = 0;            // interior-point solves tried (another ordering, a tighter box on λ)
  int rows = 0, columns = 0;   // columns: λ and the generators
  long nonzeros = 0;
  double build_seconds = 0, solve_seconds = 0;
};

// Solves the LP above for `model`. Throws std::invalid_argument for a bad
// option (naming it), a direction parallel to gravity, or a free block that
// touches nothing (it cannot be in equilibrium).
LimitAnalysisResult limit_analysis(const LimitModel& model, const LimitAnalysisOptions& options);

}  // namespace polydem
