#pragma once
// The 1-D oscillator through a real engine: Box2D 2.4's b2DistanceJoint between a static ground body and
// a dynamic body of mass m (fixed rotation, zero gravity, no sleeping), stiffness = k, damping = c.
//
// Box2D 2.4.1's conventions (src/dynamics/b2_distance_joint.cpp, InitVelocityConstraints):
//   gamma = 1 / (h (d + h k))   ("the extra factor of h ... since the lambda is an impulse"),
//   bias = C h k gamma,  soft mass = 1 / (invMass + gamma),
// and SolveVelocityConstraints: impulse = -softMass (Cdot + bias + gamma * accumulated impulse).
// That is the soft constraint of softness.h in impulse form: gamma_impulse = gamma / h and
// bias = (beta / h) C, so in exact arithmetic it steps exactly like soft_step(). Box2D computes in float
// (~1e-7 relative), and it clamps a body's translation to b2_maxTranslation = 2 m per step
// (b2_island.cpp), so a spring moving faster than 2 m per step departs from soft_step().

#include <vector>

#include "softtune/softness.h"

namespace softtune {

/// Name of the accuracy report's Box2D row and of the stage that ran it.
inline constexpr const char* kBox2DRowName = "box2d_distance_joint";

/// The joint's rest length (m) in the 1-D setup; the body starts at rest_length + x0 along x. Longer than
/// the amplitude (the joint is singular at zero length) and short, so float positions keep ~2e-7 m.
inline constexpr float kBox2DRestLength = 2.0f;

/// Steps the spring `steps` times with step h (s) from displacement x0 (m), at rest. Returns the
/// displacement after each step, x0 first (steps + 1 samples). One velocity iteration suffices for a
/// single soft constraint (it is solved exactly in one); 8 and 3 are Box2D's recommended counts.
std::vector<double> run_box2d_spring(const Oscillator& spring, double x0, double h, int steps);

}  // namespace softtune
