#pragma once
// Lacrima's GLSL programs and material scripts, compiled into the library as Qt resources
// (media/shaders, media/materials), handed to OGRE from memory: nothing to install, nothing
// to find on disk at run time.
//
// Each shader file becomes a GLSL program named after the file (".vert" vertex, ".frag"
// fragment); a line `#include "name"` is replaced by that file of the same folder. Then every
// material script is parsed, and every material the scripts define is loaded, which compiles
// and links its programs. A program that fails, or a material without a usable technique,
// throws std::runtime_error naming it (the compiler's message is in the OGRE log).
#include <string>

namespace lacrima::scene::detail {

void loadShaderLibrary(const std::string& resourceGroup, const std::string& logPath);

}  // namespace lacrima::scene::detail
