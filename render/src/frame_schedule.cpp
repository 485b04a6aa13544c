#include "softtune/render/frame_schedule.h"

#include <algorithm>
#include <cmath>

namespace softtune::render {

std::vector<int> spread_frames(int run_frames, int n) {
  std::vector<int> out;
  if (n <= 0) return out;
  if (n == 1 || run_frames <= 0) return std::vector<int>(n, 0);  // a run of no steps shows its start
  out.reserve(n);
  // Integer rounding of k R / (n - 1): (2 k R + n - 1) / (2 (n - 1)), exact for any k R below 2^62.
  const long long r = run_frames, d = n - 1;
  for (long long k = 0; k < n; ++k) out.push_back(static_cast<int>((2 * k * r + d) / (2 * d)));
  return out;
}

int first_frame_showing(const std::vector<int>& frames, int game_frame) {
  const auto it = std::lower_bound(frames.begin(), frames.end(), game_frame);
  return it == frames.end() ? -1 : static_cast<int>(it - frames.begin());
}

}  // namespace softtune::render
