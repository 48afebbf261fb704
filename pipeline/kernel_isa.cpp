#include "pipeline/kernel_isa.h"

#include <stdexcept>

namespace rc::pipeline {

const char* name(KernelIsa isa) {
  switch (isa) {
    case KernelIsa::Baseline: return "baseline";
    case KernelIsa::X86_64_V3: return "x86-64-v3";
    case KernelIsa::X86_64_V4: return "x86-64-v4";
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
  for (KernelIsa isa : {KernelIsa::Baseline, KernelIsa::X86_64_V3, KernelIsa::X86_64_V4}) {
    if (is_supported(isa)) isas.push_back(isa);
  }
  return isas;
}

KernelIsa best_kernel_isa() {
  static const KernelIsa best = supported_kernel_isas().back();
  return best;
}

void require_supported(KernelIsa isa) {
  if (!is_supported(isa)) {
    throw std::invalid_argument(std::string("kernel variant ") + name(isa) +
                                " is not supported by this CPU or build");
  }
}

}  // namespace rc::pipeline
