// stb_image is a single-header library: one translation unit must hold its code. Debian ships it prebuilt
// (libstb); this file provides it where no such library exists (vcpkg's stb). stb_image_write's code lives in
// Image/ImageIO.cpp, built there with zlib's deflate.
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>
