#pragma once
// JSON <-> the modes of a scene: the `modal_tuning` object of a scene document (targets and groups), the modes
// list (`softtune modes`, POST /api/v1/modes) and a run's modal tuning answer. Field list: docs/scenes.md,
// "Modes" and "Tuning the modes".

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "codec/json_reader.h"
#include "softtune/modes.h"
#include "softtune/scene/linearise.h"
#include "softtune/scene/modal_tuning.h"
#include "softtune/scene/runner.h"

namespace softtune::codec {

/// Reads `modal_tuning` (its reader is at "modal_tuning"): mode, at_s, groups [{id, joints}], targets
/// [{probe | body + mode, response_frames / frequency_hz, oscillation / damping_ratio}].
scene::ModalTuningSettings read_modal_tuning(ObjectReader& r);

/// [{name, free, unstable, undamped_frequency_hz, continuous {frequency_hz, damping_ratio} | null, discrete | null,
///   components [{body, coordinate, motion, amplitude, share}]}]
nlohmann::json modes_json(const std::vector<modes::Mode>& modes, const std::vector<std::string>& body_ids);

/// A run's modal tuning: groups (k, c), joints (k, c, gamma, beta, engines), targets (requested, predicted,
/// measured by the probe's fit, error), residual, least_squares, iterations, at_s, settled, modes.
nlohmann::json modal_tuning_json(const scene::Scene& scene, const scene::ModalTuningResult& modal, const scene::SceneResult& run);

/// The modes answer: name, at_s, settled, h, contact_points, balance_residual, stages, modes.
nlohmann::json linearisation_json(const std::string& name, const scene::LinearisedScene& lin,
                                  const std::vector<modes::Mode>& modes, const StageList& stages);

}  // namespace softtune::codec
