// Compiling several pipelines at once. A driver compiles a pipeline on the thread that asks for it, and a pipeline's
// creation functions are free-threaded (Vulkan spec, "Threading Behavior": only the pipeline cache, none here, would
// need external synchronisation), so pipelines of different keys compile side by side on threads of their own.
#pragma once

#include <exception>
#include <future>
#include <map>
#include <memory>
#include <set>
#include <system_error>
#include <span>
#include <vector>

namespace rt::gpu
{
/// Makes `make(key)` for every key of `keys` not in `compiled` (duplicates once), each on a thread of its own, and
/// adds them to `compiled` on the caller's thread. `make` must touch nothing shared but what the driver synchronises.
/// When some throw, the others are still added and the first exception (in `keys`' order) is rethrown.
template <class Key, class Compiled, class Make>
void compileTogether(std::map<Key, std::unique_ptr<Compiled>>& compiled, std::span<const Key> keys, Make make)
{
    std::vector<Key> missing;
    std::set<Key> seen; // keys are ordered (map keys), not necessarily comparable for equality
    for (const Key& key : keys)
        if (!compiled.contains(key) && seen.insert(key).second)
            missing.push_back(key);
    std::vector<std::future<std::unique_ptr<Compiled>>> jobs;
    jobs.reserve(missing.size());
    for (const Key& key : missing)
    {
        auto job = [&make, key] { return make(key); };
        try
        {
            jobs.push_back(std::async(std::launch::async, job));
        }
        catch (const std::system_error&) // no thread to be had: compiled on the caller's, in turn
        {
            jobs.push_back(std::async(std::launch::deferred, job));
        }
    }
    std::exception_ptr first;
    for (std::size_t i = 0; i < jobs.size(); ++i)
        try
        {
            compiled.emplace(missing[i], jobs[i].get());
        }
        catch (...)
        {
            if (!first)
                first = std::current_exception();
        }
    if (first)
        std::rethrow_exception(first);
}
} // namespace rt::gpu
