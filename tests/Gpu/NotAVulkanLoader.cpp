// Built as bin/no-vulkan/libvulkan.so.1: a library with the loader's name but none of its symbols, which
// GpuApp.NoVulkanLoaderIsOneLineDeviceError puts first on LD_LIBRARY_PATH to stand for a machine without
// Vulkan.
extern "C" int rtNotAVulkanLoader() { return 0; }
