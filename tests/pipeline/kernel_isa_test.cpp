// The one rule that picks an instruction-set variant (pipeline/kernel_isa.h): RC2000SIM_SIMD caps
// the CPU's best; unknown, empty and unrunnable values are errors naming the variable, the value
// and the allowed values.
#include "pipeline/kernel_isa.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace rc::pipeline {
namespace {

using V = std::vector<KernelIsa>;
const V kEvery = {KernelIsa::Baseline, KernelIsa::X86_64_V3, KernelIsa::X86_64_V4};
const V kAvx2Cpu = {KernelIsa::Baseline, KernelIsa::X86_64_V3};
const V kOldCpu = {KernelIsa::Baseline};

std::string error_of(const char* value, const V& supported) {
  try {
    simd_cap(value, supported);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

TEST(SimdCap, UnsetIsTheBestTheCpuRuns) {
  EXPECT_EQ(simd_cap(nullptr, kEvery), KernelIsa::X86_64_V4);
  EXPECT_EQ(simd_cap(nullptr, kAvx2Cpu), KernelIsa::X86_64_V3);
  EXPECT_EQ(simd_cap(nullptr, kOldCpu), KernelIsa::Baseline);
}

TEST(SimdCap, EachValueNamesItsVariant) {
  EXPECT_EQ(simd_cap("avx512", kEvery), KernelIsa::X86_64_V4);
  EXPECT_EQ(simd_cap("avx2", kEvery), KernelIsa::X86_64_V3);
  EXPECT_EQ(simd_cap("baseline", kEvery), KernelIsa::Baseline);
  EXPECT_EQ(simd_cap("avx2", kAvx2Cpu), KernelIsa::X86_64_V3);
  EXPECT_EQ(simd_cap("baseline", kOldCpu), KernelIsa::Baseline);
  for (KernelIsa isa : kEvery) EXPECT_EQ(simd_cap(simd_name(isa), kEvery), isa);
}

TEST(SimdCap, AVariantTheCpuCannotRunIsAnError) {
  const std::string e = error_of("avx512", kAvx2Cpu);
  EXPECT_NE(e.find("RC2000SIM_SIMD=avx512"), std::string::npos) << e;
  EXPECT_NE(e.find("cannot run"), std::string::npos) << e;
  EXPECT_NE(e.find("best it runs: avx2"), std::string::npos) << e;
  EXPECT_NE(e.find("avx512, avx2, baseline"), std::string::npos) << e;
  EXPECT_NE(error_of("avx2", kOldCpu).find("cannot run"), std::string::npos);
}

TEST(SimdCap, UnknownAndEmptyValuesAreErrors) {
  for (const char* value : {"", "AVX2", "avx", "x86-64-v3", "sse2", "avx2 ", "native"}) {
    const std::string e = error_of(value, kEvery);
    EXPECT_NE(e.find("RC2000SIM_SIMD=\"" + std::string(value) + "\""), std::string::npos) << e;
    EXPECT_NE(e.find("is not a variant"), std::string::npos) << e;
    EXPECT_NE(e.find("allowed: avx512, avx2, baseline"), std::string::npos) << e;
  }
}

// The process's own variant follows the same rule from its environment.
TEST(SimdCap, TheProcessUsesTheRuleOnItsEnvironment) {
  const V supported = supported_kernel_isas();
  ASSERT_FALSE(supported.empty());
  EXPECT_EQ(best_kernel_isa(), simd_cap(std::getenv(kSimdVariable), supported));
  const V allowed = allowed_kernel_isas();
  ASSERT_FALSE(allowed.empty());
  EXPECT_EQ(allowed.front(), KernelIsa::Baseline);
  EXPECT_EQ(allowed.back(), best_kernel_isa());
}

}  // namespace
}  // namespace rc::pipeline
