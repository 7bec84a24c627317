#include "core/HalfFloat.hpp"

#include <glm/gtc/packing.hpp>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define OG_HAVE_F16C_PATH 1
#endif

namespace og::core {
namespace {

#ifdef OG_HAVE_F16C_PATH
__attribute__((target("avx,f16c"))) void floatsToHalvesF16c(const float* in, std::uint16_t* out, std::size_t n) {
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8) {
    const __m128i h = _mm256_cvtps_ph(_mm256_loadu_ps(in + i), _MM_FROUND_TO_NEAREST_INT);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + i), h);
  }
  if (i == n) return;
  alignas(32) float tail[8] = {};
  alignas(16) std::uint16_t halves[8] = {};
  for (std::size_t k = i; k < n; ++k) tail[k - i] = in[k];
  _mm_store_si128(reinterpret_cast<__m128i*>(halves), _mm256_cvtps_ph(_mm256_load_ps(tail), _MM_FROUND_TO_NEAREST_INT));
  for (std::size_t k = i; k < n; ++k) out[k] = halves[k - i];
}

bool haveF16c() {
  static const bool have = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx") && __builtin_cpu_supports("f16c");
  }();
  return have;
}
#endif

}  // namespace

void floatsToHalves(const float* in, std::uint16_t* out, std::size_t n) {
#ifdef OG_HAVE_F16C_PATH
  if (haveF16c()) {
    floatsToHalvesF16c(in, out, n);
    return;
  }
#endif
  for (std::size_t i = 0; i < n; ++i) out[i] = glm::packHalf1x16(in[i]);
}

}  // namespace og::core
