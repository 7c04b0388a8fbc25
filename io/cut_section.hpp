// [[cut]]: 3DEC's `block cut joint-set`. After every block is known (the
// [[block]] tables and the generators' blocks, [[import]]s included), each
// [[cut]] in deck order cuts the blocks it selects by a joint set of
// parallel planes (geometry/cut.hpp: dip, dip direction, origin, spacing,
// count). A cut block is replaced, where it stood in the block list, by its
// pieces "NAME_cut1", "NAME_cut2", ... ordered along the planes' normal;
// they keep its density, motion, course and group (or take the cut's
// `group`), and its velocity field (a piece's centroid moves with
// v + ω × (c_piece - c_block)).
#pragma once

#include "io/deck_reader.hpp"

#include <span>
#include <string_view>
#include <vector>

namespace polydem {

// The keys a [[cut]] accepts (listed by deck_keys()).
std::span<const std::string_view> cut_keys();

// Applies every [[cut]] of the deck, in order, to `blocks`. Throws DeckError
// (file, line, key) on bad input.
void apply_cuts(const deck_reader::Deck& deck, std::vector<BlockSpec>& blocks);

}  // namespace polydem
