// Each pixel's cost over a frame's samples: the heatmap of where a render spends its time (--heatmap, the windows'
// cost view). The CPU engine times each pixel's paths on the host's clock; the GPU engine sums the shader clock's
// ticks of each pixel's samples (VK_KHR_shader_clock), a unit of its own that no host clock converts.
#pragma once

#include <string>
#include <vector>

namespace rt
{
struct CostMap
{
    int width = 0;
    int height = 0;
    /// Row by row from the top: the mean cost of one of the pixel's samples, in `unit`.
    std::vector<float> perSample;
    /// What a value counts, in words fit for a legend ("microseconds per sample").
    std::string unit;

    bool empty() const { return perSample.empty(); }
};
} // namespace rt
