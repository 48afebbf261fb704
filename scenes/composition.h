// A scene composed from a small JSON description (docs/scenes.md, "Composing a scene"): a room
// (the embedded Cornell Box, or any scene file or mesh), plus meshes placed in it, each with an
// optional material override, plus an area light if the room has none. This is how a user puts
// their object into the box and asks what the board makes of it.
//
//   {"schema": "rc2000sim.composition/1",
//    "room": "cornell-box",                                   or {"file": "room.obj"}
//    "meshes": [{"file": "duck.dae",
//                "rotate": {"axis": [0, 1, 0], "degrees": 30},  then one of:
//                "fit_into": {"min": [x, y, z], "max": [x, y, z]}   (uniform scale, centred)
//                "scale": 2.0, "translate": [x, y, z],
//                "material": {"reflectance": [r, g, b], "emission": [r, g, b]}}],
//    "light": {"corners": [[x,y,z], [x,y,z], [x,y,z], [x,y,z]], "emission": [r, g, b]}}
//
// Coordinates are in the room's units (the Cornell Box: millimetres). Mesh files are found relative
// to the description's folder. Errors name the file and the key.
#pragma once

#include <string>

#include "scenes/scene_file.h"

namespace rc {

// True when the file is a JSON object whose "schema" is rc2000sim.composition/1.
bool is_composition_file(const std::string& path);

// Throws SceneFileError naming the file and the key for a bad description, and passes on the
// errors of the room and mesh files it reads.
LoadedScene load_composition(const std::string& path);
// The same from the description's text, already read (from a pipe, say); `path` names it in errors
// and is the folder its mesh files are found in.
LoadedScene load_composition_text(const std::string& text, const std::string& path);

}  // namespace rc
