#pragma once
// Scene snapshots -> render draw model: the glue between the Box2D scenes and the renderer, which know
// nothing of each other (STYLE.md: dependencies point one way, server -> scenes/render -> core).

#include <vector>

#include "softtune/render/frame_pipeline.h"
#include "softtune/scene/scene.h"
#include "softtune/scene/snapshot.h"

namespace softtune::app {

/// One frame: bodies as polygons or circles coloured by role (static, dynamic, probed), springy joints
/// (distance, wheel, mouse) as springs with their rest length, every joint's anchors as dots, and a
/// caption with the scene name, time and frame.
render::DrawFrame scene_frame(const scene::Scene& scene, const scene::Snapshot& snapshot, int index, int count);

/// Every snapshot as a frame, with the scene's camera (fixed: centre and width in metres).
render::FrameSet scene_frames(const scene::Scene& scene, const std::vector<scene::Snapshot>& snapshots);

}  // namespace softtune::app
