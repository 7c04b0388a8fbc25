// Input found bad only when the scene is set up: a time step above the
// critical one, blocks overlapping at the start, a check that does not fit
// the scene. run/ knows no file, so the error names the deck key (and, for a
// block or a check, the line of its table in the deck, which the deck reader
// stored in the spec); the command line turns it into "FILE:LINE: key ..."
// with io/deck.hpp's locate_scene_error().
#pragma once

#include <stdexcept>
#include <string>

namespace polydem {

struct SceneError : std::runtime_error {
  // key: the deck key, as in docs/deck.md ("simulation.time_step", "block",
  // "check[2].block"); label: a qualifier printed after it ("('stone 3')");
  // deck_line: the line of the key's table when known, 0 when the deck text
  // must be searched for the key; detail: what is wrong.
  SceneError(std::string key, std::string label, int deck_line, std::string detail)
      : std::runtime_error("key '" + key + "'" + (label.empty() ? "" : " " + label) + ": " + detail),
        key(std::move(key)),
        deck_line(deck_line) {}
  std::string key;
  int deck_line = 0;
};

}  // namespace polydem
