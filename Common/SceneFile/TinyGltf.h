// tinygltf (syoyo/tinygltf: Debian's libtinygltf-dev, vcpkg's tinygltf), configured once for every file that
// includes it, so that each sees the same class definitions. Its code is compiled in TinyGltfImplementation.cpp.
//   - No stb of its own: images are decoded by the project's stb (Assets/ImageLoader.h, stb's code in libstb or
//     Image/StbImplementation.cpp), and only the images a material uses (SceneFile/GltfImages.h).
//   - No image files read by tinygltf: GltfImages reads them, with the same path rules and errors as buffers.
//   - Nothing written.
#pragma once

#ifndef TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE
#endif
#ifndef TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#endif
#ifndef TINYGLTF_NO_EXTERNAL_IMAGE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#endif

#include <tiny_gltf.h>
