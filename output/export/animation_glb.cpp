#include "output/export/animation_glb.h"

#include <cmath>
#include <map>
#include <vector>

#include <fmt/format.h>

#include "output/export/glb_builder.h"
#include "output/export/shape_meshes.h"
#include "output/output_writer.h"

namespace sled::runtime {
namespace {

constexpr int kBodyMaterial = 0;
constexpr int kSurfaceMaterial = 1;
constexpr int kBeltMaterial = 2;
constexpr int kEllipsoidRings = 16;
constexpr int kEllipsoidSectors = 24;

constexpr const char* kMaterials = R"(  "materials": [
    {"name": "segment", "pbrMetallicRoughness": {"baseColorFactor": [0.85, 0.66, 0.52, 1], "metallicFactor": 0, "roughnessFactor": 0.8}},
    {"name": "surface", "doubleSided": true, "pbrMetallicRoughness": {"baseColorFactor": [0.55, 0.6, 0.68, 1], "metallicFactor": 0, "roughnessFactor": 0.9}},
    {"name": "belt", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.12, 0.1, 1], "metallicFactor": 0, "roughnessFactor": 0.9}}
  ])";

std::string Floats(std::initializer_list<double> values) {
  std::string out;
  for (const double v : values)
    out += (out.empty() ? "" : ", ") + JsonNumber(static_cast<float>(v));
  return out;
}

std::string Indices(const std::vector<int>& values) {
  std::string out;
  for (const int v : values) out += (out.empty() ? "" : ", ") + std::to_string(v);
  return out;
}

// Meshes, nodes and animation channels as they are assembled into the JSON.
class SceneAssembly {
 public:
  explicit SceneAssembly(GlbBuilder& builder) : builder_(builder) {}

  int AddTriangleMesh(const std::string& name, const TriangleMesh& mesh, int material) {
    const int position = builder_.AddFloats(mesh.positions, 3, GlbBuilder::kArrayBuffer, true);
    const int normal = builder_.AddFloats(mesh.normals, 3, GlbBuilder::kArrayBuffer, false);
    const int indices = builder_.AddIndices(mesh.indices);
    meshes_.push_back(fmt::format(
        "{{\"name\": {}, \"primitives\": [{{\"attributes\": {{\"POSITION\": {}, \"NORMAL\": {}}}, "
        "\"indices\": {}, \"material\": {}, \"mode\": 4}}]}}",
        JsonString(name), position, normal, indices, material));
    return static_cast<int>(meshes_.size()) - 1;
  }

  int AddLineMesh(const std::string& name, const std::vector<float>& positions, int material) {
    const int position = builder_.AddFloats(positions, 3, GlbBuilder::kArrayBuffer, true);
    meshes_.push_back(
        fmt::format("{{\"name\": {}, \"primitives\": [{{\"attributes\": {{\"POSITION\": {}}}, "
                    "\"material\": {}, \"mode\": 1}}]}}",
                    JsonString(name), position, material));
    return static_cast<int>(meshes_.size()) - 1;
  }

  // A node; `fields` are its other members (mesh, transform), comma-first.
  int AddNode(const std::string& name, const std::string& fields) {
    nodes_.push_back(fmt::format("{{\"name\": {}{}", JsonString(name), fields));
    children_.emplace_back();
    return static_cast<int>(nodes_.size()) - 1;
  }
  void AddChild(int parent, int child) {
    children_[static_cast<std::size_t>(parent)].push_back(child);
  }

  // A channel of `node`'s `path` (translation, rotation, scale) from the shared time input.
  void AddChannel(int node, const char* path, int input, int output) {
    channels_.push_back(
        fmt::format("{{\"sampler\": {}, \"target\": {{\"node\": {}, \"path\": \"{}\"}}}}",
                    samplers_.size(), node, path));
    samplers_.push_back(fmt::format(
        "{{\"input\": {}, \"output\": {}, \"interpolation\": \"LINEAR\"}}", input, output));
  }

  std::string Members(int root) const {
    std::string out = kMaterials;
    if (!meshes_.empty()) out += ",\n  \"meshes\": [\n    " + Join(meshes_) + "\n  ]";
    std::vector<std::string> nodes;
    for (std::size_t n = 0; n < nodes_.size(); ++n) {
      nodes.push_back(
          nodes_[n] +
          (children_[n].empty() ? "" : fmt::format(", \"children\": [{}]", Indices(children_[n]))) +
          "}");
    }
    out += ",\n  \"nodes\": [\n    " + Join(nodes) + "\n  ]";
    out += fmt::format(
        ",\n  \"scenes\": [{{\"name\": \"sled\", \"nodes\": [{}]}}],\n  \"scene\": 0", root);
    if (!channels_.empty()) {
      out += fmt::format(
          ",\n  \"animations\": [{{\"name\": \"run\", \"channels\": [\n    {}\n  ], \"samplers\": "
          "[\n    {}\n  ]}}]",
          Join(channels_), Join(samplers_));
    }
    return out;
  }

 private:
  static std::string Join(const std::vector<std::string>& items) {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) out += (i ? ",\n    " : "") + items[i];
    return out;
  }

  GlbBuilder& builder_;
  std::vector<std::string> meshes_;
  std::vector<std::string> nodes_;
  std::vector<std::vector<int>> children_;
  std::vector<std::string> channels_;
  std::vector<std::string> samplers_;
};

// Node members for a translation, rotation (x, y, z, w) and scale from a recorded pose.
std::string PoseFields(const float* pose, bool with_scale) {
  std::string out = fmt::format(", \"translation\": [{}, {}, {}], \"rotation\": [{}, {}, {}, {}]",
                                JsonNumber(pose[0]), JsonNumber(pose[1]), JsonNumber(pose[2]),
                                JsonNumber(pose[3]), JsonNumber(pose[4]), JsonNumber(pose[5]),
                                JsonNumber(pose[6]));
  if (with_scale) {
    out += fmt::format(", \"scale\": [{}, {}, {}]", JsonNumber(pose[7]), JsonNumber(pose[8]),
                       JsonNumber(pose[9]));
  }
  return out;
}

// The node that carries a surface fixed in a frame: a proper rotation of the ellipsoid's axes
// (a mirrored set has one axis turned round, which leaves the symmetric shape unchanged).
std::string EllipsoidFields(int mesh, const Vec3& center, const Mat3& axes, const Vec3& semi) {
  Mat3 rotation = axes;
  if (rotation.determinant() < 0) rotation.col(2) = -rotation.col(2);
  const Eigen::Quaterniond q = Eigen::Quaterniond(rotation).normalized();
  return fmt::format(", \"mesh\": {}, \"translation\": [{}], \"rotation\": [{}], \"scale\": [{}]",
                     mesh, Floats({center.x(), center.y(), center.z()}),
                     Floats({q.x(), q.y(), q.z(), q.w()}), Floats({semi.x(), semi.y(), semi.z()}));
}

}  // namespace

bool WriteAnimationGlb(const std::string& path, const Model& model,
                       const AnimationRecorder& recorder, std::string* error) {
  GlbBuilder builder;
  SceneAssembly scene(builder);
  const bool has_frames = recorder.frames() > 0;

  // The root turns z up into y up: -90 degrees about x.
  const double half = std::sqrt(0.5);
  const int root =
      scene.AddNode("world", fmt::format(", \"rotation\": [{}]", Floats({-half, 0.0, 0.0, half})));
  const int ground = scene.AddNode("ground", "");
  scene.AddChild(root, ground);

  // The animated nodes, in the recorder's order, each with its first recorded pose.
  std::vector<int> animated;
  auto add_animated = [&](const std::string& name, std::size_t index, bool with_scale,
                          const std::string& mesh) {
    const std::string pose = has_frames ? PoseFields(recorder.pose(0, index), with_scale) : "";
    const int node = scene.AddNode(name, mesh + pose);
    scene.AddChild(root, node);
    animated.push_back(node);
  };
  for (std::size_t v = 0; v < model.nvehicle(); ++v)
    add_animated(model.vehicle_name[v], v, false, "");
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    add_animated(model.segment_name[s], recorder.nvehicle() + s, false, "");
  }
  if (recorder.nbelt_piece() > 0) {
    const int line = scene.AddLineMesh("belt piece", {0, 0, 0, 0, 0, 1}, kBeltMaterial);
    for (std::size_t p = 0; p < recorder.nbelt_piece(); ++p) {
      add_animated(recorder.belt_piece_name(p), recorder.nvehicle() + recorder.nsegment() + p, true,
                   fmt::format(", \"mesh\": {}", line));
    }
  }

  // The node a surface fixed in `frame` hangs from.
  auto frame_node = [&](const FrameRef& frame) {
    switch (frame.kind) {
      case FrameRef::Kind::kVehicle:
        return animated[static_cast<std::size_t>(frame.index)];
      case FrameRef::Kind::kSegment:
        return animated[recorder.nvehicle() + static_cast<std::size_t>(frame.index)];
      default:
        return ground;
    }
  };
  const ContactTable& contacts = model.contacts;
  std::map<double, int> shape_mesh;  // by degree
  for (std::size_t e = 0; e < contacts.nellipsoid(); ++e) {
    const double degree = std::max(2.0, contacts.ellipsoid_degree[e]);
    auto [it, fresh] = shape_mesh.try_emplace(degree, -1);
    if (fresh) {
      it->second = scene.AddTriangleMesh(
          fmt::format("ellipsoid of degree {}", degree),
          SuperellipsoidMesh(degree, kEllipsoidRings, kEllipsoidSectors), kBodyMaterial);
    }
    const int node =
        scene.AddNode(contacts.ellipsoid_name[e],
                      EllipsoidFields(it->second, contacts.ellipsoid_center[e],
                                      contacts.ellipsoid_axes[e], contacts.ellipsoid_semi_axes[e]));
    scene.AddChild(frame_node(contacts.ellipsoid_frame[e]), node);
  }
  // The segments' other shapes: ellipsoids in no contact, or an ellipsoid of the inertia.
  for (std::size_t k = 0; k < model.shape_name.size(); ++k) {
    const double degree = std::max(2.0, model.shape_degree[k]);
    auto [it, fresh] = shape_mesh.try_emplace(degree, -1);
    if (fresh) {
      it->second = scene.AddTriangleMesh(
          fmt::format("ellipsoid of degree {}", degree),
          SuperellipsoidMesh(degree, kEllipsoidRings, kEllipsoidSectors), kBodyMaterial);
    }
    const int node = scene.AddNode(
        model.shape_name[k], EllipsoidFields(it->second, model.shape_center[k], model.shape_axes[k],
                                             model.shape_semi_axes[k]));
    scene.AddChild(
        frame_node({FrameRef::Kind::kSegment, static_cast<std::int32_t>(model.shape_segment[k])}),
        node);
  }
  for (std::size_t p = 0; p < contacts.nplane(); ++p) {
    const int mesh =
        scene.AddTriangleMesh(contacts.plane_name[p],
                              ParallelogramMesh(contacts.plane_origin[p], contacts.plane_edge_u[p],
                                                contacts.plane_edge_v[p]),
                              kSurfaceMaterial);
    const int node = scene.AddNode(contacts.plane_name[p], fmt::format(", \"mesh\": {}", mesh));
    scene.AddChild(frame_node(contacts.plane_frame[p]), node);
  }

  // Animation: one time input shared by every sampler; each node's values gathered per path.
  if (recorder.frames() > 0) {
    const int input = builder.AddFloats(recorder.times(), 1, GlbBuilder::kNoTarget, true);
    std::vector<float> values;
    for (std::size_t n = 0; n < recorder.nnode(); ++n) {
      const bool belt_piece = n >= recorder.nvehicle() + recorder.nsegment();
      const struct {
        const char* path;
        std::size_t first, count;
      } parts[3] = {{"translation", 0, 3}, {"rotation", 3, 4}, {"scale", 7, 3}};
      for (const auto& part : parts) {
        if (part.first == 7 && !belt_piece) continue;
        values.clear();
        for (std::size_t f = 0; f < recorder.frames(); ++f) {
          const float* pose = recorder.pose(f, n);
          values.insert(values.end(), pose + part.first, pose + part.first + part.count);
        }
        const int output =
            builder.AddFloats(values, static_cast<int>(part.count), GlbBuilder::kNoTarget, false);
        scene.AddChannel(animated[n], part.path, input, output);
      }
    }
  }
  return builder.Write(path, scene.Members(root), error);
}

}  // namespace sled::runtime
