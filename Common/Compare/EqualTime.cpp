#include "Compare/EqualTime.h"

#include <algorithm>
#include <climits>
#include <cmath>

#include <nlohmann/json.hpp>
#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "Compare/PythonScript.h"
#include "IO/AtomicFile.h"
#include "IO/TemporaryFolder.h"
#include "Image/ImageIO.h"
#include "Image/Metrics.h"

namespace rt::compare
{
namespace
{
constexpr int kCalibrationSpp = 4;
constexpr double kTolerance = 0.15; // a render this far off its budget is rendered again with a corrected spp
constexpr int kCorrections = 3;
} // namespace

int sppForBudget(double budgetMs, double msPerSample)
{
    if (!(msPerSample > 0.0))
        return INT_MAX;
    return static_cast<int>(std::clamp(std::floor(budgetMs / msPerSample), 1.0, double(INT_MAX)));
}

Measurement renderForBudget(RenderEngine& engine, const RenderRequest& base, const Strategy& strategy,
                            double budgetMs, const Image& reference)
{
    const Measurement calibration = measure(engine, strategy.request(base, kCalibrationSpp), nullptr);
    if (calibration.cancelled)
        return calibration;
    int spp = sppForBudget(budgetMs, calibration.ms() / calibration.spp);
    Measurement m = measure(engine, strategy.request(base, spp), &reference);
    // The calibration's spp may be too few to time well (fixed costs, clocks still rising), and one render
    // can be slow by itself: render again at the rate the last one showed, until one lands within tolerance.
    for (int attempt = 0; attempt < kCorrections && !m.cancelled && m.ms() > 0.0 &&
                          std::abs(m.ms() - budgetMs) > kTolerance * budgetMs;
         ++attempt)
    {
        const int corrected = sppForBudget(budgetMs, m.ms() / m.spp);
        if (corrected == m.spp)
            break;
        m = measure(engine, strategy.request(base, corrected), &reference);
    }
    if (!m.cancelled && std::abs(m.ms() - budgetMs) > kTolerance * budgetMs)
        spdlog::warn("{}: {} spp took {:.1f} ms, not the {:.0f} ms asked for (the GPU's speed varied between renders)",
                     strategy.name(), m.spp, m.ms(), budgetMs);
    return m;
}

void writeEqualTimeGrid(const std::filesystem::path& png, const GridCaption& caption, const Image& reference,
                        const std::vector<EqualTimeTile>& tiles)
{
    const std::filesystem::path script = scriptPath("equal_time_grid.py");
    TemporaryFolder folder("ray-tracing-grid");
    nlohmann::json meta;
    meta["scene"] = caption.scene;
    meta["device"] = caption.device;
    meta["budget_ms"] = caption.budgetMs;
    meta["epsilon"] = kRelMseEpsilon;
    meta["reference"] = {{"path", (folder.path() / "reference.pfm").string()}, {"spp", caption.referenceSpp}};
    writePfm(folder.path() / "reference.pfm", reference);
    for (std::size_t i = 0; i < tiles.size(); ++i)
    {
        const std::filesystem::path pfm = folder.path() / fmt::format("tile-{}.pfm", i);
        writePfm(pfm, tiles[i].result.image);
        meta["tiles"].push_back({{"label", fmt::format("{} {}", toString(tiles[i].engine), tiles[i].label)},
                                 {"spp", tiles[i].result.spp},
                                 {"ms", tiles[i].result.ms()},
                                 {"relmse", tiles[i].result.error.relMse},
                                 {"path", pfm.string()}});
    }
    const std::filesystem::path metaPath = folder.path() / "tiles.json";
    writeFileAtomically(metaPath, meta.dump(2));
    drawFigure(png, script, {metaPath.string()});
}
} // namespace rt::compare
