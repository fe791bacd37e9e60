#pragma once
// Compile a region of a file for another instruction set (AVX2, AVX-512), with GCC (the release
// build) and clang (the sanitizer and fuzz build) alike:
//   CGTMO_TARGET_BEGIN("avx2,fma") ... CGTMO_TARGET_END()
// Code in the region runs only after a runtime CPU check by its caller.
#define CGTMO_PRAGMA(x) _Pragma(#x)
#if defined(__clang__)
#define CGTMO_TARGET_BEGIN(isa) CGTMO_PRAGMA(clang attribute push(__attribute__((target(isa))), apply_to = function))
#define CGTMO_TARGET_END() CGTMO_PRAGMA(clang attribute pop)
#else
#define CGTMO_TARGET_BEGIN(isa) CGTMO_PRAGMA(GCC push_options) CGTMO_PRAGMA(GCC target(isa))
#define CGTMO_TARGET_END() CGTMO_PRAGMA(GCC pop_options)
#endif
