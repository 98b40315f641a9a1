// libmvec's entry points follow the x86-64 vector function ABI (_ZGV<isa>N<lanes><args>_<name>): 'b' is
// SSE2 (xmm, baseline x86-64), 'd' AVX2 (ymm). The AVX2 loops are compiled for AVX2 alone and chosen once
// at run time, so the rest of the build stays baseline x86-64. Elsewhere (no libmvec ABI to call) the
// lanes are libm's, one at a time.
#include "materials/core/lane_math.h"

#include <algorithm>
#include <cmath>

#if !defined(__x86_64__)

namespace glossy::lanes {

Isa isa() { return Isa::Sse2; }
bool setIsa(Isa isa) { return isa == Isa::Sse2; }

void atan2(const double* y, const double* x, double* out, int n) {
  for (int i = 0; i < n; ++i) out[i] = std::atan2(y[i], x[i]);
}

void sinCos(const double* a, double* s, double* c, int n) {
  for (int i = 0; i < n; ++i) {
    s[i] = std::sin(a[i]);
    c[i] = std::cos(a[i]);
  }
}

}  // namespace glossy::lanes

#else

#include <immintrin.h>

extern "C" {
__m128d _ZGVbN2vv_atan2(__m128d y, __m128d x);
__m128d _ZGVbN2v_sin(__m128d a);
__m128d _ZGVbN2v_cos(__m128d a);
__m256d _ZGVdN4vv_atan2(__m256d y, __m256d x);
__m256d _ZGVdN4v_sin(__m256d a);
__m256d _ZGVdN4v_cos(__m256d a);
}

namespace glossy::lanes {

namespace {

// Initialised before main, hence the explicit __builtin_cpu_init.
const bool kCpuHasAvx2 = [] {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}();
bool useAvx2 = kCpuHasAvx2;

// A batch of n lanes as whole vectors of W: the last, partial one is copied into padded arrays (padding
// with harmless arguments, 0 and 1) and its lanes copied back.
template <int W>
struct Padded {
  alignas(32) double in0[W], in1[W], out0[W], out1[W];
  int count;
  Padded(const double* a, const double* b, int n) : count(n) {
    std::fill(in0, in0 + W, 0.0);
    std::fill(in1, in1 + W, 1.0);
    std::copy(a, a + n, in0);
    if (b) std::copy(b, b + n, in1);
  }
};

__attribute__((target("avx2,fma"))) void atan2Avx2(const double* y, const double* x, double* out, int n) {
  int i = 0;
  for (; i + 4 <= n; i += 4) _mm256_storeu_pd(out + i, _ZGVdN4vv_atan2(_mm256_loadu_pd(y + i), _mm256_loadu_pd(x + i)));
  if (i == n) return;
  Padded<4> t(y + i, x + i, n - i);
  _mm256_store_pd(t.out0, _ZGVdN4vv_atan2(_mm256_load_pd(t.in0), _mm256_load_pd(t.in1)));
  std::copy(t.out0, t.out0 + t.count, out + i);
}

__attribute__((target("avx2,fma"))) void sinCosAvx2(const double* a, double* s, double* c, int n) {
  int i = 0;
  for (; i + 4 <= n; i += 4) {
    const __m256d v = _mm256_loadu_pd(a + i);
    _mm256_storeu_pd(s + i, _ZGVdN4v_sin(v));
    _mm256_storeu_pd(c + i, _ZGVdN4v_cos(v));
  }
  if (i == n) return;
  Padded<4> t(a + i, nullptr, n - i);
  const __m256d v = _mm256_load_pd(t.in0);
  _mm256_store_pd(t.out0, _ZGVdN4v_sin(v));
  _mm256_store_pd(t.out1, _ZGVdN4v_cos(v));
  std::copy(t.out0, t.out0 + t.count, s + i);
  std::copy(t.out1, t.out1 + t.count, c + i);
}

void atan2Sse2(const double* y, const double* x, double* out, int n) {
  int i = 0;
  for (; i + 2 <= n; i += 2) _mm_storeu_pd(out + i, _ZGVbN2vv_atan2(_mm_loadu_pd(y + i), _mm_loadu_pd(x + i)));
  if (i == n) return;
  Padded<2> t(y + i, x + i, n - i);
  _mm_store_pd(t.out0, _ZGVbN2vv_atan2(_mm_load_pd(t.in0), _mm_load_pd(t.in1)));
  std::copy(t.out0, t.out0 + t.count, out + i);
}

void sinCosSse2(const double* a, double* s, double* c, int n) {
  int i = 0;
  for (; i + 2 <= n; i += 2) {
    const __m128d v = _mm_loadu_pd(a + i);
    _mm_storeu_pd(s + i, _ZGVbN2v_sin(v));
    _mm_storeu_pd(c + i, _ZGVbN2v_cos(v));
  }
  if (i == n) return;
  Padded<2> t(a + i, nullptr, n - i);
  const __m128d v = _mm_load_pd(t.in0);
  _mm_store_pd(t.out0, _ZGVbN2v_sin(v));
  _mm_store_pd(t.out1, _ZGVbN2v_cos(v));
  std::copy(t.out0, t.out0 + t.count, s + i);
  std::copy(t.out1, t.out1 + t.count, c + i);
}

}  // namespace

Isa isa() { return useAvx2 ? Isa::Avx2 : Isa::Sse2; }

bool setIsa(Isa isa) {
  if (isa == Isa::Avx2 && !kCpuHasAvx2) return false;
  useAvx2 = isa == Isa::Avx2;
  return true;
}

void atan2(const double* y, const double* x, double* out, int n) {
  useAvx2 ? atan2Avx2(y, x, out, n) : atan2Sse2(y, x, out, n);
}

void sinCos(const double* a, double* s, double* c, int n) {
  useAvx2 ? sinCosAvx2(a, s, c, n) : sinCosSse2(a, s, c, n);
}

}  // namespace glossy::lanes

#endif  // __x86_64__
