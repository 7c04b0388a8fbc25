#include "io/generators.hpp"

#include <unordered_map>

namespace polydem {

using namespace deck_reader;

std::span<const GeneratorSection> generator_sections() {
  static const GeneratorSection sections[] = {kSpireSection, kWallSection, kTowerSection, kArchSection, kColumnSection, kImportSection};
  return sections;
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

}  // namespace polydem
