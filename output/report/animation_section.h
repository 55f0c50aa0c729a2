// The animation in the page: a canvas, play and time controls, and the run's animation.glb
// carried inside the page as base64, which the viewer script (assets/viewer.js) reads and draws
// with WebGL. The page needs no file and no network to show it.
#pragma once

#include <string>

namespace sled::report {

// The section for the GLB's bytes; a note instead when `glb` is empty.
std::string AnimationSection(const std::string& glb);

}  // namespace sled::report
