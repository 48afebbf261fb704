// Instruction-set variants of the vectorised code. The same source is compiled three times on
// x86-64 (baseline SSE2, x86-64-v3 = AVX2, x86-64-v4 = AVX-512) and one variant is picked at run
// time; tests run every supported variant against the scalar code, so a variant cannot silently
// differ. Other targets have only the baseline.
//
// One rule picks the variant everywhere our code dispatches by instruction set (the streaming
// kernels here, the fast backend's face loop and end-point tree in host_sw/visibility):
// best_kernel_isa(). It is the best variant the CPU runs, capped by the environment variable
// RC2000SIM_SIMD (kSimdVariable) when that is set: "avx512", "avx2" or "baseline". A value the CPU
// (or this build) cannot run, an unknown value or an empty one is an error naming the variable,
// the value and the allowed values. Answers are bit-exact on every variant; only speed differs.
#pragma once

#include <string>
#include <vector>

namespace rc::pipeline {

enum class KernelIsa { Baseline, X86_64_V3, X86_64_V4 };

// The environment variable that caps the variant.
inline constexpr const char* kSimdVariable = "RC2000SIM_SIMD";

const char* name(KernelIsa isa);       // "baseline", "x86-64-v3", "x86-64-v4"
const char* simd_name(KernelIsa isa);  // RC2000SIM_SIMD's spelling: "baseline", "avx2", "avx512"
bool is_supported(KernelIsa isa);
std::vector<KernelIsa> supported_kernel_isas();  // baseline first, best last

// The rule, with its inputs given: `value` is RC2000SIM_SIMD's value (nullptr when unset),
// `supported` what the CPU runs (baseline first, best last). Unset: the last of `supported`;
// set: the variant it names. Throws std::invalid_argument (naming the variable, the value and
// the allowed values) for an unknown or empty value or a variant not in `supported`.
KernelIsa simd_cap(const char* value, const std::vector<KernelIsa>& supported);

// simd_cap(getenv(RC2000SIM_SIMD), supported_kernel_isas()), read once. The variant every
// dispatching site uses unless a test or benchmark names one; throws as simd_cap does (every
// time it is called, while the variable is wrong).
KernelIsa best_kernel_isa();
// The variants a benchmark or tool may pick under the cap: supported_kernel_isas() up to
// best_kernel_isa().
std::vector<KernelIsa> allowed_kernel_isas();

// Throws std::invalid_argument if this CPU cannot run the variant.
void require_supported(KernelIsa isa);

}  // namespace rc::pipeline

// Function attributes that compile one function for one variant.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define RC_HAVE_ISA_VARIANTS 1
#define RC_TARGET_X86_64_V3 __attribute__((target("arch=x86-64-v3")))
#define RC_TARGET_X86_64_V4 __attribute__((target("arch=x86-64-v4")))
#else
#define RC_HAVE_ISA_VARIANTS 0
#define RC_TARGET_X86_64_V3
#define RC_TARGET_X86_64_V4
#endif

// Picks one of three values (function pointers, pointers to tables) by variant, after checking the CPU runs it: the
// dispatching sites' one switch. Without variants in the build the baseline is the only one.
namespace rc::pipeline {
template <class T>
T pick_variant(KernelIsa isa, T baseline, T v3, T v4) {
  require_supported(isa);
  if (isa == KernelIsa::X86_64_V4) return v4;
  if (isa == KernelIsa::X86_64_V3) return v3;
  return baseline;
}
}  // namespace rc::pipeline
