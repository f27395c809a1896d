// The rows of a convergence run as CSV (RFC 4180), one per engine x strategy x spp x seed x round, written and flushed as
// each render finishes, so that an interrupted run keeps every row it measured. Read by plot_convergence.py.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

namespace rt::compare
{
struct ConvergenceRow
{
    std::string scene;
    std::string engine; // single, multi, gpu
    std::string device; // the engine's device name
    std::string strategy; // Strategy::name()
    std::string label; // the short label the plots show (distinctLabels)
    int spp = 0; // true spp
    double wallMs = 0.0; // host clock around the tracing
    double gpuMs = -1.0; // GPU timestamps around the trace dispatches; < 0 when the engine has none
    double mpathsPerSecond = 0.0;
    double mse = 0.0; // against the reference, mean over pixels and RGB
    double relMse = 0.0; // mean (I - R)^2 / (R^2 + kRelMseEpsilon)
    double rmse = 0.0;
    double referenceRelMse = -1.0; // the reference's own relMSE, part of relMse (Image/Metrics.h); < 0: unknown
    std::uint32_t seed = 0; // the render's --seed (--seeds N renders a row N times: seed, seed + 1, ...)
    int round = 0; // --rounds R times every row again in R interleaved rounds: 0 .. R - 1
    double trimmedRelMse = 0.0; // relMSE without the worst 0.1 % of pixels (Image/Metrics.h)
    double mape = 0.0;
    double flip = -1.0; // mean HDR-FLIP; < 0: not computed (only with --metric flip, round 0)
    int rank = 0; // the MPI rank that rendered it (0 for a run of one process: docs/SCALING.md)
    double cameraMraysPerSecond = -1.0; // rays traced per second by kind, in millions; < 0: not counted (the GPU
    double extensionMraysPerSecond = -1.0; // engine without --count-rays)
    double shadowMraysPerSecond = -1.0;
};

class ConvergenceCsv
{
public:
    /// Creates (truncates) `path` and writes the header. Throws OutputError naming the path.
    explicit ConvergenceCsv(const std::filesystem::path& path);
    /// Appends one row and flushes it to the file. Throws OutputError when the write fails.
    void append(const ConvergenceRow& row);

    static const char* header();

private:
    std::filesystem::path m_path;
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> m_file;
};
} // namespace rt::compare
