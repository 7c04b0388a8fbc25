// The deck reader: TOML text -> SceneSpec, validated once.
//
// A deck is TOML with SI units and angles in degrees; docs/deck.md lists
// every section and key (a test keeps that reference and deck_keys() equal).
// Reading goes: parse the TOML (syntax errors keep their line) -> apply the
// command-line overrides ("--set key.path=value") to the parsed table ->
// validate every section while filling the structs of core/scene_spec.hpp.
// Validation is always on and stops at the first problem with a DeckError
// whose message names the file, the line and the full key path:
//
//   examples/x.toml:12: key 'block[2].density': must be > 0 (got -5)
//
// A value that came from an override has no line; its error names the
// override instead:
//
//   examples/x.toml: --set key 'block[1].density': must be > 0 (got -5)
//
// Indices in key paths ([[block]], [[check]], array elements) are 1-based,
// in messages and in overrides alike.
#pragma once

#include "core/scene_spec.hpp"
#include "run/scene_error.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace polydem {

// A deck that cannot be read or is invalid. The message is complete and
// meant for the user as is ("FILE:LINE: key 'section.key': what is wrong").
struct DeckError : std::runtime_error {
  using runtime_error::runtime_error;
};

// Reads the deck file at `path`, then as parse_deck(). Throws DeckError
// (also when the file cannot be opened).
SceneSpec read_deck(const std::string& path, const std::vector<std::string>& overrides = {});

// Parses deck `text`. `path_for_messages` names the deck in messages, is
// stored as SceneSpec::deck_path and is the directory that relative record
// paths are resolved against. `overrides` are "key.path=value" strings
// (e.g. "simulation.end_time=2", "block[1].density=2000" or
// "block.1.density=2000"); each value is read as a TOML value, or as a
// string when it is not valid TOML, and replaces the deck's value before
// validation. Throws DeckError.
SceneSpec parse_deck(const std::string& text, const std::string& path_for_messages,
                     const std::vector<std::string>& overrides = {});

// Finds the line of `key` (its last part, e.g. "time_step") in the deck
// text; 0 if absent (the value came from an override).
int deck_line_of(const std::string& deck_text, const std::string& key);

// The message of an error found when the scene was set up (run/), located
// in the deck: "FILE:LINE: key '...': what", or "FILE: --set key '...'" when
// the value came from an override.
std::string locate_scene_error(const SceneError& error, const SceneSpec& spec);

// The built-in default deck (the main job: the spire under a rising
// acceleration), as TOML text: examples/default.toml, compiled in.
const std::string& default_deck_text();
inline constexpr const char* kDefaultDeckName = "<built-in default deck>";

// Every key the reader accepts, as "section.key" with arrays of tables
// unindexed ("simulation.end_time", "block.shape", "check.kind").
std::vector<std::string> deck_keys();

}  // namespace polydem
