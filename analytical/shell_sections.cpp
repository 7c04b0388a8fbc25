#include "analytical/shell_sections.hpp"

#include <cmath>
#include <stdexcept>

#include "analytical/constants.hpp"

namespace polydem::analytical {
namespace {

void check(double r, double t, double density, double E) {
  if (!(r > 0.0) || !(t > 0.0) || !(t <= r) || !(density > 0.0) || !(E > 0.0))
    throw std::invalid_argument("shell section: need 0 < t <= radius, density > 0, E > 0");
}

ShellSection finish(double area, double I, double density, double E) {
  return {area, I, density * area, E * I};
}

}  // namespace

ShellSection hollow_circle_section(double r_b, double t, double density, double E) {
  check(r_b, t, density, E);
  const double ri = r_b - t;
  const double area = pi * (r_b * r_b - ri * ri);
  const double I = 0.25 * pi * (r_b * r_b * r_b * r_b - ri * ri * ri * ri);
  return finish(area, I, density, E);
}

ShellSection hollow_octagon_section(double a_b, double t, double density, double E) {
  check(a_b, t, density, E);
  auto solid = [](double a, double& area, double& I) {
    const double side = 2.0 * a * std::tan(pi / 8.0);
    const double R = a / std::cos(pi / 8.0);
    area = 8.0 * a * a * std::tan(pi / 8.0);
    I = area * (6.0 * R * R - side * side) / 24.0;
  };
  double Ao, Io, Ai = 0.0, Ii = 0.0;
  solid(a_b, Ao, Io);
  if (a_b - t > 0.0) solid(a_b - t, Ai, Ii);
  return finish(Ao - Ai, Io - Ii, density, E);
}

}  // namespace polydem::analytical
