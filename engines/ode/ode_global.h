#pragma once
// ODE's process-wide state, shared by every in-process ODE user (the 1-D runs of ode_engine.cpp and the
// scenes of ode_scene.cpp). Debian's libode keeps global scratch (collision and step) that two threads
// stepping at once corrupt -- two concurrent POST /api/v1/verify with "ode" once crashed the server inside
// libode.so -- so every ODE call runs under one lock.

#include <mutex>

namespace softtune::engines {

/// The lock every call into libode holds.
std::mutex& ode_global_mutex();

/// dInitODE2 once per process and dAllocateODEDataForThread once per thread; call under the lock.
void init_ode_for_this_thread();

}  // namespace softtune::engines
