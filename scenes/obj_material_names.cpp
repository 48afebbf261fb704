#include "scenes/obj_material_names.h"

#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string_view>

#include "io/input_file.h"
#include "io/text_encoding.h"

namespace rc {

namespace {

constexpr std::string_view kBlank = " \t\r";

// The rest of a line after its keyword, trimmed, if the line starts with `keyword` and a blank.
bool argument_of(std::string_view line, std::string_view keyword, std::string& out) {
  const std::size_t start = line.find_first_not_of(kBlank);
  if (start == std::string_view::npos || line.substr(start, keyword.size()) != keyword) return false;
  const std::size_t after = start + keyword.size();
  if (after >= line.size() || kBlank.find(line[after]) == std::string_view::npos) return false;
  const std::size_t first = line.find_first_not_of(kBlank, after);
  if (first == std::string_view::npos) return false;
  const std::size_t last = line.find_last_not_of(kBlank);
  out = std::string(line.substr(first, last - first + 1));
  return true;
}

// The `newmtl` names of one MTL file; none if it cannot be read (Assimp goes on without it too).
void add_defined_names(const std::string& mtl_path, std::set<std::string>& names) {
  std::string text;
  try {
    text = io::read_file(mtl_path, io::kSceneLimitBytes, "a material file");
  } catch (const io::InputFileError&) {
    return;
  }
  std::istringstream in(text);
  std::string line, name;
  while (std::getline(in, line))
    if (argument_of(line, "newmtl", name)) names.insert(name);
}

}  // namespace

std::vector<std::string> undefined_obj_materials(const std::string& obj_text, const std::string& obj_path) {
  const std::filesystem::path folder = std::filesystem::path(obj_path).parent_path();
  std::set<std::string> defined;
  std::string libraries;
  std::map<std::string, std::size_t> used;  // name -> first line
  std::vector<std::string> order;
  std::istringstream in(obj_text);
  std::string line, argument;
  for (std::size_t line_no = 1; std::getline(in, line); ++line_no) {
    if (argument_of(line, "mtllib", argument)) {
      add_defined_names((folder / argument).string(), defined);
      libraries += (libraries.empty() ? "" : ", ") + argument;
    } else if (argument_of(line, "usemtl", argument) && used.emplace(argument, line_no).second) {
      order.push_back(argument);
    }
  }
  std::vector<std::string> warnings;
  for (const std::string& name : order) {
    if (defined.count(name) != 0) continue;
    warnings.push_back(io::printable_utf8(obj_path) + ":" + std::to_string(used[name]) + ": usemtl '" +
                       io::printable_utf8(name) + "' is defined in no material file (" +
                       (libraries.empty() ? std::string("no mtllib line") : "mtllib " + io::printable_utf8(libraries)) +
                       "); Assimp gives its faces its default material");
  }
  return warnings;
}

}  // namespace rc
