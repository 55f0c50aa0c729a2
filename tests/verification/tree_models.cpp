#include "tests/verification/tree_models.h"

#include <cmath>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>
#include <Eigen/Eigenvalues>

#include "tests/runtime/model_fixtures.h"

namespace sled::verification {
namespace {

using runtime::JointKind;
using runtime::Mat3;
using runtime::Vec3;

// splitmix64: the same numbers on every platform and standard library.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t Next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double Uniform(double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(Next() >> 11) * 0x1.0p-53;
  }
  Vec3 UnitVector() {
    for (;;) {
      const Vec3 v(Uniform(-1, 1), Uniform(-1, 1), Uniform(-1, 1));
      const double norm = v.norm();
      if (norm > 0.1 && norm <= 1.0) return v / norm;
    }
  }
  Eigen::Quaterniond TurnUpTo(double max_angle) {
    return Eigen::Quaterniond(Eigen::AngleAxisd(Uniform(-max_angle, max_angle), UnitVector()));
  }

 private:
  std::uint64_t state_;
};

Mat3 Rx(double angle) { return Eigen::AngleAxisd(angle, Vec3::UnitX()).toRotationMatrix(); }
Mat3 Ry(double angle) { return Eigen::AngleAxisd(angle, Vec3::UnitY()).toRotationMatrix(); }
Mat3 Rz(double angle) { return Eigen::AngleAxisd(angle, Vec3::UnitZ()).toRotationMatrix(); }

TreeSegment Segment(std::string name, int parent, JointKind joint, double mass,
                    const Vec3& principal_inertia, const Vec3& point_in_parent,
                    const Vec3& point_in_child) {
  TreeSegment s;
  s.name = std::move(name);
  s.parent = parent;
  s.joint = joint;
  s.mass = mass;
  s.inertia = principal_inertia.asDiagonal();
  s.point_in_parent = point_in_parent;
  s.point_in_child = point_in_child;
  return s;
}

// The principal moments of a uniform box: they always satisfy the triangle inequality.
Vec3 BoxInertia(double mass, const Vec3& size) {
  const Vec3 s2 = size.cwiseProduct(size);
  return mass / 12.0 * Vec3(s2.y() + s2.z(), s2.x() + s2.z(), s2.x() + s2.y());
}

std::string Number(double x) { return fmt::format("{:.17g}", x); }
std::string Triple(const Vec3& v) {
  return fmt::format("{} {} {}", Number(v.x()), Number(v.y()), Number(v.z()));
}

void EmitBody(const BodyTree& tree, const std::vector<std::vector<int>>& children, int index,
              int depth, std::string& out) {
  const TreeSegment& s = tree.segments[static_cast<std::size_t>(index)];
  const std::string indent(static_cast<std::size_t>(2 * depth + 4), ' ');
  // MuJoCo places the child body in the parent at q = 0; its joints then turn it about the joint
  // point, which is given in the child body frame. sled: R_PC = F_P R_J F_C^T, so the fixed part
  // is F_P F_C^T and the joint acts in the child body frame as F_C R_J F_C^T.
  Vec3 position = tree.root_position;
  Mat3 rotation = Mat3::Identity();
  if (s.parent >= 0) {
    rotation = s.frame_in_parent * s.frame_in_child.transpose();
    position = s.point_in_parent - rotation * s.point_in_child;
  }
  const Eigen::Quaterniond quat(rotation);
  out += fmt::format("{}<body name=\"{}\" pos=\"{}\" quat=\"{} {} {} {}\">\n", indent, s.name,
                     Triple(position), Number(quat.w()), Number(quat.x()), Number(quat.y()),
                     Number(quat.z()));
  const std::string joint_name = "j_" + s.name;
  switch (s.joint) {
    case JointKind::kFree:
      out += fmt::format("{}  <freejoint name=\"{}\"/>\n", indent, joint_name);
      break;
    case JointKind::kBall:
      out += fmt::format("{}  <joint name=\"{}\" type=\"ball\" pos=\"{}\"/>\n", indent, joint_name,
                         Triple(s.point_in_child));
      break;
    case JointKind::kPin:
      out += fmt::format("{}  <joint name=\"{}\" type=\"hinge\" pos=\"{}\" axis=\"{}\"/>\n", indent,
                         joint_name, Triple(s.point_in_child),
                         Triple(s.frame_in_child * s.axis.normalized()));
      break;
    default:
      throw std::logic_error("BuildMjcf: segment " + s.name + " has an unsupported joint kind");
  }
  // A full inertia is given as principal moments and axes: MuJoCo's own diagonalization of
  // fullinertia is only good to about 1e-7, Eigen's iterative solver to rounding error.
  const Mat3& I = s.inertia;
  if (I(0, 1) == 0 && I(0, 2) == 0 && I(1, 2) == 0) {
    out += fmt::format("{}  <inertial pos=\"0 0 0\" mass=\"{}\" diaginertia=\"{}\"/>\n", indent,
                       Number(s.mass), Triple(I.diagonal()));
  } else {
    const Eigen::SelfAdjointEigenSolver<Mat3> eigen(I);
    Mat3 axes = eigen.eigenvectors();
    if (axes.determinant() < 0) axes.col(2) = -axes.col(2);
    const Eigen::Quaterniond principal(axes);
    out += fmt::format(
        "{}  <inertial pos=\"0 0 0\" quat=\"{} {} {} {}\" mass=\"{}\" diaginertia=\"{}\"/>\n",
        indent, Number(principal.w()), Number(principal.x()), Number(principal.y()),
        Number(principal.z()), Number(s.mass), Triple(eigen.eigenvalues()));
  }
  for (const int child : children[static_cast<std::size_t>(index)]) {
    EmitBody(tree, children, child, depth + 1, out);
  }
  out += fmt::format("{}</body>\n", indent);
}

}  // namespace

BodyTree CvsBody() {
  BodyTree tree;
  tree.name = "cvs15";
  tree.root_position = Vec3(0, 0, 0.95);
  auto& s = tree.segments;
  constexpr JointKind kFree = JointKind::kFree, kBall = JointKind::kBall, kPin = JointKind::kPin;
  // Masses [kg] sum to 78.0; principal moments [kg m^2] about the centre of mass.
  s.push_back(
      Segment("pelvis", -1, kFree, 11.9, Vec3(0.12, 0.10, 0.14), Vec3::Zero(), Vec3::Zero()));
  s.push_back(Segment("center_torso", 0, kBall, 10.4, Vec3(0.11, 0.08, 0.15), Vec3(0, 0, 0.10),
                      Vec3(0, 0, -0.08)));
  s.push_back(Segment("upper_torso", 1, kBall, 17.5, Vec3(0.25, 0.20, 0.22), Vec3(0, 0, 0.10),
                      Vec3(0.01, 0, -0.15)));
  s.push_back(Segment("neck", 2, kBall, 1.1, Vec3(0.0025, 0.0025, 0.0020), Vec3(0.01, 0, 0.22),
                      Vec3(0, 0, -0.05)));
  s.push_back(Segment("head", 3, kBall, 4.5, Vec3(0.022, 0.025, 0.017), Vec3(0, 0, 0.05),
                      Vec3(-0.02, 0, -0.06)));
  for (const double side : {1.0, -1.0}) {
    const std::string prefix = side > 0 ? "left_" : "right_";
    const int upper_arm = static_cast<int>(s.size());
    s.push_back(Segment(prefix + "upper_arm", 2, kBall, 2.0, Vec3(0.013, 0.013, 0.0025),
                        Vec3(0, side * 0.19, 0.15), Vec3(0, 0, 0.14)));
    // The shoulder's joint frame leans outwards (the neutral posture is unchanged).
    s.back().frame_in_parent = Rx(-side * 0.25);
    s.back().frame_in_child = Rx(-side * 0.25);
    s.push_back(Segment(prefix + "lower_arm", upper_arm, kPin, 1.9, Vec3(0.012, 0.012, 0.0015),
                        Vec3(0, 0, -0.15), Vec3(0, 0, 0.13)));
    if (side > 0) {
      // A carrying angle at the left elbow: the pin axis turned about the vertical.
      s.back().frame_in_parent = Rz(0.3);
      s.back().frame_in_child = Rz(0.3);
    }
  }
  for (const double side : {1.0, -1.0}) {
    const std::string prefix = side > 0 ? "left_" : "right_";
    const int upper_leg = static_cast<int>(s.size());
    s.push_back(Segment(prefix + "upper_leg", 0, kBall, 7.7, Vec3(0.12, 0.12, 0.025),
                        Vec3(0, side * 0.09, -0.08), Vec3(0, 0, 0.19)));
    s.push_back(Segment(prefix + "lower_leg", upper_leg, kPin, 3.5, Vec3(0.045, 0.045, 0.006),
                        Vec3(0, 0, -0.22), Vec3(0, 0, 0.19)));
    // The knee stands slightly flexed at zero angle.
    s.back().frame_in_parent = Ry(0.05);
    s.push_back(Segment(prefix + "foot", upper_leg + 1, kBall, 1.2, Vec3(0.0012, 0.0045, 0.0045),
                        Vec3(0, 0, -0.24), Vec3(-0.05, 0, 0.04)));
  }
  return tree;
}

BodyTree Chain(int n) {
  if (n < 1) throw std::invalid_argument("Chain: needs at least one segment");
  BodyTree tree;
  tree.name = fmt::format("chain{}", n);
  tree.root_position = Vec3(0, 0, 1);
  Random random(0x5EED0000u + static_cast<std::uint64_t>(n));
  for (int k = 0; k < n; ++k) {
    TreeSegment s;
    s.name = fmt::format("link{}", k);
    s.parent = k - 1;
    s.joint = k == 0 ? JointKind::kFree : (k % 3 == 0 ? JointKind::kPin : JointKind::kBall);
    s.mass = random.Uniform(0.5, 3.0);
    const Vec3 size(random.Uniform(0.05, 0.3), random.Uniform(0.05, 0.3),
                    random.Uniform(0.05, 0.3));
    const Mat3 principal = random.TurnUpTo(1.0).toRotationMatrix();
    s.inertia = principal * BoxInertia(s.mass, size).asDiagonal() * principal.transpose();
    if (k > 0) {
      s.point_in_parent = Vec3(random.Uniform(-0.03, 0.03), random.Uniform(-0.03, 0.03),
                               random.Uniform(-0.15, -0.09));
      s.point_in_child = Vec3(random.Uniform(-0.03, 0.03), random.Uniform(-0.03, 0.03),
                              random.Uniform(0.09, 0.15));
      s.frame_in_parent = random.TurnUpTo(0.5).toRotationMatrix();
      s.frame_in_child = random.TurnUpTo(0.5).toRotationMatrix();
      s.axis = random.UnitVector();
    }
    tree.segments.push_back(std::move(s));
  }
  return tree;
}

runtime::Model BuildModel(const BodyTree& tree) {
  runtime::Model model;
  model.title = tree.name;
  model.gravity = tree.gravity;
  for (const TreeSegment& s : tree.segments) {
    if ((s.parent < 0) != (s.joint == JointKind::kFree)) {
      throw std::logic_error("BuildModel: " + s.name + ": only the root has a free joint");
    }
    const std::size_t index =
        runtime::testing::AddSegment(model, s.name, s.parent, s.joint, s.mass, s.inertia.diagonal(),
                                     s.point_in_parent, s.point_in_child, s.axis);
    model.segment_inertia[index] = s.inertia;
    model.joint_frame_in_parent[index] = s.frame_in_parent;
    model.joint_frame_in_child[index] = s.frame_in_child;
    model.joint_name[index] = "j_" + s.name;
    if (s.parent < 0) {
      const auto qa = static_cast<std::size_t>(model.q_address[index]);
      for (int k = 0; k < 3; ++k)
        model.q0[qa + static_cast<std::size_t>(k)] = tree.root_position[k];
    }
  }
  return model;
}

std::string BuildMjcf(const BodyTree& tree) {
  std::vector<std::vector<int>> children(tree.segments.size());
  std::vector<int> roots;
  for (std::size_t k = 0; k < tree.segments.size(); ++k) {
    const int parent = tree.segments[k].parent;
    (parent < 0 ? roots : children[static_cast<std::size_t>(parent)])
        .push_back(static_cast<int>(k));
  }
  std::string out = fmt::format("<mujoco model=\"{}\">\n", tree.name);
  out += "  <compiler angle=\"radian\"/>\n";
  out += fmt::format("  <option gravity=\"{}\">\n", Triple(tree.gravity));
  out += "    <flag contact=\"disable\"/>\n";
  out += "  </option>\n";
  out += "  <worldbody>\n";
  for (const int root : roots) EmitBody(tree, children, root, 0, out);
  out += "  </worldbody>\n";
  out += "</mujoco>\n";
  return out;
}

void SetRandomState(const runtime::Model& model, std::uint64_t seed, runtime::Data& data) {
  Random random(seed);
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    const auto qa = static_cast<std::size_t>(model.q_address[s]);
    const auto va = static_cast<std::size_t>(model.v_address[s]);
    double* q = data.q.data() + qa;
    switch (model.joint_kind[s]) {
      case JointKind::kFree: {
        for (int k = 0; k < 3; ++k) q[k] = random.Uniform(-1, 1);
        Eigen::Vector4d quat;
        do {
          quat = Eigen::Vector4d(random.Uniform(-1, 1), random.Uniform(-1, 1),
                                 random.Uniform(-1, 1), random.Uniform(-1, 1));
        } while (quat.norm() < 0.1 || quat.norm() > 1.0);
        quat.normalize();
        for (int k = 0; k < 4; ++k) q[3 + k] = quat[k];
        break;
      }
      case JointKind::kBall: {
        const Eigen::Quaterniond quat = random.TurnUpTo(1.0);
        q[0] = quat.w();
        q[1] = quat.x();
        q[2] = quat.y();
        q[3] = quat.z();
        break;
      }
      default:
        for (int k = 0; k < model.q_count[s]; ++k) q[k] = random.Uniform(-1, 1);
        break;
    }
    for (int k = 0; k < model.v_count[s]; ++k) {
      data.v[va + static_cast<std::size_t>(k)] = random.Uniform(-2, 2);
    }
  }
}

MujocoModelPtr LoadMjcf(const std::string& xml, std::string* error) {
  // mjVFS holds 2000 file names of 1000 characters: too large for the stack.
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  const char* kFile = "tree.xml";
  if (mj_makeEmptyFileVFS(vfs.get(), kFile, static_cast<int>(xml.size())) != 0) {
    if (error) *error = "cannot make a MuJoCo virtual file";
    return nullptr;
  }
  const int file = mj_findFileVFS(vfs.get(), kFile);
  std::memcpy(vfs->filedata[file], xml.data(), xml.size());
  char message[1000] = "";
  MujocoModelPtr m(mj_loadXML(kFile, vfs.get(), message, sizeof message));
  mj_deleteVFS(vfs.get());
  if (!m && error) *error = message;
  return m;
}

MujocoMap MapToMujoco(const BodyTree& tree, const mjModel* m) {
  MujocoMap map;
  for (const TreeSegment& s : tree.segments) {
    const int body = mj_name2id(m, mjOBJ_BODY, s.name.c_str());
    const int joint = mj_name2id(m, mjOBJ_JOINT, ("j_" + s.name).c_str());
    if (body < 0 || joint < 0) {
      throw std::logic_error("MapToMujoco: no MuJoCo body or joint for segment " + s.name);
    }
    map.body.push_back(body);
    map.qpos_address.push_back(m->jnt_qposadr[joint]);
    map.dof_address.push_back(m->jnt_dofadr[joint]);
  }
  return map;
}

void CopyStateToMujoco(const BodyTree& tree, const runtime::Model& model, const runtime::Data& data,
                       const MujocoMap& map, const mjModel* m, mjData* d) {
  (void)m;
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    const double* q = data.q.data() + model.q_address[s];
    const double* v = data.v.data() + model.v_address[s];
    double* qpos = d->qpos + map.qpos_address[s];
    double* qvel = d->qvel + map.dof_address[s];
    switch (model.joint_kind[s]) {
      case JointKind::kFree: {
        for (int k = 0; k < 7; ++k) qpos[k] = q[k];
        const Mat3 R = Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized().toRotationMatrix();
        const Vec3 velocity_world = R * Vec3(v[3], v[4], v[5]);
        for (int k = 0; k < 3; ++k) {
          qvel[k] = velocity_world[k];
          qvel[3 + k] = v[k];
        }
        break;
      }
      case JointKind::kBall: {
        const Eigen::Quaterniond frame(tree.segments[s].frame_in_child);
        const Eigen::Quaterniond joint(q[0], q[1], q[2], q[3]);
        const Eigen::Quaterniond in_body = frame * joint * frame.conjugate();
        qpos[0] = in_body.w();
        qpos[1] = in_body.x();
        qpos[2] = in_body.y();
        qpos[3] = in_body.z();
        for (int k = 0; k < 3; ++k) qvel[k] = v[k];
        break;
      }
      case JointKind::kPin:
        qpos[0] = q[0];
        qvel[0] = v[0];
        break;
      default:
        throw std::logic_error("CopyStateToMujoco: unsupported joint kind");
    }
  }
}

std::vector<double> AccelerationsAsMujocoQacc(const runtime::Model& model,
                                              const runtime::Data& data, const MujocoMap& map,
                                              const mjModel* m) {
  std::vector<double> qacc(static_cast<std::size_t>(m->nv), 0.0);
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    const auto va = static_cast<std::size_t>(model.v_address[s]);
    const auto mv = static_cast<std::size_t>(map.dof_address[s]);
    if (model.joint_kind[s] == JointKind::kFree) {
      // vdot is the spatial acceleration in segment coordinates; the centre of mass accelerates
      // by a + w x v (segment coordinates), and MuJoCo's qacc holds that in world coordinates.
      const Vec3 w(data.v[va], data.v[va + 1], data.v[va + 2]);
      const Vec3 velocity(data.v[va + 3], data.v[va + 4], data.v[va + 5]);
      const Vec3 a(data.vdot[va + 3], data.vdot[va + 4], data.vdot[va + 5]);
      const Vec3 a_world = data.rotation[s] * (a + w.cross(velocity));
      for (std::size_t k = 0; k < 3; ++k) {
        qacc[mv + k] = a_world[static_cast<Eigen::Index>(k)];
        qacc[mv + 3 + k] = data.vdot[va + k];
      }
    } else {
      for (std::size_t k = 0; k < static_cast<std::size_t>(model.v_count[s]); ++k) {
        qacc[mv + k] = data.vdot[va + k];
      }
    }
  }
  return qacc;
}

runtime::Vec6 JointWrenchAsMujocoCfrcInt(const runtime::Data& data, const MujocoMap& map,
                                         const mjModel* m, const mjData* d, std::size_t segment) {
  const Mat3& R = data.rotation[segment];
  const runtime::Vec6& wrench = data.joint_wrench[segment];
  const Vec3 force = R * wrench.tail<3>();
  const int root = m->body_rootid[map.body[segment]];
  const Vec3 centre(d->subtree_com[3 * root], d->subtree_com[3 * root + 1],
                    d->subtree_com[3 * root + 2]);
  runtime::Vec6 out;
  out.head<3>() = R * wrench.head<3>() + (data.position[segment] - centre).cross(force);
  out.tail<3>() = force;
  return out;
}

}  // namespace sled::verification
