#include "integrators/joint_modes.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace polydem {

namespace {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using Mat36 = Eigen::Matrix<double, 3, 6>;

// The displacement of block i's point p for a mass-normalised motion of the
// block: translation (world axes) over √m, rotation about the body's principal
// axes over √I. A rotation θ (body frame) moves p by (R·θ) × (p − x).
Mat36 normalised_motion(const Blocks& b, int i, const Vec3& p) {
  Mat36 g;
  g.leftCols<3>() = Mat3::Identity() / std::sqrt(b.props.mass[i]);
  const Vec3& I = b.props.principal_inertia[i];
  g.rightCols<3>() = -cross_matrix(p - b.state.position[i]) * b.state.rotation[i] *
                     Vec3(1 / std::sqrt(I.x()), 1 / std::sqrt(I.y()), 1 / std::sqrt(I.z())).asDiagonal();
  return g;
}

double largest_eigenvalue(const Mat6& k) {
  Eigen::SelfAdjointEigenSolver<Mat6> eig(k, Eigen::EigenvaluesOnly);
  return std::max(0.0, eig.eigenvalues().maxCoeff());
}

}  // namespace

JointModes joint_modes(const Blocks& b, const ContactSet& contacts, const JointLaws& laws) {
  const int n = static_cast<int>(b.free_blocks.size());
  if (n > max_joint_mode_blocks)
    throw std::invalid_argument("joint_modes: " + std::to_string(n) + " free blocks, more than the dense limit " +
                                std::to_string(max_joint_mode_blocks));
  std::vector<int> slot(static_cast<std::size_t>(b.count), -1);
  for (int j = 0; j < n; ++j) slot[b.free_blocks[j]] = j;

  // Each subcontact: its spring D, for each free side the mass-normalised
  // motion of the point (inc side +, reference side −) and that side's own
  // 6×6 part hᵀ·D·h.
  const auto& sub = contacts.sub;
  struct Spring {
    Mat3 d;
    int side[2];  // slots of the incident and reference blocks, −1 when not free
    Mat36 h[2];
    Mat6 own[2];
  };
  std::vector<Spring> springs;
  springs.reserve(sub.size());
  for (std::size_t s = 0; s < sub.size(); ++s) {
    const int ref = sub.ref_block[s], inc = sub.inc_block[s];
    const JointLaw& law = laws.between(ref, inc);
    const Vec3 nn = b.state.rotation[ref] * sub.ref_normal_local[s];
    Spring sp;
    sp.d = sub.area[s] * (law.kn * nn * nn.transpose() + law.ks * (Mat3::Identity() - nn * nn.transpose()));
    sp.side[0] = slot[inc];
    sp.side[1] = slot[ref];
    if (sp.side[0] >= 0) sp.h[0] = normalised_motion(b, inc, sub.point[s]);
    if (sp.side[1] >= 0) sp.h[1] = -normalised_motion(b, ref, sub.point[s]);
    for (int u = 0; u < 2; ++u)
      if (sp.side[u] >= 0) sp.own[u] = sp.h[u].transpose() * sp.d * sp.h[u];
    if (sp.side[0] >= 0 || sp.side[1] >= 0) springs.push_back(sp);
  }

  // The assembled stiffness and its spectrum.
  JointModes out;
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(6 * n, 6 * n);
  for (const Spring& sp : springs)
    for (int u = 0; u < 2; ++u)
      for (int v = 0; v < 2; ++v)
        if (sp.side[u] >= 0 && sp.side[v] >= 0)
          k.block<6, 6>(6 * sp.side[u], 6 * sp.side[v]) += u == v ? sp.own[u] : sp.h[u].transpose() * sp.d * sp.h[v];
  if (n > 0) {
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(k);
    out.omega.resize(static_cast<std::size_t>(6 * n));
    for (int m = 0; m < 6 * n; ++m) out.omega[m] = std::sqrt(std::max(0.0, eig.eigenvalues()(m)));
    out.omega_max = out.omega.back();
    const Eigen::VectorXd top = eig.eigenvectors().col(6 * n - 1);
    out.share.assign(static_cast<std::size_t>(b.count), 0.0);
    for (int j = 0; j < n; ++j) out.share[b.free_blocks[j]] = top.segment<6>(6 * j).squaredNorm();
  }

  // The bounds: each block's own stiffness with its neighbours held, every
  // spring weighted by 1 (own ω_b²), by 2 between free blocks (the run's
  // bound takes √2 on every block), by 1 + t with t the ratio of the blocks'
  // own ω_b² (split).
  auto own = [&](auto weight) {
    std::vector<Mat6> kb(static_cast<std::size_t>(n), Mat6::Zero());
    for (const Spring& sp : springs)
      for (int u = 0; u < 2; ++u)
        if (sp.side[u] >= 0) kb[sp.side[u]] += weight(sp, u) * sp.own[u];
    std::vector<double> l(static_cast<std::size_t>(n));
    for (int j = 0; j < n; ++j) l[j] = largest_eigenvalue(kb[j]);
    return l;
  };
  const std::vector<double> lambda = own([](const Spring&, int) { return 1.0; });
  const std::vector<double> split = own([&](const Spring& sp, int u) {
    const int other = sp.side[1 - u];
    if (other < 0) return 1.0;
    const double mine = lambda[sp.side[u]], theirs = lambda[other];
    return mine > 0 && theirs > 0 ? 1.0 + theirs / mine : 2.0;
  });
  for (int j = 0; j < n; ++j) {
    out.block_bound = std::max(out.block_bound, std::sqrt(2.0 * lambda[j]));
    out.split_bound = std::max(out.split_bound, std::sqrt(split[j]));
  }
  return out;
}

}  // namespace polydem
