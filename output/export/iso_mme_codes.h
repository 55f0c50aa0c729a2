// ISO/TS 13499 (ISO-MME) channel codes for a run's channels, mapped from the scene's output
// names and kinds (the mapping is documented in docs/outputs.md, "ISO-MME channel codes"):
//
//   1     test object: 1 (the vehicle the occupants sit in: every channel of a sled scene)
//   2     position: the body's place among the scene's bodies (1 for the first, ...), 0 for
//         channels of no body
//   3-6   main location from the words of the output's name (head HEAD, neck NECK, thorax CHST,
//         pelvis PELV, seat_pan SEPN, knee_bolster KNBO, bumper BUMP, ...); a contact's from
//         the surface the segment touches; belts SEBE, belt anchors BAFI; criteria HICR, NIJC, ...
//   7-8   fine location 1: UP/LO (upper/lower neck), LE/RI (a name ending in _l/_r or holding
//         left/right), IP (Nij in position), 00
//   9-10  fine location 2: 00, a belt span or anchor ordinal, the HIC window (15, 36), 3C/3S
//         (3 ms clip, cumulative / single peak), Nij's quadrant (TE, TF, CE, CF), TN/CO (neck
//         tension / compression); an ordinal 01..99 when the code is already taken
//   11-12 fine location 3 (dummy type): the body's `dummy` (Model::segment_dummy: H3 for a
//         Hybrid III 50th male, HF, TH, T3, E2, ER, S2; runtime/model/dummy_types.h), 00 for a body
//         that names none and for channels of no body
//   13-14 physical dimension: AC, VE, DS, AA, AV, AN, FO, MO, PR, VU, MA, TE, MF, 00
//   15    direction: X, Y, Z in SAE J211's axes (x forward, y right, z down: sled's y and z,
//         which point left and up, are negated in the data), R for a resultant, 0 for a
//         magnitude or a joint angle
//   16    filter class: P raw (sampled from the model, never filtered), A/B/C/D for CFC
//         1000/600/180/60, X for a computed criterion
//
// Every three-axis acceleration also gets its resultant (direction R), raw and filtered: the
// channel labs read HIC and 3 ms values from (11HEAD0000H3ACRA for a Hybrid III).
#pragma once

#include <string>
#include <vector>

#include "output/post/criterion_value.h"
#include "runtime/model/model.h"
#include "runtime/run/time_series.h"

namespace sled::runtime {

struct IsoMmeChannel {
  std::string code;  // 16 characters
  std::string name;  // sled's name, without the unit
  std::string unit;  // as ISO-MME writes it: m/(s*s), N, Nm, ...
  std::string dimension;
  char direction = '0';
  bool world_frame = false;  // else the segment's (or joint's, or anchor's) frame
  // The data in SAE J211's axes: -1 for a y or z component (sled's y and z point left and up).
  double sign = 1.0;
  // A resultant: the columns whose root sum of squares it is (else empty).
  std::vector<std::size_t> components;
};

// The ISO-MME filter class letter of a CFC: A (1000), B (600), C (180), D (60), 0 (none).
char FilterClassLetter(int cfc);

struct IsoMmeCodes {
  std::vector<IsoMmeChannel> raw;       // one per channel of ChannelNames(model)
  std::vector<IsoMmeChannel> filtered;  // one per filtered channel, by its name
  std::vector<IsoMmeChannel> criteria;  // one per criterion value
  // Resultants of three-axis accelerations, of raw columns and of filtered columns.
  std::vector<IsoMmeChannel> raw_resultants;
  std::vector<IsoMmeChannel> filtered_resultants;
};

// Codes for every channel and criterion value, all different.
IsoMmeCodes MapIsoMmeCodes(const Model& model, const TimeSeries& raw, const TimeSeries& filtered,
                           const std::vector<post::CriterionValue>& criteria);

}  // namespace sled::runtime
