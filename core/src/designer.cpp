#include "softtune/designer.h"

#include <numbers>

namespace softtune {

double damping_ratio_of(Oscillation level) {
  switch (level) {
    case Oscillation::free: return 0.0;
    case Oscillation::some: return 0.5;
    case Oscillation::none: return 1.0;
  }
  return 1.0;
}

double frequency_from_frames(double frames, double basis_fps) { return basis_fps / frames; }

double angular_frequency(double frequency_hz) { return 2.0 * std::numbers::pi * frequency_hz; }

double frequency_from_angular(double omega) { return omega / (2.0 * std::numbers::pi); }

double step_size(double fps, int substeps) { return 1.0 / (fps * substeps); }

}  // namespace softtune
