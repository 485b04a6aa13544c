#pragma once
// Designer units -> oscillator parameters (docs/math.md; Catto GDC 2011, "3:3:1").
// This is the one place the designer mapping lives.

namespace softtune {

/// The designer's three oscillation levels (Catto GDC 2011, "3:3:1").
enum class Oscillation { free, some, none };

/// Damping ratio of an oscillation level: free -> 0, some -> 0.5, none -> 1 (critical).
double damping_ratio_of(Oscillation level);

/// Frequency in Hz of a response that lasts `frames` frames per period on a `basis_fps` clock:
/// f = B / N (one oscillation period lasts N frames).
double frequency_from_frames(double frames, double basis_fps);

/// Angular frequency in rad/s: omega = 2 pi f.
double angular_frequency(double frequency_hz);

/// Frequency in Hz from an angular frequency in rad/s: f = omega / (2 pi).
double frequency_from_angular(double omega);

/// Solver time step in seconds: h = 1 / (fps * substeps).
double step_size(double fps, int substeps);

}  // namespace softtune
