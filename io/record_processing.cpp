#include "io/record_processing.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace polydem {

std::vector<double> record_displacement(const std::vector<double>& t, const std::vector<double>& a) {
  std::vector<double> u(t.size(), 0.0);
  double v = 0.0;
  for (std::size_t i = 1; i < t.size(); ++i) {
    const double h = t[i] - t[i - 1];
    u[i] = u[i - 1] + v * h + h * h * (2.0 * a[i - 1] + a[i]) / 6.0;
    v += 0.5 * h * (a[i - 1] + a[i]);
  }
  return u;
}

void correct_baseline(std::vector<double>& time, std::vector<double>& acceleration, int order) {
  if (order < 0 || order > kMaxBaselineOrder)
    throw std::invalid_argument("baseline order must be an integer in [0, " + std::to_string(kMaxBaselineOrder) +
                                "], got " + std::to_string(order));
  const std::size_t m = static_cast<std::size_t>(order) + 1;  // unknowns c_2 … c_{order+2}
  if (time.size() < m + 1 || time.size() != acceleration.size())
    throw std::invalid_argument("baseline correction of order " + std::to_string(order) + " needs at least " +
                                std::to_string(m + 1) + " samples");
  const std::vector<double> u = record_displacement(time, acceleration);
  const double t0 = time.front(), span = time.back() - t0;
  // Normal equations N c = r of the least-squares fit, N_jk = Σ τ^(j+k+4),
  // r_j = Σ τ^(j+2) u, j, k = 0 … order.
  std::vector<std::vector<double>> N(m, std::vector<double>(m + 1, 0.0));
  std::vector<double> powers(2 * m + 3);
  for (std::size_t i = 0; i < time.size(); ++i) {
    const double tau = (time[i] - t0) / span;
    powers[0] = 1.0;
    for (std::size_t p = 1; p < powers.size(); ++p) powers[p] = powers[p - 1] * tau;
    for (std::size_t j = 0; j < m; ++j) {
      for (std::size_t k = 0; k < m; ++k) N[j][k] += powers[j + k + 4];
      N[j][m] += powers[j + 2] * u[i];
    }
  }
  // Gaussian elimination with partial pivoting (at most 5 unknowns).
  for (std::size_t c = 0; c < m; ++c) {
    std::size_t pivot = c;
    for (std::size_t r = c + 1; r < m; ++r)
      if (std::abs(N[r][c]) > std::abs(N[pivot][c])) pivot = r;
    std::swap(N[c], N[pivot]);
    for (std::size_t r = c + 1; r < m; ++r) {
      const double f = N[r][c] / N[c][c];
      for (std::size_t k = c; k <= m; ++k) N[r][k] -= f * N[c][k];
    }
  }
  std::vector<double> coef(m, 0.0);
  for (std::size_t c = m; c-- > 0;) {
    double sum = N[c][m];
    for (std::size_t k = c + 1; k < m; ++k) sum -= N[c][k] * coef[k];
    coef[c] = sum / N[c][c];
  }
  // a −= d²p/dt² = Σ c_k k (k − 1) τ^(k−2) / span², k = j + 2.
  for (std::size_t i = 0; i < time.size(); ++i) {
    const double tau = (time[i] - t0) / span;
    double correction = 0.0, power = 1.0;
    for (std::size_t j = 0; j < m; ++j) {
      const double k = static_cast<double>(j + 2);
      correction += coef[j] * k * (k - 1.0) * power;
      power *= tau;
    }
    acceleration[i] -= correction / (span * span);
  }
}

void scale_record_time(std::vector<double>& time, double length_scale) {
  if (!(length_scale > 0.0) || !std::isfinite(length_scale))
    throw std::invalid_argument("length scale must be > 0 and finite");
  const double factor = std::sqrt(length_scale);
  for (double& t : time) t *= factor;
}

}  // namespace polydem
