#include "Render/EngineRegistry.h"

#include <array>
#include <mutex>

#include <spdlog/fmt/fmt.h>

#include "Error.h"

namespace rt::engines
{
namespace
{
constexpr std::array kKinds = {EngineKind::Single, EngineKind::Multi, EngineKind::Gpu};

struct Registry
{
    std::mutex mutex;
    std::array<EngineFactory, kKinds.size()> factories{};
};

/// Constructed on first use: registration objects run during static initialisation, in an unknown order.
Registry& registry()
{
    static Registry r;
    return r;
}

std::size_t slot(EngineKind kind) { return static_cast<std::size_t>(kind); }
} // namespace

bool add(std::initializer_list<EngineKind> kinds, EngineFactory factory)
{
    Registry& r = registry();
    const std::lock_guard lock(r.mutex);
    for (const EngineKind kind : kinds)
        if (!r.factories[slot(kind)])
            r.factories[slot(kind)] = factory;
    return true;
}

bool has(EngineKind kind)
{
    Registry& r = registry();
    const std::lock_guard lock(r.mutex);
    return r.factories[slot(kind)] != nullptr;
}

std::vector<EngineKind> available()
{
    std::vector<EngineKind> kinds;
    for (const EngineKind kind : kKinds)
        if (has(kind))
            kinds.push_back(kind);
    return kinds;
}

std::unique_ptr<RenderEngine> make(EngineKind kind, const EngineOptions& options)
{
    EngineFactory factory;
    {
        Registry& r = registry();
        const std::lock_guard lock(r.mutex);
        factory = r.factories[slot(kind)];
    }
    if (!factory)
        throw UsageError(fmt::format("this build has no {} engine", toString(kind)));
    return factory(kind, options);
}
} // namespace rt::engines
