// Study files (TOML, docs/studies.md): a design-space study as data. Every key is checked: unknown
// keys, wrong types, bad ranges and profile paths that name no field are errors that name the file,
// the line and the key. Relative scene paths are relative to the study file's folder.
//
//   name = "bank-clock"
//   [[scenes]]
//   paper = { faces = 280, patches = 1120 }
//   [axes]
//   devices = ["xc2v6000"]
//   lanes = "1-4"
//   banks = [6]
//   "banks.clock_mhz" = { from = 100, to = 200, step = 50 }
//   [fixed]
//   "pci.clock_mhz" = 33.333
#pragma once

#include <string>

#include "io/input_file.h"
#include "host_sw/studies/study.h"

namespace rc {

// The defaults a study file and `rc2000sim sweep` start from: the paper's 280-face, 1120-patch scene
// (a Table 2 scene that sweeps in seconds), Table 2's step counts, the three device profiles, 15
// bits, the concurrent driver, the calibrated host, 1-16 lanes and 5-12 banks.
Study default_study();
// The same without its scene's name (which reads the paper's table): the defaults a command shows
// when it is registered, before --configs has chosen the config folder.
Study default_study_settings();

// A study file is at most this large (a study is a page of settings, not data).
constexpr std::uint64_t kMaxStudyFileBytes = io::kProfileLimitBytes;

Study load_study_file(const std::string& path);
// The same from text; `path` names it in errors and anchors relative scene paths.
Study parse_study_text(const std::string& text, const std::string& path);

}  // namespace rc
