// The airbags of a Model (runtime/model/model.h holds one AirbagTable): uniform-pressure
// ellipsoidal bags, each fixed in a frame, fed by an inflator, venting through an orifice, and
// pushed in by the contact ellipsoids of the segments they may touch. Filled by compiler::Lower
// (compiler/lower/lower_airbags.cpp); evaluated by runtime/airbag/airbag_forces.cpp. The gas
// state of each bag (its mass and internal energy) is part of the integrated state, as two
// auxiliary states (Model::nw). Semantics: docs/runtime.md, "Airbags".
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "runtime/model/model_types.h"

namespace sled::runtime {

struct AirbagTable {
  // --- Per bag.
  std::vector<std::string> name;
  std::vector<FrameRef> frame;
  // The bag's back pole in its frame: the bag grows from it along its x axis.
  std::vector<Vec3> deploy_point;
  std::vector<Mat3> axes;       // columns: the bag's axes in the frame (x: deployment direction)
  std::vector<Vec3> semi_axes;  // of the fully deployed bag
  std::vector<double> deploy_time;
  std::vector<std::int32_t> inflow;           // time since deployment -> mass flow [kg/s]
  std::vector<double> inflow_temperature;     // of the inflator's gas [K]
  std::vector<double> vent_area;              // [m^2]
  std::vector<double> discharge_coefficient;  // of the vent orifice
  std::vector<double> ambient_pressure;       // [Pa]
  std::vector<double> gamma;                  // ratio of specific heats of the gas
  std::vector<double> gas_constant;           // specific gas constant [J/(kg K)]
  // First of the bag's two auxiliary states in the integrated state w: the gas mass m [kg], then
  // the gas's internal energy over c_v times the inflator's temperature, U / (c_v T_in) [kg] (a
  // mass too, so one absolute tolerance suits both; it equals m while the gas is at T_in).
  std::vector<std::int32_t> state_address;
  // ATB's free bag (`model = atb_free`, docs/runtime.md "ATB's free airbag"): 1 for a bag whose
  // gas is polytropic, whose vent flow goes as the square root of the gauge pressure and which,
  // once full, moves as a free body held by a spring; 0 for sled's energy-balance bag. A free
  // bag's states are its gas mass, the mass vented, then its centre (world) and velocity.
  std::vector<std::uint8_t> free_bag;
  std::vector<double> bag_mass;               // of the fabric [kg]
  std::vector<double> mass_factor;            // ATB's CMASS: the moving mass over gas + fabric
  std::vector<double> tether_stiffness;       // spring from the back pole to `position` [N/m]
  std::vector<double> vent_opening_pressure;  // gauge pressure above which the vent flows [Pa]
  std::vector<std::int32_t> first_contact;    // into the per-contact arrays
  std::vector<std::int32_t> contact_count;
  std::vector<SourcePosition> source;

  // --- Per contact: one contact ellipsoid of a segment the bag may touch. The contacts of one
  // segment are consecutive.
  std::vector<std::int32_t> contact_segment;
  std::vector<Vec3> contact_center;  // in the segment frame
  std::vector<Mat3> contact_axes;    // columns: the ellipsoid's axes in the segment frame
  std::vector<Vec3> contact_semi_axes;
  std::vector<double> contact_radius;  // bounding sphere about the centre

  std::size_t size() const { return name.size(); }
  // The number of auxiliary states bag b owns from state_address[b].
  std::int32_t state_count(std::size_t b) const { return free_bag[b] ? kFreeBagStates : 2; }
  static constexpr std::int32_t kFreeBagStates = 8;
  std::size_t ncontact() const { return contact_segment.size(); }
};

}  // namespace sled::runtime
