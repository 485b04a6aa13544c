#pragma once
// Placing modes: solve for the k, c of groups of soft rows so that targeted modes have the asked natural
// frequency and damping ratio (the designer tunes the motion they see, not one spring on its own mass).
//
// Unknowns: p = (ln k_g, ln c_g) per group (positive by construction); in exact mode (ln k_g, ln(c_g + h k_g)):
// a fast request needs c < 0 there, as one exact spring's c' (exact_softness.h), and c + h k > 0 keeps the
// step's gamma = 1 / (h (c + h k)) finite and positive. Residuals per target:
//   (ln(f / f_asked), zeta - zeta_asked),
// f, zeta of the continuous poles (standard mode) or of the discrete poles of implicit Euler at h, s = ln(z)/h
// (exact mode: the step itself lands on the request). Levenberg-Marquardt with a forward-difference Jacobian:
//   (J^T J + mu diag(J^T J)) dp = -J^T r.
// As many residuals as unknowns: solved to 1e-9; more: least squares, the residual reported; fewer: the
// solution nearest the starting guess. A target's mode is found at the starting guess by its label (find_mode:
// the mode with the largest energy share in the target's body and coordinate) and then followed by its shape
// (track_mode): after each accepted step, the mode that overlaps most with the shape it had, so a crossing of
// frequencies or a change of the largest component on the way does not swap the target for another mode.
// A target is refused (FieldError "targets.N...", and its `Refusal`) when no mode moves its body in its
// coordinate, when the tuned rows store none of its mode's energy, when exact mode asks for poles the step
// cannot represent (exact_max_omega, exact_softness.h), or when the solve cannot reach it.

#include <optional>
#include <vector>

#include "softtune/diagnostics.h"
#include "softtune/modes.h"
#include "softtune/softness.h"

namespace softtune::modes {

/// A mode named by the body and coordinate that moves most in it (find_mode), with the designer's request.
struct ModeTarget {
  int body = 0;
  Dof dof = Dof::y;
  double frequency_hz = 1.0;   ///< Hz, > 0
  double damping_ratio = 0.5;  ///< >= 0
};

/// Soft rows (indices into LinearModel::rows) that share one k, c; `start` is the solve's first guess.
struct SpringGroup {
  std::vector<int> rows;
  SpringConstants start;
};

struct ModalTuneRequest {
  std::vector<ModeTarget> targets;
  std::vector<SpringGroup> groups;
  bool discrete = false;  ///< exact mode: match the implicit Euler poles at h
  double h = 1.0 / 60.0;  ///< s
};

/// Minimum share of a targeted mode's potential energy the tuned rows must store (else they do not move it).
inline constexpr double kMinTunedEnergyShare = 1e-6;
/// A square or under-determined solve must bring every residual below this.
inline constexpr double kModalTolerance = 1e-9;

struct TargetOutcome {
  int mode = -1;                 ///< index into `modes`
  std::optional<Pole> predicted; ///< of the kind the request matched (continuous or discrete)
  double frequency_error = 0.0;  ///< f / f_asked - 1
  double damping_ratio_error = 0.0;  ///< zeta - zeta_asked
};

/// Why a solve refused. `no_mode` and `not_moved` are about the starting point's system: the caller may retry
/// from another rest state (scene/modal_tuning.h stiffens a start whose springs sag the body onto the ground).
enum class Refusal { none, step_limit, no_mode, not_moved, unreached };

struct ModalTuneResult {
  std::optional<FieldError> error;
  Refusal refusal = Refusal::none;
  int refused_target = -1;              ///< index into request.targets of the refusal's target
  /// solved k, c per group (N/m, N s/m; N m/rad, N m s/rad angular); c < 0 only in exact mode, c + h k > 0
  std::vector<SpringConstants> groups;
  std::vector<TargetOutcome> targets;
  std::vector<Mode> modes;              ///< of the solved system
  double residual = 0.0;                ///< |r| at the solution (0 for a reached square system)
  bool least_squares = false;           ///< more residuals than unknowns
  int iterations = 0;
};

/// Solves; `system` ends with the solved springs set.
ModalTuneResult solve_modal_tune(const LinearModel& model, ReducedSystem& system, const ModalTuneRequest& request);

}  // namespace softtune::modes
