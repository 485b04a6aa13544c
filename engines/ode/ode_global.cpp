#include "ode_global.h"

#include <ode/ode.h>

namespace softtune::engines {

std::mutex& ode_global_mutex() {
  static std::mutex m;
  return m;
}

void init_ode_for_this_thread() {
  static std::once_flag once;
  std::call_once(once, [] { dInitODE2(0); });
  thread_local bool allocated = false;
  if (!allocated) allocated = dAllocateODEDataForThread(dAllocateMaskAll) != 0;
}

}  // namespace softtune::engines
