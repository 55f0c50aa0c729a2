// `sled run` writes animation.glb; a reader written here (GLB container, a small JSON parser,
// accessors) reads back what the flagship scene (cut to 20 ms) gives and checks the glTF 2.0
// structure: header and chunks, accessor bounds, one node per vehicle and segment with
// translation and rotation channels over increasing times at every output row, unit
// quaternions, meshes on the unit (hyper-)ellipsoid, and belt pieces that join end to end. The
// head's node follows the head's `position` and `orientation` channels of timeseries.csv.
// Debian packages no glTF validator, so the checks are these.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "tests/compiler/csv_table.h"
#include "tests/compiler/flagship_scene.h"
#include "tests/compiler/mini_json.h"
#include "tests/compiler/sled_process.h"

namespace sled {
namespace {

namespace fs = std::filesystem;
using testing::Json;
using testing::ReadText;
using testing::SledResult;
using testing::WriteText;

using AnimationExport = testing::SledProcessTest;

std::uint32_t Word(const std::string& bytes, std::size_t at) {
  std::uint32_t word = 0;
  for (int i = 3; i >= 0; --i) {
    word = (word << 8) | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(i)]);
  }
  return word;
}

struct Glb {
  Json json;
  std::string bin;

  // An accessor's floats, after checking that it lies inside its view and the view inside the
  // buffer.
  std::vector<float> Floats(int accessor_index, int components) const {
    const Json& accessor = json["accessors"][static_cast<std::size_t>(accessor_index)];
    EXPECT_EQ(accessor["componentType"].Int(), 5126);
    const char* types[] = {"", "SCALAR", "VEC2", "VEC3", "VEC4"};
    EXPECT_EQ(accessor["type"].text, types[components]);
    const Json& view = json["bufferViews"][static_cast<std::size_t>(accessor["bufferView"].Int())];
    const std::size_t offset =
        view.Has("byteOffset") ? static_cast<std::size_t>(view["byteOffset"].number) : 0;
    const auto length = static_cast<std::size_t>(view["byteLength"].number);
    const auto count = static_cast<std::size_t>(accessor["count"].number);
    EXPECT_LE(offset + length, bin.size());
    EXPECT_LE(count * static_cast<std::size_t>(components) * 4, length);
    EXPECT_EQ(offset % 4, 0u);
    std::vector<float> values(count * static_cast<std::size_t>(components));
    if (offset + values.size() * 4 <= bin.size()) {
      std::memcpy(values.data(), bin.data() + offset, values.size() * 4);
    }
    return values;
  }
};

Glb ReadGlb(const fs::path& path) {
  const std::string bytes = ReadText(path);
  Glb glb;
  EXPECT_GE(bytes.size(), 28u);
  if (bytes.size() < 28) return glb;
  EXPECT_EQ(bytes.substr(0, 4), "glTF");
  EXPECT_EQ(Word(bytes, 4), 2u);
  EXPECT_EQ(Word(bytes, 8), bytes.size());
  const std::uint32_t json_length = Word(bytes, 12);
  EXPECT_EQ(bytes.substr(16, 4), "JSON");
  EXPECT_EQ(json_length % 4, 0u);
  glb.json = testing::JsonReader::Parse(bytes.substr(20, json_length));
  const std::size_t bin_at = 20 + json_length;
  const std::uint32_t bin_length = Word(bytes, bin_at);
  EXPECT_EQ(bytes.substr(bin_at + 4, 4), std::string("BIN\0", 4));
  EXPECT_EQ(bin_at + 8 + bin_length, bytes.size());
  glb.bin = bytes.substr(bin_at + 8, bin_length);
  EXPECT_EQ(static_cast<std::size_t>(glb.json["buffers"][0]["byteLength"].number), bin_length);
  return glb;
}

int NodeNamed(const Json& json, const std::string& name) {
  for (std::size_t n = 0; n < json["nodes"].size(); ++n) {
    if (json["nodes"][n].Has("name") && json["nodes"][n]["name"].text == name) {
      return static_cast<int>(n);
    }
  }
  return -1;
}

TEST_F(AnimationExport, TheFlagshipAnimationIsAValidGlbThatFollowsTheRun) {
  const std::string scene = testing::FlagshipScene(
      "20 ms", "    position occupant.head at (0, 0, 0) mm\n    orientation occupant.head\n");
  ASSERT_FALSE(scene.empty());
  WriteText(temp() / "flagship.sled", scene);
  const fs::path out = temp() / "out";
  const SledResult result = Sled({"run", (temp() / "flagship.sled").string(), "-o", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const testing::CsvTable csv = testing::ReadCsv(out / "timeseries.csv");
  ASSERT_EQ(csv.rows.size(), 201u);

  const Glb glb = ReadGlb(out / "animation.glb");
  const Json& json = glb.json;
  EXPECT_EQ(json["asset"]["version"].text, "2.0");

  // The root turns z up into y up; every vehicle and segment hangs from it.
  const Json& roots = json["scenes"][static_cast<std::size_t>(json["scene"].Int())]["nodes"];
  ASSERT_EQ(roots.size(), 1u);
  const Json& world = json["nodes"][static_cast<std::size_t>(roots[0].Int())];
  EXPECT_EQ(world["name"].text, "world");
  EXPECT_NEAR(world["rotation"][0].number, -std::sqrt(0.5), 1e-7);
  EXPECT_NEAR(world["rotation"][3].number, std::sqrt(0.5), 1e-7);
  std::vector<int> world_children;
  for (const Json& child : world["children"].items) world_children.push_back(child.Int());
  for (const char* name : {"sled", "occupant.head", "occupant.pelvis", "occupant.foot_r"}) {
    const int node = NodeNamed(json, name);
    ASSERT_GE(node, 0) << name;
    EXPECT_THAT(world_children, ::testing::Contains(node)) << name;
  }

  // Every accessor with bounds holds values inside them, and attains them.
  for (std::size_t a = 0; a < json["accessors"].size(); ++a) {
    const Json& accessor = json["accessors"][a];
    if (!accessor.Has("min") || accessor["componentType"].Int() != 5126) continue;
    const int components = static_cast<int>(accessor["min"].size());
    const std::vector<float> values = glb.Floats(static_cast<int>(a), components);
    for (int c = 0; c < components; ++c) {
      float low = INFINITY, high = -INFINITY;
      for (std::size_t i = static_cast<std::size_t>(c); i < values.size();
           i += static_cast<std::size_t>(components)) {
        low = std::min(low, values[i]);
        high = std::max(high, values[i]);
      }
      EXPECT_EQ(low, static_cast<float>(accessor["min"][static_cast<std::size_t>(c)].number));
      EXPECT_EQ(high, static_cast<float>(accessor["max"][static_cast<std::size_t>(c)].number));
    }
  }

  // One animation: per animated node, its channels over the shared, increasing times of the rows.
  ASSERT_EQ(json["animations"].size(), 1u);
  const Json& animation = json["animations"][0];
  std::map<int, std::map<std::string, std::vector<float>>> tracks;  // node -> path -> values
  for (const Json& channel : animation["channels"].items) {
    const Json& sampler = animation["samplers"][static_cast<std::size_t>(channel["sampler"].Int())];
    EXPECT_EQ(sampler["interpolation"].text, "LINEAR");
    const std::vector<float> times = glb.Floats(sampler["input"].Int(), 1);
    ASSERT_EQ(times.size(), csv.rows.size());
    for (std::size_t i = 0; i < times.size(); ++i) {
      EXPECT_FLOAT_EQ(times[i], static_cast<float>(csv.rows[i][0]));
      if (i > 0) {
        ASSERT_GT(times[i], times[i - 1]);
      }
    }
    const std::string path = channel["target"]["path"].text;
    const int components = path == "rotation" ? 4 : 3;
    const std::vector<float> values = glb.Floats(sampler["output"].Int(), components);
    ASSERT_EQ(values.size(), times.size() * static_cast<std::size_t>(components));
    if (path == "rotation") {
      for (std::size_t i = 0; i < values.size(); i += 4) {
        const double norm =
            std::sqrt(values[i] * values[i] + values[i + 1] * values[i + 1] +
                      values[i + 2] * values[i + 2] + values[i + 3] * values[i + 3]);
        ASSERT_NEAR(norm, 1.0, 1e-6) << "frame " << i / 4;
      }
    }
    tracks[channel["target"]["node"].Int()][path] = values;
  }
  for (const char* name : {"sled", "occupant.head", "occupant.thorax"}) {
    const int node = NodeNamed(json, name);
    EXPECT_EQ(tracks[node].count("translation"), 1u) << name;
    EXPECT_EQ(tracks[node].count("rotation"), 1u) << name;
  }

  // The head's node follows its centre of mass and its yaw, pitch and roll.
  const auto& head = tracks[NodeNamed(json, "occupant.head")];
  const std::size_t x = csv.Column("occupant.head.position.x [m]");
  const std::size_t yaw = csv.Column("occupant.head.orientation.yaw [rad]");
  ASSERT_LT(x, csv.names.size());
  ASSERT_LT(yaw, csv.names.size());
  for (std::size_t f = 0; f < csv.rows.size(); ++f) {
    for (std::size_t i = 0; i < 3; ++i) {
      ASSERT_NEAR(head.at("translation")[3 * f + i], csv.rows[f][x + i], 2e-6) << f;
    }
    const float* q = &head.at("rotation")[4 * f];
    const Eigen::Matrix3d R =
        Eigen::Quaterniond(q[3], q[0], q[1], q[2]).normalized().toRotationMatrix();
    EXPECT_NEAR(std::atan2(R(1, 0), R(0, 0)), csv.rows[f][yaw], 1e-5) << f;
    EXPECT_NEAR(std::asin(-R(2, 0)), csv.rows[f][yaw + 1], 1e-5) << f;
    EXPECT_NEAR(std::atan2(R(2, 1), R(2, 2)), csv.rows[f][yaw + 2], 1e-5) << f;
  }

  // Belts: line pieces that join end to end at every frame (piece k's end is piece k+1's start).
  std::vector<int> pieces;
  for (std::size_t k = 1;; ++k) {
    const int node = NodeNamed(json, "three_point.lap.piece" + std::to_string(k));
    if (node < 0) break;
    pieces.push_back(node);
  }
  ASSERT_GE(pieces.size(), 2u) << "the lap belt's pieces";
  const Json& line = json["meshes"][static_cast<std::size_t>(
      json["nodes"][static_cast<std::size_t>(pieces[0])]["mesh"].Int())];
  EXPECT_EQ(line["primitives"][0]["mode"].Int(), 1);
  for (std::size_t k = 0; k + 1 < pieces.size(); ++k) {
    const auto& piece = tracks[pieces[k]];
    const auto& next = tracks[pieces[k + 1]];
    ASSERT_EQ(piece.count("scale"), 1u);
    for (std::size_t f = 0; f < csv.rows.size(); ++f) {
      const float* q = &piece.at("rotation")[4 * f];
      const Eigen::Vector3d along = Eigen::Quaterniond(q[3], q[0], q[1], q[2]).normalized() *
                                    Eigen::Vector3d(0, 0, piece.at("scale")[3 * f + 2]);
      for (std::size_t i = 0; i < 3; ++i) {
        ASSERT_NEAR(piece.at("translation")[3 * f + i] + along[static_cast<long>(i)],
                    next.at("translation")[3 * f + i], 2e-5)
            << "piece " << k + 1 << " frame " << f;
      }
    }
  }

  // The head's contact ellipsoid: a child of the head node, a mesh on the unit sphere.
  const Json& head_node = json["nodes"][static_cast<std::size_t>(NodeNamed(json, "occupant.head"))];
  ASSERT_TRUE(head_node.Has("children"));
  const Json& ellipsoid = json["nodes"][static_cast<std::size_t>(head_node["children"][0].Int())];
  ASSERT_TRUE(ellipsoid.Has("mesh"));
  for (std::size_t i = 0; i < 3; ++i) EXPECT_GT(ellipsoid["scale"][i].number, 0.01);
  const Json& primitive =
      json["meshes"][static_cast<std::size_t>(ellipsoid["mesh"].Int())]["primitives"][0];
  EXPECT_EQ(primitive["mode"].Int(), 4);
  const std::vector<float> vertices = glb.Floats(primitive["attributes"]["POSITION"].Int(), 3);
  ASSERT_GT(vertices.size(), 100u);
  for (std::size_t i = 0; i < vertices.size(); i += 3) {
    const double radius = std::sqrt(vertices[i] * vertices[i] + vertices[i + 1] * vertices[i + 1] +
                                    vertices[i + 2] * vertices[i + 2]);
    ASSERT_NEAR(radius, 1.0, 1e-6);
  }
  // The buck's planes hang from the sled: two-triangle quads.
  const Json& sled = json["nodes"][static_cast<std::size_t>(NodeNamed(json, "sled"))];
  ASSERT_TRUE(sled.Has("children"));
  std::size_t quads = 0;
  for (const Json& child : sled["children"].items) {
    const Json& surface = json["nodes"][static_cast<std::size_t>(child.Int())];
    const Json& mesh =
        json["meshes"][static_cast<std::size_t>(surface["mesh"].Int())]["primitives"][0];
    const auto count = [&](int accessor) {
      return json["accessors"][static_cast<std::size_t>(accessor)]["count"].Int();
    };
    if (count(mesh["attributes"]["POSITION"].Int()) == 4 && count(mesh["indices"].Int()) == 6) {
      ++quads;
    }
  }
  EXPECT_GE(quads, 4u);  // seat pan and back, floor, toe board, knee bolster, ...

  // Every segment is drawn (issue 15: the flagship showed no arms, lower legs or neck): its
  // contact ellipsoids, its other ellipsoids, or an ellipsoid of its inertia, `SEGMENT.inertia`.
  std::size_t segments = 0;
  for (const int child : world_children) {
    const Json& node = json["nodes"][static_cast<std::size_t>(child)];
    const std::string name = node["name"].text;
    if (name.rfind("occupant.", 0) != 0) continue;
    ++segments;
    ASSERT_TRUE(node.Has("children")) << name << " is not drawn";
    bool meshed = false;
    for (const Json& shape : node["children"].items) {
      const Json& drawn = json["nodes"][static_cast<std::size_t>(shape.Int())];
      meshed = meshed || drawn.Has("mesh");
    }
    EXPECT_TRUE(meshed) << name << " has no mesh";
  }
  EXPECT_GE(segments, 15u);
}

}  // namespace
}  // namespace sled
