// The crash-test dummies a body can stand for (`dummy = ...` in a body), with the dummy type of
// ISO/TS 13499 channel codes (fine location 3, characters 11-12; crash-conventions.md §2.8), which
// the ISO-MME export writes into every code of the body's channels.
#pragma once

#include <string_view>

namespace sled::runtime {

struct DummyType {
  std::string_view word;      // as the language writes it
  std::string_view iso_code;  // two characters
  std::string_view description;
};

inline constexpr DummyType kDummyTypes[] = {
    {"hybrid3_50m", "H3", "Hybrid III 50th percentile male"},
    {"hybrid3_5f", "HF", "Hybrid III 5th percentile female"},
    {"thor", "TH", "THOR"},
    {"thor_hybrid3_legs", "T3", "THOR with Hybrid III legs"},
    {"es2", "E2", "ES-2"},
    {"es2re", "ER", "ES-2re"},
    {"sid2s", "S2", "SID-IIs"},
    {"human", "00", "a human body model: ISO/TS 13499 has no dummy type for it (00)"},
};

// The ISO/TS 13499 code of a body that names no dummy: not applicable.
inline constexpr std::string_view kNoDummyCode = "00";

}  // namespace sled::runtime
