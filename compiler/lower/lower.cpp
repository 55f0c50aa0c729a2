#include "compiler/lower/lower.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "compiler/lower/lowering.h"

namespace sled::compiler {
namespace lowering {
namespace {

std::size_t At(int index, std::size_t size, const char* what) {
  if (index < 0 || static_cast<std::size_t>(index) >= size) {
    throw std::logic_error(
        fmt::format("compiler::Lower: {} index {} out of range (size {})", what, index, size));
  }
  return static_cast<std::size_t>(index);
}

}  // namespace

const Segment& Lowering::segment(int old) const {
  return scenario_.segments[At(old, scenario_.segments.size(), "segment")];
}

const Joint& Lowering::joint(int index) const {
  return scenario_.joints[At(index, scenario_.joints.size(), "joint")];
}

std::int32_t Lowering::Function(FunctionId id) {
  if (id < 0) return -1;
  const std::size_t old = At(id, scenario_.functions.size(), "function");
  if (function_map_.empty()) function_map_.assign(scenario_.functions.size(), -1);
  if (function_map_[old] < 0) {
    const compiler::Function& f = scenario_.functions[old];
    function_map_[old] = AppendFunction(f, f.energy_loss);
  }
  return function_map_[old];
}

std::int32_t Lowering::TorqueFunction(FunctionId id, double joint_energy_loss) {
  if (id < 0) return -1;
  const compiler::Function& f = scenario_.functions[At(id, scenario_.functions.size(), "function")];
  const bool own_unloading =
      f.energy_loss > 0 || f.permanent_set > 0 || f.unload_slope || f.atb_unloading;
  if (!(joint_energy_loss > 0) || own_unloading) return Function(id);
  return AppendFunction(f, joint_energy_loss);
}

std::int32_t Lowering::AppendFunction(const compiler::Function& f, double energy_loss) {
  // ATB's factors and spike are functions of their own, appended first.
  const std::int32_t atb_return = f.atb_unloading ? Function(f.energy_return) : -1;
  const std::int32_t atb_set = f.atb_unloading ? Function(f.atb_permanent_set) : -1;
  const std::int32_t atb_spike = f.atb_unloading ? Function(f.atb_spike) : -1;
  runtime::FunctionTable& table = model_.functions;
  const auto id_in_model = static_cast<std::int32_t>(table.size());
  table.atb_return.push_back(atb_return);
  table.atb_set.push_back(atb_set);
  table.atb_spike.push_back(atb_spike);
  table.atb_spike_end.push_back(atb_spike >= 0 ? f.atb_spike_end : 0.0);
  table.atb_origin.push_back(f.atb_unloading ? f.atb_origin : 0.0);
  table.constant.push_back(f.kind == compiler::Function::Kind::kConstant ? f.constant : 0.0);
  table.energy_loss.push_back(energy_loss);
  table.permanent_set.push_back(f.permanent_set);
  table.unload_slope.push_back(f.unload_slope.value_or(0.0));
  switch (f.kind) {
    case compiler::Function::Kind::kConstant:
      table.kind.push_back(runtime::FunctionTable::Kind::kConstant);
      table.first.push_back(-1);
      table.count.push_back(0);
      break;
    case compiler::Function::Kind::kTable:
      table.kind.push_back(runtime::FunctionTable::Kind::kTable);
      table.first.push_back(static_cast<std::int32_t>(table.points_x.size()));
      table.count.push_back(static_cast<std::int32_t>(f.points.size()));
      for (const auto& [x, y] : f.points) {
        table.points_x.push_back(x);
        table.points_y.push_back(y);
      }
      break;
    case compiler::Function::Kind::kPolynomial:
      table.kind.push_back(runtime::FunctionTable::Kind::kPolynomial);
      table.first.push_back(static_cast<std::int32_t>(table.coefficients.size()));
      table.count.push_back(static_cast<std::int32_t>(f.coefficients.size()));
      table.coefficients.insert(table.coefficients.end(), f.coefficients.begin(),
                                f.coefficients.end());
      break;
  }
  return id_in_model;
}

runtime::FrameRef Lowering::Frame(const FrameRef& frame) const {
  switch (frame.kind) {
    case FrameRef::Kind::kSegment:
      if (Dropped(frame.index)) {
        throw std::logic_error(fmt::format(
            "compiler::Lower: segment {} is a right twin the Model leaves out", frame.index));
      }
      return {runtime::FrameRef::Kind::kSegment,
              new_index[At(frame.index, new_index.size(), "segment")]};
    case FrameRef::Kind::kVehicle:
      At(frame.index, scenario_.vehicles.size(), "vehicle");
      return {runtime::FrameRef::Kind::kVehicle, frame.index};
    case FrameRef::Kind::kGround:
      break;
  }
  return {runtime::FrameRef::Kind::kGround, -1};
}

runtime::Vec3 Lowering::WorldPoint(const FrameRef& frame, const Vec3& point) const {
  const Pose pose = poses.Of(frame);
  return ToEigen(pose.position) + ToEigen(pose.rotation) * ToEigen(point);
}

runtime::SourcePosition Lowering::Position(const SourceRange& range) const {
  if (!range.valid()) return {};
  const lang::SourceBuffer& buffer = sources_.buffer(range.file);
  const lang::LineColumn at = buffer.Locate(range.begin);
  return {buffer.path(), at.line, at.column};
}

void Lowering::AddOutput(const Output& output) {
  model_.output_kind.push_back(output.kind);
  model_.output_label.push_back(output.label);
  model_.output_index.push_back(output.index);
  model_.output_point.push_back(output.point);
  if (!mirror_twin.empty()) model_.output_mirrored.push_back(output.mirrored ? 1 : 0);
  model_.output_filter_class.push_back(output.filter_class);
  model_.output_filter_iso.push_back(output.iso_filter ? 1 : 0);
  // The arrays of frames start with the first output that has one (the earlier are absolute).
  const std::size_t earlier = model_.output_kind.size() - 1;
  if (output.frame && model_.output_relative.empty()) {
    model_.output_relative.resize(earlier, 0);
    model_.output_frame.resize(earlier, runtime::FrameRef{});
    model_.output_frame_mirrored.resize(earlier, 0);
  }
  if (!model_.output_relative.empty() || output.frame) {
    model_.output_relative.push_back(output.frame ? output.frame_mode : 0);
    model_.output_frame.push_back(output.frame.value_or(runtime::FrameRef{}));
    model_.output_frame_mirrored.push_back(output.frame_mirrored ? 1 : 0);
  }
}

void Lowering::AddNote(lang::DiagnosticKind kind, const SourceRange& range, std::string message) {
  notes_.push_back({kind, range, std::move(message)});
}

void Lowering::ReportNotes(lang::DiagnosticConsumer& diagnostics) {
  std::stable_sort(notes_.begin(), notes_.end(), [](const Note& a, const Note& b) {
    if (a.range.valid() != b.range.valid()) return a.range.valid();
    return a.range.valid() && lang::Precedes(a.range, b.range);
  });
  for (Note& note : notes_) {
    lang::Diagnostic diagnostic =
        lang::MakeDiagnostic(note.kind, note.range, std::move(note.message));
    if (!note.range.valid()) diagnostic.labels.clear();  // about the scenario as a whole
    diagnostics.Consume(std::move(diagnostic));
  }
  notes_.clear();
}

}  // namespace lowering

runtime::Model Lower(const CheckedScenario& scenario, const lang::SourceManager& sources,
                     const LowerOptions& options) {
  if (options.diagnostics == nullptr) {
    throw std::logic_error("compiler::Lower: LowerOptions::diagnostics is required");
  }
  runtime::Model model;
  lowering::Lowering lowering(scenario, sources, model);
  model.title = scenario.title;
  lowering.poses = ComputeInitialPoses(scenario);
  lowering::LowerTree(lowering);
  lowering::LowerContacts(lowering);
  lowering::LowerShapes(lowering);
  lowering::LowerAirbags(lowering);
  lowering::LowerScene(lowering);
  lowering::LowerFluids(lowering);
  lowering::LowerBelts(lowering);
  lowering::LowerCriteria(lowering);
  lowering::LowerInitialState(lowering);
  lowering.ReportNotes(*options.diagnostics);
  // Every array checked against its count, index and value rules, and the structure every Data
  // shares derived once; a Model that fails is a lowering bug, named field by field.
  if (const std::string errors = runtime::FinalizeModel(model); !errors.empty()) {
    throw std::logic_error("compiler::Lower: the lowered Model is not valid:\n" + errors);
  }
  return model;
}

}  // namespace sled::compiler
