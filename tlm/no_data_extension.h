// Marks a transaction whose bytes are immaterial: a timing replay moves buffers of the right size
// whose contents nobody reads (the board's lanes take a recorded answer). Targets time and count
// such a transaction exactly like any other but need not move its data; a target that does not
// know the extension copies as usual, which is also correct (it is an ignorable extension).
#pragma once

#include <tlm>

namespace rc::tlmx {

struct NoDataExtension : tlm::tlm_extension<NoDataExtension> {
  tlm::tlm_extension_base* clone() const override { return new NoDataExtension(*this); }
  void copy_from(const tlm::tlm_extension_base&) override {}
};

inline bool carries_no_data(const tlm::tlm_generic_payload& trans) {
  return trans.get_extension<NoDataExtension>() != nullptr;
}

}  // namespace rc::tlmx
