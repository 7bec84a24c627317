// jemalloc's options, compiled into every executable (CMake's og_allocator): jemalloc reads
// this symbol, the executable's own, before its first allocation (jemalloc(3), "TUNING"); the
// MALLOC_CONF environment variable, read after it, still overrides any option
// (MALLOC_CONF=thp:default,metadata_thp:disabled: no huge pages).
//
// thp:always: every block jemalloc maps from the kernel is marked MADV_HUGEPAGE, so a large
// allocation (llvmpipe's textures and buffers, which it zeroes as it makes them; the relief's
// 37 MB grid; the caches' copies) is faulted in 2 MiB at a time instead of 4 KiB. Where the
// kernel's transparent huge pages are "madvise" (Debian's default) nothing else would ask for
// them, and on a virtual machine a 4 KiB fault can cost 10 µs or more: a cached start of
// `render` 1.85 s → 0.9 s on such a machine (docs/performance.md, "Page faults"). Where they are
// "never" the option does nothing. Costs ~10 % more resident memory (whole huge pages).
#include <jemalloc/jemalloc.h>

const char* malloc_conf = "thp:always,metadata_thp:auto";
