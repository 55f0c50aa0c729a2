// A glTF 2.0 binary (.glb) under construction: one buffer (the BIN chunk) holding every accessor,
// each in a buffer view of its own, 4-byte aligned. The caller adds the accessors, then writes
// the file with the rest of the JSON (scenes, nodes, meshes, materials, animations).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace sled::runtime {

class GlbBuilder {
 public:
  // bufferView targets.
  static constexpr int kNoTarget = 0;
  static constexpr int kArrayBuffer = 34962;         // vertex attributes
  static constexpr int kElementArrayBuffer = 34963;  // indices

  // Floats in groups of `components` (1: SCALAR, 3: VEC3, 4: VEC4); min and max per component
  // are written when `bounds` (positions and animation inputs need them). The accessor's index.
  int AddFloats(std::span<const float> values, int components, int target, bool bounds);
  // Unsigned 32-bit vertex indices.
  int AddIndices(std::span<const std::uint32_t> indices);

  // The whole file: the asset header, buffer, bufferViews and accessors, then `members` (more
  // top-level JSON members, comma-separated, without the braces). False with `error` set when
  // the file cannot be written.
  bool Write(const std::string& path, const std::string& members, std::string* error) const;

 private:
  int AddView(const void* data, std::size_t bytes, int target);

  std::vector<unsigned char> buffer_;
  std::vector<std::string> views_;
  std::vector<std::string> accessors_;
};

// A JSON number from a float: the shortest text that reads back to it.
std::string JsonNumber(float value);

}  // namespace sled::runtime
