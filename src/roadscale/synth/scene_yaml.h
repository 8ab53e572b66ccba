#pragma once

#include <string>

#include "roadscale/synth/scene_options.h"

namespace roadscale::synth {

// Builds scene options from a preset and, optionally, a YAML scene file that overrides any
// of them. The file may hold these top-level keys, each optional:
//
//   preset: urban        # the base preset when `preset` below is empty
//   seed: 7              # used when `seed` below is absent
//   Camera: {fx, fy, cx, cy, width, height, h0}   # as in a camera YAML
//   Road: {...}  Vehicle: {...}  Traffic: {...}  Scenery: {...}  Texture: {...}  Image: {...}
//
// with the keys of RoadOptions, VehicleOptions, ... by their member names (e.g.
// `Road: {lanes_same: 2, grade_max: 0.04}`); `Road.pieces` is a list of
// `{length, radius | curvature, grade, bank_deg, transition}` (radius positive turns left,
// 0 or absent: straight). Unknown keys, wrong types and values that fail Check() throw
// Error naming the file and line. `preset` empty: the file's preset, else "urban".
SceneOptions LoadSceneOptions(const std::string& preset, const std::string& yaml_path);

}  // namespace roadscale::synth
