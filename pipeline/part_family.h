// Which FPGA family a device part belongs to: the part starts with the family's prefix ("XC4VSX55"
// with "XC4V"), compared without case. One rule for every table keyed by family (the float lanes'
// families, the synthesizer's counts).
#pragma once

#include <cctype>
#include <string>

namespace rc::pipeline {

inline bool part_in_family(const std::string& part, const std::string& family_prefix) {
  if (part.size() < family_prefix.size()) return false;
  for (std::size_t i = 0; i < family_prefix.size(); ++i) {
    if (std::toupper(static_cast<unsigned char>(part[i])) != std::toupper(static_cast<unsigned char>(family_prefix[i])))
      return false;
  }
  return true;
}

}  // namespace rc::pipeline
