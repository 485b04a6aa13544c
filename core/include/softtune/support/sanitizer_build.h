#pragma once
// Whether this test binary is built under ASan/UBSan or TSan (scripts/build-asan.sh, test-sanitizers.sh):
// gcc says __SANITIZE_ADDRESS__ / __SANITIZE_THREAD__, clang (the sanitizer builds) __has_feature. Tests
// whose bar depends on the allocator or on Release speed read it.

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
