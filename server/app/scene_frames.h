#pragma once
// Scene snapshots -> render draw model: the glue between the Box2D scenes and the renderer, which know
// nothing of each other (docs/conventions.md, "Dependencies point one way").

#include <string>
#include <utility>
#include <vector>

#include "app/scene_legend.h"
#include "softtune/render/frame_pipeline.h"
#include "softtune/scene/runner.h"
#include "softtune/scene/scene.h"
#include "softtune/scene/snapshot.h"

namespace softtune::app {

/// s of motion a probed point's trail shows behind it.
inline constexpr double kTrailSeconds = 0.5;

/// How many times its length a pin's anchor gap is drawn (the chain's 1.6 cm stretch is under a pixel at
/// 640x360); the settings line says so.
inline constexpr double kAnchorGapMagnify = 20.0;

/// The debug layers of a scene preview, as the engines' own debug views show them; each switchable in the
/// request ("layers": {"contacts": false, ...}) and on by default where the scene has something for it
/// (default_layers).
struct SceneLayers {
  bool contacts = true;      ///< contact points and normals (tyre on road, crate hits, the load landing)
  bool anchors = true;       ///< both anchors of every revolute and weld joint, the gap magnified
  bool rest_marks = true;    ///< a tick where each spring's rest length ends
  bool wheel_axes = true;    ///< each wheel joint's axis, rest point and travel
  bool mass_centres = true;  ///< the centre of mass of each dynamic body a joint holds or a probe follows
  bool inset = true;         ///< the tuned probe over time (probe_inset.h)
};

/// Contacts where a dynamic body can touch another; anchors with a revolute or weld joint; rest marks
/// with a soft distance or wheel joint; wheel axes with a wheel joint; centres of mass with an angle
/// probe (the vehicle's pitch turns about it); the inset with any probe.
SceneLayers default_layers(const scene::Scene& scene);

/// The role each body is drawn with: static, the first probed body (probe order) probed, another one
/// probed_second, a wheel joint's body_b wheel, else dynamic.
std::vector<render::Role> body_roles(const scene::Scene& scene);

/// The points the scene's probes follow, once each: (body index, -1) for a body probe (its centre),
/// (-1, joint index) for a joint probe (the joint's anchor on body_b). Oscillator and joint-error probes
/// follow no point.
std::vector<std::pair<int, int>> trailed_points(const scene::Scene& scene);

/// Frame `index` of `snapshots`: bodies as polygons or circles coloured by role (static, dynamic, probed),
/// every joint by its kind (a soft distance joint or a wheel joint's suspension as a spring coloured by
/// stretch, a rigid distance joint as a rod, a mouse joint as its target and the soft link to the body,
/// welds and revolutes as pins), a trail behind each probed point over the last kTrailSeconds, and a
/// caption with the scene name, time and frame.
render::DrawFrame scene_frame(const scene::Scene& scene, const std::vector<scene::Snapshot>& snapshots, int index,
                              const SceneLayers& layers = {});

/// The A/B ghost (ghost_tuning.h): the moving bodies of a second tuning's snapshot, translucent pink
/// (Role::ghost), and its tuned joints' springs translucent, drawn over the frame.
void add_ghost(render::DrawFrame& frame, const scene::Scene& ghost, const scene::Snapshot& snapshot);

/// What a camera following `scene.camera.follow` keeps in view in this snapshot: the body, the bodies
/// joined to it and those joints as drawn (a car: chassis, wheels, suspension). Empty without follow.
render::Bounds followed_bounds(const scene::Scene& scene, const scene::Snapshot& snapshot);

/// |x| (in rest lengths of the joint) past which an oscillator's spring has left the frame.
inline constexpr double kOscillatorLimit = 0.6;

/// The game frame at which oscillator `run` first passed |x| > limit_m (or blew up), or -1 if never.
int left_frame_at(const scene::OscillatorRun& run, double limit_m);

/// Game frames of a blown-up oscillator's divergence trail: the last ones before it left, and that one.
inline constexpr int kDivergenceTrailFrames = 6;

/// The scene's oscillators that copy a distance joint (the stiff preset's explicit, semi-implicit and
/// core soft springs), each drawn as a copy of that joint beside it, labelled with its method, until it
/// leaves the frame (|x| > kOscillatorLimit rest lengths); from then on its divergence: a red trail of its
/// last kDivergenceTrailFrames game frames running out of the view, and "left the view at t = T s (frame
/// K)", K the first preview frame (counted from 0) at or after it left. Frame `index` of `snapshots`.
void add_oscillators(render::DrawFrame& frame, const scene::Scene& scene, const scene::SceneResult& result,
                     const std::vector<scene::Snapshot>& snapshots, int index);

/// Every snapshot as a frame, with their times, the legend and probe inset of `result` (when given),
/// the debug `layers`, and the scene's camera: fitted to the action over the run, following `camera.follow`, or (with `camera.fit` false)
/// fixed at centre and width in metres.
render::FrameSet scene_frames(const scene::Scene& scene, const std::vector<scene::Snapshot>& snapshots,
                              const scene::SceneResult* result = nullptr, const SceneLayers& layers = {});

}  // namespace softtune::app
