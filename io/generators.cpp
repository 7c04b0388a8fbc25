#include "io/generators.hpp"

namespace polydem {

using namespace deck_reader;

std::span<const GeneratorSection> generator_sections() {
  static const GeneratorSection sections[] = {kSpireSection, kWallSection, kTowerSection};
  return sections;
}

Generated read_generators(const Deck& deck, SceneSpec& scene) {
  Generated g;
  for (const GeneratorSection& s : generator_sections()) s.read(deck, g, scene);
  return g;
}

void append_generated_blocks(const Deck& deck, const Generated& generated, std::vector<BlockSpec>& blocks) {
  const std::size_t n_listed = blocks.size();
  for (const Generated::Part& part : generated.parts) {
    for (const BlockSpec& gb : part.blocks) {
      for (std::size_t i = 0; i < n_listed; ++i)
        if (const BlockSpec& b = blocks[i]; b.name == gb.name) {
          std::string what = "generated block ";
          what.append(in_quotes(gb.name)).append(" has the name of the [[block]] at line ");
          what.append(std::to_string(b.deck_line)).append("; rename that block");
          deck.fail(part.section, part.at, what);
        }
      blocks.push_back(gb);
    }
  }
}

}  // namespace polydem
