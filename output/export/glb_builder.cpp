#include "output/export/glb_builder.h"

#include <algorithm>
#include <cstring>
#include <limits>

#include <fmt/format.h>

#include "output/atomic_file.h"
namespace sled::runtime {
namespace {

constexpr std::uint32_t kMagic = 0x46546C67;      // "glTF"
constexpr std::uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942;   // "BIN\0"

const char* TypeName(int components) {
  switch (components) {
    case 1:
      return "SCALAR";
    case 2:
      return "VEC2";
    case 3:
      return "VEC3";
    default:
      return "VEC4";
  }
}

void PutWord(AtomicFile& out, std::uint32_t word) {
  const unsigned char bytes[4] = {static_cast<unsigned char>(word & 0xff),
                                  static_cast<unsigned char>((word >> 8) & 0xff),
                                  static_cast<unsigned char>((word >> 16) & 0xff),
                                  static_cast<unsigned char>((word >> 24) & 0xff)};
  out.Write(std::string_view(reinterpret_cast<const char*>(bytes), 4));
}

}  // namespace

std::string JsonNumber(float value) { return fmt::format("{}", value); }

int GlbBuilder::AddView(const void* data, std::size_t bytes, int target) {
  const std::size_t offset = buffer_.size();
  buffer_.resize(offset + ((bytes + 3) / 4) * 4, 0);
  if (bytes > 0) std::memcpy(buffer_.data() + offset, data, bytes);
  views_.push_back(fmt::format("{{\"buffer\": 0, \"byteOffset\": {}, \"byteLength\": {}{}}}",
                               offset, bytes,
                               target == kNoTarget ? "" : fmt::format(", \"target\": {}", target)));
  return static_cast<int>(views_.size()) - 1;
}

int GlbBuilder::AddFloats(std::span<const float> values, int components, int target, bool bounds) {
  const int view = AddView(values.data(), values.size_bytes(), target);
  const std::size_t count = values.size() / static_cast<std::size_t>(components);
  std::string extra;
  if (bounds && count > 0) {
    std::vector<float> low(static_cast<std::size_t>(components), std::numeric_limits<float>::max());
    std::vector<float> high(static_cast<std::size_t>(components),
                            std::numeric_limits<float>::lowest());
    for (std::size_t i = 0; i < values.size(); ++i) {
      const std::size_t c = i % static_cast<std::size_t>(components);
      low[c] = std::min(low[c], values[i]);
      high[c] = std::max(high[c], values[i]);
    }
    auto list = [](const std::vector<float>& v) {
      std::string out;
      for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + JsonNumber(v[i]);
      return out;
    };
    extra = fmt::format(", \"min\": [{}], \"max\": [{}]", list(low), list(high));
  }
  accessors_.push_back(fmt::format(
      "{{\"bufferView\": {}, \"componentType\": 5126, \"count\": {}, \"type\": \"{}\"{}}}", view,
      count, TypeName(components), extra));
  return static_cast<int>(accessors_.size()) - 1;
}

int GlbBuilder::AddIndices(std::span<const std::uint32_t> indices) {
  const int view = AddView(indices.data(), indices.size_bytes(), kElementArrayBuffer);
  accessors_.push_back(fmt::format(
      "{{\"bufferView\": {}, \"componentType\": 5125, \"count\": {}, \"type\": \"SCALAR\"}}", view,
      indices.size()));
  return static_cast<int>(accessors_.size()) - 1;
}

bool GlbBuilder::Write(const std::string& path, const std::string& members,
                       std::string* error) const {
  auto join = [](const std::vector<std::string>& items) {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) out += (i ? ",\n    " : "\n    ") + items[i];
    return out;
  };
  std::string json = "{\n  \"asset\": {\"version\": \"2.0\", \"generator\": \"sled\"},\n";
  // A buffer holds at least one byte.
  std::vector<unsigned char> bin = buffer_;
  if (bin.empty()) bin.resize(4, 0);
  json += fmt::format("  \"buffers\": [{{\"byteLength\": {}}}],\n", bin.size());
  json += fmt::format("  \"bufferViews\": [{}\n  ],\n", join(views_));
  json += fmt::format("  \"accessors\": [{}\n  ],\n", join(accessors_));
  json += members + "\n}";
  json.resize((json.size() + 3) / 4 * 4, ' ');  // the JSON chunk is padded with spaces

  AtomicFile out(path);
  const std::size_t total = 12 + 8 + json.size() + 8 + bin.size();
  PutWord(out, kMagic);
  PutWord(out, 2);
  PutWord(out, static_cast<std::uint32_t>(total));
  PutWord(out, static_cast<std::uint32_t>(json.size()));
  PutWord(out, kJsonChunk);
  out.Write(json);
  PutWord(out, static_cast<std::uint32_t>(bin.size()));
  PutWord(out, kBinChunk);
  out.Write(std::string_view(reinterpret_cast<const char*>(bin.data()), bin.size()));
  return out.Commit(error);
}

}  // namespace sled::runtime
