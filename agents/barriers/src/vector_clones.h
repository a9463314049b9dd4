#pragma once

// A function marked DREAM_VECTOR_CLONES is built twice, for x86-64's baseline
// (SSE2: 2 doubles a vector instruction) and for AVX2 (4), and the CPU picks
// one when the library loads (GCC's function multi-versioning), so one binary
// runs everywhere and twice as wide where it can. AVX2 alone brings no fused
// multiply-add, so every operation rounds as the baseline's: the same bits
// either way. Off under AddressSanitizer and for other compilers.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__SANITIZE_ADDRESS__)
#define DREAM_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define DREAM_VECTOR_CLONES
#endif
