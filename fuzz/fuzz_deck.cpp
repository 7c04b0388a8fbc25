// libFuzzer target: the deck reader, polydem::parse_deck().
//
// Contract under test (io/deck.hpp): any text either gives a SceneSpec or
// throws DeckError naming the file, line and key. Here any exception derived
// from std::exception counts as a clear error; a crash, a sanitizer report,
// a hang or an exception of another type is a finding.
//
// Input: the deck text. Lines starting with "#@set " (a TOML comment, so the
// deck still parses) are also passed as --set overrides, which drives the
// override code (io/deck.cpp section 5) from the same corpus:
//   #@set simulation.end_time=2
//
// Work per input is bounded: inputs over kMaxInput bytes are skipped. A deck
// can still ask for a huge generated spire; libFuzzer reports inputs slower
// than -report_slow_units (scripts/fuzz.sh sets 1 s) as findings.
#include "io/deck.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

namespace {

constexpr std::size_t kMaxInput = 8192;
constexpr std::string_view kSetPrefix = "#@set ";

std::vector<std::string> overrides_in(std::string_view text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(start, end - start);
    if (line.substr(0, kSetPrefix.size()) == kSetPrefix) out.emplace_back(line.substr(kSetPrefix.size()));
    start = end + 1;
  }
  return out;
}

// A broken promise: say which, then abort (libFuzzer saves the input).
[[noreturn]] void broken(const char* what) {
  std::fprintf(stderr, "polydem_fuzz: deck accepted with %s\n", what);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > kMaxInput) return -1;  // not added to the corpus
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const polydem::SceneSpec spec = polydem::parse_deck(text, "fuzz.toml", overrides_in(text));
    // A deck that passes is trusted downstream (io/deck.cpp: "a deck that
    // passes here is trusted downstream"): check what the engine relies on.
    // A violation aborts with a message, so libFuzzer saves the input.
    if (spec.blocks.empty()) broken("no blocks");  // "a deck needs at least one [[block]] (or a generator)"
    for (const auto& b : spec.blocks) {
      if (!(b.density > 0) || !std::isfinite(b.density)) broken("a density not positive and finite");
      const auto& s = b.shape;
      if (s.vertices.size() < 4 || s.faces.size() < 4 || s.normals.size() != s.faces.size())
        broken("a block shape that is not a closed polyhedron");
      for (const auto& v : s.vertices)
        if (!v.allFinite()) broken("a non-finite vertex");
      for (const auto& f : s.faces)
        for (const int i : f)
          if (i < 0 || static_cast<std::size_t>(i) >= s.vertices.size()) broken("a face index out of range");
    }
  } catch (const std::exception&) {
    // A clear error: accepted.
  }
  return 0;
}
