// The shared state of one compiler::Lower call, and the steps that fill the Model. Internal to
// compiler/lower/.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "compiler/check/checked_scenario.h"
#include "compiler/check/initial_pose.h"
#include "lang/diagnostics/diagnostic.h"
#include "lang/source/source_manager.h"
#include "runtime/model/model.h"

namespace sled::compiler::lowering {

// The checker's arrays as the runtime's Eigen types (compiler/check/initial_pose.h).
using compiler::RotationMatrix;
using compiler::ToEigen;

// A note of the lowering: an N04xx diagnostic, reported once the Model is complete.
struct Note {
  lang::DiagnosticKind kind{};
  SourceRange range;  // invalid: about the scenario as a whole
  std::string message;
};

class Lowering {
 public:
  Lowering(const CheckedScenario& scenario, const lang::SourceManager& sources,
           runtime::Model& model)
      : scenario_(scenario), sources_(sources), model_(model) {}

  const CheckedScenario& scenario() const { return scenario_; }
  runtime::Model& model() { return model_; }

  // Segment indices: checked scenario to Model (tree order) and back.
  std::vector<int> new_index;
  std::vector<int> old_index;
  // By Model segment: the checked joint above it, -1 for a root (a null joint's child included).
  std::vector<int> joint_above;
  // By Model segment: for a root held at a point of the ground or a vehicle by a fixed-point
  // constraint, that constraint (it becomes the root's ball joint to its base); -1 otherwise.
  std::vector<int> base_constraint;
  // By checked constraint: true when it became a base joint and is no loop constraint.
  std::vector<bool> constraint_is_base_joint;
  // Poses at t = 0 in the checked scenario's segment order.
  InitialPoses poses;
  // Mirror symmetry, by checked segment: for a right segment the Model leaves out, its left
  // twin; -1 for every segment it keeps. Empty when mirror symmetry is not applied.
  std::vector<int> mirror_twin;
  // True when the checked segment is left out as the mirror image of its twin; for a frame,
  // when it is such a segment.
  bool Dropped(int old) const {
    return old >= 0 && static_cast<std::size_t>(old) < mirror_twin.size() &&
           mirror_twin[static_cast<std::size_t>(old)] >= 0;
  }
  bool Dropped(const FrameRef& frame) const {
    return frame.kind == FrameRef::Kind::kSegment && Dropped(frame.index);
  }
  // By checked contact: its pair in Model::contacts, -1 when it was left out (never touches).
  std::vector<int> contact_pair;
  // By checked airbag: its bag in Model::airbags, -1 when it was left out.
  std::vector<int> airbag_index;

  // The Model's id of a checked function, copying it into the table on first use; -1 for -1.
  std::int32_t Function(FunctionId id);
  // A joint's torque function: the checked function, or, when the joint has an energy loss and
  // the function no unloading of its own, a copy that unloads with the joint's energy loss.
  std::int32_t TorqueFunction(FunctionId id, double joint_energy_loss);
  runtime::FrameRef Frame(const FrameRef& frame) const;
  // A point given in a frame, in world coordinates at t = 0.
  runtime::Vec3 WorldPoint(const FrameRef& frame, const Vec3& point) const;
  runtime::SourcePosition Position(const SourceRange& range) const;
  const Segment& segment(int old) const;
  const Joint& joint(int index) const;

  // Records a note (kind: one of the N04xx codes) at `range`; an invalid range is about the
  // scenario as a whole.
  void AddNote(lang::DiagnosticKind kind, const SourceRange& range, std::string message);
  // Appends an output group to the Model, with every column of its per-output arrays: the one
  // place the lowering adds outputs, so those arrays stay the same length.
  struct Output {
    runtime::Model::OutputKind kind{};
    std::string label;
    std::int32_t index = -1;
    runtime::Vec3 point = runtime::Vec3::Zero();
    bool mirrored = false;  // read from a left twin (mirror symmetry)
    std::int16_t filter_class = 0;
    bool iso_filter = false;
    // `relative_to` or `expressed_in` (frame_mode, runtime::Model::OutputFrame): the frame the
    // output is measured in, and whether it is a right twin read from its left twin.
    std::optional<runtime::FrameRef> frame;
    bool frame_mirrored = false;
    std::uint8_t frame_mode = 0;
  };
  void AddOutput(const Output& output);
  // Reports the notes to `diagnostics` in source order (those without a position last).
  void ReportNotes(lang::DiagnosticConsumer& diagnostics);

 private:
  const CheckedScenario& scenario_;
  const lang::SourceManager& sources_;
  runtime::Model& model_;
  std::vector<std::int32_t> function_map_;
  // Appends a checked function to the Model's table with the given energy loss.
  std::int32_t AppendFunction(const compiler::Function& f, double energy_loss);
  std::vector<Note> notes_;
};

// Segments in tree order, their inertia, the joints above them and their coordinates.
void LowerTree(Lowering& lowering);
// Planar symmetry: the joint above Model segment `s` loses the degrees of freedom that leave
// the xz plane (called by LowerTree before the joint's coordinates are counted).
void RestrictToPlane(Lowering& lowering, std::size_t s);
// Mirror symmetry: fills lowering.mirror_twin when the scene's pairs allow it (each right
// segment hangs where its left twin does, and only right segments hang from right segments;
// no spring or loop constraint touches a right segment), else notes why it is not applied.
void PlanMirrorSymmetry(Lowering& lowering);
// Mirror symmetry, for Model segment `s` (after RestrictToPlane's turn in LowerTree): a segment
// in the plane is restricted to it; a left twin hanging from one is marked to hand its parent
// its mirror image too.
void ApplyMirrorSymmetry(Lowering& lowering, std::size_t s);
// q0 and v0 from the initial conditions (after LowerTree).
void LowerInitialState(Lowering& lowering);
// Vehicles, spring–dampers, constraints, run settings and outputs (after LowerTree).
void LowerScene(Lowering& lowering);
// Contact surfaces and the pairs that can touch (after LowerTree, before LowerScene).
void LowerContacts(Lowering& lowering);
// A `contact_force` request: its output group and channels (after LowerContacts).
void LowerContactOutput(Lowering& lowering, const OutputRequest& output);
// Belts and harnesses, in the checked scenario's order (after LowerTree).
void LowerBelts(Lowering& lowering);
// Airbags, their gas states and the contact ellipsoids they may touch (after LowerTree, before
// LowerScene, whose outputs refer to them).
void LowerAirbags(Lowering& lowering);
// The SAE J211 class of an output request's channels: its `filter`, else its kind's default.
std::int16_t FilterClassOf(const OutputRequest& request, runtime::Model::OutputKind kind);
// The injury criteria and the output groups they read, added when the scene lacks them (after
// LowerScene).
void LowerCriteria(Lowering& lowering);
// The shapes the animation draws for segments beyond their contact ellipsoids (after
// LowerContacts).
void LowerShapes(Lowering& lowering);
// The wind and water on the segments' contact ellipsoids (runtime/forces/fluid_forces.h).
void LowerFluids(Lowering& lowering);

}  // namespace sled::compiler::lowering
