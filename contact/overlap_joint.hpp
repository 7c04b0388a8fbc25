// The overlap joint model: each joint's forces from the exact integral of a
// Winkler layer over the blocks' current overlap (`simulation.joint_model =
// "overlap"`).
//
// Why. The subcontact model (joint_law.hpp) samples a joint at points fixed
// in the blocks between detections, from one clipped pair of faces; its
// force at a given pose depends on when the joint was last sampled, and a
// corner of a face it did not sample ploughs unseen. Here the normal
// pressure is kn·t(ξ) over the region Ω where the two blocks overlap, t the
// local overlap along the joint's normal (contact/overlap_integral.hpp):
// the normal force and both rocking moments are functions of the two
// blocks' poses alone, continuous as a face contact tilts onto an edge and a
// corner, and every face of both blocks takes part. Nothing is sampled, so
// nothing jumps when the contacts are detected again.
//
// The joint, per pair, at every step (velocities at t − dt/2, poses at t):
//   normal:  N = kn·∫t dA along n, at the pressure centroid p = ∫tξ/∫t,
//            where the incident block's surface is flat; where it slopes,
//            the pressure kn·t acts normal to it, and where the region ends
//            on its outline with t > 0 the rim pushes outwards (joint_load):
//            the layer's load is the exact gradient of its strain energy
//            ½·kn·∫t² dA, so it makes no energy of its own.
//   shear:   one elastic shear force F_s in the joint's plane, carried from
//            step to step and turned with the joint as the subcontacts'
//            (joint_law.hpp), incremented by −ks·A·v_s(p)·dt with A the area
//            of Ω and v_s the relative sliding velocity at p; acts at p.
//   twist:   one elastic twisting moment T about n, incremented by
//            −ks·J_p·ω_n·dt, J_p the polar moment of Ω about p and ω_n the
//            relative spin about n: a uniform shear layer twisted rigidly.
//            Where Ω shrinks, F_s and T are first scaled by the ratio of the
//            new area (polar moment) to the old: the layer that left the
//            contact takes its stress with it, and the stored shear energy
//            |F_s|²/(2·ks·A) cannot grow without work (a growing Ω leaves
//            them alone: new contact starts unsheared).
//   friction: (|F_s|/F_max)² + (T/T_max)² ≤ 1 with F_max = c·A + N·tan φ and
//            T_max = r·F_max, r = 0.94·√(J_p/A) the mean distance of Ω's
//            points from p (exact to 1 % for a disc, 0.943, and a square,
//            0.938; 8 % high for a 10:1 strip). An ellipse in place of the
//            exact limit surface of a pressed patch that slides and spins
//            at once (Goyal, Ruina & Papadopoulos, Wear 143, 1991; the
//            ellipsoidal approximation of Howe & Cutkosky, IJRR 15, 1996).
//            Beyond it both are scaled back radially; the friction's work is
//            the force times the slip, s(1 − s)·(|F_t|²/(ks·A) + T_t²/(ks·J))
//            for the trial (F_t, T_t) scaled by s. N is the elastic normal
//            force or, with friction_normal_force = "total", the elastic
//            and viscous one, as in the subcontact law.
//   damping: the stiffness-proportional dashpots of Table 1's β over Ω:
//            the normal pressure −β·kn·v_n(ξ), linear in ξ, gives a force at
//            Ω's centroid and a rocking couple −β·kn·J_c·∇v_n; the shear and
//            twist dashpots −β·ks·A·v_s and −β·ks·J_p·ω_n act while the joint
//            does not slip. The normal dashpot never pulls the pair
//            together: where it would, it is scaled down to the elastic force.
// The reaction on the reference block is equal and opposite along the same
// lines of action, so momentum and angular momentum are conserved.
//
// The joint's plane is the one the detection chose when it first found the
// pair (contact_patch.hpp: a face of one block, its reference block), fixed
// in that block and kept for as long as the pair is found again and the
// joint stays closed on it: a detection that would now prefer the other
// block's face does not move it, so the forces at a pose do not depend on
// when the contacts were last detected. A joint found open at a detection
// (no overlap along its plane, nor along the plane the detection chose)
// takes the plane found then, as does a pair lost beyond the margin and
// found again: both carry no force and no shear, so the change moves
// nothing, and a stone that tumbles meets its neighbours on the faces it
// now presents, not on the plane of the joint it left (a plane kept in the
// reference block while the stones turn past each other measures the
// overlap across them and lets them pass through). The subcontacts are still built: their points, fixed in the
// blocks, sample the joint's opening for the assessment and the records;
// they carry no force.
//
// Scope: joints without cohesion or tensile strength (the layer carries
// compression only) and the explicit damping scheme; a deck asking for
// either with this model is refused.
#pragma once

#include "contact/joint_law.hpp"
#include "contact/overlap_integral.hpp"
#include "contact/subcontacts.hpp"

#include <vector>

namespace polydem {

// The joints of pairs [begin, end): each pair's wrench into joints.wrench
// (force on the block that is not joints.ref_block, moments as PairRest),
// its state and results into the other arrays, and the sampled points'
// positions and openings into sub.point and sub.overlap (their forces are
// zero). `shapes`: the blocks' polyhedra in their body frames.
void overlap_joint_forces(const JointLaws& laws, const std::vector<Polyhedron>& shapes, const BlockState& state,
                          const std::vector<ContactPair>& pairs, Subcontacts& sub, PairJoints& joints, double dt,
                          std::size_t begin, std::size_t end, OverlapScratch& scratch);

// Books the second half of every pair's last dashpot work with the
// velocities now (t + dt/2 of that step) and clears it: before a detection
// replaces the pairs.
void settle_pair_damping(const BlockState& state, const std::vector<ContactPair>& pairs, PairJoints& joints,
                         double dt);

// After a detection: each pair of `current` found in `previous` keeps its
// plane, shear force, twisting moment and dissipation; a new pair takes the
// plane of its patch; the dissipation of pairs that are gone retires into
// current's totals.
void carry_pair_joints(const ContactSet& previous, ContactSet& current);

// After carry_pair_joints: a joint open on its kept plane (no overlap
// along it, so no force and no stored shear) takes the plane this detection
// chose for its pair when that one finds it open too. The number of planes
// changed.
int rechoose_joint_planes(const std::vector<Polyhedron>& shapes, const BlockState& state,
                          const std::vector<ContactPair>& pairs, PairJoints& joints, OverlapScratch& scratch);

// Each pair's face pairs that can meet before the next detection, the
// blocks moving by less than `reach` relative to each other (the margin):
// joints.cell_first and joints.cells.
void find_joint_cells(const std::vector<Polyhedron>& shapes, const BlockState& state,
                      const std::vector<ContactPair>& pairs, const Subcontacts& sub, double reach, PairJoints& joints,
                      OverlapScratch& scratch);

// Sums over the pairs: strain energy at the last step, and the friction and
// dashpot work so far (the retired included), J.
struct PairJointEnergies {
  double strain = 0, slip = 0, damping = 0;
};
PairJointEnergies pair_joint_energies(const ContactSet& contacts);

}  // namespace polydem
