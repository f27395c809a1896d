#include "Compare/ConvergenceCsv.h"

#include <cerrno>
#include <cstring>

#include <spdlog/fmt/fmt.h>

#include "Error.h"

namespace rt::compare
{
namespace
{
/// A CSV field, quoted when it holds a comma, a quote or a line break (device names such as "llvmpipe (LLVM
/// 15.0.7, 256 bits)" do).
std::string field(const std::string& text)
{
    if (text.find_first_of(",\"\n\r") == std::string::npos)
        return text;
    std::string quoted = "\"";
    for (const char c : text)
        quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}
} // namespace

const char* ConvergenceCsv::header()
{
    return "scene,engine,device,strategy,label,spp,wall_ms,gpu_ms,mpaths_per_s,mse,relmse,rmse,reference_relmse,seed,round,trimmed_relmse,mape,flip,rank,camera_mrays_per_s,extension_mrays_per_s,shadow_mrays_per_s";
}

ConvergenceCsv::ConvergenceCsv(const std::filesystem::path& path)
    : m_path(path), m_file(std::fopen(path.string().c_str(), "w"), &std::fclose)
{
    if (!m_file)
        throw OutputError(fmt::format("cannot write {}: {}", path.string(), std::strerror(errno)));
    if (std::fprintf(m_file.get(), "%s\n", header()) < 0 || std::fflush(m_file.get()) != 0)
        throw OutputError(fmt::format("cannot write {}: {}", path.string(), std::strerror(errno)));
}

void ConvergenceCsv::append(const ConvergenceRow& r)
{
    const std::string line =
        fmt::format("{},{},{},{},{},{},{:.4f},{:.4f},{:.4f},{:.9g},{:.9g},{:.9g},{:.9g},{},{},{:.9g},{:.9g},{:.9g},{},{:.4f},{:.4f},{:.4f}\n",
                    field(r.scene), field(r.engine), field(r.device), field(r.strategy), field(r.label), r.spp,
                    r.wallMs, r.gpuMs, r.mpathsPerSecond, r.mse, r.relMse, r.rmse, r.referenceRelMse, r.seed, r.round,
                    r.trimmedRelMse, r.mape, r.flip, r.rank, r.cameraMraysPerSecond, r.extensionMraysPerSecond,
                    r.shadowMraysPerSecond);
    if (std::fputs(line.c_str(), m_file.get()) < 0 || std::fflush(m_file.get()) != 0)
        throw OutputError(fmt::format("cannot write {}: {}", m_path.string(), std::strerror(errno)));
}
} // namespace rt::compare
