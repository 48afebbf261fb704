// What a host driver needs to know about the RC2000 to use it through its ports, and nothing else:
// the PCI windows (BAR0 registers, BAR1 banks at a stride), the bank layout and word formats the
// wrapper expects (bank_layout.h, word_format.h, register_map.h), and the wrapper model (a visibility
// oracle needs the fast one). The board describes itself (Rc2000::interface()); the driver never
// holds the board.
#pragma once

#include <cstdint>

#include "board/bank_layout.h"
#include "board/board_params.h"

namespace rc::board {

struct BoardInterface {
  std::uint64_t register_base = 0;     // BAR0: the control/status registers (register_map.h)
  std::uint64_t bank_base = 0;         // BAR1: bank b at bank_base + b * bank_stride
  std::uint64_t bank_stride = 0;
  std::uint64_t bank_capacity_bytes = 0;
  BankLayout layout;                   // which bank holds what, capacities, word formats
  WrapperModel model = WrapperModel::fast;

  std::uint64_t bank_address(unsigned bank) const { return bank_base + bank * bank_stride; }
};

}  // namespace rc::board
