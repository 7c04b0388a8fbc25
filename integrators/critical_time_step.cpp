#include "integrators/critical_time_step.hpp"

#include "integrators/split_damping.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <utility>

namespace polydem {

namespace {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec6 = Eigen::Matrix<double, 6, 1>;

// Contribution of a face point at r with weight w to the 6×6 stiffness.
void add_point(Mat6& K, const Mat3& D, const Vec3& r, double w) {
  const Mat3 X = cross_matrix(r);  // rotation θ gives displacement θ×r = −X·θ
  K.block<3, 3>(0, 0) += w * D;
  K.block<3, 3>(0, 3) += -w * D * X;
  K.block<3, 3>(3, 0) += -w * X.transpose() * D;
  K.block<3, 3>(3, 3) += w * X.transpose() * D * X;
}

// 1/√m three times, then 1/√I of each principal axis: the scaling that
// turns a block's stiffness into its mass-normalised one.
Vec6 inv_sqrt_mass(const Blocks& b, int i) {
  Vec6 inv_sqrt_m;
  const double m = b.props.mass[i];
  const Vec3& I = b.props.principal_inertia[i];
  inv_sqrt_m << 1 / std::sqrt(m), 1 / std::sqrt(m), 1 / std::sqrt(m), 1 / std::sqrt(I.x()), 1 / std::sqrt(I.y()),
      1 / std::sqrt(I.z());
  return inv_sqrt_m;
}

// Largest ω² of one block's 6×6 stiffness K against its mass and inertia.
double block_omega_squared(const Blocks& b, int i, const Mat6& K) {
  const Vec6 inv_sqrt_m = inv_sqrt_mass(b, i);
  const Mat6 Kn = inv_sqrt_m.asDiagonal() * K * inv_sqrt_m.asDiagonal();
  Eigen::SelfAdjointEigenSolver<Mat6> eig(Kn, Eigen::EigenvaluesOnly);
  return std::max(0.0, eig.eigenvalues().maxCoeff());
}

// A joint between two free blocks can vibrate up to √2 faster than the
// block on a fixed neighbour (see the header): ω = √(2 ω_b²) for the block
// bound; the joint bound's weights are already in its ω² (factor 1).
void keep_highest(CriticalStep& out, int i, double omega_b_squared, double factor = 2.0) {
  const double w = std::sqrt(factor * omega_b_squared);
  if (w > out.omega_max) {
    out.omega_max = w;
    out.governing_block = i;
  }
}

void finish(CriticalStep& out, double beta, double safety_factor, DampingScheme scheme) {
  if (out.omega_max <= 0) return;
  const double xi = 0.5 * beta * out.omega_max;
  out.damping_ratio = xi;
  if (scheme == DampingScheme::split) {
    out.critical = split_damping(xi).limit / out.omega_max;
  } else {
    out.critical = (2.0 / out.omega_max) * (std::sqrt(1.0 + xi * xi) - xi);
  }
  out.chosen = safety_factor * out.critical;
}

}  // namespace

CriticalStep critical_step_for(double omega, double beta, double safety_factor, DampingScheme scheme) {
  CriticalStep c;
  c.omega_max = omega;
  finish(c, beta, safety_factor, scheme);
  return c;
}

double highest_frequency_for_step(double dt, double beta, double safety_factor, DampingScheme scheme) {
  const double c = dt / safety_factor;
  const double explicit_omega = 2.0 / std::sqrt(c * (c + 2.0 * beta));
  if (scheme != DampingScheme::split || !(beta > 0)) return explicit_omega;
  // Asked again and again for the run's step at each detection: the last
  // answer of this thread kept.
  thread_local double last_dt = -1, last_beta = -1, last_sf = -1, last_omega = 0;
  if (dt == last_dt && beta == last_beta && safety_factor == last_sf) return last_omega;
  // The split step W(βω/2)/ω falls as ω rises, from the explicit one's
  // (W ≥ the explicit limit) to at most the springs' 2/ω: bisect between
  // the two frequencies, keeping the side whose step allows dt.
  double lo = explicit_omega, hi = 2.0 / c;
  for (int it = 0; it < 100 && hi - lo > 1e-13 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    (split_damping(0.5 * beta * mid).limit / mid >= c ? lo : hi) = mid;
  }
  last_dt = dt;
  last_beta = beta;
  last_sf = safety_factor;
  last_omega = lo;
  return lo;
}

namespace {

// The step finish() would choose for ω (falls as ω rises).
double chosen_for(double omega, double beta, double safety_factor, DampingScheme scheme) {
  return critical_step_for(omega, beta, safety_factor, scheme).chosen;
}

// An upper bound of block i's ω_b² (block_omega_squared): the largest
// Gershgorin row sum of its mass-normalised stiffness, with a margin far
// above round-off. A few dozen operations against the eigensolver's
// thousands.
double omega_squared_bound(const Blocks& b, int i, const Mat6& K) {
  const Vec6 inv_sqrt_m = inv_sqrt_mass(b, i);
  double top = 0;
  for (int r = 0; r < 6; ++r) {
    double row = 0;
    for (int c = 0; c < 6; ++c) row += std::abs(K(r, c)) * inv_sqrt_m(c);
    top = std::max(top, row * inv_sqrt_m(r));
  }
  return top * (1 + 1e-9);
}

}  // namespace

namespace {

// With `below` > 0 only the question "does some block need a step below
// `below`?" matters (a detection lowering the run's step): a block whose
// frequency bound already allows `below` cannot be the answer and skips its
// eigenvalues. When some block needs a lower step the result is exactly the
// full one (the stiffest block is among those computed); otherwise it may
// report a block that does not govern, with chosen ≥ below (or 0: none).
// Asked for every block's frequency (`per_block`), it skips none.
//
// The joint bound (StepBound::joint) takes two passes over the blocks: the
// first bounds each block's own ω_b² (Gershgorin, neighbours held), the
// second weights each joint with a moving neighbour by 1 + g_other/g_self
// (its share, header) and takes the eigenvalues of the weighted stiffness;
// joints with a fixed or kinematic neighbour keep weight 1. Any positive
// ratio gives a proved bound; Gershgorin's is cheap and gives within 1 % of
// the bound with the ratio of the blocks' exact ω_b² (joint_modes.hpp's
// split_bound: the spire 0.997 of it, the 52-stone wall 1.001, the 8-drum
// column 1.008, the arch 1.004; JointModes tests the spire and the column).
template <class StiffnessOf>
CriticalStep from_contacts(const Blocks& b, const ContactSet& contacts, const StiffnessOf& stiffness_of,
                           double beta, double safety_factor, std::vector<double>* per_block = nullptr,
                           double below = 0, int threads = 1, StepBound bound = StepBound::block,
                           DampingScheme scheme = DampingScheme::explicit_lagged,
                           const std::vector<int>* only = nullptr) {
  CriticalStep out;
  const std::vector<int>& free_blocks = only && bound == StepBound::block ? *only : b.free_blocks;
  if (per_block) per_block->assign(static_cast<std::size_t>(b.count), 0.0);
  const auto& sub = contacts.sub;
  const bool joint_bound = bound == StepBound::joint;
  // Pass 1 of the joint bound: each block's own Gershgorin bound, by block
  // index (0: not free, or no joint). The calling thread's scratch (below).
  thread_local std::vector<double> own_scratch;
  std::vector<double>& own_bound = own_scratch;
  // Block i's 6×6 stiffness on its joints, in its body frame (the inertia
  // is diagonal there), each joint `weighted` by its share (pass 2 of the
  // joint bound) or by 1; false if it has no joint.
  auto stiffness = [&](int i, Mat6& K, bool weighted) {
    K = Mat6::Zero();
    const int first = contacts.gather_offset[i], last = contacts.gather_offset[i + 1];
    if (first == last) return false;
    const Mat3& R = b.state.rotation[i];
    for (int k = first; k < last; ++k) {
      const int s = contacts.gather_sub[k];
      const auto [kn, ks] = stiffness_of(s);
      const Vec3 n = R.transpose() * (b.state.rotation[sub.ref_block[s]] * sub.ref_normal_local[s]);
      const Vec3 r = R.transpose() * (sub.point[s] - b.state.position[i]);
      const Mat3 D = sub.area[s] * (kn * n * n.transpose() + ks * (Mat3::Identity() - n * n.transpose()));
      double w = 1.0;
      if (weighted) {
        const int other = sub.ref_block[s] == i ? sub.inc_block[s] : sub.ref_block[s];
        if (b.props.motion[other] == BlockMotion::free) {
          const double mine = own_bound[i], theirs = own_bound[other];
          w = mine > 0 && theirs > 0 ? 1.0 + theirs / mine : 2.0;
        }
      }
      add_point(K, D, r, w);
    }
    return true;
  };
  const double factor = joint_bound ? 1.0 : 2.0;
  // The split scheme's step takes a search per frequency (split_damping):
  // instead, the highest frequency whose step allows `below`, once per call
  // (the step falls as the frequency rises, so the same blocks are skipped).
  const double omega_allowed = below > 0 && scheme == DampingScheme::split
                                   ? highest_frequency_for_step(below, beta, safety_factor, scheme)
                                   : 0.0;
  auto skipped = [&](int i, const Mat6& K) {
    if (!(below > 0) || per_block) return false;
    const double omega = std::sqrt(factor * omega_squared_bound(b, i, K));
    if (scheme == DampingScheme::split) return omega <= omega_allowed;
    return chosen_for(omega, beta, safety_factor, scheme) >= below;
  };
  // Each block's ω_b² into its slot (−1: no joint, or skipped), the blocks
  // in parallel with `threads` > 1; then the highest in block order: the
  // same bits on any thread count. The calling thread's scratch, reused (no
  // allocation once warmed up), named by reference: inside the region
  // thread_local would name each thread's own.
  const std::ptrdiff_t n_free = static_cast<std::ptrdiff_t>(free_blocks.size());
  thread_local std::vector<double> scratch;
  std::vector<double>& omega2 = scratch;
  omega2.resize(static_cast<std::size_t>(n_free));
  const bool parallel = threads > 1 && n_free >= 64;
  if (joint_bound) {
    own_bound.assign(static_cast<std::size_t>(b.count), 0.0);
#pragma omp parallel for schedule(dynamic, 8) if (parallel) num_threads(std::max(threads, 1))
    for (std::ptrdiff_t j = 0; j < n_free; ++j) {
      const int i = free_blocks[static_cast<std::size_t>(j)];
      Mat6 K;
      if (stiffness(i, K, false)) own_bound[static_cast<std::size_t>(i)] = omega_squared_bound(b, i, K);
    }
  }
#pragma omp parallel for schedule(dynamic, 8) if (parallel) num_threads(std::max(threads, 1))
  for (std::ptrdiff_t j = 0; j < n_free; ++j) {
    const int i = free_blocks[static_cast<std::size_t>(j)];
    Mat6 K;
    omega2[static_cast<std::size_t>(j)] = b.props.motion[i] == BlockMotion::free && stiffness(i, K, joint_bound) &&
                                                  !skipped(i, K)
                                              ? block_omega_squared(b, i, K)
                                              : -1.0;
  }
  for (std::ptrdiff_t j = 0; j < n_free; ++j) {
    const double w2 = omega2[static_cast<std::size_t>(j)];
    if (w2 < 0) continue;
    const int i = free_blocks[static_cast<std::size_t>(j)];
    keep_highest(out, i, w2, factor);
    if (per_block) (*per_block)[i] = std::sqrt(w2);
  }
  finish(out, beta, safety_factor, scheme);
  return out;
}

}  // namespace

CriticalStep critical_time_step_from_contacts(const Blocks& b, const ContactSet& contacts, const JointLaws& laws,
                                              double beta, double safety_factor, double below, int threads,
                                              StepBound bound, DampingScheme scheme, const std::vector<int>* only) {
  const auto& sub = contacts.sub;
  return from_contacts(
      b, contacts,
      [&](int s) {
        const JointLaw& law = laws.between(sub.ref_block[s], sub.inc_block[s]);
        return std::pair<double, double>{law.kn, law.ks};
      },
      beta, safety_factor, nullptr, below, threads, bound, scheme, only);
}

namespace {

// The 6×6 stiffness of block i with every face in full contact (the header).
Mat6 all_faces_stiffness(const Blocks& b, int i, double kn, double ks) {
  const Polyhedron& p = b.props.local_shape[i];
  Mat6 K = Mat6::Zero();
  for (std::size_t f = 0; f < p.faces.size(); ++f) {
    const Vec3& n = p.normals[f];
    const Mat3 D = kn * n * n.transpose() + ks * (Mat3::Identity() - n * n.transpose());
    const auto& loop = p.faces[f];
    const Vec3& a = p.vertices[loop[0]];
    for (std::size_t k = 1; k + 1 < loop.size(); ++k) {
      const Vec3& bb = p.vertices[loop[k]];
      const Vec3& c = p.vertices[loop[k + 1]];
      const double area = 0.5 * (bb - a).cross(c - a).norm();
      // Constant and linear terms: the centroid rule is exact. Quadratic
      // (rotation–rotation) term: ∫_T r rᵀ dA = A/12 (Σ v vᵀ + s sᵀ), s = a+b+c,
      // which holds entry-wise for any quadratic form in r.
      const Vec3 cen = (a + bb + c) / 3.0;
      Mat6 part = Mat6::Zero();
      add_point(part, D, cen, area);
      Mat3 quad = Mat3::Zero();
      for (const Vec3* v : {&a, &bb, &c}) {
        const Mat3 X = cross_matrix(*v);
        quad += X.transpose() * D * X;
      }
      const Mat3 Xs = cross_matrix(a + bb + c);
      quad += Xs.transpose() * D * Xs;
      quad *= area / 12.0;
      part.block<3, 3>(3, 3) = quad;
      K += part;
    }
  }
  return K;
}

}  // namespace

CriticalStep critical_time_step(const Blocks& b, const JointLaw& stiffest, double safety_factor, DampingScheme scheme) {
  CriticalStep out;
  for (int i : b.free_blocks) {
    const Mat6 K = all_faces_stiffness(b, i, stiffest.kn, stiffest.ks);
    keep_highest(out, i, block_omega_squared(b, i, K));
  }
  finish(out, stiffest.beta, safety_factor, scheme);
  return out;
}

std::vector<double> block_frequencies(const Blocks& b, const JointLaw& stiffest) {
  std::vector<double> w(static_cast<std::size_t>(b.count), 0.0);
  for (int i : b.free_blocks)
    w[i] = std::sqrt(block_omega_squared(b, i, all_faces_stiffness(b, i, stiffest.kn, stiffest.ks)));
  return w;
}

std::vector<double> block_frequencies_from_contacts(const Blocks& b, const ContactSet& contacts, const JointLaws& laws) {
  std::vector<double> w;
  const auto& sub = contacts.sub;
  from_contacts(
      b, contacts,
      [&](int s) {
        const JointLaw& law = laws.between(sub.ref_block[s], sub.inc_block[s]);
        return std::pair<double, double>{law.kn, law.ks};
      },
      0.0, 1.0, &w);
  return w;
}

}  // namespace polydem
