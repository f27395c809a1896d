// One render of a ladder comparison as a task a rank of an MPI job can run (Cluster/TaskPool.h), and how its
// measurement and the reference travel between ranks: as bytes, the numbers exact (doubles as they are, the image
// as its floats).
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "Compare/Measurement.h"
#include "Image/Image.h"

namespace rt::compare
{
/// A render of the ladder: an engine (an index into the comparison's engines), a strategy (an index into its
/// strategies), a sample count (an index into its spp list), a seed (the base seed + `seed`) and the round that
/// times it. A reference half is a task of its own (`half` 0 or 1; the other fields unused).
struct RowJob
{
    std::size_t engine = 0;
    std::size_t strategy = 0;
    std::size_t spp = 0;
    int seed = 0;
    int round = 0;
    bool keepImage = false; // the image comes back with the measurement (round 0's first seed, or --images)
    int half = -1; // >= 0: the reference's half 0 or 1, rendered by the last engine
};
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(RowJob, engine, strategy, spp, seed, round, keepImage, half)

/// What a rank sends back for a render: the measurement (its image when `withImage`) and the name of the
/// device that rendered it.
std::string packMeasurement(const Measurement& m, bool withImage, const std::string& device);
/// The inverse of packMeasurement; the device's name into `device`. Throws rt::Error when the bytes are not one.
Measurement unpackMeasurement(const std::string& bytes, std::string& device);

/// What every relMSE of a comparison is measured against (root sends it to every rank of a distributed one).
struct Reference
{
    Image image;
    std::optional<double> ownRelMse; // the reference's own noise in every relMSE (none known for a file)
    std::string description; // "4096 spp" or the file's path
    int spp = 0; // both halves together; 0 for a file
};
std::string packReference(const Reference& reference);
/// Throws rt::Error when the bytes are not one.
Reference unpackReference(const std::string& bytes);
} // namespace rt::compare
