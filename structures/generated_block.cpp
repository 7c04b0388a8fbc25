#include "structures/generated_block.hpp"

namespace polydem {

const char* to_string(BlockKind kind) {
  switch (kind) {
    case BlockKind::unit: return "unit";
    case BlockKind::header: return "header";
    case BlockKind::through_stone: return "through_stone";
    case BlockKind::closer: return "closer";
    case BlockKind::apex: return "apex";
    case BlockKind::stone: return "stone";
    case BlockKind::window_piece: return "window_piece";
    case BlockKind::tip: return "tip";
    case BlockKind::jamb: return "jamb";
    case BlockKind::lintel: return "lintel";
    case BlockKind::voussoir: return "voussoir";
    case BlockKind::base: return "base";
    case BlockKind::abutment: return "abutment";
    case BlockKind::pier: return "pier";
    case BlockKind::plinth: return "plinth";
    case BlockKind::drum: return "drum";
    case BlockKind::capital: return "capital";
  }
  return "?";
}

}  // namespace polydem
