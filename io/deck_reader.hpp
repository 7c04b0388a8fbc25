// The tools a deck section reader works with, shared by io/deck.cpp and the
// generators' section readers (io/generators.hpp): where an error is (the
// deck's file and line, or the --set override a value came from), and
// TableReader, typed and range-checked access to one TOML table that rejects
// unknown keys. Internal to io/: nothing outside io includes it (toml++ is
// heavy and io's business).
#pragma once

#include "io/deck.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <charconv>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace polydem::deck_reader {

// Values parsed from a --set override carry this as their source path.
constexpr std::string_view kOverrideSource = "--set";

std::string format_number(double v);

std::string in_quotes(std::string_view s);

std::string join_quoted(std::span<const std::string_view> items);

std::string join(std::span<const std::string_view> items);

bool contains(std::span<const std::string_view> items, std::string_view s);

std::string indexed(std::string_view base, std::size_t one_based);

// What a node holds, for "(got ...)" in messages.
std::string describe(const toml::node& n);

// ------------------------------------------------------- 2. where errors are

class Deck {
 public:
  Deck(std::string file, const toml::table& root, std::vector<std::string> overridden)
      : file_(std::move(file)), root_(root), overridden_(std::move(overridden)) {}

  const std::string& file() const { return file_; }
  const toml::table& root() const { return root_; }

  // Throws the DeckError for `key` (full path), located at node `at` (the
  // key's value, or the table that should have held a missing key).
  [[noreturn]] void fail(const std::string& key, const toml::node* at, const std::string& what) const;

 private:
  // True if an override set `key` or a table/array containing it.
  bool overridden(const std::string& key) const {
    return std::any_of(overridden_.begin(), overridden_.end(), [&](const std::string& o) {
      return key == o || (key.size() > o.size() && key.compare(0, o.size(), o) == 0 &&
                          (key[o.size()] == '.' || key[o.size()] == '['));
    });
  }

  std::string file_;
  const toml::table& root_;
  std::vector<std::string> overridden_;
};

// ------------------------------------------------------------ 3. TableReader

enum class Range { any, positive, non_negative };

class TableReader {
 public:
  // Rejects keys not in `allowed` straight away.
  TableReader(const Deck& deck, const toml::table& table, std::string path,
              std::span<const std::string_view> allowed)
      : deck_(deck), table_(table), path_(std::move(path)) {
    for (auto&& [k, v] : table_) {
      if (!contains(allowed, k.str()))
        deck_.fail(key_path(k.str()), &v, "unknown key (" + path_ + " accepts: " + join(allowed) + ")");
    }
  }

  const toml::table& table() const { return table_; }
  const Deck& deck() const { return deck_; }
  int line() const { return static_cast<int>(table_.source().begin.line); }
  bool has(std::string_view key) const { return table_.get(key) != nullptr; }
  std::string key_path(std::string_view key) const { return path_ + "." + std::string(key); }

  [[noreturn]] void fail(std::string_view key, const std::string& what) const {
    const toml::node* n = table_.get(key);
    deck_.fail(key_path(key), n ? n : &table_, what);
  }
  [[noreturn]] void missing(std::string_view key, const std::string& what) const {
    deck_.fail(key_path(key), &table_, "missing: " + what);
  }

  std::optional<double> number(std::string_view key) const {
    const toml::node* n = table_.get(key);
    if (!n) return std::nullopt;
    return number_of(*n, key_path(key));
  }

  double number(std::string_view key, double fallback, Range range) const {
    const auto v = number(key);
    if (!v) return fallback;
    check_range(key, *v, range);
    return *v;
  }

  void check_range(std::string_view key, double v, Range range) const {
    if (range == Range::positive && !(v > 0)) fail(key, "must be > 0 (got " + format_number(v) + ")");
    if (range == Range::non_negative && !(v >= 0)) fail(key, "must be >= 0 (got " + format_number(v) + ")");
  }

  std::optional<long long> integer(std::string_view key) const {
    const toml::node* n = table_.get(key);
    if (!n) return std::nullopt;
    if (const auto* i = n->as_integer()) return i->get();
    fail(key, "must be an integer (got " + describe(*n) + ")");
  }

  std::optional<bool> boolean(std::string_view key) const {
    const toml::node* n = table_.get(key);
    if (!n) return std::nullopt;
    if (const auto* b = n->as_boolean()) return b->get();
    fail(key, "must be true or false (got " + describe(*n) + ")");
  }

  std::optional<std::string> string(std::string_view key) const {
    const toml::node* n = table_.get(key);
    if (!n) return std::nullopt;
    if (const auto* s = n->as_string()) return s->get();
    fail(key, "must be a string (got " + describe(*n) + ")");
  }

  // One of `names` (mapped to `values`); `fallback` when absent.
  template <class E>
  E choice(std::string_view key, std::initializer_list<std::pair<std::string_view, E>> options, E fallback) const {
    return choice(key, std::span<const std::pair<std::string_view, E>>(options.begin(), options.size()), fallback);
  }

  template <class E>
  E choice(std::string_view key, std::span<const std::pair<std::string_view, E>> options, E fallback) const {
    const auto s = string(key);
    if (!s) return fallback;
    std::vector<std::string_view> names;
    for (const auto& [name, value] : options) {
      if (*s == name) return value;
      names.push_back(name);
    }
    fail(key, "must be one of " + join_quoted(names) + " (got " + in_quotes(*s) + ")");
  }

  // An array of exactly `n` numbers.
  std::optional<std::vector<double>> numbers(std::string_view key, std::size_t n, std::string_view form) const {
    const toml::node* node = table_.get(key);
    if (!node) return std::nullopt;
    return numbers_of(*node, key_path(key), n, form);
  }

  std::optional<Vec3> vec3(std::string_view key) const {
    const auto v = numbers(key, 3, "[x, y, z]");
    if (!v) return std::nullopt;
    return Vec3((*v)[0], (*v)[1], (*v)[2]);
  }

  // An array of points, each an array of `dim` numbers.
  std::optional<std::vector<std::vector<double>>> points(std::string_view key, std::size_t dim,
                                                         std::string_view form) const {
    const toml::node* node = table_.get(key);
    if (!node) return std::nullopt;
    const auto* arr = node->as_array();
    if (!arr) fail(key, "must be an array of points " + std::string(form) + " (got " + describe(*node) + ")");
    std::vector<std::vector<double>> out;
    for (std::size_t i = 0; i < arr->size(); ++i)
      out.push_back(numbers_of(*arr->get(i), indexed(key_path(key), i + 1), dim, form));
    return out;
  }

 private:
  double number_of(const toml::node& n, const std::string& path) const {
    double v = 0;
    if (const auto* f = n.as_floating_point())
      v = f->get();
    else if (const auto* i = n.as_integer())
      v = static_cast<double>(i->get());
    else
      deck_.fail(path, &n, "must be a number (got " + describe(n) + ")");
    if (!std::isfinite(v)) deck_.fail(path, &n, "must be finite (got " + format_number(v) + ")");
    return v;
  }

  std::vector<double> numbers_of(const toml::node& n, const std::string& path, std::size_t count,
                                 std::string_view form) const {
    const auto* arr = n.as_array();
    if (!arr || arr->size() != count) {
      std::string got = arr ? "an array of " + std::to_string(arr->size()) : describe(n);
      deck_.fail(path, &n,
                 "must be an array of " + std::to_string(count) + " numbers " + std::string(form) + " (got " + got + ")");
    }
    std::vector<double> out;
    for (std::size_t i = 0; i < count; ++i) out.push_back(number_of(*arr->get(i), indexed(path, i + 1)));
    return out;
  }

  const Deck& deck_;
  const toml::table& table_;
  std::string path_;
};

// ------------------------------------------------------ section tables

// [name] as a table, or nullptr when absent.
const toml::table* section_table(const Deck& deck, std::string_view name);

// [[name]] entries (empty when absent).
std::vector<const toml::table*> section_tables(const Deck& deck, std::string_view name);

// A reader for [name]; an empty table stands in when the section is absent.
const toml::table& table_or_empty(const Deck& deck, std::string_view name);

// What [joint] falls back on for the stiffnesses: Table 1's 98 GPa/m and
// ks = 0.4 kn, or what [spire] derives from its materials.
struct JointDefaults {
  double normal_stiffness = 98e9;
  double shear_ratio = 0.4;
};

}  // namespace polydem::deck_reader
