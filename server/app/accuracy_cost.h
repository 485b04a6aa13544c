#pragma once
// The cost of an accuracy report (request_cost.h), from its rows before any of them runs.

#include "app/request_cost.h"
#include "codec/accuracy_codec.h"

namespace softtune::app {

/// Per step rate: explicit, semi-implicit and implicit Euler once, soft and soft_exact once per
/// soft_substeps entry, and the Box2D row when asked. Each core row steps frames x substeps once to
/// record and timing_repeats times more to time (at least 1024 steps a batch): 25 ns a step (20 ns
/// measured), 100 ns a recorded frame (scoring against the analytic solution, the pole fit; 70 ns
/// measured). The Box2D row runs its frames 1 + timing_repeats times at 3 us a frame (2.2 us measured).
/// Each row keeps 8 bytes a frame; the SVG draws the rows at the request's fps at about 80 bytes a
/// point (response and error plots).
RequestCost accuracy_cost(const codec::AccuracyRequest& q, bool box2d_row, bool svg);

}  // namespace softtune::app
