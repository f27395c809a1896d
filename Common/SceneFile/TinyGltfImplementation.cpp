// tinygltf is a single-header library: this translation unit holds its code (Debian also ships it built as
// libtinygltf.so, with stb_image compiled in and its own include of the JSON library; compiling it here keeps one
// stb and one nlohmann::json in the program, wherever the header comes from).
//
// JSON: Debian's header includes <nlohmann/json.hpp>, upstream's "json.hpp"; the project's nlohmann-json is
// included here and the header's own include switched off, so both work.
#include <nlohmann/json.hpp>

#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_INCLUDE_JSON
#include "SceneFile/TinyGltf.h"
