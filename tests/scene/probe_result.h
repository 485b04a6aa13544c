#pragma once
// A scene run's probe by id, for tests that read what one probe measured.

#include <gtest/gtest.h>

#include <string>

#include "softtune/scene/runner.h"

namespace softtune::scene::test {

/// The probe `id` of `r`; a test failure (and the first probe) when the run has none of that id.
inline const ProbeResult& probe_result(const SceneResult& r, const std::string& id) {
  for (const auto& p : r.probes) {
    if (p.id == id) return p;
  }
  ADD_FAILURE() << "no probe " << id;
  return r.probes.front();
}

}  // namespace softtune::scene::test
