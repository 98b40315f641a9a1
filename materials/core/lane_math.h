// Transcendental functions over arrays of lanes (the path tracer's waves, the environment's batches),
// computed by glibc's vector math library (libmvec): 4 lanes per AVX2 instruction where the CPU has it,
// 2 per SSE2 instruction otherwise. A lane's result depends only on its own input, never on the other
// lanes or on n, so a batch of one gives what the same lane gives in any batch.
//
// Accuracy is libmvec's (at most 4 ulp; its atan2 stays within 4.4e-16 rad of libm's here): the
// lookups that use these need about 1e-12.
#pragma once

// For the loops over lanes around these calls (the models' batch forms): on x86-64 an AVX2 clone of the
// function (4 lanes an instruction, no FMA, so the same roundings) is chosen at run time where the CPU
// has it. Only on functions of internal linkage: cloned member functions trip LTO's ODR check.
#if defined(__x86_64__)
#define GLOSSY_LANE_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define GLOSSY_LANE_CLONES
#endif

namespace glossy::lanes {

// out[i] = atan2(y[i], x[i]) for i < n.
void atan2(const double* y, const double* x, double* out, int n);
// sinOut[i] = sin(a[i]), cosOut[i] = cos(a[i]) for i < n.
void sinCos(const double* a, double* sinOut, double* cosOut, int n);
// out[i] = exp(a[i]), log1p(a[i]), and expm1(a[i]), for i < n.
void exp(const double* a, double* out, int n);
void log1p(const double* a, double* out, int n);
void expm1(const double* a, double* out, int n);

// Which of libmvec's variants the calls use: AVX2 where the CPU has it (chosen at start-up), else SSE2;
// off x86-64, libm one lane at a time (reported as Sse2). Tests switch to SSE2 to check that path too;
// nothing else should.
enum class Isa { Sse2, Avx2 };
Isa isa();
bool setIsa(Isa isa);  // false (and no change) if the CPU lacks it

}  // namespace glossy::lanes
