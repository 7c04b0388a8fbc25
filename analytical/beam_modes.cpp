#include "analytical/beam_modes.hpp"

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <stdexcept>

#include "analytical/constants.hpp"

namespace polydem::analytical {

double tapered_cantilever_frequency_function(double Omega) {
  if (!(Omega > 0.0)) throw std::invalid_argument("frequency function: Omega must be > 0");
  const double z = 2.0 * std::sqrt(Omega);
  const double i1 = std::cyl_bessel_i(1.0, z);
  return std::cyl_bessel_j(1.0, z) * std::cyl_bessel_i(2.0, z) / i1 + std::cyl_bessel_j(2.0, z);
}

std::vector<double> tapered_cantilever_omegas(int n_modes) {
  if (n_modes < 1) throw std::invalid_argument("tapered_cantilever_omegas: n_modes must be >= 1");
  std::vector<double> roots;
  // Roots sit roughly where J oscillates in z = 2√Ω, about π apart in z, so a
  // step of 0.05 in z cannot jump over two of them.
  constexpr double dz = 0.05;
  double z0 = 0.5;
  double f0 = tapered_cantilever_frequency_function(z0 * z0 / 4.0);
  while (static_cast<int>(roots.size()) < n_modes) {
    const double z1 = z0 + dz;
    const double f1 = tapered_cantilever_frequency_function(z1 * z1 / 4.0);
    if ((f0 < 0.0) != (f1 < 0.0)) {
      double a = z0, b = z1, fa = f0;
      for (int it = 0; it < 200 && b - a > 1e-15 * b; ++it) {
        const double m = 0.5 * (a + b);
        const double fm = tapered_cantilever_frequency_function(m * m / 4.0);
        if ((fm < 0.0) == (fa < 0.0)) { a = m; fa = fm; } else { b = m; }
      }
      const double z = 0.5 * (a + b);
      roots.push_back(z * z / 4.0);
    }
    z0 = z1;
    f0 = f1;
  }
  return roots;
}

double tapered_cantilever_mode_shape(double Omega, double y_over_H) {
  const double s = 1.0 - y_over_H;
  const double z = 2.0 * std::sqrt(Omega);
  // A s^{-1/2} J1 + B s^{-1/2} I1 with X(1) = 0 → B = −A J1(z)/I1(z).
  const double ratio = std::cyl_bessel_j(1.0, z) / std::cyl_bessel_i(1.0, z);
  auto shape = [&](double ss) {
    if (ss <= 0.0) return std::sqrt(Omega) * (1.0 - ratio);  // limit of s^{-1/2}·(√(Ωs) + ...)
    const double zz = 2.0 * std::sqrt(Omega * ss);
    return (std::cyl_bessel_j(1.0, zz) - ratio * std::cyl_bessel_i(1.0, zz)) / std::sqrt(ss);
  };
  return shape(s) / shape(0.0);
}

std::vector<double> tapered_cantilever_omegas_fe(int n_modes, int n_elements) {
  if (n_elements < 2 || n_modes < 1 || n_modes > 2 * n_elements)
    throw std::invalid_argument("tapered_cantilever_omegas_fe: bad mode or element count");
  const int ndof = 2 * (n_elements + 1);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(ndof, ndof), M = Eigen::MatrixXd::Zero(ndof, ndof);
  const double L = 1.0 / n_elements;  // ξ units with m_b = EI_b = H = 1: eigenvalues are Ω²
  // 4-point Gauss–Legendre on [0,1]: exact for the degree-7 mass integrand.
  const std::array<double, 4> gx = {0.5 - 0.5 * 0.8611363115940526, 0.5 - 0.5 * 0.3399810435848563,
                                    0.5 + 0.5 * 0.3399810435848563, 0.5 + 0.5 * 0.8611363115940526};
  const std::array<double, 4> gw = {0.5 * 0.3478548451374538, 0.5 * 0.6521451548625461,
                                    0.5 * 0.6521451548625461, 0.5 * 0.3478548451374538};
  for (int e = 0; e < n_elements; ++e) {
    Eigen::Matrix4d ke = Eigen::Matrix4d::Zero(), me = Eigen::Matrix4d::Zero();
    for (int q = 0; q < 4; ++q) {
      const double z = gx[q], xi = (e + z) * L, s = 1.0 - xi;
      const Eigen::Vector4d N(1 - 3 * z * z + 2 * z * z * z, L * (z - 2 * z * z + z * z * z),
                              3 * z * z - 2 * z * z * z, L * (-z * z + z * z * z));
      const Eigen::Vector4d B((-6 + 12 * z) / (L * L), (-4 + 6 * z) / L, (6 - 12 * z) / (L * L), (-2 + 6 * z) / L);
      ke += gw[q] * L * s * s * s * B * B.transpose();  // EI = s^3 (eq. 3)
      me += gw[q] * L * s * N * N.transpose();          // m = s (eq. 3)
    }
    K.block<4, 4>(2 * e, 2 * e) += ke;
    M.block<4, 4>(2 * e, 2 * e) += me;
  }
  // Clamp at the base: drop w and w' of node 0.
  const int n = ndof - 2;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(K.bottomRightCorner(n, n),
                                                                   M.bottomRightCorner(n, n));
  if (solver.info() != Eigen::Success) throw std::runtime_error("tapered_cantilever_omegas_fe: eigen solve failed");
  std::vector<double> out;
  for (int i = 0; i < n_modes; ++i) out.push_back(std::sqrt(solver.eigenvalues()[i]));
  return out;
}

double rayleigh_omega(double k) {
  if (!(k > 1.5)) throw std::invalid_argument("rayleigh_omega: k must be > 1.5");
  return std::sqrt(3.0 * k * (k - 1.0) * (k + 1.0) * (2.0 * k + 1.0) / ((2.0 * k - 3.0) * (2.0 * k - 1.0)));
}

RayleighMinimum rayleigh_minimum() {
  // Ω̄ → ∞ as k → 3/2 and grows like k for large k: one interior minimum.
  double a = 1.6, b = 6.0;
  const double gr = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 200 && b - a > 1e-12; ++it) {
    const double c = b - gr * (b - a), d = a + gr * (b - a);
    if (rayleigh_omega(c) <= rayleigh_omega(d)) b = d; else a = c;
  }
  const double k = 0.5 * (a + b);
  return {k, rayleigh_omega(k)};
}

double natural_frequency_hz(double Omega, double m_b, double EI_b, double H) {
  if (!(m_b > 0.0) || !(EI_b > 0.0) || !(H > 0.0))
    throw std::invalid_argument("natural_frequency_hz: m_b, EI_b and H must be > 0");
  return Omega * std::sqrt(EI_b / (m_b * H * H * H * H)) / (2.0 * pi);  // eq. 4
}

const char* to_string(SectionShape s) { return s == SectionShape::octagon ? "octagon" : "circle"; }

SpireBeamModes spire_beam_modes(const SpireBeam& b) {
  SpireBeamModes r;
  r.beam = b;
  r.section = b.section == SectionShape::octagon ? hollow_octagon_section(b.r_b, b.thickness, b.density, b.E)
                                                 : hollow_circle_section(b.r_b, b.thickness, b.density, b.E);
  const double m_b = r.section.mass_per_height, EI_b = r.section.bending_stiffness;
  for (double Omega : tapered_cantilever_omegas(b.modes))
    r.modes.push_back({Omega, natural_frequency_hz(Omega, m_b, EI_b, b.H)});
  r.rayleigh = rayleigh_minimum();
  r.rayleigh_f_hz = natural_frequency_hz(r.rayleigh.Omega, m_b, EI_b, b.H);
  return r;
}

}  // namespace polydem::analytical
