#include "Vulkan/DeviceSelection.h"

#include <algorithm>

#include <spdlog/fmt/fmt.h>

#include "Error.h"

namespace rt::vk
{
namespace
{
constexpr std::uint32_t kRequiredApi = (1u << 22) | (2u << 12); // VK_API_VERSION_1_2 without vulkan.h

int preferenceRank(DeviceType type)
{
    switch (type)
    {
    case DeviceType::DiscreteGpu: return 0;
    case DeviceType::IntegratedGpu: return 1;
    case DeviceType::VirtualGpu: return 2;
    case DeviceType::Other: return 3;
    case DeviceType::Cpu: return 4;
    }
    return 5;
}

std::string describe(const DeviceVerdict& verdict)
{
    const DeviceCandidate& c = verdict.candidate;
    std::string missing;
    for (const std::string& m : verdict.missing)
        missing += (missing.empty() ? "" : ", ") + m;
    return fmt::format("  device {} '{}' ({}): {}", c.index, c.name, toString(c.type),
                       verdict.suitable() ? "ok" : "lacks " + missing);
}
} // namespace

const char* toString(DeviceType type)
{
    switch (type)
    {
    case DeviceType::Other: return "other";
    case DeviceType::IntegratedGpu: return "integrated GPU";
    case DeviceType::DiscreteGpu: return "discrete GPU";
    case DeviceType::VirtualGpu: return "virtual GPU";
    case DeviceType::Cpu: return "CPU";
    }
    return "?";
}

DeviceVerdict judge(const DeviceCandidate& candidate, const DeviceRequirements& requirements)
{
    DeviceVerdict verdict{candidate, {}};
    if (candidate.apiVersion < kRequiredApi)
        verdict.missing.push_back(fmt::format("Vulkan 1.2 (has {}.{})", candidate.apiVersion >> 22,
                                              (candidate.apiVersion >> 12) & 0x3FFu));
    for (const char* extension : kRequiredExtensions)
        if (std::find(candidate.extensions.begin(), candidate.extensions.end(), extension) ==
            candidate.extensions.end())
            verdict.missing.push_back(fmt::format("extension {}", extension));
    for (const FeatureRequirement& f : kRequiredFeatures)
        if (!(candidate.features.*f.member))
            verdict.missing.push_back(fmt::format("feature {}::{}", f.featureStruct, f.field));
    if (!candidate.computeQueue)
        verdict.missing.push_back("a queue family with VK_QUEUE_COMPUTE_BIT");
    if (requirements.presentation)
    {
        if (std::find(candidate.extensions.begin(), candidate.extensions.end(), kPresentationExtension) ==
            candidate.extensions.end())
            verdict.missing.push_back(fmt::format("extension {}", kPresentationExtension));
        if (!candidate.presentQueue)
            verdict.missing.push_back("a queue family with graphics, compute and presentation to the window's surface");
    }
    return verdict;
}

std::size_t selectDevice(const std::vector<DeviceCandidate>& candidates, std::optional<int> requested,
                         const DeviceRequirements& requirements, int share)
{
    if (candidates.empty())
        throw DeviceError("Vulkan reports no physical device: no driver (ICD) is installed or none loads");
    if (requested)
    {
        if (*requested < 0 || static_cast<std::size_t>(*requested) >= candidates.size())
        {
            std::string names;
            for (const DeviceCandidate& c : candidates)
                names += fmt::format("{}{}: {}", names.empty() ? "" : "; ", c.index, c.name);
            throw UsageError(fmt::format("--device {} does not exist: the devices are {} (--list-devices describes "
                                         "them)",
                                         *requested, names));
        }
        const DeviceVerdict verdict = judge(candidates[static_cast<std::size_t>(*requested)], requirements);
        if (!verdict.suitable())
            throw DeviceError(fmt::format("device {} cannot run the ray tracer:\n{}", *requested, describe(verdict)));
        return static_cast<std::size_t>(*requested);
    }
    std::optional<std::size_t> best;
    for (std::size_t i = 0; i < candidates.size(); ++i)
        if (judge(candidates[i], requirements).suitable() &&
            (!best || preferenceRank(candidates[i].type) < preferenceRank(candidates[*best].type)))
            best = i;
    if (!best)
        throw DeviceError(
            fmt::format("no Vulkan device can run the ray tracer{}:\n{}",
                        requirements.presentation ? " in a window" : "", describeDevices(candidates, requirements)));
    std::vector<std::size_t> alike; // the suitable devices of the best type
    for (std::size_t i = 0; i < candidates.size(); ++i)
        if (candidates[i].type == candidates[*best].type && judge(candidates[i], requirements).suitable())
            alike.push_back(i);
    return alike[static_cast<std::size_t>(std::max(share, 0)) % alike.size()];
}

std::string describeDevices(const std::vector<DeviceCandidate>& candidates, const DeviceRequirements& requirements)
{
    std::string out;
    for (const DeviceCandidate& c : candidates)
    {
        if (!out.empty())
            out += '\n';
        out += describe(judge(c, requirements));
    }
    return out;
}
} // namespace rt::vk
