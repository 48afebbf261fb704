// OBJ files name their materials (`usemtl NAME`) from the MTL files they load (`mtllib FILE`).
// Assimp gives a name that no loaded MTL defines its default material, silently; the mesh import
// warns once per such name (docs/scenes.md, Meshes).
#pragma once

#include <string>
#include <vector>

namespace rc {

// One warning per `usemtl` name of the OBJ text that no `newmtl` of its `mtllib` files (found beside
// `obj_path`, read with the scene size limit) defines, naming the OBJ, the first line using it and
// the MTL files looked in. An MTL file that cannot be read counts as defining nothing.
std::vector<std::string> undefined_obj_materials(const std::string& obj_text, const std::string& obj_path);

}  // namespace rc
