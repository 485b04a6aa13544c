#pragma once
// Scenes the scene tests share: designer requests, boxes, joints, probes, the talk's Buddhas (planks hung at
// offsets along them) and a hanging weight on one soft distance joint.

#include <optional>
#include <string>
#include <vector>

#include "softtune/scene/scene.h"

namespace softtune::scene::test {

inline TuneRequest designer(double frames, Oscillation level, SoftMode mode = SoftMode::standard) {
  TuneRequest q;
  q.response_frames = frames;
  q.oscillation = level;
  q.mode = mode;
  return q;
}

inline BodySettings box(const std::string& id, double w, double h, Eigen::Vector2d at, std::optional<double> mass, bool is_static = false) {
  BodySettings b;
  b.id = id;
  b.shape.width = w;
  b.shape.height = h;
  b.position = at;
  b.mass = mass;
  b.is_static = is_static;
  return b;
}

inline JointSettings joint(const std::string& id, JointKind kind, const std::string& a, const std::string& b, std::optional<TuneRequest> tuning) {
  JointSettings j;
  j.id = id;
  j.kind = kind;
  j.body_a = a;
  j.body_b = b;
  j.tuning = tuning;
  return j;
}

// A probe reading `target`: a body, joint or oscillator id depending on the kind.
inline ProbeSettings probe(const std::string& id, ProbeKind kind, const std::string& target) {
  ProbeSettings p;
  p.id = id;
  p.kind = kind;
  if (kind == ProbeKind::displacement || kind == ProbeKind::angle) p.body = target;
  else if (kind == ProbeKind::oscillator) p.oscillator = target;
  else p.joint = target;
  return p;
}

// The talk's Buddhas: identical 2 m x 0.2 m, 4 kg planks in zero gravity, each hung at `offsets` along it.
inline Scene buddhas(const std::vector<double>& offsets) {
  Scene s;
  s.name = "buddhas";
  s.world.gravity = {0, 0};
  s.world.duration_s = 4.0;
  s.bodies.push_back(box("ceiling", 30, 0.2, {7.5, 3.1}, std::nullopt, true));
  for (std::size_t i = 0; i < offsets.size(); ++i) {
    const double x = 5.0 * i;
    s.bodies.push_back(box("plank" + std::to_string(i), 2.0, 0.2, {x, 0}, 4.0));
    JointSettings j = joint("hanger" + std::to_string(i), JointKind::distance, "ceiling", "plank" + std::to_string(i),
                            designer(60, Oscillation::some, SoftMode::exact));
    j.anchor_a = {x + offsets[i], 3.0};
    j.anchor_b = {x + offsets[i], 0.0};
    j.length = 2.98;
    s.joints.push_back(j);
    s.probes.push_back(probe(j.id, ProbeKind::joint_length, j.id));
  }
  return s;
}

// One stiff soft distance joint, fixed rotation: the body moves exactly like the core's soft step (implicit
// Euler) on the same (m_eff, k, c) -- Box2D works in float, so to float precision.
inline Scene hanging_weight(double frequency_hz, Oscillation level) {
  Scene s;
  s.name = "weight";
  s.world.gravity = {0, 0};
  s.world.duration_s = 1.0;
  s.bodies.push_back(box("anchor", 0.5, 0.2, {0, 2}, std::nullopt, true));
  BodySettings weight = box("weight", 0.3, 0.3, {0, 0.9}, 1.0);
  weight.fixed_rotation = true;
  s.bodies.push_back(weight);
  TuneRequest q;
  q.frequency_hz = frequency_hz;
  q.oscillation = level;
  JointSettings j = joint("spring", JointKind::distance, "anchor", "weight", q);
  j.anchor_a = {0, 2};
  j.anchor_b = {0, 0.9};
  j.length = 1.0;
  s.joints.push_back(j);
  OscillatorSettings o;
  o.id = "soft";
  o.method = Method::soft;
  o.joint = "spring";
  o.initial_displacement = 0.1;
  s.oscillators.push_back(o);
  ProbeSettings body_probe = probe("body", ProbeKind::displacement, "weight");
  body_probe.axis = {0, -1};
  s.probes = {body_probe, probe("core", ProbeKind::oscillator, "soft")};
  return s;
}


}  // namespace softtune::scene::test
