// Linked into each app (not into rt_common: a static library's object that nothing references would be
// dropped). A build for x86-64-v3 or v4 run on a CPU without AVX2 or AVX-512 dies with SIGILL in whatever
// code runs first (static initialisers, CLI11 building the flags) before main could say why: this check runs
// before all of them (a constructor of priority 101), in code compiled for the baseline x86-64
// (Common/CMakeLists.txt). RT_REQUIRES_X86_LEVEL is the level the build targets (3 or 4).
#if defined(RT_REQUIRES_X86_LEVEL) && defined(__GNUC__)
#include <cstdio>
#include <cstdlib>

#include "Cli/CpuLevel.h"

namespace
{
__attribute__((constructor(101))) void requireX86Level()
{
    const bool ok = RT_REQUIRES_X86_LEVEL >= 4 ? rt::cpuHasX86Level4() : rt::cpuHasX86Level3();
    if (!ok)
    {
        std::fputs(RT_REQUIRES_X86_LEVEL >= 4
                       ? "error: this build needs a CPU with AVX-512 (x86-64-v4); rebuild with -DRT_X86_LEVEL=x86-64-v2\n"
                       : "error: this build needs a CPU with AVX2 (x86-64-v3); rebuild with -DRT_X86_LEVEL=x86-64-v2\n",
                   stderr);
        std::_Exit(1);
    }
}
} // namespace
#endif
