#pragma once
// Whether this binary is built under ASan/UBSan or TSan (scripts/build-asan.sh, test-sanitizers.sh):
// gcc says __SANITIZE_ADDRESS__ / __SANITIZE_THREAD__, clang (the sanitizer builds) __has_feature. Tests
// whose bar depends on the allocator or on Release speed read it, and the run-time limits (server/http
// service.cpp and app/job_runner.cpp, by kInstrumentationSlowdown).

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define SOFTTUNE_SANITIZED_BUILD 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define SOFTTUNE_SANITIZED_BUILD 1
#endif
#endif
#ifndef SOFTTUNE_SANITIZED_BUILD
#define SOFTTUNE_SANITIZED_BUILD 0
#endif

namespace softtune::support {
/// How many times slower a sanitizer build runs the same work (the chain sweep 57 times under ASan): the
/// run-time limits (server/http/service.cpp, server/app/job_runner.cpp) are scaled by it, so that they stop
/// mispriced work, not the instrumentation of work the price allows. 1 in a plain build.
inline constexpr double kInstrumentationSlowdown = SOFTTUNE_SANITIZED_BUILD ? 60.0 : 1.0;
}  // namespace softtune::support
