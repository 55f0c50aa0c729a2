// animation.glb: the run's motion as a glTF 2.0 binary that browsers (three.js viewers) and
// Blender open. One node per vehicle and per segment, placed in the world frame by translation
// and rotation channels at the output rate (linear interpolation); each carries its contact
// surfaces as child nodes: ellipsoids and hyper-ellipsoids as meshes of the unit shape scaled to
// the semi-axes, finite planes as quads. Surfaces fixed to the ground hang from a static
// `ground` node. Belts are line pieces following the belt path (AnimationRecorder), animated by
// translation, rotation and scale. Units are metres. All of these hang from one root node, `world`,
// that turns sled's z-up axes into glTF's y-up ones (-90 degrees about x), so a viewer shows
// the scene upright and the animated nodes' values are in sled's world frame.
#pragma once

#include <string>

#include "output/export/animation_recorder.h"

namespace sled::runtime {

bool WriteAnimationGlb(const std::string& path, const Model& model,
                       const AnimationRecorder& recorder, std::string* error);

}  // namespace sled::runtime
