#pragma once
// Which game frames a preview shows: spread over the whole run, the first at t = 0 and the last at the
// run's end, whatever the frame count (a stride rounded down had ended `chain --frames 300` at 4.98 s of
// 8 s). Preview frames count from 0 everywhere, like their files (frame_0000.png) and URLs (/0.png).

#include <vector>

namespace softtune::render {

/// The game frames of an n-frame preview of a run of `run_frames` steps (game frames 0..run_frames):
/// frame k at round(k run_frames / (n - 1)), so frame 0 is game frame 0 and frame n - 1 is run_frames.
/// Distinct while n <= run_frames + 1 (the caller clamps n there); n = 1 gives {0}; n <= 0 gives {}.
std::vector<int> spread_frames(int run_frames, int n);

/// The preview frame that first shows game frame `game_frame` (the first k with frames[k] >= it), or -1
/// when the preview ends before it.
int first_frame_showing(const std::vector<int>& frames, int game_frame);

}  // namespace softtune::render
