#pragma once
/// \file
/// \brief Whether the io tests were built with a sanitizer: the mesh loader leaves out the child
/// process's memory cap there (adsd/io/src/child_process_reader.h), so the tests of that cap skip.

namespace adsd::test {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
inline constexpr bool kUnderSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
inline constexpr bool kUnderSanitizer = true;
#else
inline constexpr bool kUnderSanitizer = false;
#endif
#else
inline constexpr bool kUnderSanitizer = false;
#endif

}  // namespace adsd::test
