// Pictures for reports: rc2000sim writes CSV, then asks Debian's python3-matplotlib (installed by
// scripts/) to draw it with a script from apps/plots/. A missing python only costs the picture.
#pragma once

#include <string>

namespace rc {

// Runs apps/plots/<script> INPUT OUTPUT (a PNG, or a folder for scripts that draw several);
// returns false (and warns on stderr) if it could not.
bool plot(const std::string& script, const std::string& csv_path, const std::string& output);

}  // namespace rc
