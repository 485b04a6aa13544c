#pragma once
// Ranges of every scene field (docs/scenes.md). Designer fields use core/validation.h.

#include <cstddef>

namespace softtune::scene::limits {
inline constexpr double kMaxGravity = 1000.0;            ///< m/s^2, per component
inline constexpr double kMaxSceneFps = 10000.0;          ///< Hz
inline constexpr int kMaxSceneSubsteps = 100;
inline constexpr int kMaxIterations = 100;               ///< velocity and position iterations
inline constexpr double kMaxDurationS = 600.0;           ///< s
inline constexpr double kMaxSceneSteps = 2.0e5;          ///< frames * substeps: bounds the run time
inline constexpr double kMaxBodySteps = 2.0e7;           ///< frames * substeps * (bodies + joints): about 20 s of Box2D
inline constexpr double kMaxWorldCoordinate = 1.0e4;     ///< m; Box2D works in float, so keep it modest
inline constexpr double kMinSize = 1.0e-3, kMaxSize = 1.0e3;  ///< m, shapes and lengths
inline constexpr double kMinJointLength = 0.005;         ///< m, Box2D's b2_linearSlop; also the shortest polygon edge
                                                         ///< (b2PolygonShape::Set welds closer vertices)
inline constexpr std::size_t kMaxPolygonVertices = 8;    ///< Box2D's b2_maxPolygonVertices
inline constexpr double kMinBodyMass = 1.0e-6, kMaxBodyMass = 1.0e9;  ///< kg
inline constexpr double kMinDensity = 1.0e-6, kMaxDensity = 1.0e9;    ///< kg/m^2
inline constexpr double kMaxSpeed = 1.0e4;               ///< m/s
inline constexpr double kMaxAngularSpeed = 1.0e3;        ///< rad/s
inline constexpr std::size_t kMaxBodies = 500, kMaxJoints = 500, kMaxOscillators = 16, kMaxProbes = 64;
inline constexpr std::size_t kMaxIdLength = 64;
inline constexpr std::size_t kMaxModeTargets = 16, kMaxJointGroups = 16;
/// Dynamic bodies a linearisation takes (3 coordinates each): the SVD and the 6n x 6n eigenproblem grow as n^3.
inline constexpr std::size_t kMaxModeBodies = 100;
/// N/m (weld: N m/rad), and N s/m for |damping|: a joint's typed values (Box2D 2.4 stores them as float).
inline constexpr double kMaxTypedStiffness = 1.0e15;
inline constexpr std::size_t kMaxRates = 16;             ///< entries of rates.fps, rates.substeps and an expectation's fps, substeps
}  // namespace softtune::scene::limits
