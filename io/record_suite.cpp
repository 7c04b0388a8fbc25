#include "io/record_suite.hpp"

#include "io/deck.hpp"
#include "io/deck_reader.hpp"
#include "io/ground_motion_record.hpp"
#include "io/record_processing.hpp"

#include <toml++/toml.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <vector>

namespace polydem {
namespace {

using namespace deck_reader;

constexpr std::string_view kFileKeys[] = {"suite", "record"};
constexpr std::string_view kSuiteKeys[] = {"name", "baseline_order", "length_scale"};
constexpr std::string_view kRecordKeys[] = {"name", "file", "direction", "scale", "component"};
constexpr std::string_view kComponentKeys[] = {"file", "direction", "scale"};

// One component's keys (`file` required), from a [[record]] table itself or
// one of its [[record.component]] tables; reads and processes the record.
SuiteComponent read_component(const TableReader& r, const RecordSuite& suite) {
  SuiteComponent c;
  c.line = r.line();
  const auto file = r.string("file");
  if (!file) r.missing("file", "every record needs file = \"path\" (PEER .AT2, ESM .ASC or two-column .csv)");
  if (file->empty()) r.fail("file", "must not be empty");
  std::filesystem::path p(*file);
  if (p.is_relative()) p = std::filesystem::path(r.deck().file()).parent_path() / p;
  c.record_path = p.lexically_normal().string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(c.record_path, ec))
    r.fail("file", "file not found: " + c.record_path + " (relative paths are relative to the suite file's directory)");
  if (const auto d = r.vec3("direction")) {
    if (!(d->norm() > 0)) r.fail("direction", "must not be the zero vector");
    c.direction = d->normalized();
  }
  c.scale = r.number("scale", 1.0, Range::positive);
  try {
    GroundMotionRecord rec = read_record(c.record_path, 1.0);
    if (suite.length_scale != 1.0) scale_record_time(rec.time, suite.length_scale);
    if (suite.baseline_order >= 0) correct_baseline(rec.time, rec.acceleration, suite.baseline_order);
    c.time = std::move(rec.time);
    c.acceleration = std::move(rec.acceleration);
  } catch (const std::exception& e) {  // the record's own file and line, or a correction it cannot take
    r.fail("file", e.what());
  }
  return c;
}

std::string file_stem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

// The tables of `node` at `key`, a non-empty array written [[HEADER]], each
// with its key KEY[i] for messages.
std::vector<std::pair<std::string, const toml::table*>> tables_of(const Deck& deck, const toml::node& node,
                                                                  const std::string& key, const std::string& header) {
  const auto* array = node.as_array();
  if (!array || array->empty())
    deck.fail(key, &node, "must be an array of tables: write [[" + header + "]] (got " + describe(node) + ")");
  std::vector<std::pair<std::string, const toml::table*>> out;
  for (std::size_t i = 0; i < array->size(); ++i) {
    const std::string at = indexed(key, i + 1);
    const auto* table = array->get(i)->as_table();
    if (!table) deck.fail(at, array->get(i), "must be a table: write [[" + header + "]]");
    out.emplace_back(at, table);
  }
  return out;
}

}  // namespace

RecordSuite parse_record_suite(const std::string& text, const std::string& path) {
  toml::table root;
  try {
    root = toml::parse(std::string_view(text), std::string_view(path));
  } catch (const toml::parse_error& e) {
    throw DeckError(path + ":" + std::to_string(e.source().begin.line) +
                    ": TOML syntax error: " + std::string(e.description()));
  }
  const Deck deck(path, root, {});
  for (auto&& [key, node] : root)
    if (!contains(kFileKeys, key.str()))
      deck.fail(std::string(key.str()), &node, "unknown key (a suite file has [suite] and [[record]] tables)");
  static const toml::table empty;
  const toml::node* suite_node = root.get("suite");
  if (suite_node && !suite_node->as_table()) deck.fail("suite", suite_node, "must be a table: write [suite]");
  const TableReader top(deck, suite_node ? *suite_node->as_table() : empty, "suite", kSuiteKeys);
  RecordSuite suite;
  suite.path = path;
  suite.name = top.string("name").value_or(file_stem(path));
  if (const auto order = top.integer("baseline_order")) {
    if (*order < 0 || *order > kMaxBaselineOrder)
      top.fail("baseline_order", "must be an integer in [0, " + std::to_string(kMaxBaselineOrder) + "] (got " +
                                     std::to_string(*order) + ")");
    suite.baseline_order = static_cast<int>(*order);
  }
  suite.length_scale = top.number("length_scale", 1.0, Range::positive);

  const toml::node* records = root.get("record");
  if (!records) deck.fail("record", &root, "missing: a suite needs at least one [[record]] with file = \"path\"");
  std::set<std::string> names;
  for (const auto& [key, table] : tables_of(deck, *records, "record", "record")) {
    const TableReader r(deck, *table, key, kRecordKeys);
    SuiteRecord rec;
    rec.line = r.line();
    const toml::node* components = table->get("component");
    if (components) {
      for (const std::string_view own : {"file", "direction", "scale"})
        if (r.has(own))
          r.fail(own, "give the record's file, direction and scale either in the [[record]] table or in its "
                      "[[record.component]] tables, not both");
      for (const auto& [ckey, ct] : tables_of(deck, *components, key + ".component", "record.component"))
        rec.components.push_back(read_component(TableReader(deck, *ct, ckey, kComponentKeys), suite));
    } else {
      rec.components.push_back(read_component(r, suite));
    }
    rec.name = r.string("name").value_or(file_stem(rec.components.front().record_path));
    if (rec.name.empty()) r.fail("name", "must not be empty");
    if (!names.insert(rec.name).second) {
      if (r.has("name")) r.fail("name", "names another record too: " + in_quotes(rec.name));
      r.fail("file", "gives the same name as another record (" + in_quotes(rec.name) + "): set name = \"...\"");
    }
    suite.records.push_back(std::move(rec));
  }
  return suite;
}

RecordSuite read_record_suite(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DeckError(path + ": cannot open the record suite");
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse_record_suite(ss.str(), path);
}

}  // namespace polydem
