#pragma once

#include <string>
#include <string_view>

namespace roadscale {

// Why `bytes` (a file starting with the PNG signature) is not a complete PNG: "truncated in
// chunk IDAT", "checksum mismatch in chunk IDAT", "no IEND chunk", ...; empty when every
// chunk is whole with a matching CRC and the file ends with IEND. Checked before decoding
// because libpng prints its own "libpng error: Read Error" line on stderr for a truncated
// file, and the CLI's error must be the only line. Files without the signature are not
// PNGs: also empty (OpenCV decodes or rejects them).
std::string PngStructureProblem(std::string_view bytes);

}  // namespace roadscale
