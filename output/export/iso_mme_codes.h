// ISO/TS 13499 (ISO-MME) channel codes for a run's channels, mapped from the scene's output
// names and kinds (the mapping is documented in docs/outputs.md, "ISO-MME channel codes"):
//
//   1     test object: 1 (the vehicle the occupants sit in: every channel of a sled scene)
//   2     position: the body's place among the scene's bodies (1 for the first, ...), 0 for
//         channels of no body
//   3-6   main location from the words of the output's name (head HEAD, neck NECK, thorax CHST,
//         pelvis PELV, seat_pan SEPN, knee_bolster KNBO, ...); belts SEBE, belt anchors BAFI;
//         criteria HICR, NIJC, ...
//   7-8   fine location 1: UP/LO (upper/lower neck), LE/RI (a name ending in _l/_r or holding
//         left/right), 00
//   9-10  fine location 2: 00, a belt span or anchor ordinal, the HIC window (15, 36), XC/XS
//         (3 ms cumulative / continuous); an ordinal 01..99 when the code is already taken
//   11-12 fine location 3 (dummy type): 00, sled's bodies are no certified dummy
//   13-14 physical dimension: AC, VE, DS, AA, AV, AN, FO, MO, 00
//   15    direction: X for x; 2 and 3 for y and z (sled's axes point left and up, opposite to
//         SAE J211's right and down, which ISO-MME writes as 2 and 3); 0 for a magnitude or a
//         joint angle; R for a criterion
//   16    filter class: 0 raw, A/B/C/D for CFC 1000/600/180/60, X for a computed criterion
#pragma once

#include <string>
#include <vector>

#include "output/post/criterion_value.h"
#include "runtime/model.h"
#include "runtime/time_series.h"

namespace sled::runtime {

struct IsoMmeChannel {
  std::string code;  // 16 characters
  std::string name;  // sled's name, without the unit
  std::string unit;  // as ISO-MME writes it: m/(s*s), N, Nm, ...
  std::string dimension;
  char direction = '0';
  bool world_frame = false;  // else the segment's (or joint's, or anchor's) frame
};

// The ISO-MME filter class letter of a CFC: A (1000), B (600), C (180), D (60), 0 (none).
char FilterClassLetter(int cfc);

struct IsoMmeCodes {
  std::vector<IsoMmeChannel> raw;       // one per channel of ChannelNames(model)
  std::vector<IsoMmeChannel> filtered;  // one per filtered channel, by its name
  std::vector<IsoMmeChannel> criteria;  // one per criterion value
};

// Codes for every channel and criterion value, all different.
IsoMmeCodes MapIsoMmeCodes(const Model& model, const TimeSeries& raw, const TimeSeries& filtered,
                           const std::vector<post::CriterionValue>& criteria);

}  // namespace sled::runtime
