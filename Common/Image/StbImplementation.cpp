// stb_image and stb_image_write are single-header libraries: one translation unit must hold their code.
// Debian ships it prebuilt (libstb); this file provides it where no such library exists (vcpkg's stb).
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
