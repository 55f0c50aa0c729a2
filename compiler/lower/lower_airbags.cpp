// Airbags: each bag's pose in its frame, its gas and vent, the two auxiliary states of its gas
// (mass and internal energy, starting empty), and the contact ellipsoids of the segments it may
// touch. A bag fixed in a segment the Model leaves out (mirror symmetry) is left out, and a
// listed segment it cannot touch (its own carrier, a segment without an ellipsoid, a right twin
// the Model leaves out) is dropped from its contacts, each with a note.
#include <fmt/format.h>

#include "compiler/lower/lowering.h"
#include "runtime/contact/contact_geometry.h"

namespace sled::compiler::lowering {
namespace {

// Appends the contact ellipsoids of checked segment `old` to the bag just added; false (with a
// note) when the bag cannot touch it.
bool LowerBagContact(Lowering& lowering, const Airbag& bag, int old) {
  runtime::AirbagTable& table = lowering.model().airbags;
  const Segment& segment = lowering.segment(old);
  auto note = [&](std::string_view why) {
    lowering.AddNote(lang::DiagnosticKind::kLeftOutOfModel, bag.range,
                     fmt::format("airbag `{}` cannot touch `{}`: {}; left out of its "
                                 "contacts",
                                 bag.name, segment.name, why));
    return false;
  };
  if (bag.frame.kind == FrameRef::Kind::kSegment && bag.frame.index == old) {
    return note("the bag is fixed in it");
  }
  if (lowering.Dropped(old)) {
    return note("mirror symmetry leaves this right segment out of the Model");
  }
  if (segment.ellipsoids.empty()) return note("it has no contact ellipsoid");
  const int index = lowering.new_index[static_cast<std::size_t>(old)];
  const std::vector<std::uint8_t>& counts = lowering.model().segment_mirror_count;
  if (static_cast<std::size_t>(index) < counts.size() &&
      counts[static_cast<std::size_t>(index)] == 2) {
    lowering.AddNote(lang::DiagnosticKind::kReducedBySymmetry, bag.range,
                     fmt::format("mirror symmetry: airbag `{}` touches `{}`, whose right twin the "
                                 "Model leaves out; the twin's push on the gas is not counted",
                                 bag.name, segment.name));
  }
  for (int e : segment.ellipsoids) {
    const Ellipsoid& ellipsoid = lowering.scenario().ellipsoids.at(static_cast<std::size_t>(e));
    if (ellipsoid.degree != 2.0) {
      lowering.AddNote(lang::DiagnosticKind::kSimulatedApproximately, bag.range,
                       fmt::format("airbag `{}` touches `{}` as an ellipsoid of degree "
                                   "2 with its semi-axes",
                                   bag.name, ellipsoid.name));
    }
    table.contact_segment.push_back(index);
    table.contact_center.push_back(ToEigen(ellipsoid.center));
    table.contact_axes.push_back(RotationMatrix(ellipsoid.orientation));
    table.contact_semi_axes.push_back(ToEigen(ellipsoid.semi_axes));
    table.contact_radius.push_back(runtime::BoundingRadius(ToEigen(ellipsoid.semi_axes), 2.0));
  }
  return true;
}

}  // namespace

void LowerAirbags(Lowering& lowering) {
  const CheckedScenario& scenario = lowering.scenario();
  runtime::Model& model = lowering.model();
  runtime::AirbagTable& table = model.airbags;
  lowering.airbag_index.assign(scenario.airbags.size(), -1);
  for (std::size_t b = 0; b < scenario.airbags.size(); ++b) {
    const Airbag& bag = scenario.airbags[b];
    if (lowering.Dropped(bag.frame)) {
      lowering.AddNote(lang::DiagnosticKind::kLeftOutOfModel, bag.range,
                       fmt::format("airbag `{}` is left out: mirror symmetry leaves "
                                   "the segment it is fixed in out of the Model",
                                   bag.name));
      continue;
    }
    if (scenario.run.end > 0 && bag.deploy_time >= scenario.run.end) {
      lowering.AddNote(lang::DiagnosticKind::kLeftOutOfModel, bag.range,
                       fmt::format("airbag `{}` deploys at {} s, when the run has ended", bag.name,
                                   bag.deploy_time));
    }
    lowering.airbag_index[b] = static_cast<int>(table.size());
    table.name.push_back(bag.name);
    table.frame.push_back(lowering.Frame(bag.frame));
    table.deploy_point.push_back(ToEigen(bag.position));
    table.axes.push_back(RotationMatrix(bag.orientation));
    table.semi_axes.push_back(ToEigen(bag.semi_axes));
    table.deploy_time.push_back(bag.deploy_time);
    table.inflow.push_back(lowering.Function(bag.inflow));
    table.inflow_temperature.push_back(bag.gas_temperature);
    table.vent_area.push_back(bag.vent_area);
    table.discharge_coefficient.push_back(bag.discharge_coefficient);
    table.ambient_pressure.push_back(bag.ambient_pressure);
    table.gamma.push_back(bag.gamma);
    table.gas_constant.push_back(bag.gas_constant);
    table.source.push_back(lowering.Position(bag.range));
    table.free_bag.push_back(bag.free_bag ? 1 : 0);
    table.bag_mass.push_back(bag.bag_mass);
    table.mass_factor.push_back(bag.mass_factor);
    table.tether_stiffness.push_back(bag.tether_stiffness);
    table.vent_opening_pressure.push_back(bag.vent_opening_pressure);
    // The gas starts empty (mass, then internal energy or, for ATB's free bag, the mass vented);
    // a free bag's motion states are set when it is full.
    table.state_address.push_back(model.nw);
    const std::int32_t states = table.state_count(table.size() - 1);
    model.w0.insert(model.w0.end(), static_cast<std::size_t>(states), 0.0);
    model.nw += states;
    table.first_contact.push_back(static_cast<std::int32_t>(table.ncontact()));
    for (int segment : bag.contact_segments) LowerBagContact(lowering, bag, segment);
    table.contact_count.push_back(static_cast<std::int32_t>(table.ncontact()) -
                                  table.first_contact.back());
    if (table.contact_count.back() == 0) {
      lowering.AddNote(lang::DiagnosticKind::kLeftOutOfModel, bag.range,
                       fmt::format("airbag `{}` touches no segment: it inflates and "
                                   "vents, and pushes on nothing",
                                   bag.name));
    }
  }
}

}  // namespace sled::compiler::lowering
