#include "io/generators.hpp"

#include <algorithm>
#include <unordered_map>

namespace polydem {

using namespace deck_reader;

namespace {

std::vector<GeneratorSection>& registry() {
  static std::vector<GeneratorSection> sections;
  return sections;
}

std::string two_digits(int v) {
  std::string s = std::to_string(v);
  if (s.size() < 2) s.insert(s.begin(), '0');
  return s;
}

// The course a block's BlockSpec gives: the course it lies in; outside any
// course, an arch's voussoir its ring and a column's drum its place.
int course_of(const GeneratedBlock& b) {
  if (b.course >= 0) return b.course;
  if (b.kind == BlockKind::voussoir) return b.ring;
  if (b.kind == BlockKind::drum) return b.index;
  return -1;
}

std::string group_of(const GeneratorTable& table, const GeneratedBlock& b) {
  std::string g = table.group_prefix;
  switch (table.grouping) {
    case Grouping::course:
      if (b.kind == BlockKind::base || b.kind == BlockKind::tip)
        g.append(to_string(b.kind));
      else
        g.append("course").append(two_digits(b.course));
      break;
    case Grouping::face: g.append("face").append(std::to_string(b.face)); break;
    case Grouping::leaf: g.append(b.leaf >= 0 ? "leaf" + std::to_string(b.leaf) : std::string("through")); break;
    case Grouping::kind: g.append(to_string(b.kind)); break;
    case Grouping::section: g.append(table.name); break;
  }
  return g;
}

bool is_support(BlockKind kind) { return kind == BlockKind::base || kind == BlockKind::abutment; }

}  // namespace

std::span<const GeneratorSection> generator_sections() { return registry(); }

RegisteredSection::RegisteredSection(const GeneratorSection& section) {
  std::vector<GeneratorSection>& sections = registry();
  const auto at = std::upper_bound(sections.begin(), sections.end(), section.order,
                                   [](int order, const GeneratorSection& s) { return order < s.order; });
  sections.insert(at, section);
}

Generated read_generators(const Deck& deck, SceneSpec& scene) {
  Generated g;
  for (const GeneratorSection& s : generator_sections()) s.read(deck, g, scene);
  return g;
}

void append_generated_blocks(const Deck& deck, const Generated& generated, std::vector<BlockSpec>& blocks) {
  const std::size_t n_listed = blocks.size();
  std::unordered_map<std::string, std::size_t> part_of;  // generated name -> index of its part
  for (std::size_t p = 0; p < generated.parts.size(); ++p) {
    const Generated::Part& part = generated.parts[p];
    for (const BlockSpec& gb : part.blocks) {
      for (std::size_t i = 0; i < n_listed; ++i)
        if (const BlockSpec& b = blocks[i]; b.name == gb.name) {
          std::string what = "generated block ";
          what.append(in_quotes(gb.name)).append(" has the name of the [[block]] at line ");
          what.append(std::to_string(b.deck_line)).append("; rename that block");
          deck.fail(part.section, part.at, what);
        }
      if (const auto it = part_of.find(gb.name); it != part_of.end()) {
        const Generated::Part& other = generated.parts[it->second];
        std::string what = "generated block ";
        what.append(in_quotes(gb.name)).append(" has the name of a block of [").append(other.section);
        what.append("] at line ").append(std::to_string(other.deck_line));
        what.append("; give the sections different names (key `name`)");
        deck.fail(part.section, part.at, what);
      }
      part_of.emplace(gb.name, p);
      blocks.push_back(gb);
    }
  }
}

// ------------------------------------------- the reader of the generators

std::vector<std::string_view> keys_under(std::span<const std::string_view> keys, std::string_view prefix) {
  std::vector<std::string_view> out;
  for (std::string_view k : keys) {
    if (prefix.empty() && k.find('.') == std::string_view::npos) out.push_back(k);
    if (!prefix.empty() && k.rfind(prefix, 0) == 0) out.push_back(k.substr(prefix.size()));
  }
  return out;
}

std::vector<const toml::table*> generator_tables(const Deck& deck, const GeneratorRules& rules) {
  if (!rules.single) return section_tables(deck, rules.section);
  const toml::table* t = section_table(deck, rules.section);
  return t ? std::vector<const toml::table*>{t} : std::vector<const toml::table*>{};
}

int integer_in(const TableReader& r, std::string_view key, int fallback, int lo, int hi) {
  const auto n = r.integer(key);
  if (!n) return fallback;
  if (*n < lo || *n > hi)
    r.fail(key, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "] (got " + std::to_string(*n) + ")");
  return static_cast<int>(*n);
}

void open_openings(const GeneratorRules& rules, GeneratorTable& table, std::initializer_list<std::string_view> required,
                   const std::string& why) {
  const toml::node* n = table.table->get("opening");
  if (!n) return;
  const TableReader& r = table.reader();
  const std::string section(rules.section);
  const auto* arr = n->as_array();
  if (!arr)
    r.fail("opening", "must be an array of tables: write [[" + section + ".opening]] under its [[" + section +
                          "]] (got " + describe(*n) + ")");
  std::vector<const toml::table*> openings;
  for (std::size_t i = 0; i < arr->size(); ++i) {
    const auto* ot = arr->get(i)->as_table();
    if (!ot)
      r.deck().fail(indexed(r.key_path("opening"), i + 1), arr->get(i),
                    "must be a table: write [[" + section + ".opening]] (got " + describe(*arr->get(i)) + ")");
    openings.push_back(ot);
  }
  const std::vector<std::string_view> keys = keys_under(rules.keys, "opening.");
  const std::string path = r.key_path("opening");
  for (std::size_t i = 0; i < openings.size(); ++i) {
    const TableReader& o = table.readers.emplace_back(r.deck(), *openings[i], indexed(path, i + 1), keys);
    for (std::string_view k : required)
      if (!o.has(k)) o.missing(k, why);
  }
}

GeneratorTable open_generator_table(const Deck& deck, const GeneratorRules& rules, const toml::table& table,
                                    std::size_t i, std::size_t count) {
  GeneratorTable out;
  out.path = rules.single ? std::string(rules.section) : indexed(rules.section, i + 1);
  out.table = &table;
  std::vector<std::string_view> own = keys_under(rules.keys, "");
  out.readers.emplace_back(deck, table, out.path, own);
  const TableReader& r = out.reader();
  const std::string numbered = std::string(rules.section) + std::to_string(i + 1);
  switch (rules.naming) {
    case Naming::none: break;
    case Naming::owned:
      out.name = r.string("name").value_or(numbered);
      if (out.name.empty() || out.name.find_first_of(" \t\n\"") != std::string::npos)
        r.fail("name", "must be a non-empty name without spaces or quotes (it starts every block's name)");
      break;
    case Naming::prefix:
      out.name = count > 1 ? numbered : std::string(rules.section);
      if (const auto n = r.string("name")) {
        if (n->empty()) r.fail("name", "must not be empty (it prefixes the blocks' names)");
        out.name = *n;
      }
      break;
  }
  out.grouping = rules.grouping;
  return out;
}

void close_generator_table(const GeneratorRules& rules, GeneratorTable& table,
                           std::span<const GeneratorTable> earlier) {
  const TableReader& r = table.reader();
  table.density = r.number("density", table.density, Range::positive);
  if (!rules.motion_key.empty())
    table.support_motion = r.choice<BlockMotion>(
        rules.motion_key, {{"fixed", BlockMotion::fixed}, {"kinematic", BlockMotion::kinematic}}, table.support_motion);
  if (!rules.group_by.empty()) {
    table.grouping = r.choice<Grouping>("group_by", rules.group_by, table.grouping);
    table.group_prefix = r.string("group").value_or("");
  }
  if (rules.naming != Naming::owned) return;
  for (std::size_t j = 0; j < earlier.size(); ++j) {
    if (earlier[j].name != table.name) continue;
    const toml::node* at = table.table->get("name");
    std::string what(rules.section);
    what.append(" ").append(in_quotes(table.name)).append(" is also the name of ");
    what.append(indexed(rules.section, j + 1)).append(" at line ").append(std::to_string(earlier[j].line()));
    what.append(" (block names start with it)");
    r.deck().fail(indexed(rules.section, earlier.size() + 1) + ".name", at ? at : table.table, what);
  }
}

void fail_spec(const GeneratorTable& table, const GeneratorSpecError& e, std::string_view key) {
  if (e.opening >= 0) table.readers[static_cast<std::size_t>(e.opening) + 1].fail(key, e.detail);
  table.reader().fail(key, e.detail);
}

void fail_geometry(const GeneratorRules& rules, const GeneratorTable& table, const GeometryError& e) {
  table.reader().deck().fail(table.path, table.table,
                             "cannot build the " + std::string(rules.section) + ": " + e.what());
}

void add_generated_part(const GeneratorRules& rules, const GeneratorTable& table,
                        const std::vector<GeneratedBlock>& blocks, std::size_t i, std::size_t& total,
                        Generated& out) {
  Generated::Part part;
  part.section = table.path;
  part.at = table.table;
  part.deck_line = table.line();
  part.blocks.reserve(blocks.size());
  for (const GeneratedBlock& g : blocks) {
    BlockSpec b;
    b.name = rules.naming == Naming::prefix ? table.name + "_" + g.name : g.name;
    b.shape = g.shape;
    b.density = table.density;
    b.motion = is_support(g.kind) ? table.support_motion : BlockMotion::free;
    b.course = course_of(g);
    b.group = group_of(table, g);
    b.deck_line = part.deck_line;
    part.blocks.push_back(std::move(b));
  }
  out.parts.push_back(std::move(part));
  total += blocks.size();
  if (rules.max_blocks > 0 && total > rules.max_blocks) {
    const std::string section(rules.section);
    table.reader().deck().fail(indexed(section, i + 1), table.table,
                               "the [[" + section + "]] tables up to this one build " + std::to_string(total) +
                                   " blocks (at most " + std::to_string(rules.max_blocks) + " in a deck)");
  }
}

}  // namespace polydem
