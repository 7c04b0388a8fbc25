// Every input the fuzzers found (fuzz/regressions/) is now refused with a
// clear error, quickly and without a huge allocation.
#include "io/deck.hpp"
#include "io/ground_motion_record.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace polydem {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<fs::path> inputs(const std::string& kind) {
  std::vector<fs::path> out;
  const fs::path dir = fs::path(POLYDEM_SOURCE_DIR) / "fuzz" / "regressions" / kind;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

template <class Error, class F>
void expect_refused(const fs::path& p, F parse) {
  const auto start = std::chrono::steady_clock::now();
  EXPECT_THROW(parse(read_text(p), p.filename().string()), Error) << p;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 1.0) << p << " took " << seconds << " s";
}

TEST(FuzzRegressions, Records) {
  const auto at2 = inputs("at2");
  const auto csv = inputs("csv_record");
  ASSERT_FALSE(at2.empty());
  ASSERT_FALSE(csv.empty());
  for (const auto& p : at2)
    expect_refused<RecordError>(p, [](const std::string& t, const std::string& n) { return parse_at2(t, n); });
  for (const auto& p : csv)
    expect_refused<RecordError>(p, [](const std::string& t, const std::string& n) { return parse_csv_record(t, n); });
}

TEST(FuzzRegressions, Decks) {
  const auto decks = inputs("deck");
  ASSERT_FALSE(decks.empty());
  for (const auto& p : decks)
    expect_refused<DeckError>(p, [](const std::string& t, const std::string& n) { return parse_deck(t, n); });
}

}  // namespace
}  // namespace polydem
