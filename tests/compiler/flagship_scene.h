// The flagship scene (examples/frontal_sled.sled) cut short, for tests of what `sled run` writes:
// the same occupant, buck, belts, contacts, outputs and criteria, up to `end` (like `30 ms`),
// plus `extra_outputs` in its output block.
#pragma once

#include <string>

#include "tests/compiler/sled_process.h"

namespace sled::testing {

inline std::string FlagshipScene(const std::string& end, const std::string& extra_outputs = "") {
  std::string scene = ReadText(kSourceRoot / "examples" / "frontal_sled.sled");
  const std::string full = "end = 200 ms";
  const std::size_t at = scene.find(full);
  if (at == std::string::npos) return "";
  scene.replace(at, full.size(), "end = " + end);
  const std::size_t criteria = scene.find("    criteria =");
  if (criteria != std::string::npos) scene.insert(criteria, extra_outputs);
  return scene;
}

}  // namespace sled::testing
