// OFLAB_SSE41_CLONES marks a function whose loops take floors and ceilings per row, per
// sample or per pixel (the scan conversion's spans, the brick pattern).
// On x86-64 Linux the function is cloned for SSE4.1, the clone chosen when the process
// starts, so that std::floor and std::ceil take one rounding instruction each instead of the
// baseline's emulation of about a dozen. Both are exact, so either clone gives the same
// values (SSE4.1 brings no fused multiply-add: the compiler contracts nothing more). A call
// to a marked function is not inlined: mark a function called once per band or render, not
// per pixel. Elsewhere (the WebAssembly page) it marks nothing.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__) && defined(__linux__)
#define OFLAB_SSE41_CLONES __attribute__((target_clones("sse4.1", "default")))
#else
#define OFLAB_SSE41_CLONES
#endif
