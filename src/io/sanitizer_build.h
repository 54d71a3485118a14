#pragma once
// kSanitizerBuild: whether this build runs under AddressSanitizer or ThreadSanitizer, whose
// runtimes reserve huge address ranges and make system calls of their own (LeakSanitizer's
// clone and ptrace at exit, for one). GCC says so with __SANITIZE_*__, clang with __has_feature.

namespace raylab {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
inline constexpr bool kSanitizerBuild = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
inline constexpr bool kSanitizerBuild = true;
#else
inline constexpr bool kSanitizerBuild = false;
#endif
#else
inline constexpr bool kSanitizerBuild = false;
#endif

} // namespace raylab
