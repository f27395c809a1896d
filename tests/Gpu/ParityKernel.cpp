#include "ParityKernel.h"

#include <cstring>

#include "Assets/AssetPaths.h"
#include "ComputeKernel.h"
#include "GpuTestEnvironment.h"
#include "Scene/Perlin.h"

namespace rt::gpu::test
{
std::vector<std::uint32_t> runParity(ParityMode mode, const std::vector<std::uint32_t>& inputs,
                                     const std::vector<LightData>& lights, const LightBvh* lightBvh,
                                     std::uint32_t sharedCases)
{
    const ParityLayout layout = kParityLayouts[mode];
    const auto cases =
        sharedCases > 0 ? sharedCases : static_cast<std::uint32_t>(inputs.size() / layout.inputWords);
    const std::uint32_t push[4] = {mode, cases, sharedCases > 0 ? 0u : layout.inputWords, layout.outputWords};
    const std::vector<LightData> lightBuffer = lights.empty() ? std::vector<LightData>(1) : lights;
    const LightBvh noBvh{std::vector<LightBvhNode>(1), std::vector<std::uint32_t>(1)};
    const LightBvh& bvh = lightBvh != nullptr ? *lightBvh : noBvh;
    const std::vector<std::byte> out = runKernel(
        sharedEngine()->context(), executableDir() / "shaders" / "Tests" / "Parity.comp.spv",
        {{inputs.data(), inputs.size() * 4},
         {nullptr, std::size_t(cases) * layout.outputWords * 4},
         {&perlinTables(), sizeof(shader::PerlinData)},
         {lightBuffer.data(), lightBuffer.size() * sizeof(LightData)},
         {bvh.nodes.data(), bvh.nodes.size() * sizeof(LightBvhNode)},
         {bvh.leaves.data(), bvh.leaves.size() * 4}},
        1, push, sizeof(push), (cases + 63) / 64);
    std::vector<std::uint32_t> words(out.size() / 4);
    std::memcpy(words.data(), out.data(), out.size());
    return words;
}
} // namespace rt::gpu::test
