// libmvec's entry points follow the x86-64 vector function ABI (_ZGV<isa>N<lanes><args>_<name>): 'b' is
// SSE2 (xmm, baseline x86-64), 'd' AVX2 (ymm). The AVX2 blocks are compiled for AVX2 alone and chosen once
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

void exp(const double* a, double* out, int n) {
  for (int i = 0; i < n; ++i) out[i] = std::exp(a[i]);
}

void log1p(const double* a, double* out, int n) {
  for (int i = 0; i < n; ++i) out[i] = std::log1p(a[i]);
}

void expm1(const double* a, double* out, int n) {
  for (int i = 0; i < n; ++i) out[i] = std::expm1(a[i]);
}

}  // namespace glossy::lanes

#else

#include <immintrin.h>

extern "C" {
__m128d _ZGVbN2vv_atan2(__m128d y, __m128d x);
__m128d _ZGVbN2v_sin(__m128d a);
__m128d _ZGVbN2v_cos(__m128d a);
__m128d _ZGVbN2v_exp(__m128d a);
__m128d _ZGVbN2v_log1p(__m128d a);
__m128d _ZGVbN2v_expm1(__m128d a);
// Declared AVX2 like the blocks that call them: clang refuses a ymm argument to a baseline-ISA function.
#define GLOSSY_AVX2 __attribute__((target("avx2,fma")))
GLOSSY_AVX2 __m256d _ZGVdN4vv_atan2(__m256d y, __m256d x);
GLOSSY_AVX2 __m256d _ZGVdN4v_sin(__m256d a);
GLOSSY_AVX2 __m256d _ZGVdN4v_cos(__m256d a);
GLOSSY_AVX2 __m256d _ZGVdN4v_exp(__m256d a);
GLOSSY_AVX2 __m256d _ZGVdN4v_log1p(__m256d a);
GLOSSY_AVX2 __m256d _ZGVdN4v_expm1(__m256d a);
#undef GLOSSY_AVX2
}

namespace glossy::lanes {

namespace {

// Initialised before main, hence the explicit __builtin_cpu_init.
const bool kCpuHasAvx2 = [] {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}();
bool useAvx2 = kCpuHasAvx2;

// One vector's worth of lanes per call (4 for AVX2, 2 for SSE2): in0, in1 are the arguments, out0, out1
// the results (atan2: out0 = atan2(in0, in1); sinCos: out0 = sin in0, out1 = cos in0). Only these touch
// the ISA's registers; the loop around them is the same for both.
using Block = void (*)(const double* in0, const double* in1, double* out0, double* out1);

__attribute__((target("avx2,fma"))) void atan2Avx2(const double* y, const double* x, double* out, double*) {
  _mm256_storeu_pd(out, _ZGVdN4vv_atan2(_mm256_loadu_pd(y), _mm256_loadu_pd(x)));
}
__attribute__((target("avx2,fma"))) void sinCosAvx2(const double* a, const double*, double* s, double* c) {
  const __m256d v = _mm256_loadu_pd(a);
  _mm256_storeu_pd(s, _ZGVdN4v_sin(v));
  _mm256_storeu_pd(c, _ZGVdN4v_cos(v));
}
__attribute__((target("avx2,fma"))) void expAvx2(const double* a, const double*, double* out, double*) {
  _mm256_storeu_pd(out, _ZGVdN4v_exp(_mm256_loadu_pd(a)));
}
__attribute__((target("avx2,fma"))) void log1pAvx2(const double* a, const double*, double* out, double*) {
  _mm256_storeu_pd(out, _ZGVdN4v_log1p(_mm256_loadu_pd(a)));
}
__attribute__((target("avx2,fma"))) void expm1Avx2(const double* a, const double*, double* out, double*) {
  _mm256_storeu_pd(out, _ZGVdN4v_expm1(_mm256_loadu_pd(a)));
}
void expSse2(const double* a, const double*, double* out, double*) { _mm_storeu_pd(out, _ZGVbN2v_exp(_mm_loadu_pd(a))); }
void log1pSse2(const double* a, const double*, double* out, double*) {
  _mm_storeu_pd(out, _ZGVbN2v_log1p(_mm_loadu_pd(a)));
}
void expm1Sse2(const double* a, const double*, double* out, double*) {
  _mm_storeu_pd(out, _ZGVbN2v_expm1(_mm_loadu_pd(a)));
}
void atan2Sse2(const double* y, const double* x, double* out, double*) {
  _mm_storeu_pd(out, _ZGVbN2vv_atan2(_mm_loadu_pd(y), _mm_loadu_pd(x)));
}
void sinCosSse2(const double* a, const double*, double* s, double* c) {
  const __m128d v = _mm_loadu_pd(a);
  _mm_storeu_pd(s, _ZGVbN2v_sin(v));
  _mm_storeu_pd(c, _ZGVbN2v_cos(v));
}

// n lanes as whole blocks of the ISA in use (avx2's 4 lanes or sse2's 2): the last, partial one goes
// through arrays padded with harmless arguments (0 and 1), and only its real lanes are copied back. in1
// and out1 may be null where the operation has no second argument or result.
void forBlocks(Block avx2, Block sse2, const double* in0, const double* in1, double* out0, double* out1, int n) {
  const Block block = useAvx2 ? avx2 : sse2;
  const int w = useAvx2 ? 4 : 2;
  int i = 0;
  for (; i + w <= n; i += w) block(in0 + i, in1 ? in1 + i : nullptr, out0 + i, out1 ? out1 + i : nullptr);
  if (i == n) return;
  double a[4] = {0.0, 0.0, 0.0, 0.0}, b[4] = {1.0, 1.0, 1.0, 1.0}, r0[4], r1[4];
  std::copy(in0 + i, in0 + n, a);
  if (in1) std::copy(in1 + i, in1 + n, b);
  block(a, b, r0, r1);
  std::copy(r0, r0 + (n - i), out0 + i);
  if (out1) std::copy(r1, r1 + (n - i), out1 + i);
}

}  // namespace

Isa isa() { return useAvx2 ? Isa::Avx2 : Isa::Sse2; }

bool setIsa(Isa isa) {
  if (isa == Isa::Avx2 && !kCpuHasAvx2) return false;
  useAvx2 = isa == Isa::Avx2;
  return true;
}

void atan2(const double* y, const double* x, double* out, int n) { forBlocks(atan2Avx2, atan2Sse2, y, x, out, nullptr, n); }
void sinCos(const double* a, double* s, double* c, int n) { forBlocks(sinCosAvx2, sinCosSse2, a, nullptr, s, c, n); }
void exp(const double* a, double* out, int n) { forBlocks(expAvx2, expSse2, a, nullptr, out, nullptr, n); }
void log1p(const double* a, double* out, int n) { forBlocks(log1pAvx2, log1pSse2, a, nullptr, out, nullptr, n); }
void expm1(const double* a, double* out, int n) { forBlocks(expm1Avx2, expm1Sse2, a, nullptr, out, nullptr, n); }

}  // namespace glossy::lanes

#endif  // __x86_64__
