// What kind of build this translation unit is compiled in, for the few places that must differ.
#pragma once

/// Defined to 1 when the translation unit is compiled with AddressSanitizer (GCC defines
/// `__SANITIZE_ADDRESS__`; clang answers `__has_feature(address_sanitizer)`). The sanitizer suite
/// (CMake option CAMOPT_SANITIZE, scripts/test_sanitizers.sh) builds with ASan and UBSan together, so this marks the sanitized build.
#if defined(__SANITIZE_ADDRESS__)
#define CAMOPT_SANITIZED_BUILD 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CAMOPT_SANITIZED_BUILD 1
#endif
#endif
