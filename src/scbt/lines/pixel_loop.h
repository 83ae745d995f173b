// SCBT_PIXEL_LOOP marks a function whose loops run over every pixel of a window. The project
// builds for the baseline of its target (SSE2 on x86-64) so that its binaries run on any
// machine; on x86-64 such a function is also compiled for AVX2 and the loader picks the version
// the CPU can run (function multi-versioning), so that its 8- and 16-bit arithmetic vectorises
// twice as wide where it can. Elsewhere the macro is empty.
#pragma once

#if defined(__x86_64__) && defined(__has_attribute)
#if __has_attribute(target_clones)
#define SCBT_PIXEL_LOOP __attribute__((target_clones("avx2", "default")))
#endif
#endif

#ifndef SCBT_PIXEL_LOOP
#define SCBT_PIXEL_LOOP
#endif
