// Three-vectors stored as three arrays, x, y and z: a structure of arrays.
//
// The joint law runs over a pair's subcontacts four at a time
// (contact/joint_law_kernels.hpp); with the vectors' components apart, four
// subcontacts' x components are one contiguous load, where an array of Vec3
// interleaves them (x y z x y z ...) and filling the lanes costs more than
// the arithmetic they save.
//
// Reading gives a Vec3 by value. Writing goes through set(): operator[]
// returns a const Vec3, so `a[i] = v` does not compile instead of writing
// to a temporary.
#pragma once

#include "geometry/polyhedron.hpp"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace polydem {

struct Vec3Array {
  std::vector<double> x, y, z;

  std::size_t size() const { return x.size(); }
  bool empty() const { return x.empty(); }
  const Vec3 operator[](std::size_t i) const { return Vec3(x[i], y[i], z[i]); }
  void set(std::size_t i, const Vec3& v) {
    x[i] = v.x();
    y[i] = v.y();
    z[i] = v.z();
  }
  void set_zero(std::size_t i) { x[i] = y[i] = z[i] = 0.0; }
  // New entries are zero.
  void resize(std::size_t n) {
    x.resize(n);
    y.resize(n);
    z.resize(n);
  }
  void assign(std::size_t n, const Vec3& v) {
    x.assign(n, v.x());
    y.assign(n, v.y());
    z.assign(n, v.z());
  }
  void fill_zero() {
    std::fill(x.begin(), x.end(), 0.0);
    std::fill(y.begin(), y.end(), 0.0);
    std::fill(z.begin(), z.end(), 0.0);
  }
  void push_back(const Vec3& v) {
    x.push_back(v.x());
    y.push_back(v.y());
    z.push_back(v.z());
  }
  void clear() {
    x.clear();
    y.clear();
    z.clear();
  }
  bool operator==(const Vec3Array&) const = default;
};

}  // namespace polydem
