// Every Vulkan entry point the engine calls, by the level it is loaded at (X-macro lists, expanded in
// Loader.h and Loader.cpp). Add a function here before calling it.

// Loaded from vkGetInstanceProcAddr(nullptr, ...): usable before an instance exists.
#define RT_VK_GLOBAL_FUNCTIONS(X)                                                                              \
    X(vkCreateInstance)                                                                                        \
    X(vkEnumerateInstanceExtensionProperties)                                                                  \
    X(vkEnumerateInstanceLayerProperties)                                                                      \
    X(vkEnumerateInstanceVersion)

// Loaded from vkGetInstanceProcAddr(instance, ...).
#define RT_VK_INSTANCE_FUNCTIONS(X)                                                                            \
    X(vkDestroyInstance)                                                                                       \
    X(vkEnumeratePhysicalDevices)                                                                              \
    X(vkGetPhysicalDeviceProperties)                                                                           \
    X(vkGetPhysicalDeviceProperties2)                                                                          \
    X(vkGetPhysicalDeviceFeatures2)                                                                            \
    X(vkGetPhysicalDeviceMemoryProperties)                                                                     \
    X(vkGetPhysicalDeviceQueueFamilyProperties)                                                                \
    X(vkEnumerateDeviceExtensionProperties)                                                                    \
    X(vkCreateDevice)                                                                                          \
    X(vkGetDeviceProcAddr)                                                                                     \
    X(vkCreateDebugUtilsMessengerEXT)                                                                          \
    X(vkDestroyDebugUtilsMessengerEXT)                                                                         \
    X(vkGetPhysicalDeviceFormatProperties)                                                                     \
    X(vkDestroySurfaceKHR)                                                                                     \
    X(vkGetPhysicalDeviceSurfaceSupportKHR)                                                                    \
    X(vkGetPhysicalDeviceSurfaceCapabilitiesKHR)                                                               \
    X(vkGetPhysicalDeviceSurfaceFormatsKHR)                                                                    \
    X(vkGetPhysicalDeviceSurfacePresentModesKHR)

// Loaded from vkGetDeviceProcAddr(device, ...) once the device exists (extension functions included).
#define RT_VK_DEVICE_FUNCTIONS(X)                                                                              \
    X(vkDestroyDevice)                                                                                         \
    X(vkGetDeviceQueue)                                                                                        \
    X(vkDeviceWaitIdle)                                                                                        \
    X(vkQueueSubmit)                                                                                           \
    X(vkAllocateMemory)                                                                                        \
    X(vkFreeMemory)                                                                                            \
    X(vkMapMemory)                                                                                             \
    X(vkCreateBuffer)                                                                                          \
    X(vkDestroyBuffer)                                                                                         \
    X(vkGetBufferMemoryRequirements)                                                                           \
    X(vkBindBufferMemory)                                                                                      \
    X(vkGetBufferDeviceAddress)                                                                                \
    X(vkCreateImage)                                                                                           \
    X(vkDestroyImage)                                                                                          \
    X(vkGetImageMemoryRequirements)                                                                            \
    X(vkBindImageMemory)                                                                                       \
    X(vkCreateImageView)                                                                                       \
    X(vkDestroyImageView)                                                                                      \
    X(vkCreateSampler)                                                                                         \
    X(vkDestroySampler)                                                                                        \
    X(vkCreateFence)                                                                                           \
    X(vkDestroyFence)                                                                                          \
    X(vkWaitForFences)                                                                                         \
    X(vkCreateCommandPool)                                                                                     \
    X(vkDestroyCommandPool)                                                                                    \
    X(vkAllocateCommandBuffers)                                                                                \
    X(vkFreeCommandBuffers)                                                                                    \
    X(vkBeginCommandBuffer)                                                                                    \
    X(vkEndCommandBuffer)                                                                                      \
    X(vkCmdPipelineBarrier)                                                                                    \
    X(vkCmdCopyBuffer)                                                                                         \
    X(vkCmdCopyBufferToImage)                                                                                  \
    X(vkCmdCopyImageToBuffer)                                                                                  \
    X(vkCmdClearColorImage)                                                                                    \
    X(vkCmdBindPipeline)                                                                                       \
    X(vkCmdBindDescriptorSets)                                                                                 \
    X(vkCmdPushConstants)                                                                                      \
    X(vkCmdDispatch)                                                                                           \
    X(vkCmdDispatchIndirect)                                                                                   \
    X(vkCmdFillBuffer)                                                                                         \
    X(vkCmdWriteTimestamp)                                                                                     \
    X(vkCmdResetQueryPool)                                                                                     \
    X(vkCreateQueryPool)                                                                                       \
    X(vkDestroyQueryPool)                                                                                      \
    X(vkGetQueryPoolResults)                                                                                   \
    X(vkCreateShaderModule)                                                                                    \
    X(vkDestroyShaderModule)                                                                                   \
    X(vkCreateDescriptorSetLayout)                                                                             \
    X(vkDestroyDescriptorSetLayout)                                                                            \
    X(vkCreateDescriptorPool)                                                                                  \
    X(vkDestroyDescriptorPool)                                                                                 \
    X(vkAllocateDescriptorSets)                                                                                \
    X(vkUpdateDescriptorSets)                                                                                  \
    X(vkCreatePipelineLayout)                                                                                  \
    X(vkDestroyPipelineLayout)                                                                                 \
    X(vkCreateComputePipelines)                                                                                \
    X(vkDestroyPipeline)                                                                                       \
    X(vkCreateAccelerationStructureKHR)                                                                        \
    X(vkDestroyAccelerationStructureKHR)                                                                       \
    X(vkGetAccelerationStructureBuildSizesKHR)                                                                 \
    X(vkGetAccelerationStructureDeviceAddressKHR)                                                              \
    X(vkCmdBuildAccelerationStructuresKHR)                                                                     \
    X(vkCreateRayTracingPipelinesKHR)                                                                          \
    X(vkGetRayTracingShaderGroupHandlesKHR)                                                                    \
    X(vkCmdTraceRaysKHR)                                                                                       \
    X(vkCmdTraceRaysIndirectKHR)                                                                               \
    X(vkResetFences)                                                                                           \
    X(vkResetCommandBuffer)                                                                                    \
    X(vkCreateSemaphore)                                                                                       \
    X(vkDestroySemaphore)                                                                                      \
    X(vkCreateRenderPass)                                                                                      \
    X(vkDestroyRenderPass)                                                                                     \
    X(vkCreateFramebuffer)                                                                                     \
    X(vkDestroyFramebuffer)                                                                                    \
    X(vkCreateGraphicsPipelines)                                                                               \
    X(vkCmdBeginRenderPass)                                                                                    \
    X(vkCmdEndRenderPass)                                                                                      \
    X(vkCmdBindVertexBuffers)                                                                                  \
    X(vkCmdSetViewport)                                                                                        \
    X(vkCmdSetScissor)                                                                                         \
    X(vkCmdDraw)                                                                                               \
    X(vkCreateSwapchainKHR)                                                                                    \
    X(vkDestroySwapchainKHR)                                                                                   \
    X(vkGetSwapchainImagesKHR)                                                                                 \
    X(vkAcquireNextImageKHR)                                                                                   \
    X(vkQueuePresentKHR)
