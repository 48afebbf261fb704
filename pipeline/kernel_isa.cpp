#include "pipeline/kernel_isa.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace rc::pipeline {

namespace {
constexpr KernelIsa kAll[] = {KernelIsa::Baseline, KernelIsa::X86_64_V3, KernelIsa::X86_64_V4};

std::string allowed_values() {
  return "allowed: avx512, avx2, baseline (or leave it unset for the best this CPU runs)";
}
}  // namespace

const char* name(KernelIsa isa) {
  switch (isa) {
    case KernelIsa::Baseline: return "baseline";
    case KernelIsa::X86_64_V3: return "x86-64-v3";
    case KernelIsa::X86_64_V4: return "x86-64-v4";
  }
  return "?";
}

const char* simd_name(KernelIsa isa) {
  switch (isa) {
    case KernelIsa::Baseline: return "baseline";
    case KernelIsa::X86_64_V3: return "avx2";
    case KernelIsa::X86_64_V4: return "avx512";
  }
  return "?";
}

bool is_supported(KernelIsa isa) {
  if (isa == KernelIsa::Baseline) return true;
#if RC_HAVE_ISA_VARIANTS
  __builtin_cpu_init();
  if (isa == KernelIsa::X86_64_V3) return __builtin_cpu_supports("x86-64-v3");
  if (isa == KernelIsa::X86_64_V4) return __builtin_cpu_supports("x86-64-v4");
#endif
  return false;
}

std::vector<KernelIsa> supported_kernel_isas() {
  std::vector<KernelIsa> isas;
  for (KernelIsa isa : kAll) {
    if (is_supported(isa)) isas.push_back(isa);
  }
  return isas;
}

KernelIsa simd_cap(const char* value, const std::vector<KernelIsa>& supported) {
  if (supported.empty()) throw std::logic_error("simd_cap: no supported variant given");
  if (value == nullptr) return supported.back();
  const std::string variable = kSimdVariable;
  for (KernelIsa isa : kAll) {
    if (std::strcmp(value, simd_name(isa)) != 0) continue;
    if (std::find(supported.begin(), supported.end(), isa) == supported.end()) {
      throw std::invalid_argument(variable + "=" + value + ": this CPU or build cannot run " + name(isa) +
                                  " (best it runs: " + simd_name(supported.back()) + "); " + allowed_values());
    }
    return isa;
  }
  throw std::invalid_argument(variable + "=\"" + value + "\" is not a variant; " + allowed_values());
}

KernelIsa best_kernel_isa() {
  // Read once; a wrong value throws here on every call (the static is not set by a throw).
  static const KernelIsa best = simd_cap(std::getenv(kSimdVariable), supported_kernel_isas());
  return best;
}

std::vector<KernelIsa> allowed_kernel_isas() {
  std::vector<KernelIsa> isas = supported_kernel_isas();
  const KernelIsa cap = best_kernel_isa();
  isas.erase(std::remove_if(isas.begin(), isas.end(), [cap](KernelIsa isa) { return isa > cap; }), isas.end());
  return isas;
}

void require_supported(KernelIsa isa) {
  if (!is_supported(isa)) {
    throw std::invalid_argument(std::string("kernel variant ") + name(isa) +
                                " is not supported by this CPU or build");
  }
}

}  // namespace rc::pipeline
