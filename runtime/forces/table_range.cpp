#include "runtime/forces/table_range.h"

#include <cmath>

#include <fmt/format.h>

#include "runtime/contact/contact_forces.h"
#include "runtime/contact/contact_reach.h"
#include "runtime/dynamics/joint.h"
#include "runtime/forces/forces.h"
#include "runtime/model/data.h"

namespace sled::runtime {
namespace {

bool IsTable(const FunctionTable& functions, std::int32_t id) {
  return id >= 0 && static_cast<std::size_t>(id) < functions.size() &&
         functions.kind[static_cast<std::size_t>(id)] == FunctionTable::Kind::kTable;
}

std::pair<double, double> RowRange(const FunctionTable& functions, std::int32_t id) {
  const auto f = static_cast<std::size_t>(id);
  const auto first = static_cast<std::size_t>(functions.first[f]);
  const auto count = static_cast<std::size_t>(functions.count[f]);
  return {functions.points_x[first], functions.points_x[first + count - 1]};
}

// A joint's torque function reads |angle| unless its table covers negative angles
// (RestoringTorque).
double JointArgument(const FunctionTable& functions, std::int32_t id, double angle) {
  return RowRange(functions, id).first < 0 ? angle : std::abs(angle);
}

constexpr const char* kJointSlots[3][3] = {{"flexure", "twist", ""},             // ball
                                           {"flexure", "", ""},                  // pin, slip
                                           {"precession", "nutation", "spin"}};  // Euler

}  // namespace

void SizeTableWatch(const Model& model, TableWatch& watch) {
  watch.contact.assign(model.contacts.npair(), {});
  watch.belt.assign(model.belts.size(), {});
  watch.joint.assign(3 * model.nsegment(), {});
  watch.spring.assign(model.nspring(), {});
  watch.airbag.assign(model.airbags.size(), {});
}

void RecordTableArgument(const FunctionTable& functions, std::int32_t id, double t, double x,
                         TableOverrun& record) {
  if (!IsTable(functions, id)) return;
  const auto [low, high] = RowRange(functions, id);
  // A sliver past a row, from rounding, is no extrapolation.
  const double slack = 1e-9 * std::max(1.0, std::max(std::abs(low), std::abs(high)));
  if (!(x > high + slack || x < low - slack)) return;
  const double distance = x > high ? x - high : low - x;
  if (!record.seen) {
    record.seen = true;
    record.first_time = t;
    record.first_argument = x;
    record.farthest_argument = x;
    return;
  }
  // Rows are read from a step's dense output after the step's end was watched: the earliest
  // time seen is the first.
  if (t < record.first_time) {
    record.first_time = t;
    record.first_argument = x;
  }
  const double farthest = record.farthest_argument > high ? record.farthest_argument - high
                                                          : low - record.farthest_argument;
  if (distance > farthest) record.farthest_argument = x;
}

void WatchTablesAtRow(const Model& model, Data& data) {
  const FunctionTable& functions = model.functions;
  WatchContactTables(model, data);
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    const auto& f = model.joint_function[s];
    if (!IsTable(functions, f[0]) && !IsTable(functions, f[1]) && !IsTable(functions, f[2])) {
      continue;
    }
    const auto qa = static_cast<std::size_t>(model.q_address[s]);
    double angles[3] = {0.0, 0.0, 0.0};
    switch (model.joint_kind[s]) {
      case JointKind::kPin:
      case JointKind::kSlip:
        angles[0] = data.q[qa];
        break;
      case JointKind::kEuler:
        for (std::size_t k = 0; k < 3; ++k) angles[k] = data.q[qa + k];
        break;
      case JointKind::kBall: {
        const SwingTwist swing = DecomposeSwingTwist(QuaternionAt(data.q, qa).normalized());
        angles[0] = swing.flexure;
        angles[1] = swing.twist;
        break;
      }
      default:
        continue;
    }
    for (std::size_t k = 0; k < 3; ++k) {
      if (!IsTable(functions, f[k])) continue;
      RecordTableArgument(functions, f[k], data.time, JointArgument(functions, f[k], angles[k]),
                          data.table_watch.joint[3 * s + k]);
    }
  }
  for (std::size_t k = 0; k < model.nspring(); ++k) {
    RecordTableArgument(functions, model.spring_function[k], data.time,
                        data.spring_length[k] - model.spring_free_length[k],
                        data.table_watch.spring[k]);
  }
  const AirbagTable& bags = model.airbags;
  for (std::size_t b = 0; b < bags.size(); ++b) {
    if (data.airbags.inflow_phase[b] != 1) continue;
    RecordTableArgument(functions, bags.inflow[b], data.time, data.time - bags.deploy_time[b],
                        data.table_watch.airbag[b]);
  }
}

std::string TableExtrapolation::Describe() const {
  const bool above = farthest_argument > high;
  return fmt::format(
      "{} left its table's rows ({} {:.6g} to {:.6g}) at t = {:.6g} s, at {:.6g}; the farthest "
      "was {:.6g}, {:.3g} beyond the {} row, where the table's {} segment is extended",
      element, argument, low, high, first_time, first_argument, farthest_argument,
      above ? farthest_argument - high : low - farthest_argument, above ? "last" : "first",
      above ? "last" : "first");
}

std::vector<TableExtrapolation> TableExtrapolations(const Model& model, const Data& data) {
  std::vector<TableExtrapolation> found;
  const FunctionTable& functions = model.functions;
  auto add = [&](const TableOverrun& record, std::int32_t function, std::string element,
                 const char* argument) {
    if (!record.seen) return;
    const auto [low, high] = RowRange(functions, function);
    found.push_back({std::move(element), argument, record.first_time, record.first_argument,
                     record.farthest_argument, low, high});
  };
  const ContactTable& contacts = model.contacts;
  for (std::size_t k = 0; k < contacts.npair(); ++k) {
    add(data.table_watch.contact[k], contacts.pair_function[k], ContactPairName(contacts, k),
        "deflection [m]");
  }
  for (std::size_t b = 0; b < model.belts.size(); ++b) {
    add(data.table_watch.belt[b], model.belts.function[b],
        fmt::format("belt `{}`", model.belts.name[b]), "strain");
  }
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    const int row = model.joint_kind[s] == JointKind::kBall    ? 0
                    : model.joint_kind[s] == JointKind::kEuler ? 2
                                                               : 1;
    for (std::size_t k = 0; k < 3; ++k) {
      add(data.table_watch.joint[3 * s + k], model.joint_function[s][k],
          fmt::format("joint `{}` {}", model.joint_name[s], kJointSlots[row][k]),
          model.joint_kind[s] == JointKind::kSlip ? "displacement [m]" : "angle [rad]");
    }
  }
  for (std::size_t k = 0; k < model.nspring(); ++k) {
    add(data.table_watch.spring[k], model.spring_function[k],
        fmt::format("spring `{}`", model.spring_name[k]), "elongation [m]");
  }
  for (std::size_t b = 0; b < model.airbags.size(); ++b) {
    add(data.table_watch.airbag[b], model.airbags.inflow[b],
        fmt::format("airbag `{}` inflator", model.airbags.name[b]), "time since deployment [s]");
  }
  return found;
}

}  // namespace sled::runtime
