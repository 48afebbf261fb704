// Control/status registers of the FPGA wrapper, 32 bits each, in PCI BAR0 (docs/board.md has the
// table and the pass protocol). Parameter registers hold their value until rewritten; START in
// CONTROL is a strobe; DONE and ERROR in STATUS are cleared by writing 1 (which also drops the
// interrupt).
#pragma once

#include <cstdint>

namespace rc::board::reg {

constexpr std::uint64_t kId = 0x00;           // RO  0x52433230 ("RC20")
constexpr std::uint64_t kConfig = 0x04;       // RO  lanes [7:0], fractional bits (float lanes: 1+E+M) [15:8], groups [23:16], banks [31:24]
constexpr std::uint64_t kControl = 0x08;      // WO  bit 0 START, bit 1 CLEAR (first face overwrites results);
                                              // each START snapshots the registers and is queued (two deep,
                                              // ControlRegs::kStartQueue); a pass starts when the last ends
constexpr std::uint64_t kStatus = 0x0C;       // R/W1C  bit 0 BUSY (RO), bit 1 DONE, bit 2 ERROR
constexpr std::uint64_t kRayCount = 0x10;     // rays in the ray banks (the pass's batch)
constexpr std::uint64_t kFaceCount = 0x14;    // face records in the face bank (the pass's set)
constexpr std::uint64_t kFaceFirst = 0x18;    // scene index of the set's first face
constexpr std::uint64_t kSourceFace = 0x1C;   // scene index of the first face of the shooter's sheet; 0xFFFFFFFF: none
constexpr std::uint64_t kStartX = 0x20;       // segment start (shooting patch centre), 0.N codes
constexpr std::uint64_t kStartY = 0x24;
constexpr std::uint64_t kStartZ = 0x28;
constexpr std::uint64_t kMaskStart = 0x2C;    // rays of the batch ending on faces before the set
constexpr std::uint64_t kPassCyclesLo = 0x30; // RO  device cycles of the last pass
constexpr std::uint64_t kPassCyclesHi = 0x34; // RO
constexpr std::uint64_t kPasses = 0x38;       // RO  passes completed
constexpr std::uint64_t kErrorCode = 0x3C;    // RO  why ERROR was set (ErrorCode)
constexpr std::uint64_t kSourceFaces = 0x40;  // faces of the shooter's sheet from SOURCE_FACE on; 1 at reset
                                              // (scenes/sheets.h; written only when it changes)
// The pipelined driver's windows (docs/board.md, "Pipelined passes"): where in its banks a pass finds its
// rays, writes its result words and finds its own-surface table, in bank words. 0 at reset, so a
// driver that never writes them (the unpipelined protocol) uses the banks from word 0 as before.
constexpr std::uint64_t kRayBase = 0x44;      // word offset of the pass's rays in every ray bank
constexpr std::uint64_t kResultBase = 0x48;   // word offset of the pass's result words in the result bank
constexpr std::uint64_t kTableBase = 0x4C;    // word offset of the own-surface table from its usual place
// The guard band on the lanes' t test (docs/board.md, "T_GUARD"; pipeline/fixed_format.h): bits [7:0] are g,
// a segment is blocked by a face only for g < t*s < |det| - g; bits [31:8] are held but unused. 0 at reset:
// the paper's test, so a driver that never writes it gets the paper's answers. Fixed-point lanes only
// (the driver refuses a guard with float lanes).
constexpr std::uint64_t kTGuard = 0x50;
constexpr std::uint64_t kTGuardMask = 0xFF;
constexpr std::uint64_t kSize = 0x54;         // bytes of register space in use
constexpr std::uint64_t kBarSize = 0x1000;    // BAR0 size

constexpr std::uint32_t kIdValue = 0x52433230;
constexpr std::uint32_t kStart = 1u << 0;
constexpr std::uint32_t kClear = 1u << 1;
constexpr std::uint32_t kBusy = 1u << 0;
constexpr std::uint32_t kDone = 1u << 1;
constexpr std::uint32_t kError = 1u << 2;
constexpr std::uint32_t kNoFace = 0xFFFFFFFFu;
// Own-surface table entries (word_format.h): bit 31 set when the face continues the previous face's
// sheet (its rays are the same range); bits 30..0 the rays of the pass that end on the face's sheet.
constexpr std::uint32_t kSameSheet = 1u << 31;
constexpr std::uint32_t kSheetRays = kSameSheet - 1;

enum ErrorCode : std::uint32_t {
  kOk = 0,
  kTooManyRays = 1,     // RAY_COUNT beyond the ray or result banks (or, results on chip, the block RAM)
  kTooManyFaces = 2,    // FACE_COUNT beyond the face bank
  kMaskOverrun = 3,     // MASK_START + table entries exceed RAY_COUNT
  kStartWhileBusy = 4,  // a START beyond the queue (ControlRegs::kStartQueue)
  kBadStartPoint = 5,   // START_X/Y/Z not a 0.N code of the configured width
  kWindowOverrun = 6,   // RAY_BASE, RESULT_BASE or TABLE_BASE puts the pass's words beyond their bank
};

}  // namespace rc::board::reg
