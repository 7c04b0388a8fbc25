// Deck sections that generate blocks: [spire], [[wall]], [[tower]],
// [[arch]], [[column]] (the generators of structures/) and [[import]]. The
// deck reader knows them only through generator_sections(): each has a
// section name, the keys it accepts (checked like every section's, listed by
// deck_keys()), and a reader that adds its blocks to a Generated part (and
// may set the joints' defaults from its materials, and its own fields of the
// SceneSpec).
//
// One reader serves every generator of structures/ (read_generator<G>): it
// opens each table, reads what every generator has (the name and its
// default, the density, the supports' motion, the grouping), checks the
// names, builds each table with the generator and reports a spec it cannot
// build at the deck key responsible (file, line, key), limits the blocks a
// deck asks for, and turns each GeneratedBlock into a BlockSpec (name,
// motion, course and group from the block's fields). A generator's section
// file, io/NAME_section.cpp, supplies only its rules (section name, keys,
// how its tables are named and grouped), a function reading its spec and
// one calling the generator, and registers itself there
// (RegisteredSection); its place among the sections, which fixes the order
// of the blocks, is its `order`.
#pragma once

#include "io/deck_reader.hpp"
#include "structures/generated_block.hpp"
#include "structures/generator_specs.hpp"

#include <deque>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace polydem {

// The blocks the generators made, by section, before the [[block]] ones are
// known (their names are checked against those afterwards).
struct Generated {
  struct Part {
    std::string section;     // "spire", "arch[2]"
    const toml::node* at = nullptr;  // the section's table, for messages
    int deck_line = 0;       // stored in each block's BlockSpec::deck_line
    std::vector<BlockSpec> blocks;
  };
  std::vector<Part> parts;
  std::optional<deck_reader::JointDefaults> joint;  // the last generator's, if it sets them
  GeneratorSpecs specs;  // what the scene keeps of the sections (SceneSpec::generators)
};

struct GeneratorSection {
  std::string_view name;
  std::span<const std::string_view> keys;
  int order = 0;  // sections are read by increasing order: it fixes the order of the blocks
  // Reads the section if the deck has it (does nothing otherwise).
  void (*read)(const deck_reader::Deck& deck, Generated& out, SceneSpec& scene);
};

// Every registered section, by increasing order.
std::span<const GeneratorSection> generator_sections();

// Registers a section: a section file defines one at namespace scope.
struct RegisteredSection {
  explicit RegisteredSection(const GeneratorSection& section);
};

// Every generator section the deck has, in the sections' order.
Generated read_generators(const deck_reader::Deck& deck, SceneSpec& scene);

// The generated blocks after the [[block]] ones; a generated name that a
// [[block]] or an earlier generator's block already has is a DeckError naming
// the generator's section.
void append_generated_blocks(const deck_reader::Deck& deck, const Generated& generated,
                             std::vector<BlockSpec>& blocks);

// ------------------------------------------- the reader of the generators

// How a section's tables are named.
enum class Naming {
  none,    // one table ([spire]); the blocks keep the generator's names
  owned,   // the generator starts every block's name with it: "wallN" by default, no spaces or
           // quotes, unique among the section's tables
  prefix,  // "NAME_" goes before every block's name: "arch" by default ("archN" with several), not empty
};

// What a block's group says (GeneratedBlock's fields): "courseCC" (a base
// or a tip its kind), "faceF", "leafL" or "through", the kind, or the
// table's name.
enum class Grouping { course, face, leaf, kind, section };

struct GeneratorRules {
  std::string_view section;                 // "wall": [[wall]], "spire": [spire] (`single`)
  std::span<const std::string_view> keys;   // its keys; "opening.KEY" are its [[wall.opening]]'s
  int order = 0;                            // GeneratorSection::order
  bool single = false;                      // one [section] table rather than [[section]] tables
  Naming naming = Naming::prefix;
  std::string_view motion_key;              // the supports' motion ("base_motion"); empty: none
  Grouping grouping = Grouping::kind;       // the default grouping
  std::span<const std::pair<std::string_view, Grouping>> group_by;  // `group_by` and `group` keys; empty: none
  std::size_t max_blocks = 0;               // all its tables together build at most this many; 0: no limit
};

// One table of a generator section as the shared reader holds it.
struct GeneratorTable {
  std::string path;                              // "wall[2]"; "spire" for a single table
  const toml::table* table = nullptr;
  std::deque<deck_reader::TableReader> readers;  // [0] the table's, then its openings' (for their errors)
  std::string name;                              // "" with Naming::none
  double density = 2600.0;
  BlockMotion support_motion = BlockMotion::fixed;  // a base's or an abutment's
  Grouping grouping = Grouping::kind;
  std::string group_prefix;

  const deck_reader::TableReader& reader() const { return readers.front(); }
  int line() const { return reader().line(); }
};

// The keys of `rules.keys` directly in the table (prefix empty), or those
// starting with `prefix` ("opening."), without it.
std::vector<std::string_view> keys_under(std::span<const std::string_view> keys, std::string_view prefix);

// An integer key in [lo, hi]; `fallback` when absent.
int integer_in(const deck_reader::TableReader& r, std::string_view key, int fallback, int lo, int hi);

// The [[SECTION.opening]] tables of the table: a reader for each is added to
// table.readers (keys: those of `rules.keys` under "opening."); each must
// have the keys `required` (`why` says which).
void open_openings(const GeneratorRules& rules, GeneratorTable& table,
                   std::initializer_list<std::string_view> required, const std::string& why);

// An opening's sill, width, height and head (a lintel's bearing, an arch's
// voussoirs and ring), as [[wall.opening]] and [[tower.opening]] give them.
template <class Opening>
void read_opening(const deck_reader::TableReader& o, Opening& op) {
  using deck_reader::Range;
  using Head = decltype(op.head);
  op.sill = o.number("sill", 0.0, Range::non_negative);
  op.width = o.number("width", 0.0, Range::positive);
  op.height = o.number("height", 0.0, Range::positive);
  op.head = o.choice<Head>("head", {{"lintel", Head::lintel}, {"arch", Head::arch}}, op.head);
  if (op.head == Head::lintel) {
    for (const char* k : {"voussoirs", "ring"})
      if (o.has(k)) o.fail(k, "applies to head = \"arch\" only");
    op.bearing = o.number("bearing", 0.0, Range::positive);
  } else {
    if (o.has("bearing")) o.fail("bearing", "applies to head = \"lintel\" only");
    op.voussoirs = integer_in(o, "voussoirs", op.voussoirs, 3, 64);
    op.ring = o.number("ring", 0.0, Range::positive);
  }
}

// The tables of the section, [section] (at most one) or [[section]].
std::vector<const toml::table*> generator_tables(const deck_reader::Deck& deck, const GeneratorRules& rules);

// Opens the i-th of `count` tables: its reader and its name.
GeneratorTable open_generator_table(const deck_reader::Deck& deck, const GeneratorRules& rules,
                                    const toml::table& table, std::size_t i, std::size_t count);

// Reads what every generator's table has after its own keys (density,
// supports' motion, grouping) and checks its name against the earlier
// tables'.
void close_generator_table(const GeneratorRules& rules, GeneratorTable& table,
                           std::span<const GeneratorTable> earlier);

// A spec the generator cannot build: a DeckError at `key` of the table (of
// its opening, when the error names one), or, for any other GeometryError,
// at the table as a whole.
[[noreturn]] void fail_spec(const GeneratorTable& table, const GeneratorSpecError& e, std::string_view key);
[[noreturn]] void fail_geometry(const GeneratorRules& rules, const GeneratorTable& table, const GeometryError& e);

// The table's blocks as one part of the deck; `total` counts the section's
// blocks so far (a DeckError past rules.max_blocks).
void add_generated_part(const GeneratorRules& rules, const GeneratorTable& table,
                        const std::vector<GeneratedBlock>& blocks, std::size_t i, std::size_t& total,
                        Generated& out);

// Reads every table of generator G's section. G gives
//   static const GeneratorRules rules;
//   using Spec = ...;   // what a table says
//   static Spec read(GeneratorTable& table, std::vector<Spec>& earlier);
//                       // its own keys; may change earlier tables' specs (a wall's corner)
//   static Model build(const Spec&);   // Model has `blocks`; throws GeneratorSpecError
// and may give
//   static std::string key_of(const GeneratorTable&, const GeneratorSpecError&);
//                       // the deck key of a spec error (default: its field)
//   static void finish(const GeneratorTable&, const Spec&, Model&, Generated&);
//                       // after the build: keys read from the model, the scene's share
// Every table is read before any is built.
template <class G>
void read_generator(const deck_reader::Deck& deck, Generated& out, SceneSpec&) {
  const GeneratorRules& rules = G::rules;
  const std::vector<const toml::table*> found = generator_tables(deck, rules);
  std::vector<GeneratorTable> tables;
  std::vector<typename G::Spec> specs;
  for (std::size_t i = 0; i < found.size(); ++i) {
    GeneratorTable table = open_generator_table(deck, rules, *found[i], i, found.size());
    typename G::Spec spec = G::read(table, specs);
    close_generator_table(rules, table, tables);
    tables.push_back(std::move(table));
    specs.push_back(std::move(spec));
  }
  std::size_t total = 0;
  for (std::size_t i = 0; i < tables.size(); ++i) {
    decltype(G::build(specs[i])) model;
    try {
      model = G::build(specs[i]);
    } catch (const GeneratorSpecError& e) {
      if constexpr (requires { G::key_of(tables[i], e); })
        fail_spec(tables[i], e, G::key_of(tables[i], e));
      else
        fail_spec(tables[i], e, e.field);
    } catch (const GeometryError& e) {
      fail_geometry(rules, tables[i], e);
    }
    if constexpr (requires { G::finish(tables[i], specs[i], model, out); }) G::finish(tables[i], specs[i], model, out);
    add_generated_part(rules, tables[i], model.blocks, i, total, out);
  }
}

// The GeneratorSection of generator G.
template <class G>
GeneratorSection generator_section() {
  return {G::rules.section, G::rules.keys, G::rules.order, &read_generator<G>};
}

}  // namespace polydem
