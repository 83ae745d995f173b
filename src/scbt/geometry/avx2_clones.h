// SCBT_AVX2_CLONES marks a function whose loops vectorise. The project builds for the baseline of
// its target (SSE2 on x86-64) so that its binaries run on any machine; on x86-64 such a function
// is also compiled for AVX2 and the loader picks the version the CPU can run (function
// multi-versioning), so that its loops run twice as wide where they can. AVX2 does not bring
// fused multiply-add (that is FMA, a separate target), so both versions round every value alike.
// Elsewhere the macro is empty. Clang will not multiversion a function after its first use, so
// mark free functions defined before any call (not members called from a header).
#pragma once

#if defined(__x86_64__) && defined(__has_attribute)
#if __has_attribute(target_clones)
#define SCBT_AVX2_CLONES __attribute__((target_clones("avx2", "default")))
#endif
#endif

#ifndef SCBT_AVX2_CLONES
#define SCBT_AVX2_CLONES
#endif
