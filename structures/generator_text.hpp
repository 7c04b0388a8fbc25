// Text the block generators (spire, wall, tower, arch, column) put in block
// names and error messages. Internal to structures/.
#pragma once

#include <algorithm>
#include <sstream>
#include <string>

namespace polydem::generator_text {

// A number as a stream prints it by default ("0.25", "1e-05").
inline std::string num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// v with leading zeros to `width` digits ("course03").
inline std::string zero_padded(int v, int width) {
  std::string s = std::to_string(v);
  while (static_cast<int>(s.size()) < width) s.insert(s.begin(), '0');
  return s;
}

// The digits of the largest index, so that names sort in index order.
inline int digits_for(int max_value) { return std::max(1, static_cast<int>(std::to_string(max_value).size())); }

}  // namespace polydem::generator_text
