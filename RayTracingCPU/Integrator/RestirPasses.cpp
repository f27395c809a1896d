#include "Integrator/RestirPasses.h"

#include <algorithm>

#include "Integrator/PathIntegrator.h"
#include "Shared/Medium.h"

namespace rt::cpu
{
namespace
{
// The restir-di streams of a (seed, pixel, sample), apart from the camera path's own: the path's numbers, and so
// its vertex, are the same in both passes and the same as nee-mis's.
constexpr std::uint32_t kCandidateStream = 0x52535431u;
constexpr std::uint32_t kSpatialStream = 0x52535432u;
/// Spatial reuse's inputs at most: the pixel's own and its neighbours.
constexpr int kMaxInputs = 1 + 64;

using Shading = CpuShading<PathCode{}>;

using Input = Shading::RestirInput;

/// The scene, the shading and the medium flag a pass shares.
struct PassContext
{
    const CpuScene& scene;
    Shading shading;
    const shader::RenderUniforms& uniforms;
    bool media;

    /// Shared/Shading/Restir.h combineReservoirs over inputs[0, n) at inputs[0]'s vertex.
    shader::Reservoir combine(const Input* inputs, int n, shader::Rng& rng)
    {
        shading.restirInputs = inputs;
        return shading.combineReservoirs(inputs[0].vertex, n, rng);
    }
};

/// The camera path of sample `sampleIndex` of pixel (x, y) up to its first vertex where NEE would run: the
/// surface there (material kNoIndex if it has none), `path` and `segment` as they arrive at it.
shader::RestirSurface findSurface(PassContext& c, const PathJob& job, shader::PathState& path, std::uint32_t& segment,
                                  RestirRowTally& tally)
{
    shader::RestirSurface surface{};
    surface.hit.material = kNoIndex;
    float depth = 0.0f;
    const TraceRay::Needs needs = c.scene.rayNeeds();
    for (segment = 0; segment < c.uniforms.depth; ++segment)
    {
        HitRecord hit{};
        countPathRay(tally.counts, segment);
        const bool found = c.scene.intersect(TraceRay(Ray{path.origin, path.direction, job.ray.time}, needs), 0.0f,
                                             kInfinity, hit, job.mediumSeed);
        const shader::HitPayload payload =
            hitPayload(c.scene, Ray{path.origin, path.direction, job.ray.time}, found, hit);
        if (found)
            depth += length(payload.position - path.origin);
        if (c.shading.resamplesDirectAt(payload, segment, path))
        {
            surface.hit = payload;
            surface.incoming = path.direction;
            surface.depth = depth;
            return surface;
        }
        shader::ShadowRay shadow{};
        if (!c.shading.shadePathVertex(path, segment, payload, shadow, false))
            break; // no shadow ray is pending: NEE runs only where the vertex would be resampled
    }
    return surface;
}

} // namespace

RestirBuffers::RestirBuffers(int w, int h)
    : surfaces(std::size_t(w) * h), temporal(std::size_t(w) * h, shader::emptyReservoir()),
      final(std::size_t(w) * h, shader::emptyReservoir()), width(w), height(h)
{
    for (shader::RestirSurface& s : surfaces)
        s.hit.material = kNoIndex;
}

void restirCandidatesRow(const CpuScene& scene, const shader::RenderUniforms& uniforms, RestirBuffers& buffers, int y,
                         std::uint32_t sampleIndex, RestirRowTally& tally)
{
    PassContext c{scene, Shading(scene, uniforms), uniforms, scene.hasMedia()};
    const float candidates = float(uniforms.restirCandidates);
    for (int x = 0; x < buffers.width; ++x)
    {
        const std::size_t i = std::size_t(y) * buffers.width + x;
        const PathJob job = cameraJob(c.shading, c.media, std::uint32_t(x), std::uint32_t(y), sampleIndex);
        shader::PathState path = shader::startPath(job.ray.origin, job.ray.direction, job.rng);
        std::uint32_t segment = 0;
        const shader::RestirSurface last = buffers.surfaces[i];
        const shader::Reservoir lastReservoir = buffers.final[i];
        const shader::RestirSurface surface = findSurface(c, job, path, segment, tally);
        buffers.surfaces[i] = surface;
        Input inputs[2];
        inputs[0].vertex = c.shading.restirVertexOf(surface);
        inputs[0].pixel = uvec2(std::uint32_t(x), std::uint32_t(y));
        inputs[0].sampleIndex = sampleIndex;
        inputs[0].reservoir = shader::emptyReservoir();
        if (!inputs[0].vertex.valid)
        {
            buffers.temporal[i] = inputs[0].reservoir;
            continue;
        }
        // Initial resampling (Alg. 3): M candidates from the render's light selection and sampler.
        shader::Rng rng = shader::rngForSample(uniforms.seed ^ kCandidateStream, std::uint32_t(i), sampleIndex);
        shader::Reservoir& r = inputs[0].reservoir;
        float weightSum = 0.0f;
        const float xi = shader::nextFloat(rng);
        for (std::uint32_t k = 0; k < uniforms.restirCandidates; ++k)
        {
            const float uSelect = shader::stratifiedCandidateNumber(k, uniforms.restirCandidates, xi);
            const vec2 uLight = shader::nextFloat2(rng);
            const float uTake = shader::nextFloat(rng);
            std::uint32_t light;
            vec3 point;
            float target;
            std::uint32_t lightSample;
            const float w =
                c.shading.restirCandidate(inputs[0].vertex, uSelect, uLight, light, point, target, lightSample);
            countLightSample(tally.counts.lightSamples, lightSample);
            shader::offerCandidate(r, weightSum, light, point, target, w, uTake);
        }
        r.count = candidates;
        r.weight = shader::contributionWeight(weightSum, r.target, candidates);
        if (r.weight > 0.0f && !c.shading.restirVisible(inputs[0].vertex, r.point, inputs[0].pixel, sampleIndex))
            r.weight = 0.0f; // visibility reuse (§4.1)
        // Temporal reuse (Alg. 5; pairwise MIS with k = 1): the pixel's last final reservoir, its M capped.
        int n = 1;
        if (buffers.history && uniforms.restirTemporalCap > 0u && lastReservoir.count > 0.0f &&
            last.hit.material != kNoIndex)
        {
            inputs[1].reservoir = lastReservoir;
            inputs[1].reservoir.count = std::min(lastReservoir.count, float(uniforms.restirTemporalCap) * candidates);
            inputs[1].vertex = c.shading.restirVertexOf(last);
            inputs[1].pixel = inputs[0].pixel;
            inputs[1].sampleIndex = sampleIndex - 1u;
            n = 2;
        }
        buffers.temporal[i] = n == 1 ? r : c.combine(inputs, n, rng);
    }
    tally.counts.rays.shadow += c.shading.restirShadowRays;
}

void restirShadeRow(const CpuScene& scene, const shader::RenderUniforms& uniforms, RestirBuffers& buffers, int y,
                    std::uint32_t sampleIndex, vec3* radiance, RestirRowTally& tally)
{
    PassContext c{scene, Shading(scene, uniforms), uniforms, scene.hasMedia()};
    const int k = std::min<int>(int(uniforms.restirSpatial), kMaxInputs - 1);
    Input inputs[kMaxInputs];
    const TraceRay::Needs needs = scene.rayNeeds();
    for (int x = 0; x < buffers.width; ++x)
    {
        const std::size_t i = std::size_t(y) * buffers.width + x;
        const shader::RestirSurface& surface = buffers.surfaces[i];
        inputs[0].reservoir = buffers.temporal[i];
        inputs[0].vertex = c.shading.restirVertexOf(surface);
        inputs[0].pixel = uvec2(std::uint32_t(x), std::uint32_t(y));
        inputs[0].sampleIndex = sampleIndex;
        const PathJob job = cameraJob(c.shading, c.media, std::uint32_t(x), std::uint32_t(y), sampleIndex);
        shader::Reservoir final = inputs[0].reservoir;
        if (inputs[0].vertex.valid && k > 0)
        {
            // Spatial reuse (Alg. 5's neighbours; pairwise MIS): k pixels drawn in a disk, similar ones kept.
            shader::Rng rng = shader::rngForSample(uniforms.seed ^ kSpatialStream, std::uint32_t(i), sampleIndex);
            int n = 1;
            for (int j = 0; j < k; ++j)
            {
                uvec2 neighbour;
                if (!c.shading.restirNeighbour(uvec2(std::uint32_t(x), std::uint32_t(y)), shader::nextFloat2(rng),
                                               std::uint32_t(buffers.width), std::uint32_t(buffers.height), neighbour))
                    continue;
                const std::size_t ni = std::size_t(neighbour.y) * buffers.width + neighbour.x;
                const shader::RestirSurface& other = buffers.surfaces[ni];
                if (other.hit.material == kNoIndex || !(buffers.temporal[ni].count > 0.0f))
                    continue;
                Input& in = inputs[n];
                in.vertex = c.shading.restirVertexOf(other);
                if (!c.shading.restirSimilar(surface, inputs[0].vertex, other, in.vertex))
                    continue;
                in.reservoir = buffers.temporal[ni];
                in.pixel = neighbour;
                in.sampleIndex = sampleIndex;
                ++n;
            }
            if (n > 1)
                final = c.combine(inputs, n, rng);
        }
        buffers.final[i] = final;

        // The camera path again, from its first segment: its numbers find the same vertex, whose direct light is
        // f(y) W of the final reservoir; nee-mis's at every later vertex.
        shader::PathState path = shader::startPath(job.ray.origin, job.ray.direction, job.rng);
        bool resampled = false;
        for (std::uint32_t segment = 0; segment < uniforms.depth; ++segment)
        {
            HitRecord hit{};
            countPathRay(tally.counts, segment);
            const bool found = scene.intersect(TraceRay(Ray{path.origin, path.direction, job.ray.time}, needs), 0.0f,
                                               kInfinity, hit, job.mediumSeed);
            const shader::HitPayload payload =
                hitPayload(scene, Ray{path.origin, path.direction, job.ray.time}, found, hit);
            const bool here = !resampled && c.shading.resamplesDirectAt(payload, segment, path);
            vec3 direct(0.0f);
            if (here && final.weight > 0.0f)
                direct = path.beta * c.shading.restirIntegrand(inputs[0].vertex, final.light, final.point) * final.weight;
            // No shadow ray is pending at the resampled vertex: `direct` is added after its emission, as NEE's would be.
            const bool goesOn = continuePath(c.shading, scene, path, job, segment, payload, here, tally.counts);
            path.radiance += direct;
            resampled = resampled || here;
            if (!goesOn)
                break;
        }
        radiance[x] = path.radiance;
    }
    tally.counts.rays.shadow += c.shading.restirShadowRays;
}
} // namespace rt::cpu
