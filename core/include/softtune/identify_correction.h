#pragma once
// What to type instead (issue 19): from what an engine did with what was typed to what to type so it does
// what was asked, for any engine, modelled or not. The engine is treated as a black box that maps a typed
// (frequency, damping ratio) -- or the stiffness and damping they stand for, k = m omega^2, c = 2 m zeta
// omega -- to a measured one. A modelled engine's `exact` (engine_model.h) comes from its model instead;
// this is the route for every other engine, and for a modelled one whose recording disagrees with its model.
//
// The map is read in (u, v) = (ln f / 0.01, zeta / 0.02): the request's bar (1 % in frequency, 0.02 in
// damping ratio) is one unit on either axis, so "within the bar" is a unit box and a step's length weighs
// both errors alike. The residual is r = (ln(f_measured / f_asked) / 0.01, (zeta_measured - zeta_asked) /
// 0.02).
//
// One recording: the model is J = I, which is the scaled correction f' = f_typed f_asked / f_measured
// (exact for an engine whose frequency error is a constant factor: a wrong mass, a time-step convention)
// and zeta' = zeta_typed + zeta_asked - zeta_measured (exact for an engine whose step adds numerical
// damping, which implicit and soft steps do). More recordings: every round, oldest first, updates J by
// Broyden's rule (the smallest change that makes J map the step from the best round so far to this round
// onto the change it measured), so J learns the coupling a soft step has between frequency and damping
// (Box2D 2.4 at 8 Hz and 60 fps: typing more stiffness also adds damping). The next values are a
// trust-region step from the best round so far (trust_step.h): a round that did worse than the model said
// halves the region, one that did as the model said doubles it, so a response that jumps cannot send the
// next values to absurd ones, and the rounds cannot oscillate between two recordings.

#include <cstddef>
#include <span>

namespace softtune {

/// A response as a frequency (Hz) and a damping ratio: what was asked, typed or measured.
struct ResponseValues {
  double frequency_hz = 0.0;   ///< Hz
  double damping_ratio = 0.0;  ///< >= 0 measured; typed may be negative (lowest_typed_damping_ratio)
};

/// One recording: what was typed and what the engine then did.
struct CorrectionRound {
  ResponseValues typed;
  ResponseValues measured;
};

enum class CorrectionMethod {
  scaled,  ///< one recording: frequency scaled by asked / measured, damping ratio moved by the difference
  secant,  ///< two or more recordings: the 2-D secant (Broyden) model through all of them, in a trust region
};

/// Where the rounds stand (docs/identify.md, "What to type instead").
enum class CorrectionVerdict {
  converging,    ///< record again with `next`
  met,           ///< the best round is within the bar: keep its typed values (`next` repeats them)
  beyond_reach,  ///< the rounds' model says no typed values reach the request: `next` is the closest it sees
                 ///< (the best round once rounds stop improving), or it needs a damping ratio below the floor
  stalled,       ///< rounds stopped improving although the model said they would: the response jumps or the
                 ///< recordings are noisier than the bar; `next` repeats the best round
};

struct Correction {
  ResponseValues next;  ///< what to type next
  CorrectionMethod method = CorrectionMethod::scaled;
  CorrectionVerdict verdict = CorrectionVerdict::converging;
  ResponseValues expected;     ///< what the model expects the engine to do with `next`
  std::size_t best_round = 0;  ///< index into the rounds (oldest first): the nearest within the bar, else the
                               ///< nearest to the request
  double trust_radius = 0.0;   ///< the step's limit, in units of the bar (1 % frequency, 0.02 ratio)
};

/// The bar a round is held to: relative frequency error and absolute damping-ratio error (issue 19).
inline constexpr double kCorrectionFrequencyBar = 0.01;
inline constexpr double kCorrectionDampingBar = 0.02;
/// The first trust region, in units of the bar: ln 2 in frequency alone (a factor of 2), or 1.4 in ratio.
inline constexpr double kCorrectionFirstRadius = 70.0;
/// The largest trust region a run of good rounds can grow to, in units of the bar.
inline constexpr double kCorrectionMaxRadius = 140.0;
/// A trust region shrunk below this (0.25 % / 0.005) means rounds stopped improving: `stalled`.
inline constexpr double kCorrectionMinRadius = 0.25;

/// The lowest damping ratio worth typing into an engine stepping every `step_s` seconds, for a request at
/// `frequency_hz`: -omega h / 4. A negative typed damping cancels a step's own numerical damping (what a
/// modelled implicit engine's `exact` does: exact_softness.h, c' may be negative); at zeta = -omega h / 2,
/// c + h k = 0 and an implicit step turns rigid (Box2D sets gamma = 0), so half of that is the floor.
double lowest_typed_damping_ratio(double frequency_hz, double step_s);

/// The correction for `asked` from `rounds` (oldest first; at least one, every frequency > 0). It types a
/// damping ratio below 0, down to `lowest_damping_ratio`, only once a round typed with at most half the
/// asked ratio (or 0.02) still measured more than asked plus 0.02: the engine damps by itself (an implicit
/// or soft step). Pass 0 for an engine that refuses negative damping.
Correction correct_response(const ResponseValues& asked, std::span<const CorrectionRound> rounds,
                            double lowest_damping_ratio = 0.0);

/// Whether a measured response is within the bar of the asked one.
bool meets_bar(const ResponseValues& asked, const ResponseValues& measured);

}  // namespace softtune
