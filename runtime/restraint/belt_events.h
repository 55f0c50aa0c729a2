// The events of belts and harnesses: everything a belt carries from one moment to the next that
// is not in the state changes here, at a located event, never between two steps.
//
// - A junction that sticks starts to slip, one way or the other, where its tighter side's
//   tension reaches the capstan ratio times the slacker side's (kSlipIntoFirst/Second: the
//   function r(T~_slacker) - T~_tighter falls through zero; T~ is the tension extended below
//   zero strain and r(.) the capstan bound of belt_slip.h, so slack spans have a cone too).
// - A junction that slips sticks where its slip stops (kStop: the rate of its transfer, in the
//   direction it slips, falls through zero).
// - A wrap that sticks re-anchors where the webbing starts or stops touching the body
//   (kContact: the body's reach across the straight line changes sign), since only a body that
//   touches the webbing carries it.
// - A span whose webbing keeps a loading history turns it where its strain turns while it
//   loads (kTurn: the strain rate falls through zero beyond the largest strain so far).
// At a stick and at a re-anchoring, the junction holds the webbing it has and sticks to the body
// point under the webbing's middle. The rates (UpdateBeltRates, when an event needs one) come
// from the belt geometry's central differences along the motion and the slip equations' slope.
#pragma once

#include <cstddef>
#include <vector>

#include "runtime/model/data.h"

namespace sled::runtime {

enum class BeltEventKind : std::uint8_t { kSlipIntoFirst, kSlipIntoSecond, kStop, kContact, kTurn };

struct BeltEvent {
  BeltEventKind kind;
  std::size_t index;  // the junction, or for kTurn the span
};

// The events of the Model's belts: four (three at a tie point) per junction with friction, one
// per span whose webbing keeps a history.
std::vector<BeltEvent> BeltEvents(const Model& model, const Data& data);

// After Forward at data's state: the slip and strain rates the event functions need, when one
// needs them (a junction slips, a hysteretic span loads). Leaves data's kinematics and belts as
// Forward left them (copied before the differences and back after, in data.belt_rates_copy).
void UpdateBeltRates(const Model& model, Data& data);

// Sizes data.belt_rates_copy (SetUpBelts), so that UpdateBeltRates allocates nothing.
void SizeBeltRatesCopy(Data& data);

// The event's function at data's state (after Forward and UpdateBeltRates); 1 while the event
// cannot happen in the junction's or span's present mode.
double BeltEventFunction(const Model& model, const Data& data, const BeltEvent& event);

// The event's change, at data's state (after Forward): a new mode, the webbing held and the body
// point stuck to, or a turned loading history. Only a fall through zero changes anything.
void HandleBeltEvent(const Model& model, Data& data, const BeltEvent& event, int direction);

}  // namespace sled::runtime
