// libFuzzer targets: the block file readers of io/block_files.hpp ([[import]]).
// Built three times from this file:
//   polydem_fuzz_obj   parse_obj()   (Wavefront OBJ text)
//   polydem_fuzz_ply   parse_ply()   (PLY, ASCII or binary)
//   polydem_fuzz_vtu   parse_vtu()   (VTK XML unstructured grid, polyhedral cells)
// (POLYDEM_FUZZ_PLY or POLYDEM_FUZZ_VTU selects the second or third).
//
// Contract under test: any bytes either give parts or throw BlockFileError;
// each part then becomes a valid block (validate() passes) or is refused
// with a BlockFileError. Anything else escaping, a crash, a sanitizer report
// or a hang is a finding.
#include "io/block_files.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 64 * 1024) return -1;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
#if defined(POLYDEM_FUZZ_PLY)
    const polydem::BlockFile f = polydem::parse_ply(text, "fuzz.ply");
#elif defined(POLYDEM_FUZZ_VTU)
    const polydem::BlockFile f = polydem::parse_vtu(text, "fuzz.vtu");
#else
    const polydem::BlockFile f = polydem::parse_obj(text, "fuzz.obj");
#endif
    for (std::size_t i = 0; i < f.parts.size(); ++i) {
      try {
        polydem::validate(polydem::part_block(f, i));
      } catch (const polydem::BlockFileError&) {
        // a part refused with its reason: accepted
      }
    }
  } catch (const polydem::BlockFileError&) {
    // a clear error: accepted
  }
  return 0;
}
