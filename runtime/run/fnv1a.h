// FNV-1a: a stable 64-bit hash of bytes (std::hash may differ between library versions). The
// checkpoints' checksum and the sweep folder's record of the scene files use it.
#pragma once

#include <cstdint>
#include <string_view>

namespace sled::runtime {

inline std::uint64_t Fnv1a(std::string_view text) {
  std::uint64_t hash = 14695981039346656037ull;
  for (const char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ull;
  }
  return hash;
}

}  // namespace sled::runtime
