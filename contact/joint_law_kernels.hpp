// The joint law four subcontacts at a time: the kernels' interface.
//
// A pair's subcontacts share the common plane and both blocks' motions;
// joint_law.cpp works those out once per pair into a PairFrame, and a kernel
// runs the pair's subcontacts in lanes of four (a face on a face makes four:
// one load per component). The kernels are written once
// (joint_law_kernel.inc) over a lane type (core/code_path.hpp) and compiled
// three times: in plain doubles (every machine), in AVX2 lanes and for
// AVX-512VL (the same 256-bit lanes in 32 registers), chosen at run time
// (core/code_path.hpp). Each lane type performs the same IEEE operations in
// the same order, so a run gives the same bits whichever the machine takes,
// on one thread or two (tests/contact/joint_law_lanes_test.cpp,
// tests/verification/determinism_test.cpp).
#pragma once

#include <cstddef>
#include <cstdint>

namespace polydem {

// A joint's law: its stiffnesses, strength and dashpots (contact/joint_law.hpp
// make_joint_law makes it from a deck's [joint]).
struct JointLaw {
  double kn = 0, ks = 0;  // Pa/m
  double tan_phi = 0;
  double cohesion = 0;          // Pa
  double tensile_strength = 0;  // Pa
  double beta = 0;              // s
  // The Coulomb cap on the normal force with its dashpot's (closing) part,
  // not the spring's alone ([joint] friction_normal_force = "total").
  bool friction_on_total = false;
  // New joints of this law start bonded (cohesion or tension).
  bool bonds() const { return cohesion > 0 || tensile_strength > 0; }
};

}  // namespace polydem

namespace polydem::lanes {

// Which dashpots of a subcontact act (the split damping scheme's state per
// subcontact, integrators/split_damping.hpp).
enum DashpotState : std::uint8_t { kNormalDashpot = 1, kShearDashpot = 2 };

// What a pair's subcontacts share, in the world frame; matrices column-major
// (Eigen's storage, m(i, j) = m[i + 3j]).
struct PairFrame {
  double n[3];       // the common plane's unit normal, from the reference block
  double plane;      // n·x_ref
  double xc[3];      // the incident block's centre
  double Rc[9];      // the incident block's rotation
  double dv[3];      // v_inc − v_ref
  double wc[3];      // the incident block's angular velocity
  double wr[3];      // the reference block's
  double xcr[3];     // x_inc − x_ref
  double spin[9];    // the joint's rotation over the last step (joint_law.hpp)
};


// The subcontact arrays the law reads and writes (Subcontacts' storage).
struct SubcontactArrays {
  const double *ipx, *ipy, *ipz;  // inc_point_local
  const double* offset;           // ref_offset_local
  const double* area;
  std::uint8_t* bonded;
  double *sfx, *sfy, *sfz;  // shear_force
  double *dfx, *dfy, *dfz;  // damping_force
  double* slip_energy;
  double* damping_energy;
  double* overlap;
  double* normal_force;
  double* point;  // Vec3 array: x y z per subcontact
  double* force;  // Vec3 array
  // The split damping scheme's per-subcontact dashpot state (DashpotState
  // bits, joint_law.hpp), written only when not null.
  std::uint8_t* dashpot = nullptr;
};

// The law for subcontacts s0 .. s0 + count − 1 of one pair. Bonded flags
// are read as nonzero and written as 0 or 1 (the only values the rest of the
// code writes). The AVX2 and AVX-512VL kernels only where the CPU has them
// (lanes_available(), wide_lanes_available()).
// `law.beta`: the part of the dashpots applied here (the split scheme's
// 1 − θ of them).
void pair_law_portable(const PairFrame& f, const JointLaw& law, double dt, const SubcontactArrays& a, std::size_t s0,
                       std::size_t count);
void pair_law_avx2(const PairFrame& f, const JointLaw& law, double dt, const SubcontactArrays& a, std::size_t s0,
                   std::size_t count);
void pair_law_avx512(const PairFrame& f, const JointLaw& law, double dt, const SubcontactArrays& a, std::size_t s0,
                     std::size_t count);

using PairLawKernel = void (*)(const PairFrame&, const JointLaw&, double, const SubcontactArrays&, std::size_t,
                               std::size_t);

// The split damping scheme's second pass for one pair (joint_law.hpp
// apply_dashpot_rest): what the pair's subcontacts share, with the blocks'
// predicted velocities, and the arrays it reads and writes. Its result is
// the pair's: the rest force on the incident block and its moment about
// each block's centroid, each summed over the pair's subcontacts in a fixed
// order (lane k takes subcontacts k, k + 4, …; then (l0 + l1) + (l2 + l3)).
struct RestFrame {
  double n[3];       // the common plane's unit normal
  const double* Rc;  // the incident block's rotation (the state's)
  double xcr[3];     // x_inc − x_ref
  double dv[3];      // v_inc − v_ref, predicted
  double wc[3];      // the incident block's predicted angular velocity
  double wr[3];      // the reference block's
  double cn, cs;     // θ·β·kn, θ·β·ks
};
struct RestArrays {
  const double *ipx, *ipy, *ipz;  // inc_point_local
  const double* area;
  const std::uint8_t* bonded;
  const std::uint8_t* dashpot;  // DashpotState
  double* normal_force;
  double *rx, *ry, *rz;  // the rest force per subcontact (0 where no dashpot acts), for the records
};
// Out: force[3] on the incident block, moment[3] about its centroid,
// moment_ref[3] of the reaction about the reference block's centroid.
struct PairRest {
  double force[3], moment[3], moment_ref[3];
};
void pair_rest_portable(const RestFrame& f, const RestArrays& a, std::size_t s0, std::size_t count, PairRest& out);
void pair_rest_avx2(const RestFrame& f, const RestArrays& a, std::size_t s0, std::size_t count, PairRest& out);
void pair_rest_avx512(const RestFrame& f, const RestArrays& a, std::size_t s0, std::size_t count, PairRest& out);
using PairRestKernel = void (*)(const RestFrame&, const RestArrays&, std::size_t, std::size_t, PairRest&);

// The kernels of `path` (core/code_path.hpp) on this machine.
struct JointLawKernels {
  PairLawKernel law;
  PairRestKernel rest;
};

}  // namespace polydem::lanes
