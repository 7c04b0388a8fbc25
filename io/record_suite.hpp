// Reads a record suite file (TOML; docs/records.md, "Record suites") into
// core/record_suite.hpp's RecordSuite, reading every record it names.
#pragma once

#include "core/record_suite.hpp"

#include <string>

namespace polydem {

// Reads and checks the suite at `path`: unknown keys, wrong types, a scale
// that is not > 0, a zero direction, a missing record file, a record the
// readers refuse (io/ground_motion_record.hpp) are errors. Throws DeckError
// (io/deck.hpp) whose message names the suite file, the line and the key
// ("suite.toml:7: key 'record[2].scale': must be > 0 (got -1)"); a record's
// own error follows its key.
RecordSuite read_record_suite(const std::string& path);

// The same from `text`; relative record paths are resolved against the
// directory of `path_for_messages`.
RecordSuite parse_record_suite(const std::string& text, const std::string& path_for_messages);

}  // namespace polydem
