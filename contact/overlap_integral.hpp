// The Winkler joint integrated exactly over the current overlap of two blocks.
//
// What is integrated. A joint between two rigid blocks is modelled as a thin
// elastic layer of normal stiffness kn (Pa/m) lying on a plane of unit
// normal n, the Winkler foundation: each point of the layer carries a
// pressure kn·t proportional to the local overlap t, independently of its
// neighbours. Block A (the reference block) lies below the plane, block B (the
// incident block) above; n points out of A into B and is chosen by the caller,
// who keeps it for the pair from step to step. For a point ξ of the plane,
//   top_A(ξ) = the highest point of A along n above ξ,
//   bot_B(ξ) = the lowest point of B along n above ξ,
//   t(ξ)     = top_A(ξ) − bot_B(ξ),          the local overlap (penetration),
//   Ω        = {ξ in both shadows : t(ξ) > 0}, the joint's contact region.
// The layer's pressure kn·t pushes B along +n and A along −n, and its strain
// energy is W = ½ kn ∫_Ω t² dA. The force is a function of the blocks' pose
// alone: nothing is sampled, nothing is carried from the previous step.
//
// How. top_A is made of A's faces with n_f·n > 0 (its upper hull along n),
// bot_B of B's faces with n_f·n < 0; faces perpendicular to n (within 1e-9)
// project to segments and carry nothing. Over each cell of the overlay of a projected
// face a of A and a projected face b of B both heights are linear, so t is
// linear and the cell's part of Ω,
//   Q_ab = proj(a) ∩ proj(b) ∩ {t_ab ≥ 0},
// is a convex polygon. Each Q_ab is built by clipping proj(a) by the edges of
// proj(b) (Sutherland–Hodgman) and then by the half-plane t ≥ 0; heights are
// interpolated along the edges they lie on (A's along a's edges, B's along
// b's), and B's plane is evaluated only at a's vertices inside proj(b), then
// clamped to b's height range, which it lies in exactly. Pairs of faces that
// cannot overlap (disjoint bounding boxes of their shadows, or a's highest
// vertex not above b's lowest) are skipped: the skip only removes exact
// zeros, there is no threshold on area or angle. Every vertex of both blocks
// near the plane is in some cell: a corner of a third face of B that dips
// into A is counted as much as the face the caller thinks of as incident.
//
// The integrals, over a fan of triangles (ξ_0, ξ_1, ξ_2) of each convex Q_ab,
// with triangle area A_T and nodal overlaps t_i (exact for linear fields):
//   ∫ f g dA = A_T/12 · (Σ f_i g_i + Σ f_i · Σ g_j),  f, g ∈ {1, t, ξ}.
// So ∫t dA = A_T·Σt_i/3, ∫t² dA = A_T/12·(Σt_i² + (Σt_i)²), ∫tξ dA =
// A_T/12·(Σt_iξ_i + Σt_i·Σξ_j), and likewise ∫ξ and ∫ξξᵀ. These are the
// linear finite element's consistent nodal loads summed (as in mortar
// contact): the resultant force and both tilting moments are exact.
//
// What the caller gets. The normal force on B is kn·∫t dA along n; it acts at
// the pressure centroid ∫tξ/∫t; the moment about any point follows from ∫t
// and ∫tξ; the strain energy is ½ kn ∫t² dA; the joint's normal stiffness
// d(force)/d(approach) is kn·area(Ω), and its rocking stiffness follows from
// ∫ξξᵀ (the polar moment J about the pressure centroid, and the moment of a
// linear velocity field for a dashpot). joint_load() turns the moments into
// force, moment and energy.
//
// Continuity. Every output is a continuous function of the two poses (Ω
// moves continuously; clipping and fans add only zero-area pieces at
// degeneracies), so a face contact that tilts onto an edge and then a corner
// passes through without a jump in force or stiffness. The force then scales
// as depth for a face, depth² × edge length for an edge (the layer indented
// by a wedge) and depth³ for a corner (by a pyramid). ∫t, ∫tξ and ∫t² are
// Lipschitz in the pose with constants of the scene's size; the area and
// ∫ξ, ∫ξξᵀ are Lipschitz where the two surfaces meet at an angle, and
// continuous (not Lipschitz) as the angle between parallel faces goes to zero
// with the zero line inside the face.
//
// Degeneracies. Faces perpendicular to n, collinear edges of neighbouring
// stones, coincident vertices and zero-area cells give zero contributions:
// every division is by a difference of strictly opposite signs (clipping) or
// by n_f·n > 0 with the result clamped to the face's height range, so no NaN
// can arise. Separated blocks (A's highest vertex not above B's lowest) return
// exact zeros.
//
// Frame and precision. The outputs are in a 2D frame of the plane (a
// JointFrame: origin o, in-plane unit axes e1, e2 with e1 × e2 = n); ξ are
// coordinates about o. Second moments lose relative precision as |ξ|²/size²
// when o is far from the contact: put o near the contact (a point of the
// joint, the midpoint of the two blocks' centres), and keep it for the pair.
//
// References. Winkler foundation: E. Winkler, Die Lehre von der Elasticität
// und Festigkeit (1867). Common-plane joints between rigid blocks: P. A.
// Cundall, Formulation of a three-dimensional distinct element model, Part I
// (IJRMMS 25, 1988); R. Hart, P. A. Cundall, J. Lemos, Part II (IJRMMS 25,
// 1988). Contact representation and its stiffness in masonry block models:
// J. V. Lemos, Contact representation in rigid block models of masonry
// (IJMRI 2, 2017). Consistent nodal loads over clipped overlap polygons: the
// mortar method (M. A. Puso, T. A. Laursen, CMAME 193, 2004).
#pragma once

#include "contact/contact_patch.hpp"

#include <vector>

namespace polydem {

using Mat2 = Eigen::Matrix2d;

// The joint's plane and its in-plane axes, all world: e1, e2, n orthonormal
// and right-handed (e1 × e2 = n); the plane passes through `origin`.
struct JointFrame {
  Vec3 origin = Vec3::Zero();
  Vec3 e1 = Vec3::UnitX(), e2 = Vec3::UnitY(), n = Vec3::UnitZ();
};

// A frame for unit normal n about `origin`; e1 is built from the coordinate
// axis least aligned with n (a fixed rule, so the same n gives the same frame).
JointFrame make_joint_frame(const Vec3& n, const Vec3& origin);

// The joint's integrals over Ω; ξ are plane coordinates (ξ·e1, ξ·e2) about
// the frame's origin, t the overlap (m).
struct OverlapMoments {
  double area = 0;                       // ∫ dA, m²
  double volume = 0;                     // ∫ t dA, m³ (the overlap volume of the layer)
  double overlap_squared = 0;            // ∫ t² dA, m⁴
  Vec2 area_moment = Vec2::Zero();       // ∫ ξ dA, m³
  Vec2 volume_moment = Vec2::Zero();     // ∫ t ξ dA, m⁴
  Mat2 area_inertia = Mat2::Zero();      // ∫ ξ ξᵀ dA, m⁴
  double max_overlap = 0;                // largest t over Ω, m (0 when Ω is empty)
  int cells = 0;                         // face pairs with a non-empty clipped polygon
  // B's surface slopes over the cells, for the layer's exact (conservative)
  // load (joint_load): with h_B(ξ) = h0 + g·ξ on a cell,
  Vec2 slope_volume = Vec2::Zero();      // Σ g ∫t dA, m³
  double slope_twist = 0;                // Σ (g₂ ∫tξ₁ − g₁ ∫tξ₂) dA, m⁴
  Vec2 height_volume = Vec2::Zero();     // Σ g ∫t h_B dA, m⁴
  // Where Ω ends on an edge of B's lower hull (B's silhouette) with t > 0:
  // ∫t²ν ds, ∫t²(ξ × ν)·n ds and ∫t² h_B ν ds along those sides, ν their
  // outward normal in the plane.
  Vec2 rim_force = Vec2::Zero();         // m³
  double rim_twist = 0;                  // m⁴
  Vec2 rim_height = Vec2::Zero();        // m⁴
};

// A face of A and a face of B whose cell may be non-empty.
struct FacePair {
  int a, b;
};

// Buffers reused across calls (one per thread): no allocation once warmed up.
struct OverlapScratch {
  struct FaceShadow {
    int face;                        // face index in its block
    double xmin, xmax, ymin, ymax;   // bounding box of the projected face
    double hmin, hmax;               // height range along n
    double m1, m2, mn;               // face normal in the frame (e1, e2, n)
  };
  struct Node {
    double x, y;     // plane coordinates
    double ha, hb;   // heights of A's and B's face above (x, y)
    double t;        // ha − hb, once both are known
    int b_edge;      // edge of proj(b) the node lies on, −1: a vertex of proj(a)
  };
  std::vector<double> xa, ya, ha, xb, yb, hb;  // vertices in the frame
  std::vector<FaceShadow> top_a, bottom_b;     // A's faces facing +n, B's facing −n
  std::vector<Node> poly, next;
  std::vector<double> bx, by, bh;              // proj(b), counter-clockwise
  std::vector<FacePair> face_pairs;            // overlap_face_pairs' callers' buffer
  std::vector<char> b_lower;                   // per face of B: in its lower hull
};

// The integrals of the Winkler joint between A (below) and B (above) on the
// plane of `frame` (n out of A into B).
OverlapMoments overlap_integral(const PosedBlock& a, const PosedBlock& b, const JointFrame& frame,
                                OverlapScratch& scratch);

// The plane point (world) of ξ.
Vec3 plane_point(const JointFrame& frame, const Vec2& xi);

// The pressure centroid ∫tξ/∫t in plane coordinates (the frame's origin when
// Ω is empty).
Vec2 pressure_centroid(const OverlapMoments& m);

// The face pairs of A and B that can have a cell while the blocks move
// relative to each other by less than `reach` (m) and the normal n (world)
// turns with A by less than a hundredth of a radian: every pair but those
// whose shadows' discs (about their vertices' mean, so whatever the in-plane
// axes) are farther apart than `reach`, whose heights are `reach` apart, or
// whose faces face away. Sorted by A's face, then B's.
void overlap_face_pairs(const PosedBlock& a, const PosedBlock& b, const Vec3& n, double reach,
                        std::vector<FacePair>& out, OverlapScratch& scratch);

// overlap_integral over the cells of the face pairs [begin, end) (sorted by
// A's face) only: the same integrals, to the bit, while every non-empty cell
// is among them.
OverlapMoments overlap_integral(const PosedBlock& a, const PosedBlock& b, const JointFrame& frame,
                                const FacePair* begin, const FacePair* end, OverlapScratch& scratch);

// Polar moment of area of Ω about the plane point c: ∫|ξ − c|² dA, m⁴.
double polar_moment(const OverlapMoments& m, const Vec2& c);

// What the layer does to B: the load whose work is exactly the loss of the
// strain energy W = ½ kn ∫t² as B moves (n fixed in A). Moving B changes
// t(ξ) by its motion along n and, where B's surface is sloped (∇h_B = g),
// by its motion along the slope; so the load is a pressure kn·t acting
// along n − g at B's surface point above ξ (normal to B's face, kn·t per
// unit of the face's area along n):
//   force  = kn·(∫t·n − Σ g ∫t),
//   moment = kn·∫t·(ξ + h_B·n − about) × (n − g) dA,
// integrated exactly from the cells' sums, and where Ω ends on B's
// silhouette with t > 0 (a side moving with B) the rim's −½kn∮t²ν ds at
// B's surface there. On a flat face (g = 0) inside the other it is kn·∫t
// along n at the pressure centroid. A receives −force and −moment
// (about the same point): W depends on the blocks' relative pose only, so
// the pair's load does no work in a rigid motion of both and its work in any
// relative motion is −dW. Also the strain energy ½ kn ∫t².
struct JointLoad {
  Vec3 force = Vec3::Zero();   // on B, N
  Vec3 moment = Vec3::Zero();  // on B about `about`, N·m
  double energy = 0;           // J
  double stiffness = 0;        // kn·area(Ω), N/m
};
JointLoad joint_load(const OverlapMoments& m, const JointFrame& frame, double kn, const Vec3& about);

}  // namespace polydem
