// Instruction-set variants of the streaming kernels. The same source loop is compiled three
// times on x86-64 (baseline SSE2, x86-64-v3 = AVX2, x86-64-v4 = AVX-512) and the best one the CPU
// supports is used; tests run every supported variant against the scalar code, so a variant
// cannot silently differ. Other targets have only the baseline.
#pragma once

#include <string>
#include <vector>

namespace rc::pipeline {

enum class KernelIsa { Baseline, X86_64_V3, X86_64_V4 };

const char* name(KernelIsa isa);
bool is_supported(KernelIsa isa);
std::vector<KernelIsa> supported_kernel_isas();  // baseline first, best last
KernelIsa best_kernel_isa();

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
