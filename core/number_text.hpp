// The shortest text that reads back to the same double ("0.1", "2.5e-05"):
// deck messages, JSON, sweep point values and their directory names all
// write numbers this way, so the same value always has the same text.
#pragma once

#include <charconv>
#include <string>

namespace polydem {

inline std::string shortest_text(double x) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);  // shortest round trip
  return std::string(buf, r.ptr);
}

}  // namespace polydem
