#pragma once
// What to type instead (issue 19): from what an engine did with what was typed to what to type so it does
// what was asked, for any engine, modelled or not. The engine is treated as a black box that maps a typed
// (frequency, damping ratio) -- or the stiffness and damping they stand for, k = m omega^2, c = 2 m zeta
// omega -- to a measured one. A modelled engine's `exact` (engine_model.h) comes from its model instead;
// this is the route for every other engine, and for a modelled one whose recording disagrees with its model.
//
// One recording: the frequency scaled by the measured ratio, f' = f_typed f_asked / f_measured (exact for
// an engine whose frequency error is a constant factor: a wrong mass, a time-step convention), and the
// damping ratio moved by the difference, zeta' = zeta_typed + zeta_asked - zeta_measured (exact for an
// engine whose step adds numerical damping, which implicit and soft steps do: in Box2D 2.4 and ODE at 60 fps
// this lands nearer the request than scaling zeta, which overshoots). Two or more recordings (the user typed the correction and recorded
// again): a secant through the last two, on ln f against ln f_typed and on zeta against zeta_typed, which
// also takes out an error that grows with the value (a stiffness-dependent numerical damping).

#include <span>

namespace softtune {

/// A response as a frequency (Hz) and a damping ratio: what was asked, typed or measured.
struct ResponseValues {
  double frequency_hz = 0.0;   ///< Hz
  double damping_ratio = 0.0;  ///< >= 0
};

/// One recording: what was typed and what the engine then did.
struct CorrectionRound {
  ResponseValues typed;
  ResponseValues measured;
};

enum class CorrectionMethod {
  scaled,  ///< one recording: frequency scaled by asked / measured, damping ratio moved by the difference
  secant,  ///< two recordings: the secant through them
};

struct Correction {
  ResponseValues next;  ///< what to type next
  CorrectionMethod method = CorrectionMethod::scaled;
};

/// A secant slope outside [1/kCorrectionMaxSlope, kCorrectionMaxSlope] (a flat or reversed response, two
/// recordings too alike) is not trusted: that value is scaled from the last recording instead.
inline constexpr double kCorrectionMaxSlope = 5.0;

/// The correction for `asked` from `rounds` (oldest first; at least one, every frequency > 0).
Correction correct_response(const ResponseValues& asked, std::span<const CorrectionRound> rounds);

}  // namespace softtune
