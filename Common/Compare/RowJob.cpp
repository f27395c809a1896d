#include "Compare/RowJob.h"

#include <cstring>
#include <vector>

#include "Error.h"

namespace rt::compare
{
namespace
{
/// A JSON line, then the doubles' and the image's bytes as they are in memory (the ranks of one job share a
/// byte order and float format: one build, one architecture).
std::string pack(const nlohmann::json& head, const std::vector<double>& numbers, const Image* image)
{
    std::string bytes = head.dump() + "\n";
    const std::size_t numberBytes = numbers.size() * sizeof(double);
    const std::size_t imageBytes = image ? image->pixelCount() * sizeof(vec3) : 0;
    const std::size_t start = bytes.size();
    bytes.resize(start + numberBytes + imageBytes);
    std::memcpy(bytes.data() + start, numbers.data(), numberBytes);
    if (imageBytes > 0)
        std::memcpy(bytes.data() + start + numberBytes, image->data(), imageBytes);
    return bytes;
}

struct Unpacked
{
    nlohmann::json head;
    std::vector<double> numbers;
    Image image;
};

Unpacked unpack(const std::string& bytes, std::size_t numberCount)
{
    const std::size_t line = bytes.find('\n');
    if (line == std::string::npos)
        throw Error("MPI: a rank's render arrived without its header");
    Unpacked u;
    u.head = nlohmann::json::parse(bytes.substr(0, line));
    const int width = u.head.value("width", 0);
    const int height = u.head.value("height", 0);
    const std::size_t numberBytes = numberCount * sizeof(double);
    const std::size_t imageBytes = std::size_t(width) * std::size_t(height) * sizeof(vec3);
    if (width < 0 || height < 0 || bytes.size() != line + 1 + numberBytes + imageBytes)
        throw Error("MPI: a rank's render arrived with the wrong length");
    u.numbers.resize(numberCount);
    std::memcpy(u.numbers.data(), bytes.data() + line + 1, numberBytes);
    if (imageBytes > 0)
    {
        u.image = Image(width, height);
        std::memcpy(u.image.data(), bytes.data() + line + 1 + numberBytes, imageBytes);
    }
    return u;
}

constexpr std::size_t kMeasurementNumbers = 13;
} // namespace

std::string packMeasurement(const Measurement& m, bool withImage, const std::string& device)
{
    const bool image = withImage && m.image.pixelCount() > 0;
    const nlohmann::json head = {{"spp", m.spp},
                                 {"device", device},
                                 {"width", image ? m.image.width() : 0},
                                 {"height", image ? m.image.height() : 0}};
    const ErrorMetrics& e = m.error;
    return pack(head, {m.wallMs, m.gpuMs, m.mpathsPerSecond, e.mse, e.rmse, e.relMse, e.trimmedRelMse, e.mape, e.psnr,
                       e.flip, m.mraysPerSecond.camera, m.mraysPerSecond.extension, m.mraysPerSecond.shadow},
                image ? &m.image : nullptr);
}

Measurement unpackMeasurement(const std::string& bytes, std::string& device)
{
    Unpacked u = unpack(bytes, kMeasurementNumbers);
    Measurement m;
    m.spp = u.head.at("spp").get<int>();
    device = u.head.at("device").get<std::string>();
    const std::vector<double>& n = u.numbers;
    m.wallMs = n[0];
    m.gpuMs = n[1];
    m.mpathsPerSecond = n[2];
    m.error.mse = n[3];
    m.error.rmse = n[4];
    m.error.relMse = n[5];
    m.error.trimmedRelMse = n[6];
    m.error.mape = n[7];
    m.error.psnr = n[8];
    m.error.flip = n[9];
    m.mraysPerSecond = {n[10], n[11], n[12]};
    m.image = std::move(u.image);
    return m;
}

std::string packReference(const Reference& r)
{
    const nlohmann::json head = {{"description", r.description},
                                 {"spp", r.spp},
                                 {"has_own_relmse", r.ownRelMse.has_value()},
                                 {"width", r.image.width()},
                                 {"height", r.image.height()}};
    return pack(head, {r.ownRelMse.value_or(0.0)}, &r.image);
}

Reference unpackReference(const std::string& bytes)
{
    Unpacked u = unpack(bytes, 1);
    Reference r;
    r.image = std::move(u.image);
    r.description = u.head.at("description").get<std::string>();
    r.spp = u.head.at("spp").get<int>();
    if (u.head.at("has_own_relmse").get<bool>())
        r.ownRelMse = u.numbers[0];
    return r;
}
} // namespace rt::compare
