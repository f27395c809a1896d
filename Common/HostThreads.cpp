#include "HostThreads.h"

#include <algorithm>
#include <exception>
#include <thread>
#include <vector>

#if defined(__linux__)
#include <sched.h>
#endif

namespace rt
{
int usableCores()
{
#if defined(__linux__)
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof(set), &set) == 0)
        return std::max(1, CPU_COUNT(&set));
#endif
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

void runInParallel(int parts, const std::function<void(int part)>& work)
{
    std::vector<std::exception_ptr> errors(static_cast<std::size_t>(parts));
    const auto guarded = [&](int part) {
        try
        {
            work(part);
        }
        catch (...)
        {
            errors[static_cast<std::size_t>(part)] = std::current_exception();
        }
    };
    {
        std::vector<std::jthread> threads;
        for (int part = 0; part + 1 < parts; ++part)
            threads.emplace_back(guarded, part);
        guarded(parts - 1);
    }
    for (const std::exception_ptr& e : errors)
        if (e)
            std::rethrow_exception(e);
}
} // namespace rt
