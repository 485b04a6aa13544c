#include "mujoco_engine.h"

#include <mujoco/mujoco.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <sstream>

#include "softtune/engines/mujoco.h"

namespace softtune::engines {
namespace {

// MuJoCo prints warnings and writes MUJOCO_LOG.TXT by default; a run keeps them in mjData's counters.
void quiet_warning(const char*) {}

double value_or(const Parameters& p, std::string_view name, double fallback) {
  const std::optional<double> v = parameter_value(p, name);
  return v ? *v : fallback;
}

std::string setting_choice(const EngineRun& run, int index) {
  const SettingSpec& spec = kMujocoModel.settings[index];
  const double v = static_cast<std::size_t>(index) < run.settings.size() ? run.settings[index] : spec.default_value;
  return std::string(spec.choices[static_cast<std::size_t>(v)]);
}

RunTrajectory run_mujoco(const EngineRun& run) {
  if (setting_choice(run, kMujocoIntegrator) == "implicitfast") return {};
  const std::string xml = mujoco_mjcf(run);
  // Set once (thread-safe static initialisation): runs may go on concurrently (softtune verify).
  static const bool quiet = (mju_user_warning = quiet_warning, true);
  (void)quiet;

  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  const char* file = "softtune.xml";
  if (mj_makeEmptyFileVFS(vfs.get(), file, static_cast<int>(xml.size())) != 0) return {};
  std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), file)], xml.data(), xml.size());
  char error[1000] = "";
  mjModel* m = mj_loadXML(file, vfs.get(), error, sizeof(error));
  mj_deleteVFS(vfs.get());
  if (!m) return {};
  mjData* d = mj_makeData(m);

  const bool plank = run.body == RunBody::rotating_plank;
  const PlankGeometry g = rotating_plank(run.effective_mass);
  auto stretch = [&]() {
    if (!plank) return d->qpos[0];
    // Anchor = (x + o sin q, y - o cos q); world site at (-L, -o).
    const double ax = d->qpos[0] + g.offset * std::sin(d->qpos[2]) + kMujocoRestLength;
    const double ay = d->qpos[1] - g.offset * std::cos(d->qpos[2]) + g.offset;
    return std::hypot(ax, ay) - kMujocoRestLength;
  };
  d->qpos[0] = run.x0;
  RunTrajectory x;
  x.reserve(static_cast<std::size_t>(run.steps) + 1);
  x.push_back(stretch());
  for (int i = 0; i < run.steps; ++i) {
    mj_step(m, d);
    x.push_back(stretch());
  }
  mj_deleteData(d);
  mj_deleteModel(m);
  return x;
}

}  // namespace

std::string mujoco_mjcf(const EngineRun& run) {
  std::ostringstream s;
  s.precision(17);
  const Parameters& p = run.parameters;
  const PlankGeometry g = rotating_plank(run.effective_mass);
  const bool plank = run.body == RunBody::rotating_plank;
  std::ostringstream soft;
  soft.precision(17);
  soft << "solref=\"" << value_or(p, "solref[0]", kMujocoDefaultTimeconst) << ' '
       << value_or(p, "solref[1]", kMujocoDefaultDampratio) << "\" solimp=\"" << value_or(p, "solimp[0]", 0.9) << ' '
       << value_or(p, "solimp[1]", 0.95) << ' ' << value_or(p, "solimp[2]", 0.001) << ' '
       << value_or(p, "solimp[3]", 0.5) << ' ' << value_or(p, "solimp[4]", 2.0) << '"';
  s << "<mujoco model=\"softtune\">\n"
    << "  <option timestep=\"" << run.dt << "\" gravity=\"0 0 0\" integrator=\""
    << setting_choice(run, kMujocoIntegrator) << "\">\n"
    << "    <flag refsafe=\"" << setting_choice(run, kMujocoRefsafe) << "\"/>\n"
    << "  </option>\n"
    << "  <worldbody>\n";
  if (plank) s << "    <site name=\"w\" pos=\"" << -kMujocoRestLength << ' ' << -g.offset << " 0\"/>\n";
  s << "    <body name=\"b\">\n"
    << "      <joint name=\"x\" type=\"slide\" axis=\"1 0 0\"/>\n";
  if (plank) {
    s << "      <joint name=\"y\" type=\"slide\" axis=\"0 1 0\"/>\n"
      << "      <joint name=\"q\" type=\"hinge\" axis=\"0 0 1\"/>\n"
      << "      <inertial pos=\"0 0 0\" mass=\"" << g.mass << "\" diaginertia=\"" << g.inertia << ' ' << g.inertia
      << ' ' << g.inertia << "\"/>\n"
      << "      <site name=\"a\" pos=\"0 " << -g.offset << " 0\"/>\n";
  } else {
    s << "      <inertial pos=\"0 0 0\" mass=\"" << run.effective_mass << "\" diaginertia=\"1 1 1\"/>\n";
  }
  s << "    </body>\n"
    << "  </worldbody>\n";
  if (plank) {
    s << "  <tendon>\n    <spatial name=\"t\">\n      <site site=\"w\"/>\n      <site site=\"a\"/>\n"
      << "    </spatial>\n  </tendon>\n"
      << "  <equality>\n    <tendon tendon1=\"t\" " << soft.str() << "/>\n  </equality>\n";
  } else {
    s << "  <equality>\n    <joint joint1=\"x\" " << soft.str() << "/>\n  </equality>\n";
  }
  s << "</mujoco>\n";
  return s.str();
}

const RealEngine kMujocoEngine = {"mujoco", "MuJoCo 2.2.2 (libmujoco-dev)", run_mujoco};

}  // namespace softtune::engines
