// Deck sections that generate blocks: [spire] (io/spire_section.cpp),
// [[wall]] (io/wall_section.cpp) and [[tower]] (io/tower_section.cpp);
// arches and columns join here. The deck reader knows them only through
// this table: each has a section name, the keys it accepts
// (checked like every section's, listed by deck_keys()), and a reader that
// adds its blocks to a Generated part (and may set the joints' defaults from
// its materials, and its own fields of the SceneSpec).
//
// Adding a generator: the geometry in geometry/ (CGAL inside its .cpp), a
// section reader io/NAME_section.cpp with its keys, one row in
// generator_sections() (io/generators.cpp), docs/deck.md, and tests.
#pragma once

#include "io/deck_reader.hpp"
#include "structures/generator_specs.hpp"

#include <optional>
#include <span>
#include <string>
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
  // Reads the section if the deck has it (does nothing otherwise).
  void (*read)(const deck_reader::Deck& deck, Generated& out, SceneSpec& scene);
};

std::span<const GeneratorSection> generator_sections();

// A generator's blocks as one part of the deck: `spec_of(block)` gives each
// BlockSpec's name, shape, motion, course and group; the density and the
// deck line are the section's, the same for every block.
template <class Block, class SpecOf>
Generated::Part generated_part(std::string section, const toml::node* at, int deck_line, double density,
                               const std::vector<Block>& blocks, SpecOf&& spec_of) {
  Generated::Part part;
  part.section = std::move(section);
  part.at = at;
  part.deck_line = deck_line;
  part.blocks.reserve(blocks.size());
  for (const Block& g : blocks) {
    BlockSpec b = spec_of(g);
    b.density = density;
    b.deck_line = deck_line;
    part.blocks.push_back(std::move(b));
  }
  return part;
}

// The name of section `table` (the i-th, 0-based, of `kind`) must differ
// from the earlier sections' names (their block names start with it): a
// DeckError at KIND[i].name naming the earlier one and its line. `earlier`
// are sections with `spec.name` and `line`.
template <class Section>
void require_new_section_name(const deck_reader::Deck& deck, std::string_view kind, const toml::table& table,
                              std::size_t i, const std::string& name, const std::vector<Section>& earlier) {
  for (std::size_t j = 0; j < earlier.size(); ++j) {
    if (earlier[j].spec.name != name) continue;
    const toml::node* at = table.get("name");
    std::string what(kind);
    what.append(" ").append(deck_reader::in_quotes(name)).append(" is also the name of ");
    what.append(deck_reader::indexed(kind, j + 1)).append(" at line ").append(std::to_string(earlier[j].line));
    what.append(" (block names start with it)");
    deck.fail(deck_reader::indexed(kind, i + 1) + ".name", at ? at : &table, what);
  }
}

// Every generator section the deck has, in the table's order.
Generated read_generators(const deck_reader::Deck& deck, SceneSpec& scene);

// The generated blocks after the [[block]] ones; a generated name that a
// [[block]] or an earlier generator's block already has is a DeckError naming
// the generator's section.
void append_generated_blocks(const deck_reader::Deck& deck, const Generated& generated,
                             std::vector<BlockSpec>& blocks);

// [spire] (io/spire_section.cpp).
extern const GeneratorSection kSpireSection;
// [[wall]] (io/wall_section.cpp).
extern const GeneratorSection kWallSection;
// [[tower]] (io/tower_section.cpp).
extern const GeneratorSection kTowerSection;
// [[arch]] (io/arch_section.cpp).
extern const GeneratorSection kArchSection;
// [[column]] (io/column_section.cpp).
extern const GeneratorSection kColumnSection;
// [[import]] (io/import_section.cpp): blocks from OBJ, PLY and VTU files.
extern const GeneratorSection kImportSection;

}  // namespace polydem
